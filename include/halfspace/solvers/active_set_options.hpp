// The options of the primal-dual active-set phase (active_set_start.hpp).
// SolverOptions reaches them through MultilevelOptions (solver_options.hpp).
#pragma once

namespace halfspace::solvers {

struct ActiveSetOptions {
  // Each linear solve stops when the norm of its residual on the set has
  // fallen by this factor (an inexact Newton step), tested before M^-1 is
  // applied, so no application is spent on the test; 0.2 took the fewest
  // FFT pairs of 0.1-0.3 on rough surfaces, 256^2-2048^2
  // (docs/development-log.md, "fewer FFT pairs per solve").
  double inner_reduction = 0.2;
  // Conjugate-gradient iterations per linear solve at least and at most.
  // One deflated step can reach inner_reduction alone while the pressure on
  // the set is still far from the solve's, and a set update from it moves
  // cells it should not: at 16384^2 the updates then did not settle and
  // the phase gave up, where two steps per solve settle the set
  // (docs/development-log.md, "16384^2 solved: two steps per linear solve
  // of the active-set phase").
  int min_inner = 2;
  int max_inner = 50;
  // Set updates at most.
  int max_outer = 12;
  // The phase ends once an update changes at most this share of the set.
  double settled_changes = 1e-3;

  // Throws SolverOptionError naming the option ("active_set.inner_reduction",
  // ...) unless 0 < inner_reduction < 1, 1 <= min_inner <= max_inner,
  // max_outer >= 1 and 0 <= settled_changes < 1.
  void validate() const;
};

}  // namespace halfspace::solvers
