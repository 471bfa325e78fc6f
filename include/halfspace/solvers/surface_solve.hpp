// A surface's contact solve as every front end runs it (the program and the
// Python package): heights -> initial gap -> make_solver -> solve (the
// warm-started sweep over several loads is analysis::sweep_surface). The solver and its operator live
// only for the call, so their memory is free before the caller computes
// statistics or writes files.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/solvers/loading.hpp"
#include "halfspace/solvers/solve_result.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::solvers {

// The separation at zero approach of the rigid surface `heights` (m, one per
// cell of `grid`): max(h) - h. Throws InputError if the sizes differ.
Eigen::ArrayXd initial_gap(const Grid& grid, std::span<const double> heights);

// Solves the contact of the rigid surface `heights` (m, one per cell of
// `grid`, (ny, nx) row-major, peaks positive) pressed into a half-space of
// composite modulus e_star (Pa) under `loading`, optionally warm-started from
// `initial_pressure` (Pa, one per cell, or empty). Uses the threads in force
// (set_threads). SolveResult::wall_seconds is the solve's time (without
// building the solver) when the solver does not record it. Throws InputError
// for sizes that do not match the grid or options the solver refuses; any
// exception thrown by options.progress passes through, with the solver
// destroyed.
SolveResult solve_surface(const Grid& grid, std::span<const double> heights, double e_star, const Loading& loading,
                          const SolverOptions& options, std::span<const double> initial_pressure = {});

// The same on a coated half-space (layered_material.hpp) instead of a
// homogeneous one.
SolveResult solve_surface(const Grid& grid, std::span<const double> heights, const LayeredMaterial& coating,
                          const Loading& loading, const SolverOptions& options,
                          std::span<const double> initial_pressure = {});
}  // namespace halfspace::solvers
