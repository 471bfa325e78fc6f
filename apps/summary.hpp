// The one-screen report of a finished solve, printed by `halfspace solve`.
#pragma once

#include <cstdio>

#include "halfspace/solvers/solve_result.hpp"
#include "solve_setup.hpp"

namespace halfspace::app {

// Writes the setup (surface, grid, material, load, solver) and the outcome
// (status, iterations, residual, force, pressure, approach, contact) to `out`.
void print_summary(std::FILE* out, const SolveSetup& setup, const SolveResult& result);

// One line for stderr when the solve did not converge, starting "error: ".
std::string non_convergence_message(const SolveSetup& setup, const SolveResult& result);

}  // namespace halfspace::app
