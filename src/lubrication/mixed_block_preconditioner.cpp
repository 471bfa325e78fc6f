// The mixed film's block Gauss–Seidel preconditioner
// (mixed_block_preconditioner.hpp).
#include "mixed_block_preconditioner.hpp"

#include <fmt/format.h>

#include "halfspace/linalg/parallel.hpp"

namespace halfspace::lubrication::detail {

MixedBlockPreconditioner::MixedBlockPreconditioner(const Grid& grid, int line_axis, const LocalInfluence& local)
    : local_(local), n_(grid.size()), multigrid_(grid, line_axis, true) {
  const auto ni = static_cast<Eigen::Index>(n_);
  spot_index_.assign(n_, -1);
  total_.resize(ni);
  mass_rhs_.resize(ni);
  v_s_.resize(ni);
}

bool MixedBlockPreconditioner::factorise(const CsrMatrix& mass, const CsrMatrix& film, const std::vector<char>& closed,
                                         const Eigen::VectorXd& dp_ds, double pressure_scale, double film_scale,
                                         std::string& message) {
  film_ = &film;
  closed_ = &closed;
  dp_ds_ = &dp_ds;
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
    local_.for_each(spot_node_[c], [&](std::size_t m, double k_value) {
      if (spot_index_[m] >= 0) spot_entries_.emplace_back(static_cast<int>(c), spot_index_[m], k_value);
    });
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
    double rhs = film_scale_ * in[ni + static_cast<Eigen::Index>(k)];
    local_.for_each(k, [&](std::size_t m, double k_value) {
      if (spot_index_[m] >= 0) return;
      const auto mm = static_cast<Eigen::Index>(m);
      rhs -= k_value * (dp_ds[mm] * v_s[mm] + pressure_ * in[ni + mm]);
    });
    spot_rhs_[static_cast<Eigen::Index>(c)] = rhs;
  }
  spot_total_ = spots_lu_.solve(spot_rhs_);
}

void MixedBlockPreconditioner::apply(const Eigen::VectorXd& in, Eigen::VectorXd& out) {
  const auto ni = static_cast<Eigen::Index>(n_);
  const CsrMatrix& film = *film_;
  const Eigen::VectorXd& dp_ds = *dp_ds_;
  const bool spots = !spot_node_.empty();
  // The spots' total pressure with v_s = 0, then the mass rows given it.
  total_ = pressure_ * in.tail(ni);
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
  out.head(ni) = v_s_;
  out.tail(ni) = in.tail(ni);
  if (!spots) return;
  // The spots again with the mass rows' v_s.
  solve_spots(in, v_s_);
  for (std::size_t c = 0; c < spot_node_.size(); ++c) {
    const auto k = static_cast<Eigen::Index>(spot_node_[c]);
    out[ni + k] = (spot_total_[static_cast<Eigen::Index>(c)] - dp_ds[k] * v_s_[k]) / pressure_;
  }
}

double MixedBlockPreconditioner::bytes_per_node(double row_entries) {
  return FilmMultigrid::bytes_per_node(row_entries) + 4.0 * 8.0;
}

}  // namespace halfspace::lubrication::detail
