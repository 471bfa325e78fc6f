// GMRES on the EHL Newton system (film_krylov_solver.hpp). The Jacobian,
//
//   J = (A_p + A_h K) diag(dp/ds) + A_theta diag(dtheta/ds)  (+ h0 column, load row),
//
// is applied with one product of the influence operator per iteration. The
// preconditioner keeps K only within a few cells of each node: at high
// loads the mass rows are dominated by the Couette difference of the film,
// A_h K, a difference of K across neighbouring nodes that decays much
// faster than K itself (the observation behind Venner & Lubrecht's 2000
// "differential deflection"), so the truncated operator captures the stiff
// part and GMRES the smooth far field in few iterations. B is inverted
// approximately (film_preconditioner.hpp: a multigrid V-cycle M, or B's
// sparse LU), and the bordered system (h0 column c, load row r) by the
// Schur complement: z = (r^T M f - g) / (r^T M c), y = M f - z M c.
#include "film_krylov_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <tuple>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::lubrication::detail {

namespace {
// Entries per row of the preconditioner: the (up to 8) local terms' film
// derivatives each spread over the (2r + 1)^2 truncated K, of which the
// neighbouring nodes' overlap (a 5 x 3 cross of terms) leaves about
// (2r + 3)(2r + 5) distinct columns.
double preconditioner_row_entries(int r) {
  return (2.0 * r + 3.0) * (2.0 * r + 5.0);
}
// The loosest relative residual of a multigrid-preconditioned step (solve()).
constexpr double kLoosestMultigridForcing = 1e-3;
}  // namespace

void FilmKrylovSettings::validate() const {
  if (restart < 2 || restart > 500) {
    throw OptionError("krylov_restart", fmt::format("{}", restart), "is invalid: allowed range is 2 to 500");
  }
  if (max_iterations < 1) {
    throw OptionError("krylov_max_iterations", fmt::format("{}", max_iterations),
                      "is invalid: at least 1 GMRES iteration");
  }
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw OptionError("krylov_tolerance", format_number(tolerance), "is invalid: allowed range is 0 < tolerance < 1");
  }
  if (neighbourhood < 0 || neighbourhood > 8) {
    throw OptionError("preconditioner_neighbourhood", fmt::format("{}", neighbourhood),
                      "is invalid: allowed range is 0 to 8 cells");
  }
}

double film_krylov_memory_estimate(std::size_t nodes, const FilmKrylovSettings& settings) {
  const double per_row = preconditioner_row_entries(settings.neighbourhood);
  const double per_node = 8.0 * (settings.restart + 1)            // GMRES basis
                          + 8.0 * 16.0 * sizeof(LocalTerm) / 8.0  // local rows (up to 16 terms)
                          + per_row * 12.0                        // the sparse part in compressed rows
                          + film_preconditioner_bytes_per_node(settings.preconditioner, per_row) +
                          8.0 * 40.0;  // the Newton state and work vectors
  return per_node * static_cast<double>(nodes);
}

FilmKrylovSolver::FilmKrylovSolver(InfluenceOperator& op, const ReynoldsStencil& topology,
                                   const FilmKrylovSettings& settings, const FilmSlab& slab)
    : op_(op),
      topology_(topology),
      settings_(settings),
      slab_(slab),
      n_(slab.own_nodes()),
      first_(slab.own_first()),
      local_(op, settings.neighbourhood, slab.first_row()) {
  const auto ni = static_cast<Eigen::Index>(n_);
  const auto stencil = static_cast<Eigen::Index>(slab.stencil_nodes());
  const int m = settings_.restart;
  dp_ds_.resize(stencil);
  dtheta_ds_.resize(stencil);
  product_in_.resize(ni);
  product_out_.resize(ni);
  if (slab.distributed()) {
    v_stencil_.setZero(stencil);
    product_stencil_.setZero(stencil);
  }
  const int line_axis = topology.couette_y() > topology.couette_x() ? 1 : 0;
  Grid block_grid = slab.own_grid();
  if (slab.distributed()) {
    std::tie(below_, above_) = slab.rows_around_limits(kSlabOverlapRows);
    const Grid& whole = slab.whole_grid();
    block_grid = Grid::plane(whole.nx(), n_ / whole.nx() + below_ + above_, whole.dx(), whole.dy(), whole.boundary());
    block_in_.setZero(static_cast<Eigen::Index>(block_grid.size()));
    block_out_.setZero(block_in_.size());
  }
  preconditioner_ = make_film_preconditioner(settings_.preconditioner, block_grid, line_axis);
  krylov_.setup(ni + 1, ni, m,
                [this](const Eigen::VectorXd& in, Eigen::VectorXd& out) { apply_preconditioner(in, out); });
  krylov_.distribute(slab.krylov_distribution());
}

