// `halfspace solve`: runs a checked setup through the FFT operator and the
// Polonsky-Keer solver, writes the result file and reports.
#pragma once

#include "command.hpp"
#include "halfspace/half_space.hpp"
#include "solve_place.hpp"
#include "solve_setup.hpp"

namespace halfspace::app {

// The half-space of `setup`: its coating, or the homogeneous E*.
HalfSpace half_space(const SolveSetup& setup);

// Solves, writes setup.output (also when not converged) and prints the
// summary unless setup.quiet. Returns kExitOk when converged, else
// kExitNotConverged after printing the reason to stderr. Throws InputError
// (FileError) when the result cannot be written.
int run_solve(const SolveSetup& setup);
// The same on this process alone, setup.heights the whole surface (the
// serial program; the first MPI process for a grid not split into slabs).
// Makes no collective call.
int run_solve_here(const SolveSetup& setup);
// The same at `place`, the serial program's or this process's slab
// (collective then): the frictional solve, the load sweep or one normal
// solve.
int run_solve_at(const SolveSetup& setup, const SolvePlace& place);

// Registers `solve` on the program's parser.
Command add_solve_command(CLI::App& program);

}  // namespace halfspace::app
