// Builds the solver SolverOptions describe, with the operator it needs, so
// front ends (the CLI, sweeps) handle every solver the same way.
#pragma once

#include <memory>

#include "halfspace/grid.hpp"
#include "halfspace/solvers/contact_solver.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::solvers {

// A solver for contacts on `grid` with composite modulus e_star (Pa), owning
// its influence operator. Uses the threads in force (set_threads) for FFT
// plans. Throws SolverOptionError (an InputError) naming the option if
// options.validate(grid) does.
std::unique_ptr<ContactSolver> make_solver(const Grid& grid, double e_star, const SolverOptions& options = {});

}  // namespace halfspace::solvers
