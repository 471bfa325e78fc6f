// The normal solve, then the tangential history under its pressure
// (frictional_solve.hpp).
#include "halfspace/solvers/frictional_solve.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <string>

#include "halfspace/linalg/parallel.hpp"
#include "halfspace/operators/tangential_operator.hpp"
#include "halfspace/solvers/coupled_step.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/solvers/tangential_solver.hpp"

namespace halfspace::solvers {
namespace {

// The sum the tangential solver takes as P (sum of p times the cell area,
// over every process), so that the sliding force mu P is its own to rounding.
double normal_force(const Grid& grid, const SolveResult& normal, const linalg::Communicator& comm) {
  const Eigen::ArrayXd& p = normal.pressure;
  return linalg::sums<1>(comm, static_cast<std::size_t>(p.size()),
                         [&](std::size_t i) {
                           const double value = p[static_cast<Eigen::Index>(i)];
                           return std::array<double, 1>{std::isfinite(value) ? value : 0.0};
                         })[0] *
         grid.cell_area();
}

bool same_load(const TangentialLoading& a, const TangentialLoading& b) {
  return a.control == b.control && a.x == b.x && a.y == b.y;
}

// The outcome of a step whose load is the previous step's: its state, no
// slip increment, no dissipation, no iterations.
TangentialResult repeated(const TangentialResult& previous) {
  TangentialResult result = previous;
  result.status = SolveStatus::converged;
  result.message.clear();
  result.dissipated_energy = 0.0;
  result.iterations = 0;
  result.coupling_tangential_iterations = 0;
  result.residual = 0.0;
  result.residual_history.clear();
  result.operator_applications = 0;
  result.wall_seconds = 0.0;
  return result;
}

// A coupled step's tangential result with the alternation's record, its
// status the whole step's.
TangentialResult recorded(const CoupledStepResult& step) {
  TangentialResult t = step.tangential;
  t.coupling_alternations = step.alternations;
  t.coupling_tangential_iterations = step.tangential_iterations;
  t.coupling_residual = step.coupling_residual;
  t.coupled = true;
  if (!step.converged()) {
    t.status = step.status;
    t.message = step.message;
  }
  return t;
}

// The coupled history (frictional_solve.hpp): the normal loading in
// increments at zero tangential load, then the steps, each a coupled step
// from the state the previous left, the normal solves warm-started from the
// previous pressure.
void solve_coupled(const Grid& grid, std::span<const double> heights, const ElasticPair& pair, const Loading& loading,
                   const SolverOptions& normal, const FrictionOptions& friction, const Layout& layout,
                   FrictionalSolveResult& result) {
  result.coupled = true;
  const Eigen::ArrayXd gap0 = initial_gap(grid, heights, layout);
  const std::span<const double> gap(gap0.data(), static_cast<std::size_t>(gap0.size()));
  const std::unique_ptr<ContactSolver> normal_solver = make_solver(grid, pair.half_space(), normal, layout);
  const std::unique_ptr<TangentialOperator> made = layout.make_tangential_operator(grid, pair, normal.fft_planning);
  TangentialOperator& op = *made;
  std::size_t current = 0;
  TangentialSolver tangential(op, friction.tangential_options(current));
  CoupledStepSolver coupled(*normal_solver, op, tangential, friction.coupled_step);
  TangentialState state = TangentialState::unloaded(op.local_size());
  // At rest tangentially while the normal load grows: the history's control at zero.
  const bool force = friction.sliding_direction || friction.history.front().control == TangentialControl::force;
  const TangentialLoading rest = force ? TangentialLoading::force(0.0) : TangentialLoading::displacement(0.0);
  Eigen::ArrayXd warm;
  auto warm_span = [&] { return std::span<const double>(warm.data(), static_cast<std::size_t>(warm.size())); };
  const int increments = friction.normal_load_steps;
  for (int k = 1; k <= increments; ++k) {
    Loading part = loading;
    part.value = k == increments ? loading.value : loading.value * k / increments;
    CoupledStepResult step = coupled.solve(gap, part, rest, state, warm_span());
    result.normal = std::move(step.normal);
    if (!step.converged()) {
      result.normal.status = step.status;
      result.normal.message = step.message;
    }
    result.loading_steps.push_back(recorded(step));
    if (!step.converged()) return;
    state = result.loading_steps.back().state;
    warm = result.normal.pressure;
  }
  std::vector<TangentialLoading> loads;
  for (std::size_t k = 0; k < friction.steps(); ++k) {
    current = k;
    const TangentialLoading load = friction.sliding_direction ? TangentialLoading{} : friction.history[k];
    if (k > 0 && !friction.sliding_direction && same_load(load, loads.back())) {
      // As the uncoupled history: a repeated load leaves the state as it is.
      result.steps.push_back(repeated(result.steps.back()));
      result.step_normals.push_back(result.step_normals.back());
    } else {
      CoupledStepResult step = coupled.solve(gap, loading, load, state, warm_span(), friction.sliding_direction);
      result.steps.push_back(recorded(step));
      result.step_normals.push_back(std::move(step.normal));
    }
    loads.push_back(load);
    if (!result.steps.back().converged()) return;
    state = result.steps.back().state;
    warm = result.step_normals.back().pressure;
  }
}

}  // namespace

bool FrictionalSolveResult::converged() const {
  if (!normal.converged() || steps.size() != requested_steps) return false;
  for (const TangentialResult& step : loading_steps) {
    if (!step.converged()) return false;
  }
  for (const TangentialResult& step : steps) {
    if (!step.converged()) return false;
  }
  return true;
}

std::string FrictionalSolveResult::failure() const {
  if (!normal.converged()) return fmt::format("the normal contact did not converge: {}", normal.message);
  for (std::size_t k = 0; k < loading_steps.size(); ++k) {
    if (!loading_steps[k].converged()) {
      return fmt::format("normal loading increment {} did not converge: {}", k + 1, loading_steps[k].message);
    }
  }
  for (std::size_t k = 0; k < steps.size(); ++k) {
    if (!steps[k].converged()) {
      return steps[k].message.empty()
                 ? fmt::format("tangential step {} of {} did not converge ({} iterations, residual {:.3g} > {:.3g})",
                               k + 1, requested_steps, steps[k].iterations, steps[k].residual, steps[k].tolerance)
                 : fmt::format("tangential step {} of {} did not converge: {}", k + 1, requested_steps,
                               steps[k].message);
    }
  }
  if (steps.size() != requested_steps) {
    return fmt::format("only {} of {} tangential steps were solved", steps.size(), requested_steps);
  }
  return {};
}

std::vector<TangentialResult> solve_tangential_history(const Grid& grid, const ElasticPair& pair,
                                                       const SolveResult& normal, const FrictionOptions& friction,
                                                       FftPlanning planning, const Layout& layout) {
  friction.validate();
  FrictionOptions::check_body(grid, pair);
  const std::unique_ptr<TangentialOperator> made = layout.make_tangential_operator(grid, pair, planning);
  TangentialOperator& op = *made;
  std::size_t current = 0;  // the step the progress callback reports
  TangentialSolver solver(op, friction.tangential_options(current));
  const std::span<const double> pressure(normal.pressure.data(), static_cast<std::size_t>(normal.pressure.size()));
  std::vector<TangentialResult> steps;
  steps.reserve(friction.steps());
  std::vector<TangentialLoading> loads;  // what each step imposed
  TangentialState state = TangentialState::unloaded(op.local_size());
  for (std::size_t k = 0; k < friction.steps(); ++k) {
    TangentialLoading loading;
    if (friction.sliding_direction) {
      // Gross sliding: the force mu P along the direction, which the solver
      // meets with every contact cell at mu p.
      const auto [x, y] = *friction.sliding_direction;
      const double force =
          friction.tangential.friction_coefficient * normal_force(grid, normal, op.communicator()) / std::hypot(x, y);
      loading = TangentialLoading::force(force * x, force * y);
    } else {
      loading = friction.history[k];
    }
    current = k;
    if (k > 0 && same_load(loading, loads.back())) {
      // A step that repeats the previous load (the turning point written at
      // the end of one branch and the start of the next) leaves the state
      // as it is: no slip increment anywhere, so the conditions hold as the
      // previous step left them, and nothing is dissipated. The solver
      // would find the same state to rounding; the history keeps it exact.
      steps.push_back(repeated(steps.back()));
    } else {
      steps.push_back(solver.solve(pressure, loading, state));
    }
    loads.push_back(loading);
    if (!steps.back().converged()) break;
    state = steps.back().state;
  }
  return steps;
}

FrictionalSolveResult solve_frictional_surface(const Grid& grid, std::span<const double> heights,
                                               const ElasticPair& pair, const Loading& loading,
                                               const SolverOptions& normal, const FrictionOptions& friction,
                                               const Layout& layout) {
  friction.validate(grid, normal, loading);
  FrictionOptions::check_body(grid, pair);
  FrictionalSolveResult result;
  result.requested_steps = friction.steps();
  result.dundurs_beta = pair.dundurs_beta();
  if (friction.coupled(pair)) {
    solve_coupled(grid, heights, pair, loading, normal, friction, layout, result);
    return result;
  }
  result.normal = solve_surface(grid, heights, pair.half_space(), loading, normal, {}, layout);
  if (!result.normal.converged()) return result;
  result.steps = solve_tangential_history(grid, pair, result.normal, friction, normal.fft_planning, layout);
  return result;
}

double friction_memory_estimate(const Grid& grid, std::size_t steps) {
  // Per cell: the operator's padded symbols and transforms (about 4 padded
  // cells of complex values per field on free grids), about 224 bytes; the
  // solver's workspace (mu p and six pairs of fields) and the step being
  // solved, about 100; each kept step's six fields and stick map, 56. A
  // history of several steps is written from a file image assembled in
  // memory (io/friction_history_writer.cpp), held twice while copied out:
  // the kept steps' fields and the normal result's (33), uncompressed at
  // worst. One step is written as a result, in place when large
  // (io::kInMemoryResultBytes), so the solve's estimate covers it.
  const auto cells = static_cast<double>(grid.size());
  const auto kept = static_cast<double>(steps);
  const double image = steps > 1 ? 2.0 * (33.0 + 56.0 * kept) : 0.0;
  return cells * (324.0 + 56.0 * kept + image);
}

}  // namespace halfspace::solvers
