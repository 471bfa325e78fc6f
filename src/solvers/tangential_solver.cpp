// The partial-slip problem of tangential_solver.hpp. Each iteration
// evaluates the slip increment ds (the gradient) and the approach, measures
// the duality gap, steps, projects onto the discs (and the force) and makes
// u = C q exactly.
//
// The iteration's shared passes are tangential_iteration.hpp; its two
// methods, each in its own file, tangential_conjugate_gradient.cpp (the
// default) and tangential_projected_gradient.cpp.
#include "halfspace/solvers/tangential_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/solvers/grid_transfer.hpp"
#include "halfspace/solvers/solver_options.hpp"
#include "tangential_active_set.hpp"
#include "tangential_conjugate_gradient.hpp"
#include "tangential_iteration.hpp"
#include "tangential_projected_gradient.hpp"

namespace halfspace::solvers {
namespace {

using namespace tangential;

}  // namespace

std::string_view to_string(TangentialControl control) {
  return control == TangentialControl::force ? "tangential force" : "tangential displacement";
}

void TangentialLoading::validate() const {
  if (!std::isfinite(x) || !std::isfinite(y)) {
    throw InputError(fmt::format("{} ({}, {}) is invalid: both components must be finite", to_string(control), x, y));
  }
}

TangentialState TangentialState::unloaded(std::size_t cells) {
  const auto n = static_cast<Eigen::Index>(cells);
  TangentialState state;
  for (Eigen::ArrayXd* field :
       {&state.shear_x, &state.shear_y, &state.displacement_x, &state.displacement_y, &state.slip_x, &state.slip_y}) {
    field->setZero(n);
  }
  return state;
}

void TangentialOptions::validate() const {
  const auto at_least = [](std::string_view option, int value, int least, std::string_view rule) {
    if (value < least) throw SolverOptionError(std::string(option), fmt::format("{}", value), std::string(rule));
  };
  const auto fraction = [](std::string_view option, double value) {
    if (!(value > 0.0 && value < 1.0)) {
      throw SolverOptionError(std::string(option), fmt::format("{}", value), "is invalid: allowed range is (0, 1)");
    }
  };
  if (!(std::isfinite(friction_coefficient) && friction_coefficient >= 0.0)) {
    throw SolverOptionError("friction", fmt::format("{}", friction_coefficient),
                            "is invalid: the friction coefficient mu must be finite and non-negative");
  }
  fraction("tolerance", tolerance);
  at_least("max_iterations", max_iterations, 1, "is invalid: must be at least 1");
  at_least("release_period", release_period, 1, "is invalid: must be at least 1");
  at_least("active_set_updates", active_set_updates, 0, "is invalid: must be at least 0 (0: no active-set phase)");
  fraction("coarse_tolerance", coarse_tolerance);
  if (method != TangentialMethod::conjugate_gradient && method != TangentialMethod::projected_gradient) {
    throw SolverOptionError("method", fmt::format("{}", static_cast<int>(method)),
                            "is invalid: allowed are conjugate_gradient (0) and projected_gradient (1)");
  }
  if (precision != Precision::double_precision && precision != Precision::mixed) {
    throw SolverOptionError("precision", fmt::format("{}", static_cast<int>(precision)),
                            "is invalid: allowed are double (0) and mixed (1)");
  }
  if (coarse_start != TangentialCoarseStart::off && coarse_start != TangentialCoarseStart::on &&
      coarse_start != TangentialCoarseStart::automatic) {
    throw SolverOptionError("coarse_start", fmt::format("{}", static_cast<int>(coarse_start)),
                            "is invalid: allowed are off (0), on (1) and automatic (2)");
  }
}

void TangentialSolver::set_tolerance(double tolerance) {
  TangentialOptions options = options_;
  options.tolerance = tolerance;
  options.validate();
  options_.tolerance = tolerance;
}

TangentialSolver::TangentialSolver(TangentialOperator& op, TangentialOptions options)
    : op_(op), options_(std::move(options)) {
  options_.validate();
  const auto n = static_cast<Eigen::Index>(op_.local_size());
  radius_.setZero(n);
  for (Eigen::ArrayXd* field : {&gx_, &gy_, &tx_, &ty_, &rx_, &ry_}) field->setZero(n);
  if (options_.method == TangentialMethod::conjugate_gradient) {
    kind_.assign(op_.local_size(), 0);
    if (options_.active_set_updates > 0) {
      tangent_motion_.assign(op_.local_size(), 0.0F);
      curvature_.assign(op_.local_size(), 0.0F);
    }
  }
}

TangentialResult TangentialSolver::solve(std::span<const double> pressure, const TangentialLoading& loading,
                                         const TangentialState& previous) {
  return solve(pressure, loading, previous, {}, {});
}

bool TangentialSolver::coarse_start(std::span<const double> pressure, const TangentialLoading& loading,
                                    const TangentialState& previous, CoarseStart& record) {
  const Grid& grid = op_.grid();
  const std::optional<Grid> coarse = coarser_grid(grid, kCoarseStartMinCellsPerAxis);
  if (!coarse) return false;
  const std::size_t m = coarse->size();
  const auto cells = static_cast<Eigen::Index>(m);
  // The coarse contact: block-averaged pressure and previous traction (the
  // force kept), the previous displacement made by the coarse operator so
  // that the coarse step starts from rest where the fine one does.
  Eigen::ArrayXd coarse_pressure(cells);
  restrict_by_average(grid, pressure, {coarse_pressure.data(), m});
  TangentialState coarse_previous = TangentialState::unloaded(m);
  restrict_by_average(grid, {previous.shear_x.data(), grid.size()}, {coarse_previous.shear_x.data(), m});
  restrict_by_average(grid, {previous.shear_y.data(), grid.size()}, {coarse_previous.shear_y.data(), m});
  coarse_previous.approach_x = previous.approach_x;
  coarse_previous.approach_y = previous.approach_y;
  TangentialOperator coarse_op(*coarse, op_.pair());
  TangentialResult solved;
  try {
    if (coarse_previous.shear_x.matrix().squaredNorm() + coarse_previous.shear_y.matrix().squaredNorm() > 0.0) {
      coarse_op.apply({coarse_previous.shear_x.data(), m}, {coarse_previous.shear_y.data(), m},
                      {coarse_previous.displacement_x.data(), m}, {coarse_previous.displacement_y.data(), m});
      record.operator_work += 0.25;
    }
    TangentialOptions options = options_;
    options.tolerance = std::max(options_.coarse_tolerance, options_.tolerance);
    options.progress = {};
    TangentialSolver level(coarse_op, options);
    solved = level.solve({coarse_pressure.data(), m}, loading, coarse_previous);
  } catch (const InputError&) {
    // Checked on the fine grid; the coarse one can differ only by rounding
    // (a force a hair above the averaged mu P). Go without a start.
    return false;
  }
  const double weight = static_cast<double>(m) / static_cast<double>(grid.size());
  record.levels += 1 + solved.coarse.levels;
  record.iterations += solved.iterations + solved.coarse.iterations;
  record.operator_work += weight * (solved.operator_applications + solved.coarse.operator_work);
  record.preconditioner_work += weight * (solved.preconditioner_applications + solved.coarse.preconditioner_work);
  // Only a start: short of its tolerance it still helps, broken down not.
  if (!(solved.state.shear_x.allFinite() && solved.state.shear_y.allFinite())) return false;
  const double mu = options_.friction_coefficient;
  for (Eigen::Index j = 0; j < cells; ++j) {
    const double radius = mu * coarse_pressure[j];
    const double inverse = radius > 0.0 ? 1.0 / radius : 0.0;
    solved.state.shear_x[j] *= inverse;
    solved.state.shear_y[j] *= inverse;
  }
  prolong_constant(grid, {solved.state.shear_x.data(), m}, {tx_.data(), grid.size()});
  prolong_constant(grid, {solved.state.shear_y.data(), m}, {ty_.data(), grid.size()});
  return true;
}

TangentialResult TangentialSolver::solve(std::span<const double> pressure, const TangentialLoading& loading,
                                         const TangentialState& previous, std::span<const double> fixed_x,
                                         std::span<const double> fixed_y) {
  const auto start_time = std::chrono::steady_clock::now();
  const std::size_t n = op_.local_size();
  const Grid& grid = op_.grid();
  const linalg::Communicator& comm = op_.communicator();
  check_field_size("pressure", pressure.size(), grid, n);
  for (const Eigen::ArrayXd* field : {&previous.shear_x, &previous.shear_y, &previous.displacement_x,
                                      &previous.displacement_y, &previous.slip_x, &previous.slip_y}) {
    check_field_size("previous tangential state", static_cast<std::size_t>(field->size()), grid, n);
  }
  loading.validate();
  const double mu = options_.friction_coefficient;
  const auto [pressure_sum, contact_cells, bad] = sums<3>(comm, n, [&](std::size_t i) {
    const double p = pressure[i];
    return std::array<double, 3>{std::isfinite(p) ? p : 0.0, p > 0.0 ? 1.0 : 0.0,
                                 std::isfinite(p) && p >= 0.0 ? 0.0 : 1.0};
  });
  if (bad > 0.0) throw InputError("pressure holds a negative or non-finite value: friction needs a contact pressure");
  for_each_index(n, [&](std::size_t i) { radius_[static_cast<Eigen::Index>(i)] = mu * pressure[i]; });
  contact_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (radius_[static_cast<Eigen::Index>(i)] > 0.0) contact_.push_back(i);
  }

