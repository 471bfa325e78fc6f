// pk-multilevel on a slab-distributed grid: the serial MultilevelSolver
// (levels, coarse tolerance, warm-start rule) over SlabLevelTransfer, with
// each distributed level's solver made by make_distributed_solver (the one
// place that knows which distributed operator a grid takes) and each
// gathered level's by the serial make_solver. Compiled only with
// HALFSPACE_MPI.
#pragma once

#include <memory>

#include "halfspace/grid.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/slab_fourier_operator.hpp"
#include "halfspace/solvers/contact_solver.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::mpi {

// Fields given to and returned by the solver hold this process's rows
// (slab_layout), as make_distributed_solver's, whose `elasticity` it takes. `comm` must outlive the
// solver. Collective; options are checked by make_distributed_solver.
std::unique_ptr<solvers::ContactSolver> make_distributed_multilevel(const Grid& grid, const SlabElasticity& elasticity,
                                                                    const solvers::SolverOptions& options,
                                                                    const MpiCommunicator& comm);

}  // namespace halfspace::mpi
