// Load sweeps with warm starts. Starting step k from the pressure of step k-1
// saves most of the iterations when the loads are close: the contact set
// changes little, and the Polonsky-Keer iteration only has to move its edge.
#include "halfspace/analysis/load_sweep.hpp"

#include <fmt/format.h>

#include <Eigen/Core>
#include <cmath>
#include <memory>

#include "halfspace/error.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/solvers/surface_solve.hpp"

namespace halfspace::analysis {
namespace {

// The sweep with the solver `make` builds, freed before returning.
template <typename MakeSolver>
std::vector<SweepStep> sweep_with(const Grid& grid, std::span<const double> heights, MakeSolver make, ControlMode mode,
                                  std::span<const double> values, const LoadSweepOptions& sweep) {
  const Eigen::ArrayXd gap = solvers::initial_gap(grid, heights);
  const std::unique_ptr<ContactSolver> solver = make();
  return run_load_sweep(*solver, grid, {gap.data(), grid.size()}, mode, values, sweep);
}

}  // namespace

std::vector<SweepStep> run_load_sweep(ContactSolver& solver, const Grid& grid, std::span<const double> initial_gap,
                                      ControlMode mode, std::span<const double> values,
                                      const LoadSweepOptions& options) {
  if (values.empty()) throw InputError("load sweep: no load given");
  if (initial_gap.size() != grid.size()) {
    throw InputError(fmt::format("load sweep: the initial gap has {} entries, but the grid has {} cells",
                                 initial_gap.size(), grid.size()));
  }
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
    double mean_gap = 0.0;
    for (const double g : initial_gap) mean_gap += g;
    mean_gap /= static_cast<double>(initial_gap.size());
    for (const double value : values) solvers::check_periodic_approach(value, mean_gap);
  }

  std::vector<SweepStep> steps;
  steps.reserve(loads.size());
  for (std::size_t k = 0; k < loads.size(); ++k) {
    if (options.on_step_start) options.on_step_start(k, loads.size(), loads[k]);
    SweepStep step;
    step.loading = loads[k];
    const SweepStep* previous = steps.empty() ? nullptr : &steps.back();
    step.warm_started = options.warm_start && previous != nullptr && previous->result.converged();
    std::span<const double> start;
    if (step.warm_started) start = {previous->result.pressure.data(), grid.size()};
    step.result = solver.solve(initial_gap, loads[k], start);
    step.statistics =
        contact_statistics(grid, {step.result.pressure.data(), grid.size()}, {step.result.gap.data(), grid.size()});
    steps.push_back(std::move(step));
    if (options.on_step_done) options.on_step_done(k, loads.size(), steps.back());
    if (steps.back().result.status == solvers::SolveStatus::stopped) break;  // the caller's progress said so
  }
  return steps;
}

std::vector<SweepStep> sweep_surface(const Grid& grid, std::span<const double> heights, double e_star, ControlMode mode,
                                     std::span<const double> values, const solvers::SolverOptions& options,
                                     const LoadSweepOptions& sweep) {
  return sweep_with(
      grid, heights, [&] { return solvers::make_solver(grid, e_star, options); }, mode, values, sweep);
}

std::vector<SweepStep> sweep_surface(const Grid& grid, std::span<const double> heights, const LayeredMaterial& coating,
                                     ControlMode mode, std::span<const double> values,
                                     const solvers::SolverOptions& options, const LoadSweepOptions& sweep) {
  return sweep_with(
      grid, heights, [&] { return solvers::make_solver(grid, coating, options); }, mode, values, sweep);
}

}  // namespace halfspace::analysis
