// The MPI side of the halfspace program (HALFSPACE_MPI builds only):
// MPI_COMM_WORLD as the solvers' communicator and the first process's grid
// on every process; mpi_program.cpp, mpi_generate.cpp, mpi_stress.cpp and
// mpi_lubricate.cpp define processes.hpp's functions (the surface shared
// out in slabs, the distributed solve, generate, stress and lubricate
// commands).
#pragma once

#include <functional>
#include <optional>

#include "../processes.hpp"
#include "halfspace/mpi/agreement.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"

namespace halfspace::app {

// MPI_COMM_WORLD as the solvers' communicator (between the session's start
// and end, which Processes owns).
mpi::MpiCommunicator mpi_world();

// The grid of the first process (whole on it, nullopt elsewhere), to every
// process. Collective.
Grid broadcast_grid(const mpi::MpiCommunicator& world, const std::optional<Grid>& grid);

// Runs `run` on every process; a failure that only some processes meet in
// the middle of collective work ends them all (MPI_Abort), since the others
// wait in a transform or a reduction and cannot learn of it.
int run_on_slabs(const mpi::MpiCommunicator& world, const std::function<int()>& run);

}  // namespace halfspace::app
