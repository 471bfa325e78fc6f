// GMRES on the mixed film's Newton system (mixed_film_krylov.hpp). With the
// unknowns [s, q, h0], p_f = P max(s, 0), theta = 1 + min(s, 0), p_c = P q,
// and dh = K (dp_f + dp_c) + dh0 the film's change, the Jacobian applied to
// v = [v_s, v_q, v_0] is
//
//   mass row k:    sum over k's local terms (node j) of
//                    by_pressure dp_f_j + by_fraction dtheta_j + by_film D_j dh_j
//   contact row k: v_q_k (open: p_c = 0), or dh_k / H (closed: h = 0), or
//                  a_k v_q_k + b_k dh_k / H (smoothed rows' weights)
//   load row:      dA / w sum(dp_f + dp_c)
//
// with dp_f = P v_s on full nodes, dtheta = v_s on cavitated ones, dp_c =
// P v_q and D_j = dh_R / dh (reynolds_film's slope: 0 in contact; on point
// contacts 1 also where the step lifts h_j above 1.5 h_b: mixed_film.cpp's
// take_step_branches), the same rows mixed_film.cpp's
// dense path assembles. One operator product per product with J. The preconditioner is J with K
// truncated to (2r + 1)^2 cells around each node: in the mass rows, as the
// EHL film's preconditioner, the film's Couette difference A_h K is local
// (Venner & Lubrecht 2000's differential deflection), and in the closed
// contact rows the truncated K keeps the stiff local part of the contact
// operator, leaving GMRES its smooth far field. The bordered system (h0
// column c, load row l) is solved through B's approximate inverse (the
// block Gauss–Seidel's or the LU's) by the Schur complement.
#include "mixed_film_krylov.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <tuple>

#include "csr_rows_in_runs.hpp"
#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::lubrication::detail {

namespace {
// Entries per node of the preconditioner: a mass row's (up to 8) local terms
// spread over the (2r + 1)^2 truncated K, twice (s and q), and a contact
// row's (2r + 1)^2, twice.
double preconditioner_node_entries(int r) {
  const double patch = (2.0 * r + 1.0) * (2.0 * r + 1.0);
  return 2.0 * (2.0 * r + 3.0) * (2.0 * r + 5.0) + 2.0 * patch;
}
// SparseLU's fill relative to the entries: an allowance (measured peaks,
// the program's own 30 MB taken off: 10.9 kB per node at 64^2, 21.8 kB at
// 128^2 on a rough point contact, against 25 kB estimated with this).
constexpr double kFillAllowance = 20.0;
}  // namespace

double mixed_krylov_memory_estimate(std::size_t nodes, const MixedKrylovSettings& settings) {
  const double entries = preconditioner_node_entries(settings.neighbourhood);
  // The block preconditioner's M and F hold a mass row's entries each (half
  // of the node's), the V-cycle its levels; the LU the whole sparse part,
  // its copy and its fill.
  // The block preconditioner also keeps the truncated K around each node.
  const double patch = (2.0 * settings.neighbourhood + 1.0) * (2.0 * settings.neighbourhood + 1.0);
  const double preconditioner =
      settings.preconditioner == KrylovPreconditioner::multigrid
          ? entries * 12.0 + patch * 12.0 + MixedBlockPreconditioner::bytes_per_node(0.5 * entries)
          : entries * (12.0 + 12.0) + entries * kFillAllowance * 12.0;
  const double per_node = 2.0 * 8.0 * (settings.restart + 1)  // GMRES basis, 2 unknowns per node
                          + 16.0 * sizeof(LocalTerm)          // local rows
                          + 16.0 * (sizeof(int) + 16.0)       // their derivatives on the solve's branches
                          + preconditioner + 8.0 * 60.0;      // the Newton state and work vectors
  return per_node * static_cast<double>(nodes);
}

