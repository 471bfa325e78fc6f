// `mpirun -np N halfspace solve` with several loads: the load sweep on slabs
// of rows (HALFSPACE_MPI builds only).
#pragma once

#include "../solve_setup.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"

namespace halfspace::app {

// Solves setup.load_values in order on this process's rows, each step
// warm-started from the previous converged one as the serial sweep
// (analysis::run_load_sweep); the first process gathers every step's fields,
// computes its statistics and writes the serial program's files
// (finish_sweep). Returns the serial run_sweep's exit code on every process.
// Collective; throws InputError alike on every process for an invalid load.
int run_sweep_on_slabs(const SolveSetup& setup, const mpi::MpiCommunicator& world);

}  // namespace halfspace::app
