// The MPI side of the halfspace program (HALFSPACE_MPI builds only): the
// session, MPI_COMM_WORLD as the solvers' communicator, and the distributed
// solve command.
#pragma once

#include <functional>
#include <optional>

#include "../solve_setup.hpp"
#include "halfspace/mpi/agreement.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/slab_fourier_operator.hpp"

namespace halfspace::app {

// MPI_Init (through mpi::Session) and MPI_Finalize, once each.
void start_mpi(int& argc, char**& argv);
void stop_mpi();

// MPI_COMM_WORLD; valid between start_mpi and stop_mpi.
const mpi::MpiCommunicator& mpi_world();

// processes.hpp's make_setup_everywhere.
SolveSetup make_distributed_setup(const std::function<SolveSetup(const SurfaceSharing& share)>& make);

// The half-space of `setup`: its coating, or the homogeneous E*.
mpi::SlabElasticity slab_elasticity(const SolveSetup& setup);

// processes.hpp's run_distributed_solve.
std::optional<int> run_solve_on_slabs(const SolveSetup& setup);

}  // namespace halfspace::app
