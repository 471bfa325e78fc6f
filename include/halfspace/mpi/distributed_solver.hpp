// The contact solvers that run on a grid spread over MPI processes, and the
// refusal of those that do not yet: what SolverOptions asks for is either
// solved distributed or refused with a message that names the alternative,
// never solved wrongly. Compiled only with HALFSPACE_MPI.
#pragma once

#include <memory>

#include "halfspace/grid.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/slab_fourier_operator.hpp"
#include "halfspace/solvers/contact_solver.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::mpi {

// Whether make_distributed_solver takes `options` on `grid`: a 2D grid
// (periodic or free), solver pk, pk-fourier or pk-multilevel (block
// deflation as the serial solvers take it), with or without a hardness cap;
// with adhesion (the adhesive solver, which then replaces the type) on
// periodic grids.
bool distributable(const Grid& grid, const solvers::SolverOptions& options);

// Throws SolverOptionError naming the option and what to use instead unless
// distributable(grid, options), e.g. "type = lemke is not available
// with more than one process yet: use solver pk-multilevel, pk-fourier or pk".
void check_distributable(const Grid& grid, const solvers::SolverOptions& options);

// Throws SolverOptionError naming the boundary unless a coated half-space
// on `grid` is distributed: periodic grids (the layered kernel is a Fourier
// symbol); free ones, whose padded operator would need the coated real-space
// coefficients and the layered remainder on the slabs, not yet.
void check_distributable(const Grid& grid, const LayeredMaterial& coating);

// Polonsky-Keer (pk: the paper's form; pk-fourier: the projected form with
// the Fourier preconditioner, with block deflation if asked for;
// pk-multilevel: distributed_multilevel.hpp, whose distributed levels are
// made here) on the slab operator of `grid` (periodic: SlabFourierOperator;
// free: SlabFreeOperator) of the homogeneous or (periodic grids) coated
// half-space `elasticity`, over `comm`, or with adhesion the adhesive solver
// on the periodic slab operator; `comm` must outlive the solver. Fields given to and returned by the solver
// hold this process's rows (slab_layout). Collective; throws as
// check_distributable and SolverOptions::validate do (for a coating, as
// solvers::make_solver's coated overload).
std::unique_ptr<solvers::ContactSolver> make_distributed_solver(const Grid& grid, const SlabElasticity& elasticity,
                                                                const solvers::SolverOptions& options,
                                                                const MpiCommunicator& comm);

}  // namespace halfspace::mpi
