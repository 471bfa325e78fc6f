// A load sweep: one contact solver run over a list of loads (or approaches)
// in the given order, each step warm-started from the previous one, with the
// contact statistics of every step and the summary table built from them.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "halfspace/analysis/contact_statistics.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/half_space.hpp"
#include "halfspace/solvers/contact_solver.hpp"
#include "halfspace/solvers/layout.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::analysis {

struct SweepStep {
  Loading loading;               // what was imposed at this step
  SolveResult result;            // the solver's outcome, fields included
  ContactStatistics statistics;  // of result
  bool warm_started = false;     // started from the previous step's pressure
};

struct LoadSweepOptions {
  // Start each step from the previous step's pressure when that step
  // converged (a failed step's pressure may be far off, or not finite).
  bool warm_start = true;
  // Adhesive solvers: any finite load is valid (a negative approach holds
  // the surfaces apart, a negative force pulls), and the list may go up and
  // back down (loading, then unloading); the solver checks each value.
  bool signed_loads = false;
  // Called before step k (0-based) of `steps` is solved, and after it with
  // its outcome. Run on the calling thread, so they may print; may be empty.
  std::function<void(std::size_t step, std::size_t steps, const Loading& loading)> on_step_start;
  std::function<void(std::size_t step, std::size_t steps, const SweepStep& outcome)> on_step_done;
  // Each step's contact statistics; empty: contact_statistics of the whole
  // grid (a distributed sweep gives the slab statistics, collective).
  std::function<ContactStatistics(const SolveResult& result)> statistics;
};

// Solves `initial_gap` (m, one entry per cell of `grid` that `layout`
// holds on this process; `grid` must be the solver's, built on `layout`)
// under loads `values` (in the unit of `mode`) in the given order. A step
// that does not converge is kept, with its status, and the sweep goes on
// (cold-started); one its progress callback stopped is the last. The
// solver's own per-iteration progress is whatever it was built with
// (SolverOptions::progress). Throws InputError if `values` is empty or a
// value is invalid for `mode` (checked before the first solve), or if the
// solver rejects the problem. Collective on a distributed layout.
std::vector<SweepStep> run_load_sweep(ContactSolver& solver, const Grid& grid, std::span<const double> initial_gap,
                                      ControlMode mode, std::span<const double> values,
                                      const LoadSweepOptions& options = {},
                                      const solvers::Layout& layout = solvers::serial_layout());

// The load sweep of run_load_sweep on the surface `heights` (the cells
// `layout` holds here) of a homogeneous (E*) or coated half-space, with one
// solver built for all steps. Throws as solvers::solve_surface and
// run_load_sweep do.
std::vector<SweepStep> sweep_surface(const Grid& grid, std::span<const double> heights, const HalfSpace& half_space,
                                     ControlMode mode, std::span<const double> values,
                                     const solvers::SolverOptions& options, const LoadSweepOptions& sweep = {},
                                     const solvers::Layout& layout = solvers::serial_layout());

}  // namespace halfspace::analysis
