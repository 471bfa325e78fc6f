// A frictional contact as every front end runs it (the program and the
// Python package): the normal solve of the surface (surface_solve.hpp),
// then the tangential load steps in order under its pressure, each from the
// state the previous one left (tangential_solver.hpp). For elastically
// similar bodies (Dundurs' beta = 0) the pressure does not depend on the
// shear, so the normal problem is solved once. For dissimilar ones (unless
// FrictionOptions::coupling is off) every step is a coupled step
// (coupled_step.hpp): the normal loading first, in
// FrictionOptions::normal_load_steps increments at zero tangential load,
// then the tangential steps, each with its own pressure.
#pragma once

#include <span>
#include <vector>

#include "halfspace/elastic_pair.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/solvers/friction_options.hpp"
#include "halfspace/solvers/layout.hpp"
#include "halfspace/solvers/loading.hpp"
#include "halfspace/solvers/solve_result.hpp"
#include "halfspace/solvers/solver_options.hpp"
#include "halfspace/solvers/tangential_result.hpp"

namespace halfspace::solvers {

struct FrictionalSolveResult {
  SolveResult normal;
  // One per tangential step solved, in order. A history stops at the first
  // step that does not converge (the next would start from a state that is
  // not one), and is empty when the normal solve did not converge.
  std::vector<TangentialResult> steps;
  std::size_t requested_steps = 0;
  double dundurs_beta = 0.0;  // of the pair
  bool coupled = false;       // the coupled problem was solved (beta != 0 and FrictionOptions::coupling)
  // Coupled only: the shear each normal loading increment left (the last
  // one's state starts the history; `normal` is its normal solution), and
  // each tangential step's normal solution (its pressure under its shear).
  std::vector<TangentialResult> loading_steps;
  std::vector<SolveResult> step_normals;

  // The normal solve and every requested step converged.
  bool converged() const;
  // Why not, in one sentence naming the solve or the step; empty when converged.
  std::string failure() const;
};

// Solves the rigid surface `heights` (m, one per cell) pressed under
// `loading` into the pair's half-space (ElasticPair::half_space: E* of the
// pair, or body 1's coating), then the
// tangential steps of `friction`; coupled for dissimilar bodies (the file
// comment). Throws SolverOptionError as
// FrictionOptions::validate(grid, normal, loading) does, InputError
// for sizes that do not match the grid, and the tangential solver's
// InputError when, under approach control, a force step exceeds mu P. On a
// distributed `layout` the heights and the result's fields are this
// process's cells, every sum and maximum is over its communicator, and the
// call is collective.
FrictionalSolveResult solve_frictional_surface(const Grid& grid, std::span<const double> heights,
                                               const ElasticPair& pair, const Loading& loading,
                                               const SolverOptions& normal, const FrictionOptions& friction,
                                               const Layout& layout = serial_layout());

// The tangential steps of `friction` under the converged normal solution
// `normal` (its pressure), for a front end that made the normal solve itself;
// uncoupled (the pressure fixed) whatever the pair.
// A step whose load equals the previous step's (the turning point that ends
// one branch of a loop and starts the next) is not solved again: its state
// is the previous one, exactly (no slip increment), with no dissipation.
// On `layout` as solve_frictional_surface.
std::vector<TangentialResult> solve_tangential_history(const Grid& grid, const ElasticPair& pair,
                                                       const SolveResult& normal, const FrictionOptions& friction,
                                                       FftPlanning planning = FftPlanning::estimate,
                                                       const Layout& layout = serial_layout());

// Bytes a frictional solve adds to the normal one's peak on `grid` with
// `steps` tangential steps kept for writing: the tangential operator's padded
// symbols and transforms, the solver's workspace, and per kept step its
// state (six fields) and stick map; for a history of several steps, its file
// image assembled in memory.
double friction_memory_estimate(const Grid& grid, std::size_t steps);

}  // namespace halfspace::solvers

namespace halfspace {
using solvers::FrictionalSolveResult;
}  // namespace halfspace