  const double area = grid.cell_area();
  Problem problem;
  problem.radius = radius_.data();
  problem.contact = contact_;
  problem.previous = &previous;
  const bool fixed = !fixed_x.empty() || !fixed_y.empty();
  if (fixed) {
    check_field_size("fixed tangential displacement x", fixed_x.size(), grid, n);
    check_field_size("fixed tangential displacement y", fixed_y.size(), grid, n);
    if (fx_.size() != static_cast<Eigen::Index>(n)) {
      fx_.setZero(static_cast<Eigen::Index>(n));
      fy_.setZero(static_cast<Eigen::Index>(n));
    }
    for_each_index(n, [&](std::size_t i) {
      const auto j = static_cast<Eigen::Index>(i);
      fx_[j] = previous.displacement_x[j] - fixed_x[i];
      fy_[j] = previous.displacement_y[j] - fixed_y[i];
    });
    problem.previous_x = fx_.data();
    problem.previous_y = fy_.data();
  } else {
    problem.previous_x = previous.displacement_x.data();
    problem.previous_y = previous.displacement_y.data();
  }
  problem.force_controlled = loading.control == TangentialControl::force;
  problem.capacity = mu * pressure_sum;
  problem.contact_cells = contact_cells;
  problem.cell_area = area;
  const double limit = problem.capacity * area;  // mu P
  bool sliding = false;
  if (problem.force_controlled) {
    problem.target_x = loading.x / area;
    problem.target_y = loading.y / area;
    const double force = std::hypot(loading.x, loading.y);
    if (force > limit * (1.0 + kSlidingForce)) {
      throw InputError(fmt::format(
          "tangential force {:.6g} exceeds the friction limit mu P = {:.6g} (mu = {}, P = {:.6g}): the contact slides; "
          "impose a tangential displacement to follow sliding",
          force, limit, mu, pressure_sum * area));
    }
    sliding = force > 0.0 && force >= limit * (1.0 - kSlidingForce);
  } else {
    problem.delta_x = loading.x - previous.approach_x;
    problem.delta_y = loading.y - previous.approach_y;
  }