void FilmKrylovSolver::apply_jacobian(const Eigen::VectorXd& v, Eigen::VectorXd& out) {
  const auto ni = static_cast<Eigen::Index>(n_);
  const auto first = static_cast<Eigen::Index>(first_);
  product_in_ = dp_ds_.segment(first, ni).cwiseProduct(v.head(ni));
  op_.apply(std::span<const double>(product_in_.data(), n_), std::span<double>(product_out_.data(), n_));
  // The rows reach the halo's nodes: v and K dp/ds v there from their owners.
  const double* values = slab_.on_stencil(v.head(ni), v_stencil_);
  const double* deformation = slab_.on_stencil(product_out_, product_stencil_);
  const double by_offset = v[ni];
  linalg::for_each_index(n_, [&](std::size_t k) {
    const auto kk = static_cast<Eigen::Index>(k);
    if (topology_.fixed(first_ + k)) {
      out[kk] = v[kk];
      return;
    }
    double sum = 0.0;
    for (std::size_t t = rows_->start[k]; t < rows_->start[k + 1]; ++t) {
      const LocalTerm& term = rows_->terms[t];
      const auto j = static_cast<Eigen::Index>(term.node);
      sum += (term.by_pressure * dp_ds_[j] + term.by_fraction * dtheta_ds_[j]) * values[j] +
             term.by_film * (deformation[j] + by_offset);
    }
    out[kk] = sum / mass_scale_;
  });
  out[ni] = area_over_load_ * slab_.sum(dp_ds_.segment(first, ni).dot(v.head(ni)));
}

void FilmKrylovSolver::apply_preconditioner(const Eigen::VectorXd& in, Eigen::VectorXd& out) {
  if (!slab_.distributed()) return preconditioner_->apply(in, out);
  // Restricted additive Schwarz: the block's right-hand side with the
  // neighbours' overlap rows, its approximate inverse, this process's rows.
  slab_.rows_around(in.data(), below_, above_, 1, block_in_.data());
  preconditioner_->apply(block_in_, block_out_);
  out = block_out_.segment(static_cast<Eigen::Index>(below_ * slab_.whole_grid().nx()), static_cast<Eigen::Index>(n_));
}