MixedKrylovSolver::MixedKrylovSolver(InfluenceOperator& op, const ReynoldsStencil& topology,
                                     const MixedKrylovSettings& settings, bool load_control, const FilmSlab& slab,
                                     ArnoldiStorage* arnoldi)
    : op_(op),
      topology_(topology),
      settings_(settings),
      slab_(slab),
      n_(slab.own_nodes()),
      first_(slab.own_first()),
      local_(op, settings.neighbourhood, slab.first_row()) {
  const auto ni = static_cast<Eigen::Index>(n_);
  const auto stencil = static_cast<Eigen::Index>(slab.stencil_nodes());
  const bool spread = slab.distributed();
  if (spread && settings_.preconditioner != KrylovPreconditioner::multigrid) {
    throw InputError(
        "the mixed film's sparse-lu preconditioner runs on one process: use the multigrid preconditioner on several");
  }
  m_ = 2 * ni + (load_control ? 1 : 0);
  scales_.load_control = load_control;
  dp_ds_.setZero(stencil);
  dtheta_ds_.setZero(stencil);
  closed_stencil_.setZero(stencil);
  total_.resize(ni);
  deflection_.resize(ni);
  if (spread) {
    v_stencil_.setZero(stencil);
    deflection_stencil_.setZero(stencil);
  }
  krylov_.setup(
      m_, 2 * ni, settings_.restart,
      [this](const Eigen::VectorXd& in, Eigen::VectorXd& out) { apply_preconditioner(in, out); }, arnoldi);
  krylov_.distribute(slab.krylov_distribution());
  if (settings_.preconditioner != KrylovPreconditioner::multigrid) {
    preconditioner_ = make_film_preconditioner(KrylovPreconditioner::sparse_lu, op.grid(), 0);
    return;
  }
  // K near each own node, in whole-grid columns (it does not change).
  gather_rows_in_runs(near_, n_, row_runs_, row_count_, [&](std::size_t k, std::vector<std::pair<int, double>>& row) {
    local_.for_each(slab.whole_node(first_ + k),
                    [&](std::size_t node, double k_value) { row.emplace_back(static_cast<int>(node), k_value); });
  });
  const int line_axis = topology.couette_y() > topology.couette_x() ? 1 : 0;
  Grid block_grid = slab.own_grid();
  if (spread) {
    std::tie(below_, above_) = slab.rows_around_limits(kSlabOverlapRows);
    const Grid& whole = slab.whole_grid();
    block_grid = Grid::plane(whole.nx(), n_ / whole.nx() + below_ + above_, whole.dx(), whole.dy(), whole.boundary());
    const auto block_n = static_cast<Eigen::Index>(block_grid.size());
    block_in_.setZero(2 * block_n);
    block_out_.setZero(2 * block_n);
    slab.gather_rows(near_, below_, above_, block_near_, block_scratch_);
  }
  block_ = std::make_unique<MixedBlockPreconditioner>(block_grid, line_axis);
}

void MixedKrylovSolver::apply_jacobian(const Eigen::VectorXd& v, Eigen::VectorXd& out) {
  const auto ni = static_cast<Eigen::Index>(n_);
  const auto first = static_cast<Eigen::Index>(first_);
  const double P = scales_.pressure;
  total_ = dp_ds_.segment(first, ni).cwiseProduct(v.head(ni)) + P * v.segment(ni, ni);
  op_.apply(std::span<const double>(total_.data(), n_), std::span<double>(deflection_.data(), n_));
  if (scales_.load_control) deflection_.array() += v[2 * ni];
  // The mass rows reach the halo's nodes: v_s and the film's change there
  // from their owners.
  const double* values = slab_.on_stencil(v.head(ni), v_stencil_);
  const double* deflection = slab_.on_stencil(deflection_, deflection_stencil_);
  const std::vector<char>& closed = *closed_;
  linalg::for_each_index(n_, [&](std::size_t k) {
    const auto kk = static_cast<Eigen::Index>(k);
    if (topology_.fixed(first_ + k)) {
      out[kk] = v[kk];
    } else {
      double sum = 0.0;
      for (std::size_t t = rows_->start[k]; t < rows_->start[k + 1]; ++t) {
        const int j = term_node_[t];
        sum += term_by_s_[t] * values[j];
        sum += term_by_deflection_[t] * deflection[j];
      }
      out[kk] = sum / scales_.mass;
    }
    if (!rows_->contact_by_q.empty()) {
      out[ni + kk] = rows_->contact_by_q[k] * v[ni + kk] + rows_->contact_by_film[k] * deflection_[kk] / scales_.film;
    } else {
      out[ni + kk] = closed[k] != 0 ? deflection_[kk] / scales_.film : v[ni + kk];
    }
  });
  if (scales_.load_control) {
    out[2 * ni] =
        scales_.area_over_load * slab_.sum(dp_ds_.segment(first, ni).dot(v.head(ni)) + P * v.segment(ni, ni).sum());
  }
}

