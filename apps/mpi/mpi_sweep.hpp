// `mpirun -np N halfspace solve` with several loads: the load sweep on slabs
// of rows (HALFSPACE_MPI builds only).
#pragma once

#include <optional>
#include <span>

#include "../plot_tool.hpp"
#include "../solve_setup.hpp"
#include "halfspace/mpi/distributed_layout.hpp"

namespace halfspace::app {

// Solves setup.load_values in order on this process's rows, each step
// warm-started from the previous converged one as the serial sweep
// (analysis::run_load_sweep); every process keeps its rows of every step's
// fields and writes them into the serial program's sweep file
// (mpi::write_sweep_slabs), the first process then the CSV and the summary
// (report_sweep, with the figures of `plot`, the first process's tool for
// --plot). Returns the serial run_sweep's exit code on every process.
// Collective; throws InputError alike on every process for an invalid load.
// `heights` are this process's rows of the surface, `layout` the processes'.
int run_sweep_on_slabs(const SolveSetup& setup, std::span<const double> heights, const mpi::DistributedLayout& layout,
                       const std::optional<PlotTool>& plot);

}  // namespace halfspace::app