bool FilmKrylovSolver::factorise(std::string& message) {
  // Rows in compressed form, each row's entries gathered, sorted and
  // summed, on all threads (csr_rows_in_runs.hpp). Every entry of the
  // pattern is kept, zero or not, so that the pattern is the same at every
  // Newton step (the LU analyses it once).
  // On several processes the columns are whole-grid nodes (the block's
  // rows are then gathered: gather_block_rows), and K's neighbourhood is
  // kept where it lies in the stencil.
  const bool spread = slab_.distributed();
  const auto column_of = [&](std::size_t stencil_node) {
    return static_cast<int>(spread ? slab_.whole_node(stencil_node) : stencil_node);
  };
  gather_rows_in_runs(matrix_, n_, row_runs_, row_count_, [&](std::size_t k, std::vector<std::pair<int, double>>& row) {
    const auto kk = static_cast<Eigen::Index>(k);
    krylov_.border_column[kk] = 0.0;
    if (topology_.fixed(first_ + k)) {
      row.emplace_back(column_of(first_ + k), 1.0);
      return;
    }
    for (std::size_t t = rows_->start[k]; t < rows_->start[k + 1]; ++t) {
      const LocalTerm& term = rows_->terms[t];
      const auto j = static_cast<Eigen::Index>(term.node);
      row.emplace_back(column_of(term.node),
                       (term.by_pressure * dp_ds_[j] + term.by_fraction * dtheta_ds_[j]) / mass_scale_);
      krylov_.border_column[kk] += term.by_film / mass_scale_;
      local_.for_each(slab_.whole_node(term.node), [&](std::size_t m, double k_value) {
        const std::size_t at = slab_.stencil_node(m);
        if (at == FilmSlab::kOutside) return;
        row.emplace_back(static_cast<int>(m),
                         term.by_film / mass_scale_ * k_value * dp_ds_[static_cast<Eigen::Index>(at)]);
      });
    }
  });
  if (spread) slab_.gather_rows(matrix_, below_, above_, block_, block_scratch_);
  const bool factorised = preconditioner_->factorise(spread ? block_ : matrix_, message);
  if (!slab_.all(factorised)) {
    if (factorised) message = "the EHL preconditioner could not be factorised on another process";
    return false;
  }
  krylov_.load_row = area_over_load_ * dp_ds_.segment(static_cast<Eigen::Index>(first_), static_cast<Eigen::Index>(n_));
  return krylov_.factorise_border("the EHL preconditioner is singular: no node carries pressure to balance the load",
                                  message);
}

KrylovOutcome FilmKrylovSolver::solve(const LocalRows& rows, const std::vector<char>& branch_full,
                                      double pressure_scale, double mass_scale, double area_over_load, double forcing,
                                      const Eigen::VectorXd& residual, Eigen::VectorXd& step) {
  // With the multigrid the loosest steps are solved to 1e-3 instead of the
  // caller's forcing (at most 1e-2): its approximate local inverse leaves
  // the early GMRES iterates' errors spread over many nodes, and directions
  // solved only to 1e-2 made the semi-smooth Newton creep at short steps
  // (256^2 point contact: 12 fine steps at 1e-3, a stall at 1e-2;
  // docs/development-log.md).
  const double loosest = settings_.preconditioner == KrylovPreconditioner::multigrid ? kLoosestMultigridForcing : 1.0;
  const double tolerance = std::max(settings_.tolerance, std::min(forcing, loosest));
  rows_ = &rows;
  mass_scale_ = mass_scale;
  area_over_load_ = area_over_load;
  for (std::size_t j = 0; j < n_; ++j) {
    const auto jj = static_cast<Eigen::Index>(first_ + j);
    const bool fixed = topology_.fixed(first_ + j);
    dp_ds_[jj] = !fixed && branch_full[j] != 0 ? pressure_scale : 0.0;
    dtheta_ds_[jj] = !fixed && branch_full[j] == 0 ? 1.0 : 0.0;
  }
  slab_.exchange(dp_ds_.data());
  slab_.exchange(dtheta_ds_.data());
  // The preconditioner of an earlier step serves while the branches are
  // the same (LaggedPreconditioner); GMRES from 0, on the retry too.
  const bool same_branches = slab_.all(
      factorised_ && (dp_ds_.segment(static_cast<Eigen::Index>(first_), static_cast<Eigen::Index>(n_)).array() ==
                      krylov_.load_row.array() / area_over_load_)
                         .all());
  const KrylovNewtonStep::Rule rule{
      .tolerance = tolerance,
      .refactorise = !same_branches,
      .failure =
          "the EHL Newton step's GMRES solve did not converge: relative residual {0:.3g} (tolerance {2:.3g}) "
          "after {1} iterations"};
  return krylov_.solve([this](const Eigen::VectorXd& v, Eigen::VectorXd& out) { apply_jacobian(v, out); },
                       [this](std::string& message) { return factorised_ = factorise(message); }, residual,
                       settings_.max_iterations, rule, step);
}

}  // namespace halfspace::lubrication::detail