void MixedKrylovSolver::apply_preconditioner(const Eigen::VectorXd& in, Eigen::VectorXd& out) {
  if (!block_) return preconditioner_->apply(in, out);
  if (!slab_.distributed()) return block_->apply(in, out);
  // Restricted additive Schwarz: the block's right-hand side (mass rows,
  // then contact rows) with the neighbours' overlap rows, its approximate
  // inverse, this process's rows of both halves.
  const auto ni = static_cast<Eigen::Index>(n_);
  const Eigen::Index block_n = block_in_.size() / 2;
  slab_.rows_around(in.data(), below_, above_, 1, block_in_.data());
  slab_.rows_around(in.data() + ni, below_, above_, 1, block_in_.data() + block_n);
  block_->apply(block_in_, block_out_);
  const auto own_at = static_cast<Eigen::Index>(below_ * slab_.whole_grid().nx());
  out.resize(2 * ni);
  out.head(ni) = block_out_.segment(own_at, ni);
  out.tail(ni) = block_out_.segment(block_n + own_at, ni);
}

void MixedKrylovSolver::film_change(const Eigen::VectorXd& step, Eigen::VectorXd& out) {
  const auto ni = static_cast<Eigen::Index>(n_);
  total_ = dp_ds_.segment(static_cast<Eigen::Index>(first_), ni).cwiseProduct(step.head(ni)) +
           scales_.pressure * step.segment(ni, ni);
  out.resize(ni);
  op_.apply(std::span<const double>(total_.data(), n_), std::span<double>(out.data(), n_));
  if (scales_.load_control) out.array() += step[2 * ni];
}

// Mass row k (an own node) of the sparse part: its local terms' d/ds
// through s_entry(whole-grid node, value) (the identity on a fixed node),
// and each open film term's by_film K around its node through
// film_entry(whole-grid node, by_film K); with `every_entry` also the zero
// ones (closed film terms), so that the LU's pattern stays the same at
// every Newton step. Called from several threads at once.
template <class SEntry, class FilmEntry>
void MixedKrylovSolver::mass_row(std::size_t k, bool every_entry, SEntry&& s_entry, FilmEntry&& film_entry) const {
  if (topology_.fixed(first_ + k)) {
    s_entry(slab_.whole_node(first_ + k), 1.0);
    return;
  }
  const double mass = scales_.mass;
  for (std::size_t t = rows_->start[k]; t < rows_->start[k + 1]; ++t) {
    const std::size_t whole = slab_.whole_node(static_cast<std::size_t>(term_node_[t]));
    s_entry(whole, term_by_s_[t] / mass);
    const double by_film = term_by_deflection_[t] / mass;
    if (by_film == 0.0 && !every_entry) continue;
    local_.for_each(whole, [&](std::size_t node, double k_value) { film_entry(node, by_film * k_value); });
  }
}

// The mass rows' h0 derivatives into krylov_.border_column's first n entries.
void MixedKrylovSolver::mass_rows_border() {
  const double mass = scales_.mass;
  linalg::for_each_index(n_, [&](std::size_t k) {
    double sum = 0.0;
    if (!topology_.fixed(first_ + k)) {
      for (std::size_t t = rows_->start[k]; t < rows_->start[k + 1]; ++t) sum += term_by_deflection_[t] / mass;
    }
    krylov_.border_column[static_cast<Eigen::Index>(k)] = sum;
  });
}