  // The coarse-grid start (serial, no fixed part): the fraction of each
  // disc in tx_, ty_ (workspace not yet in use), before the result's
  // fields exist, so that the coarse levels do not add to the peak.
  CoarseStart coarse;
  const bool serial = comm.size() == 1 && n == grid.size();
  const bool coarse_started = !sliding && serial && !fixed && options_.coarse_start_wanted() &&
                              options_.method == TangentialMethod::conjugate_gradient && mu > 0.0 &&
                              coarse_start(pressure, loading, previous, coarse);

  TangentialResult result;
  result.coarse = coarse;
  result.friction_coefficient = mu;
  result.dundurs_beta = op_.pair().dundurs_beta();
  result.tolerance = options_.tolerance;
  result.normal_force = pressure_sum * area;
  result.residual_history.reserve(static_cast<std::size_t>(std::min(options_.max_iterations, 1024)) + 1);
  TangentialState& state = result.state;
  state = TangentialState::unloaded(n);
  Fields fields{state.shear_x.data(),
                state.shear_y.data(),
                state.displacement_x.data(),
                state.displacement_y.data(),
                gx_.data(),
                gy_.data(),
                tx_.data(),
                ty_.data(),
                rx_.data(),
                ry_.data(),
                kind_.data()};
  if (coarse_started) {
    for_each_index(n, [&](std::size_t i) {
      const auto j = static_cast<Eigen::Index>(i);
      state.shear_x[j] = tx_[j] * radius_[j];
      state.shear_y[j] = ty_[j] * radius_[j];
    });
  }
  for (Eigen::ArrayXd* field : {&tx_, &ty_, &rx_, &ry_}) field->setZero();
  TangentialIteration it(op_, options_, problem, result, fields);
  ConjugateGradientMethod conjugate_gradient(it);
  ProjectedGradientMethod projected_gradient(it);
  const double inverse_lipschitz = 1.0 / op_.largest_eigenvalue_bound();
  double delta_x = 0.0;
  double delta_y = 0.0;
  int k = 0;
  if (sliding) {
    // Gross sliding: every contact cell at mu p along Q; the approach the
    // smallest at which every cell slips forward along Q.
    const double force = std::hypot(loading.x, loading.y);
    const double ex = loading.x / force;
    const double ey = loading.y / force;
    for_each_index(n, [&](std::size_t i) {
      const auto j = static_cast<Eigen::Index>(i);
      state.shear_x[j] = radius_[j] * ex;
      state.shear_y[j] = radius_[j] * ey;
    });
    op_.apply({fields.qx, n}, {fields.qy, n}, {fields.ux, n}, {fields.uy, n});
    ++result.operator_applications;
    const double along = linalg::max_of(comm, n, [&](std::size_t i) {
      const auto j = static_cast<Eigen::Index>(i);
      return radius_[j] > 0.0 ? (state.displacement_x[j] - problem.previous_x[i]) * ex +
                                    (state.displacement_y[j] - problem.previous_y[i]) * ey
                              : -std::numeric_limits<double>::infinity();
    });
    delta_x = along * ex;
    delta_y = along * ey;
    for_each_index(n, [&](std::size_t i) {
      const auto j = static_cast<Eigen::Index>(i);
      const bool contact = radius_[j] > 0.0;
      gx_[j] = contact ? state.displacement_x[j] - problem.previous_x[i] - delta_x : 0.0;
      gy_[j] = contact ? state.displacement_y[j] - problem.previous_y[i] - delta_y : 0.0;
    });
    result.status = SolveStatus::converged;
    result.message = "gross sliding: the tangential force equals mu P";
  } else {
    it.start(coarse_started);
    bool conjugate = options_.method == TangentialMethod::conjugate_gradient;
    if (conjugate && options_.active_set_updates > 0) {
      // The sets settled by the active-set phase, then its traction projected
      // onto the force, from which the conjugate gradients finish (and
      // first check the duality gap on an exact product).
      TangentialActiveSet active_set(it, tangent_motion_, curvature_);
      const ActiveSetPhase phase = active_set.run(options_.active_set_updates, options_.max_iterations);
      result.active_set_updates = phase.updates;
      result.active_set_iterations = phase.iterations;
      it.resume();
    }
    const int offset = result.active_set_iterations;
    double best = std::numeric_limits<double>::infinity();
    int best_at = 0;
    int stalls = 0;
    int projected_left = 0;  // projected steps before conjugate gradients resume
    int release_period = options_.release_period;
    const int stall_window = coarse_started ? kStalledConjugateStepsAfterCoarseStart : kStalledConjugateSteps;
    for (;; ++k) {
      it.evaluate(offset + k);
      if (it.finished(offset + k)) break;
      if (conjugate) {
        // A stall (the gap not halved in stall_window steps) hands
        // over to projected gradients, which converge whatever the sets do:
        // for kProjectedStepsAfterStall steps, which settle the sets the
        // conjugate gradients swung, after which these resume from a
        // steepest-descent step; for good after kConjugateStalls stalls.
        // (Projected gradients to the end took 760-3400 iterations where
        // the conjugate gradients resumed took about 100: docs/
        // development-log.md, 2026-11-30.) Each stall also doubles the
        // release period: the sets that swung get longer inner solves
        // between their updates (4096^2: 196 iterations, where the fixed
        // period reached the fourth stall and crawled).
        if (it.residual() < 0.5 * best) {
          best = it.residual();
          best_at = k;
        } else if (k - best_at > stall_window) {
          conjugate = false;
          projected_left = ++stalls < kConjugateStalls ? kProjectedStepsAfterStall : -1;
          release_period *= 2;
          projected_gradient.begin();
        }
      } else if (projected_left > 0 && --projected_left == 0) {
        conjugate = true;
        conjugate_gradient.restart();
        best = it.residual();
        best_at = k;
      }
      if (conjugate) {
        // Releases only every release_period iterations: an active-set
        // outer loop whose inner conjugate gradients run on frozen releases
        // (Hintermueller, Ito & Kunisch 2002 update the sets between solves).
        conjugate_gradient.allow_release(k % release_period == 0);
        conjugate_gradient.step();
      } else {
        projected_gradient.step(inverse_lipschitz);
      }
    }
    delta_x = it.approach_x();
    delta_y = it.approach_y();
    result.residual = it.residual();
  }
  result.iterations = k + result.active_set_iterations;

