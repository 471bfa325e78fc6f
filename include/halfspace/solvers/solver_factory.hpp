// Builds the solver SolverOptions describe, with the operator it needs, so
// front ends (the CLI, sweeps) handle every solver the same way.
#pragma once

#include <memory>
#include <variant>

#include "halfspace/grid.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/solvers/adhesive_contact_solver.hpp"
#include "halfspace/solvers/contact_solver.hpp"
#include "halfspace/solvers/polonsky_keer.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::solvers {

// A solver for contacts on `grid` with composite modulus e_star (Pa), owning
// its influence operator. Uses the threads in force (set_threads) for FFT
// plans. Throws SolverOptionError (an InputError) naming the option if
// options.validate(grid) does.
std::unique_ptr<ContactSolver> make_solver(const Grid& grid, double e_star, const SolverOptions& options = {});

// The same for a coated half-space under a rigid indenter (layered_material.hpp):
// its kernel in the operator, the Fourier preconditioner and every multilevel
// level. Throws InputError if `material` is out of range, SolverOptionError
// for the dense solvers (lemke, lcpquad), whose matrix is the homogeneous one.
std::unique_ptr<ContactSolver> make_solver(const Grid& grid, const LayeredMaterial& material,
                                           const SolverOptions& options = {});

// The Polonsky-Keer options of `options` at `tolerance`: its iteration limit,
// progress and pressure bounds; the projected form (which takes a
// preconditioner) if `projected`, else the paper's.
PolonskyKeerOptions polonsky_keer_options(const SolverOptions& options, double tolerance, bool projected);

// The adhesive solver's options of `options` (which must hold adhesion):
// its law, tolerance, form, the hardness cap, iteration limit, planning and
// progress.
AdhesiveSolverOptions adhesive_solver_options(const SolverOptions& options);
// The modulus at a contact edge's scale, which sets the adhesive law's
// cohesive zone: a homogeneous body's E* (Pa), or a coating's layer's plane-
// strain modulus (the layer meets the rigid surface).
double contact_modulus(const std::variant<double, LayeredMaterial>& elasticity);

// Whether pk-multilevel on `grid` deflates its finest grid: deflation on,
// or automatic where DeflationOptions::automatic_applies and there is no
// hardness cap. (With MultilevelOptions::active_set the serial solver
// also deflates wherever the block covers the grid.)
bool multilevel_deflates(const Grid& grid, const SolverOptions& options);

}  // namespace halfspace::solvers