bool MixedKrylovSolver::factorise_block(std::string& message) {
  const auto ni = static_cast<Eigen::Index>(n_);
  const double H = scales_.film;
  const std::vector<char>& closed = *closed_;
  const bool spread = slab_.distributed();
  mass_rows_border();
  for (std::size_t k = 0; k < n_; ++k) closed_stencil_[static_cast<Eigen::Index>(first_ + k)] = closed[k];
  slab_.exchange(closed_stencil_.data());
  // M takes the film's K on the open cells (through dp/ds), F all of it;
  // on a slab M keeps the cells the stencil holds.
  gather_rows_in_runs(matrix_, n_, row_runs_, row_count_, [&](std::size_t k, std::vector<std::pair<int, double>>& row) {
    mass_row(
        k, false, [&](std::size_t node, double entry) { row.emplace_back(static_cast<int>(node), entry); },
        [&](std::size_t node, double entry) {
          const std::size_t at = slab_.stencil_node(node);
          if (at == FilmSlab::kOutside) return;
          const auto aa = static_cast<Eigen::Index>(at);
          if (closed_stencil_[aa] == 0.0) row.emplace_back(static_cast<int>(node), entry * dp_ds_[aa]);
        });
  });
  gather_rows_in_runs(film_matrix_, n_, row_runs_, row_count_,
                      [&](std::size_t k, std::vector<std::pair<int, double>>& row) {
                        mass_row(
                            k, false, [](std::size_t, double) {},
                            [&](std::size_t node, double entry) { row.emplace_back(static_cast<int>(node), entry); });
                      });
  const bool smoothed = !rows_->contact_by_q.empty();
  for (std::size_t k = 0; k < n_; ++k) {
    const double by_film = smoothed ? rows_->contact_by_film[k] : 1.0;
    krylov_.border_column[ni + static_cast<Eigen::Index>(k)] = closed[k] != 0 ? by_film / H : 0.0;
  }
  bool factorised = false;
  if (!spread) {
    factorised = block_->factorise(matrix_, film_matrix_, near_, closed, dp_ds_, scales_.pressure, H,
                                   smoothed ? &rows_->contact_by_q : nullptr,
                                   smoothed ? &rows_->contact_by_film : nullptr, message);
  } else {
    // The block's rows and nodes from their owners: M, F, and per node the
    // closed row, dp/ds and the smoothed weights.
    slab_.gather_rows(matrix_, below_, above_, block_mass_, block_scratch_);
    slab_.gather_rows(film_matrix_, below_, above_, block_film_, block_scratch_);
    constexpr std::size_t kNodeData = 4;
    node_data_.resize(n_ * kNodeData);
    for (std::size_t k = 0; k < n_; ++k) {
      node_data_[k * kNodeData] = closed[k];
      node_data_[k * kNodeData + 1] = dp_ds_[static_cast<Eigen::Index>(first_ + k)];
      node_data_[k * kNodeData + 2] = smoothed ? rows_->contact_by_q[k] : 0.0;
      node_data_[k * kNodeData + 3] = smoothed ? rows_->contact_by_film[k] : 0.0;
    }
    const std::size_t block_n = static_cast<std::size_t>(block_in_.size() / 2);
    block_node_data_.resize(block_n * kNodeData);
    slab_.rows_around(node_data_.data(), below_, above_, kNodeData, block_node_data_.data());
    block_closed_.resize(block_n);
    block_dp_ds_.resize(static_cast<Eigen::Index>(block_n));
    block_by_q_.resize(block_n);
    block_by_film_.resize(block_n);
    for (std::size_t k = 0; k < block_n; ++k) {
      block_closed_[k] = block_node_data_[k * kNodeData] != 0.0 ? 1 : 0;
      block_dp_ds_[static_cast<Eigen::Index>(k)] = block_node_data_[k * kNodeData + 1];
      block_by_q_[k] = block_node_data_[k * kNodeData + 2];
      block_by_film_[k] = block_node_data_[k * kNodeData + 3];
    }
    factorised = block_->factorise(block_mass_, block_film_, block_near_, block_closed_, block_dp_ds_, scales_.pressure,
                                   H, smoothed ? &block_by_q_ : nullptr, smoothed ? &block_by_film_ : nullptr, message);
  }
  if (!slab_.all(factorised)) {
    if (factorised) message = "the mixed film's preconditioner could not be factorised on another process";
    return false;
  }
  return true;
}

