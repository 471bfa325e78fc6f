// The mixed film's block Gauss–Seidel preconditioner
// (mixed_block_preconditioner.hpp).
#include "mixed_block_preconditioner.hpp"

#include <fmt/format.h>

#include "halfspace/linalg/parallel.hpp"

namespace halfspace::lubrication::detail {

MixedBlockPreconditioner::MixedBlockPreconditioner(const Grid& grid, int line_axis)
    : n_(grid.size()), multigrid_(grid, line_axis, true) {
  const auto ni = static_cast<Eigen::Index>(n_);
  spot_index_.assign(n_, -1);
  total_.resize(ni);
  mass_rhs_.resize(ni);
  v_s_.resize(ni);
  open_q_.resize(ni);
  weight_q_.resize(n_);
  weight_film_.resize(n_);
}

bool MixedBlockPreconditioner::factorise(const CsrMatrix& mass, const CsrMatrix& film, const CsrMatrix& near,
                                         const std::vector<char>& closed, const Eigen::VectorXd& dp_ds,
                                         double pressure_scale, double film_scale, const std::vector<double>* by_q,
                                         const std::vector<double>* by_film, std::string& message) {
  film_ = &film;
  near_ = &near;
  dp_ds_ = &dp_ds;
  for (std::size_t k = 0; k < n_; ++k) {
    const bool is_closed = closed[k] != 0;
    weight_q_[k] = by_q != nullptr ? (*by_q)[k] : (is_closed ? 0.0 : 1.0);
    weight_film_[k] = by_film != nullptr ? (*by_film)[k] : (is_closed ? 1.0 : 0.0);
  }
  pressure_ = pressure_scale;
  film_scale_ = film_scale;
  if (!multigrid_.factorise(mass, message)) return false;
  spot_node_.clear();
  for (std::size_t k = 0; k < n_; ++k) {
    spot_index_[k] = closed[k] != 0 ? static_cast<int>(spot_node_.size()) : -1;
    if (closed[k] != 0) spot_node_.push_back(k);
  }
  const auto spots = static_cast<Eigen::Index>(spot_node_.size());
  spot_rhs_.resize(spots);
  spot_total_.resize(spots);
  if (spots == 0) return true;
  spot_entries_.clear();
  for (std::size_t c = 0; c < spot_node_.size(); ++c) {
    const std::size_t k = spot_node_[c];
    for (int e = near.start[k]; e < near.start[k + 1]; ++e) {
      const auto m = static_cast<std::size_t>(near.column[e]);
      if (spot_index_[m] >= 0) spot_entries_.emplace_back(static_cast<int>(c), spot_index_[m], near.value[e]);
    }
    const double shift = weight_q_[k] * film_scale_ / (weight_film_[k] * pressure_);
    if (shift != 0.0) spot_entries_.emplace_back(static_cast<int>(c), static_cast<int>(c), shift);
  }
  spots_.resize(spots, spots);
  spots_.setFromTriplets(spot_entries_.begin(), spot_entries_.end());
  spots_lu_.compute(spots_);  // the spots change between Newton steps: analysed afresh (they are small)
  if (spots_lu_.info() != Eigen::Success) {
    message = fmt::format("the mixed film's preconditioner: the {} closed contact rows' truncated K is singular: {}",
                          spots, spots_lu_.lastErrorMessage());
    return false;
  }
  return true;
}

void MixedBlockPreconditioner::solve_spots(const Eigen::VectorXd& in, const Eigen::VectorXd& v_s) {
  const auto ni = static_cast<Eigen::Index>(n_);
  const Eigen::VectorXd& dp_ds = *dp_ds_;
  for (std::size_t c = 0; c < spot_node_.size(); ++c) {
    const std::size_t k = spot_node_[c];
    const auto kk = static_cast<Eigen::Index>(k);
    const double by_film = weight_film_[k];
    double rhs = film_scale_ * (in[ni + kk] + weight_q_[k] * dp_ds[kk] * v_s[kk] / pressure_) / by_film;
    const CsrMatrix& near = *near_;
    for (int e = near.start[k]; e < near.start[k + 1]; ++e) {
      const auto m = static_cast<std::size_t>(near.column[e]);
      if (spot_index_[m] >= 0) continue;
      const auto mm = static_cast<Eigen::Index>(m);
      rhs -= near.value[e] * (dp_ds[mm] * v_s[mm] + pressure_ * in[ni + mm] / weight_q_[m]);
    }
    spot_rhs_[static_cast<Eigen::Index>(c)] = rhs;
  }
  spot_total_ = spots_lu_.solve(spot_rhs_);
}

void MixedBlockPreconditioner::apply(const Eigen::VectorXd& in, Eigen::VectorXd& out) {
  const auto ni = static_cast<Eigen::Index>(n_);
  const CsrMatrix& film = *film_;
  const Eigen::VectorXd& dp_ds = *dp_ds_;
  const bool spots = !spot_node_.empty();
  // The open rows' v_q, the spots' total pressure with v_s = 0, then the
  // mass rows given it.
  linalg::for_each_index(n_, [&](std::size_t k) {
    const auto kk = static_cast<Eigen::Index>(k);
    open_q_[kk] = spot_index_[k] >= 0 ? 0.0 : in[ni + kk] / weight_q_[k];
    total_[kk] = pressure_ * open_q_[kk];
  });
  if (spots) {
    v_s_.setZero();
    solve_spots(in, v_s_);
    for (std::size_t c = 0; c < spot_node_.size(); ++c) {
      total_[static_cast<Eigen::Index>(spot_node_[c])] = spot_total_[static_cast<Eigen::Index>(c)];
    }
  }
  linalg::for_each_index(n_, [&](std::size_t k) {
    double sum = in[static_cast<Eigen::Index>(k)];
    for (int e = film.start[k]; e < film.start[k + 1]; ++e) sum -= film.value[e] * total_[film.column[e]];
    mass_rhs_[static_cast<Eigen::Index>(k)] = sum;
  });
  multigrid_.apply(mass_rhs_, v_s_);
  out.resize(2 * ni);
  linalg::for_each_index(n_, [&](std::size_t k) {
    const auto kk = static_cast<Eigen::Index>(k);
    out[kk] = v_s_[kk];
    out[ni + kk] = open_q_[kk];
  });
  if (!spots) return;
  // The spots again with the mass rows' v_s.
  solve_spots(in, v_s_);
  for (std::size_t c = 0; c < spot_node_.size(); ++c) {
    const auto k = static_cast<Eigen::Index>(spot_node_[c]);
    out[ni + k] = (spot_total_[static_cast<Eigen::Index>(c)] - dp_ds[k] * v_s_[k]) / pressure_;
  }
}

double MixedBlockPreconditioner::bytes_per_node(double row_entries) {
  return FilmMultigrid::bytes_per_node(row_entries) + 7.0 * 8.0;
}

}  // namespace halfspace::lubrication::detail
