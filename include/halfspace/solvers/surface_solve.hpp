// A surface's contact solve as every front end runs it (the program and the
// Python package, the MPI program): heights -> initial gap -> make_solver -> solve (the
// warm-started sweep over several loads is analysis::sweep_surface). The solver and its operator live
// only for the call, so their memory is free before the caller computes
// statistics or writes files.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/half_space.hpp"
#include "halfspace/solvers/layout.hpp"
#include "halfspace/solvers/loading.hpp"
#include "halfspace/solvers/solve_result.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::solvers {

// The separation at zero approach of the rigid surface `heights` (m, the
// cells of `grid` this process holds as `layout` holds them: all of them
// serially): max(h) - h, the maximum taken over every process. Throws
// InputError if the sizes differ. Collective on a distributed layout.
Eigen::ArrayXd initial_gap(const Grid& grid, std::span<const double> heights, const Layout& layout = serial_layout());

// Solves the contact of the rigid surface `heights` (m, as initial_gap takes
// them, (ny, nx) row-major, peaks positive) pressed into `half_space`
// (homogeneous E* in Pa, or coated) under `loading`, optionally warm-started
// from `initial_pressure` (Pa, one per cell held, or empty), on `layout`'s
// operators. Uses the threads in force (set_threads). SolveResult::wall_seconds
// is the solve's time (without building the solver) when the solver does
// not record it. Throws InputError for sizes that do not match the grid or
// options the solver or the layout refuses; any exception thrown by
// options.progress passes through, with the solver destroyed. Collective on
// a distributed layout (the result's fields are this process's cells).
SolveResult solve_surface(const Grid& grid, std::span<const double> heights, const HalfSpace& half_space,
                          const Loading& loading, const SolverOptions& options,
                          std::span<const double> initial_pressure = {}, const Layout& layout = serial_layout());

// Whether solve_surface_in_place keeps the initial gap in the heights'
// place: a Polonsky-Keer solver (pk, pk-fourier, pk-multilevel, without
// adhesion) under load control, whose answer depends on the initial gap only
// through g0 + K p - approach with an approach of its own, so that the gap
// less a constant serves. That gap is -h, the heights' exact negation,
// undone bit for bit afterwards (max(h) - h cannot be undone exactly).
bool initial_gap_in_heights(const Loading& loading, const SolverOptions& options);

// solve_surface on heights it may borrow: where initial_gap_in_heights
// holds, their storage holds the initial gap during the solve (the surface
// is not held twice), and they are given back unchanged, also when the
// solve throws; else they are only read. The result is solve_surface's bit
// for bit (which solves on a copy the same way).
SolveResult solve_surface_in_place(const Grid& grid, std::span<double> heights, const HalfSpace& half_space,
                                   const Loading& loading, const SolverOptions& options,
                                   std::span<const double> initial_pressure = {},
                                   const Layout& layout = serial_layout());
}  // namespace halfspace::solvers
