// `halfspace solve` with several loads: the load sweep, its files (HDF5 and
// CSV), its summary table and figures.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "halfspace/analysis/load_sweep.hpp"
#include "halfspace/io/result_metadata.hpp"
#include "halfspace/solvers/loading.hpp"
#include "plot_tool.hpp"
#include "solve_place.hpp"
#include "solve_setup.hpp"

namespace halfspace::app {

// Solves setup.load_values in order (warm starts) at `place`, writes
// setup.output and the CSV beside it (also when a step did not converge),
// prints the summary table unless setup.quiet and draws the figures if
// setup.plot (the first process). Returns kExitOk when every step
// converged, kExitNotConverged otherwise (after printing the failed steps
// to stderr), kExitPlotFailed when only the figures failed. Throws
// InputError (FileError) for bad input or when a file cannot be written.
int run_sweep_at(const SolveSetup& setup, const SolvePlace& place);

// After the HDF5 file and its CSV are written: the summary table, the
// figures and the failed steps (the first process).
int report_sweep(const SolveSetup& setup, std::span<const analysis::SweepStep> steps,
                 const std::optional<PlotTool>& plot);

// What the result files of `setup` record about the run (io::result_metadata).
io::SolveProvenance provenance(const SolveSetup& setup);

// "force 10 N", "mean pressure 2e+05 Pa", "approach 1e-06 m" (N/m in 1D).
std::string describe_load(ControlMode mode, double value, const Grid& grid);

}  // namespace halfspace::app
