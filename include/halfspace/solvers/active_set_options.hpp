// The options of the primal-dual active-set phase (active_set_start.hpp).
// SolverOptions reaches them through MultilevelOptions (solver_options.hpp).
#pragma once

namespace halfspace::solvers {

struct ActiveSetOptions {
  // Each linear solve stops when its preconditioned residual norm
  // sqrt(r.M^-1 r) has fallen by this factor (an inexact Newton step; 0.1
  // took the fewest products of 0.01-0.3 on rough surfaces, 256^2-1024^2).
  double inner_reduction = 0.1;
  // Conjugate-gradient iterations per linear solve at most.
  int max_inner = 50;
  // Set updates at most.
  int max_outer = 12;
  // The phase ends once an update changes at most this share of the set.
  double settled_changes = 1e-3;

  // Throws SolverOptionError naming the option ("active_set.inner_reduction",
  // ...) unless 0 < inner_reduction < 1, max_inner >= 1, max_outer >= 1 and
  // 0 <= settled_changes < 1.
  void validate() const;
};

}  // namespace halfspace::solvers
