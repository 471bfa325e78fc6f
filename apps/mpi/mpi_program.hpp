// The MPI side of the halfspace program (HALFSPACE_MPI builds only):
// MPI_COMM_WORLD as the solvers' communicator, the surface shared out in
// slabs, and the distributed solve command.
#pragma once

#include <functional>
#include <optional>

#include "../solve_setup.hpp"
#include "halfspace/mpi/agreement.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"

namespace halfspace::app {

// MPI_COMM_WORLD as the solvers' communicator (between the session's start
// and end, which processes.cpp's Processes owns).
mpi::MpiCommunicator mpi_world();

// The grid of the first process (whole on it, nullopt elsewhere), to every
// process. Collective.
Grid broadcast_grid(const mpi::MpiCommunicator& world, const std::optional<Grid>& grid);

// processes.hpp's make_setup_everywhere.
SolveSetup make_distributed_setup(const std::function<SolveSetup(const SurfaceSharing& share)>& make);

// processes.hpp's run_distributed_solve.
std::optional<int> run_solve_on_slabs(const SolveSetup& setup);

}  // namespace halfspace::app