  // The state and the step's integrals.
  if (fixed) {
    // The state's displacement is the whole: C q and the fixed part.
    for_each_index(n, [&](std::size_t i) {
      const auto j = static_cast<Eigen::Index>(i);
      state.displacement_x[j] += fixed_x[i];
      state.displacement_y[j] += fixed_y[i];
    });
  }
  state.approach_x = previous.approach_x + delta_x;
  state.approach_y = previous.approach_y + delta_y;
  result.stick.setZero(static_cast<Eigen::Index>(n));
  const auto [qx_sum, qy_sum, stick_cells, dissipated] = sums<4>(comm, n, [&](std::size_t i) {
    const auto j = static_cast<Eigen::Index>(i);
    if (!(radius_[j] > 0.0)) {
      state.slip_x[j] = 0.0;
      state.slip_y[j] = 0.0;
      return std::array<double, 4>{};
    }
    const double qx = state.shear_x[j];
    const double qy = state.shear_y[j];
    const bool stick = !at_limit(qx, qy, radius_[j]);
    result.stick[j] = stick ? 1.0 : 0.0;
    state.slip_x[j] = previous.slip_x[j] + gx_[j];
    state.slip_y[j] = previous.slip_y[j] + gy_[j];
    return std::array<double, 4>{qx, qy, stick ? 1.0 : 0.0, -(qx * gx_[j] + qy * gy_[j])};
  });
  result.force_x = qx_sum * area;
  result.force_y = qy_sum * area;
  result.stick_fraction = contact_cells > 0.0 ? stick_cells / contact_cells : 0.0;
  result.slip_fraction = contact_cells > 0.0 ? 1.0 - result.stick_fraction : 0.0;
  result.gross_sliding = contact_cells > 0.0 && stick_cells == 0.0;
  result.dissipated_energy = dissipated * area;
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return result;
}

}  // namespace halfspace::solvers
