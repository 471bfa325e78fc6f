// The Panagiotopoulos alternation of coupled_step.hpp.
#include "halfspace/solvers/coupled_step.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::solvers {

namespace {
constexpr double kTightestTangentialTolerance = 1e-12;
}  // namespace

void CoupledStepOptions::validate() const {
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw SolverOptionError("coupling_tolerance", fmt::format("{}", tolerance), "is invalid: allowed range is (0, 1)");
  }
  if (max_alternations < 1) {
    throw SolverOptionError("max_alternations", fmt::format("{}", max_alternations), "is invalid: must be at least 1");
  }
}

CoupledStepSolver::CoupledStepSolver(ContactSolver& normal, TangentialOperator& op, TangentialSolver& tangential,
                                     CoupledStepOptions options)
    : normal_(normal), op_(op), tangential_(tangential), options_(options) {
  options_.validate();
  const auto n = static_cast<Eigen::Index>(op_.local_size());
  for (Eigen::ArrayXd* field : {&w_, &w_new_, &gap_, &vx_, &vy_}) field->setZero(n);
}

CoupledStepResult CoupledStepSolver::solve(std::span<const double> initial_gap, const Loading& normal_loading,
                                           const TangentialLoading& loading, const TangentialState& previous,
                                           std::span<const double> start_pressure,
                                           const std::optional<std::array<double, 2>>& sliding) {
  const std::size_t n = op_.local_size();
  if (initial_gap.size() != n || previous.size() != n || (!start_pressure.empty() && start_pressure.size() != n)) {
    throw InputError(fmt::format("coupled step: a field's size does not match the grid's {} cells", n));
  }
  const double mu = tangential_.options().friction_coefficient;
  const double cell_area = op_.grid().cell_area();
  const linalg::Communicator& comm = op_.communicator();
  auto span = [n](Eigen::ArrayXd& a) { return std::span<double>(a.data(), n); };
  auto cspan = [n](const Eigen::ArrayXd& a) { return std::span<const double>(a.data(), n); };
  op_.apply_traction_coupling(cspan(previous.shear_x), cspan(previous.shear_y), span(w_));
  CoupledStepResult result;
  // The alternation's change cannot fall below the noise of the tangential
  // solves it alternates with, each converged only to its own tolerance (in
  // near-full slip the slip directions are barely determined and the change
  // stalls at a few times that tolerance): when a pass fails to halve the
  // change, the tangential tolerance is tightened tenfold, down to
  // kTightestTangentialTolerance, for the rest of this step.
  struct RestoredTolerance {
    TangentialSolver& solver;
    double tolerance;
    ~RestoredTolerance() { solver.set_tolerance(tolerance); }
  } restored{tangential_, tangential_.options().tolerance};
  double previous_residual = 0.0;
  Eigen::ArrayXd warm;
  if (!start_pressure.empty())
    warm = Eigen::Map<const Eigen::ArrayXd>(start_pressure.data(), static_cast<Eigen::Index>(n));
  for (int pass = 1; pass <= options_.max_alternations; ++pass) {
    result.alternations = pass;
    for (std::size_t i = 0; i < n; ++i)
      gap_[static_cast<Eigen::Index>(i)] = initial_gap[i] + w_[static_cast<Eigen::Index>(i)];
    // The step's solve times are its alternations' together (the last
    // alternation's warm-started normal solve alone may take no time).
    const double normal_seconds = result.normal.wall_seconds;
    result.normal =
        normal_.solve(cspan(gap_), normal_loading, warm.size() == 0 ? std::span<const double>{} : cspan(warm));
    result.normal.wall_seconds += normal_seconds;
    if (!result.normal.converged()) {
      result.status = result.normal.status;
      result.message =
          fmt::format("the normal solve of alternation {} did not converge: {}", pass, result.normal.message);
      return result;
    }
    warm = result.normal.pressure;
    const std::span<const double> pressure = cspan(result.normal.pressure);
    op_.apply_pressure_coupling(pressure, span(vx_), span(vy_));
    TangentialLoading step = loading;
    if (sliding) {
      const double total =
          linalg::sums<1>(comm, n, [&](std::size_t i) { return std::array<double, 1>{pressure[i]}; })[0];
      const double force = mu * total * cell_area / std::hypot((*sliding)[0], (*sliding)[1]);
      step = TangentialLoading::force(force * (*sliding)[0], force * (*sliding)[1]);
    }
    // Each alternation's tangential solve starts from the step's start: from
    // the last alternation's traction it took as many iterations (docs/
    // development-log.md, a faster tangential step).
    const double tangential_seconds = result.tangential.wall_seconds;
    result.tangential = tangential_.solve(pressure, step, previous, cspan(vx_), cspan(vy_));
    result.tangential.wall_seconds += tangential_seconds;
    result.tangential_iterations += result.tangential.iterations;
    if (!result.tangential.converged()) {
      result.status = result.tangential.status;
      result.message =
          fmt::format("the tangential solve of alternation {} did not converge: {}", pass, result.tangential.message);
      return result;
    }
    // The normal displacement the new shear makes, against the one the
    // normal solve saw.
    const TangentialState& s = result.tangential.state;
    op_.apply_traction_coupling(cspan(s.shear_x), cspan(s.shear_y), span(w_new_));
    const double scale = linalg::max_of(
        comm, n, [&](std::size_t i) { return std::abs(result.normal.displacement[static_cast<Eigen::Index>(i)]); });
    const double change = linalg::max_of(comm, n, [&](std::size_t i) {
      const auto j = static_cast<Eigen::Index>(i);
      return std::abs(w_new_[j] - w_[j]);
    });
    result.coupling_residual = scale > 0.0 ? change / scale : change;
    // The returned normal solution carries the shear's displacement it was solved with.
    if (result.coupling_residual <= options_.tolerance) {
      result.normal.displacement += w_;
      result.status = SolveStatus::converged;
      result.message.clear();
      return result;
    }
    const double tolerance = tangential_.options().tolerance;
    if (pass > 1 && result.coupling_residual > 0.5 * previous_residual && tolerance > kTightestTangentialTolerance) {
      tangential_.set_tolerance(std::max(0.1 * tolerance, kTightestTangentialTolerance));
    }
    previous_residual = result.coupling_residual;
    w_.swap(w_new_);
  }
  result.normal.displacement += w_new_;  // the one it was solved with (swapped above); reported, not converged
  result.status = SolveStatus::iteration_limit;
  result.message = fmt::format(
      "the normal-tangential alternation did not converge in {} alternations (the shear's last change moved the "
      "surfaces normally by {:.3g} of the normal displacement > {:.3g})",
      options_.max_alternations, result.coupling_residual, options_.tolerance);
  return result;
}

}  // namespace halfspace::solvers