bool MixedKrylovSolver::factorise(std::string& message) {
  if (block_) {
    if (!factorise_block(message)) return false;
    return factorise_border(message);
  }
  // The sparse LU (one process: the stencil is the grid).
  const auto ni = static_cast<Eigen::Index>(n_);
  const double P = scales_.pressure, H = scales_.film;
  const std::vector<char>& closed = *closed_;
  mass_rows_border();
  // Every entry of the pattern is written, zero or not, so that the pattern
  // is the same at every Newton step (branches and contacts change) and is
  // analysed once.
  matrix_.clear();
  row_scratch_.clear();
  for (std::size_t k = 0; k < n_; ++k) {
    mass_row(
        k, true, [&](std::size_t node, double entry) { row_scratch_.emplace_back(static_cast<int>(node), entry); },
        [&](std::size_t node, double entry) {
          row_scratch_.emplace_back(static_cast<int>(node), entry * dp_ds_[static_cast<Eigen::Index>(node)]);
          row_scratch_.emplace_back(static_cast<int>(n_ + node), entry * P);
        });
    matrix_.append_row(row_scratch_);
  }
  // The contact rows: the identity on q (open), the truncated film
  // (closed), or the smoothed rows' weights of both.
  const bool smoothed = !rows_->contact_by_q.empty();
  for (std::size_t k = 0; k < n_; ++k) {
    const auto kk = static_cast<Eigen::Index>(k);
    const double by_q = smoothed ? rows_->contact_by_q[k] : (closed[k] != 0 ? 0.0 : 1.0);
    const double by_film = smoothed ? rows_->contact_by_film[k] : (closed[k] != 0 ? 1.0 : 0.0);
    row_scratch_.emplace_back(static_cast<int>(n_ + k), by_q);
    local_.for_each(k, [&](std::size_t node, double k_value) {
      const auto mm = static_cast<Eigen::Index>(node);
      row_scratch_.emplace_back(static_cast<int>(node), by_film * k_value * dp_ds_[mm] / H);
      row_scratch_.emplace_back(static_cast<int>(n_ + node), by_film * k_value * P / H);
    });
    krylov_.border_column[ni + kk] = by_film / H;
    matrix_.append_row(row_scratch_);
  }
  if (!preconditioner_->factorise(matrix_, message)) return false;
  return factorise_border(message);
}

bool MixedKrylovSolver::factorise_border(std::string& message) {
  if (!scales_.load_control) return true;
  const auto ni = static_cast<Eigen::Index>(n_);
  krylov_.load_row.head(ni) = scales_.area_over_load * dp_ds_.segment(static_cast<Eigen::Index>(first_), ni);
  krylov_.load_row.tail(ni).setConstant(scales_.area_over_load * scales_.pressure);
  return krylov_.factorise_border("the mixed film's preconditioner is singular: no pressure balances the load",
                                  message);
}

KrylovOutcome MixedKrylovSolver::solve(const MixedRows& rows, const std::vector<char>& branch_full,
                                       const std::vector<char>& closed, const MixedScales& scales, double forcing,
                                       const Eigen::VectorXd& residual, Eigen::VectorXd& step, bool warm) {
  rows_ = &rows;
  closed_ = &closed;
  const bool load_control = scales_.load_control;
  scales_ = scales;
  scales_.load_control = load_control;
  for (std::size_t j = 0; j < n_; ++j) {
    const auto jj = static_cast<Eigen::Index>(first_ + j);
    const bool fixed = topology_.fixed(first_ + j);
    dp_ds_[jj] = !fixed && branch_full[j] != 0 ? scales.pressure : 0.0;
    dtheta_ds_[jj] = !fixed && branch_full[j] == 0 ? 1.0 : 0.0;
  }
  slab_.exchange(dp_ds_.data());
  slab_.exchange(dtheta_ds_.data());
  // Each local term's derivatives by its node's s and by the film's change
  // there, on these branches: GMRES applies them at every iteration.
  term_node_.resize(rows.terms.size());
  term_by_s_.resize(rows.terms.size());
  term_by_deflection_.resize(rows.terms.size());
  linalg::for_each_index(rows.terms.size(), [&](std::size_t t) {
    const LocalTerm& term = rows.terms[t];
    const auto j = static_cast<Eigen::Index>(term.node);
    term_node_[t] = static_cast<int>(term.node);
    term_by_s_[t] = term.by_pressure * dp_ds_[j] + term.by_fraction * dtheta_ds_[j];
    term_by_deflection_[t] = term.by_film * rows.film_slope[term.node];
  });
  // The retry after a stale preconditioner failed goes on from where it
  // stopped (GMRES's residual only falls); GMRES's estimate and the true
  // residual part by rounding: allow 10x.
  const KrylovNewtonStep::Rule rule{
      .tolerance = std::max(settings_.tolerance, forcing),
      .allowance = 10.0,
      .warm = warm,
      .retry_warm = true,
      .failure = "the mixed film's GMRES reached a relative residual of {0:.3g} in {1} iterations (tolerance {2:.3g})"};
  return krylov_.solve([this](const Eigen::VectorXd& v, Eigen::VectorXd& out) { apply_jacobian(v, out); },
                       [this](std::string& message) { return factorise(message); }, residual, settings_.max_iterations,
                       rule, step);
}

}  // namespace halfspace::lubrication::detail
