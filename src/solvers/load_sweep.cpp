// Load sweeps with warm starts. Starting step k from the pressure of step k-1
// saves most of the iterations when the loads are close: the contact set
// changes little, and the Polonsky-Keer iteration only has to move its edge.
#include "halfspace/solvers/load_sweep.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "halfspace/error.hpp"

namespace halfspace::solvers {
namespace {

// Each column reads its value with a captureless lambda (a plain function
// pointer in the table).
constexpr std::array kColumns{
    SummaryColumn{
        "load", "",
        "the controlled value of the step: force (N, N/m in 1D), mean pressure (Pa) or approach (m), as load_mode says",
        [](const SweepStep& s) { return s.loading.value; }},
    SummaryColumn{"mean_pressure", "Pa", "total force over the domain area",
                  [](const SweepStep& s) { return s.result.mean_pressure; }},
    SummaryColumn{"total_force", "force", "sum of pressure times cell area",
                  [](const SweepStep& s) { return s.result.total_force; }},
    SummaryColumn{"approach", "m", "rigid-body approach", [](const SweepStep& s) { return s.result.approach; }},
    SummaryColumn{"contact_fraction", "1", "cells with pressure > 0 over all cells",
                  [](const SweepStep& s) { return s.statistics.contact_fraction; }},
    SummaryColumn{"mean_gap", "m", "mean gap over all cells", [](const SweepStep& s) { return s.statistics.mean_gap; }},
    SummaryColumn{"rms_gap", "m", "root mean square gap over all cells",
                  [](const SweepStep& s) { return s.statistics.rms_gap; }},
    SummaryColumn{"free_volume", "volume", "sum of gap times cell area (m^3; m^2 in 1D)",
                  [](const SweepStep& s) { return s.statistics.free_volume; }},
    SummaryColumn{"max_pressure", "Pa", "largest pressure", [](const SweepStep& s) { return s.result.max_pressure; }},
    SummaryColumn{"clusters", "1", "number of contact clusters (connected components)",
                  [](const SweepStep& s) { return static_cast<double>(s.statistics.clusters()); }},
    SummaryColumn{"iterations", "1", "solver iterations",
                  [](const SweepStep& s) { return static_cast<double>(s.result.iterations); }},
    SummaryColumn{"residual", "1", "final value of the solver's stopping measure",
                  [](const SweepStep& s) { return s.result.residual; }},
    SummaryColumn{"seconds", "s", "wall-clock time of the step's solve",
                  [](const SweepStep& s) { return s.result.wall_seconds; }},
    SummaryColumn{"converged", "1", "1 if the step converged, else 0",
                  [](const SweepStep& s) { return s.result.converged() ? 1.0 : 0.0; }},
};

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
      throw InputError(fmt::format("{} = {} is invalid: must be finite", to_string(mode), value));
    }
    loads.push_back(loading);
  }
  if (mode == ControlMode::approach && grid.periodic()) {
    // Checked up front rather than by the solver at the failing step, so that
    // a bad list does not cost the steps before it.
    double mean_gap = 0.0;
    for (const double g : initial_gap) mean_gap += g;
    mean_gap /= static_cast<double>(initial_gap.size());
    for (const double value : values) {
      if (value >= mean_gap) {
        throw InputError(
            fmt::format("approach = {} m is invalid for a periodic surface: it must be below the mean initial gap {} m "
                        "(full contact needs infinite pressure there)",
                        value, mean_gap));
      }
    }
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
    step.statistics = surface::contact_statistics(grid, step.result);
    steps.push_back(std::move(step));
    if (options.on_step_done) options.on_step_done(k, loads.size(), steps.back());
  }
  return steps;
}

std::span<const SummaryColumn> summary_columns() {
  return kColumns;
}

}  // namespace halfspace::solvers
