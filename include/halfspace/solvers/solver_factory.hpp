// Builds the solver SolverOptions describe, with the operator it needs on
// the layout given (serial or distributed), so front ends (the CLI, sweeps,
// the MPI program) handle every solver the same way.
#pragma once

#include <memory>

#include "halfspace/grid.hpp"
#include "halfspace/half_space.hpp"
#include "halfspace/solvers/adhesive_contact_solver.hpp"
#include "halfspace/solvers/contact_solver.hpp"
#include "halfspace/solvers/layout.hpp"
#include "halfspace/solvers/polonsky_keer.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::solvers {

// A solver for contacts on `grid` of `half_space` (homogeneous E* in Pa, or
// a coated half-space, layered_material.hpp), owning its influence
// operator, made by `layout` (serial_layout(): the whole grid here; a
// distributed one: fields given to and returned by the solver hold this
// process's rows), which must outlive the solver. A coating's kernel goes
// into the operator, the Fourier preconditioner and every multilevel level.
// Uses the threads in force (set_threads) for FFT plans. Collective on a
// distributed layout. Throws SolverOptionError (an InputError) naming the
// option if options.validate does (with a coating, validate(grid, coating):
// the dense solvers lemke and lcpquad take the homogeneous matrix only) or
// the layout refuses it (Layout::check), InputError for an invalid modulus
// or coating.
std::unique_ptr<ContactSolver> make_solver(const Grid& grid, const HalfSpace& half_space,
                                           const SolverOptions& options = {}, const Layout& layout = serial_layout());

// The Polonsky-Keer options of `options` at `tolerance`: its iteration limit,
// progress and pressure bounds; the projected form (which takes a
// preconditioner) if `projected`, else the paper's.
PolonskyKeerOptions polonsky_keer_options(const SolverOptions& options, double tolerance, bool projected);

// The adhesive solver's options of `options` (which must hold adhesion):
// its law, tolerance, form, the hardness cap, iteration limit, planning and
// progress.
AdhesiveSolverOptions adhesive_solver_options(const SolverOptions& options);

// Whether pk-multilevel on `grid` deflates its finest grid: deflation on,
// or automatic where DeflationOptions::automatic_applies and there is no
// hardness cap. (Where MultilevelOptions::active_set_applies, the solver
// also deflates from DeflationOptions::kAutomaticWithActiveSetFromCells.)
bool multilevel_deflates(const Grid& grid, const SolverOptions& options);

}  // namespace halfspace::solvers
