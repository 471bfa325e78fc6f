// The MPI side of the halfspace program (HALFSPACE_MPI builds only):
// MPI_COMM_WORLD as the solvers' communicator and the first process's grid
// on every process; mpi_program.cpp, mpi_generate.cpp and mpi_stress.cpp
// define processes.hpp's functions (the surface shared out in slabs, the
// distributed solve, generate and stress commands).
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

}  // namespace halfspace::app
