// Load sweeps with warm starts. Starting step k from the pressure of step k-1
// saves most of the iterations when the loads are close: the contact set
// changes little, and the Polonsky-Keer iteration only has to move its edge.
#include "halfspace/analysis/load_sweep.hpp"

#include <fmt/format.h>

#include <Eigen/Core>
#include <cmath>
#include <memory>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/solvers/surface_solve.hpp"

namespace halfspace::analysis {

std::vector<SweepStep> run_load_sweep(ContactSolver& solver, const Grid& grid, std::span<const double> initial_gap,
                                      ControlMode mode, std::span<const double> values, const LoadSweepOptions& options,
                                      const solvers::Layout& layout) {
  if (values.empty()) throw InputError("load sweep: no load given");
  const std::size_t cells = layout.rows(grid).count * grid.nx();
  check_field_size("load sweep: the initial gap", initial_gap.size(), grid, cells);
  std::vector<Loading> loads;
  for (const double value : values) {
    const Loading loading{mode, value};
    if (!options.signed_loads) {
      loading.validate();
    } else if (!std::isfinite(value)) {
      throw InputError(fmt::format("{} = {} is invalid: must be finite", to_string(mode), format_number(value)));
    }
    loads.push_back(loading);
  }
  if (mode == ControlMode::approach && grid.periodic()) {
    // Checked up front rather than by the solver at the failing step, so that
    // a bad list does not cost the steps before it.
    const double mean_gap = linalg::sum(layout.communicator(), cells, [&](std::size_t i) { return initial_gap[i]; }) /
                            static_cast<double>(grid.size());
    for (const double value : values) solvers::check_periodic_approach(value, mean_gap);
  }
  const auto statistics = [&](const SolveResult& result) {
    if (options.statistics) return options.statistics(result);
    return contact_statistics(grid, {result.pressure.data(), cells}, {result.gap.data(), cells});
  };

  std::vector<SweepStep> steps;
  steps.reserve(loads.size());
  for (std::size_t k = 0; k < loads.size(); ++k) {
    if (options.on_step_start) options.on_step_start(k, loads.size(), loads[k]);
    SweepStep step;
    step.loading = loads[k];
    const SweepStep* previous = steps.empty() ? nullptr : &steps.back();
    step.warm_started = options.warm_start && previous != nullptr && previous->result.converged();
    std::span<const double> start;
    if (step.warm_started) start = {previous->result.pressure.data(), cells};
    step.result = solver.solve(initial_gap, loads[k], start);
    step.statistics = statistics(step.result);
    steps.push_back(std::move(step));
    if (options.on_step_done) options.on_step_done(k, loads.size(), steps.back());
    if (steps.back().result.status == solvers::SolveStatus::stopped) break;  // the caller's progress said so
  }
  return steps;
}

std::vector<SweepStep> sweep_surface(const Grid& grid, std::span<const double> heights, const HalfSpace& half_space,
                                     ControlMode mode, std::span<const double> values,
                                     const solvers::SolverOptions& options, const LoadSweepOptions& sweep,
                                     const solvers::Layout& layout) {
  const Eigen::ArrayXd gap = solvers::initial_gap(grid, heights, layout);
  // The solver is freed before returning.
  const std::unique_ptr<ContactSolver> solver = solvers::make_solver(grid, half_space, options, layout);
  return run_load_sweep(*solver, grid, {gap.data(), static_cast<std::size_t>(gap.size())}, mode, values, sweep, layout);
}

}  // namespace halfspace::analysis
