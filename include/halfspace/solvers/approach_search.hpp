// Load control for a solver driven by the approach: the approach whose
// displacement-controlled equilibrium carries a target force, found by a
// search that follows one path of states (expanding secant steps until the
// target is bracketed, then regula falsi with the Illinois modification,
// bisection as its safeguard), for solvers whose states depend on the path
// to them (an adhesive contact's jumps in and out of contact).
#pragma once

#include <limits>

#include "halfspace/solvers/solve_result.hpp"

namespace halfspace::solvers {

// What the search drives: displacement-controlled solves from the current
// state, and that state kept and restored.
class ApproachDriven {
 public:
  virtual ~ApproachDriven() = default;
  // The equilibrium at `approach` (m), started from the current state, which
  // it becomes.
  virtual SolveResult solve_at(double approach) = 0;
  // Keep the current state as the bracket's end below (above = false) or
  // above the target force; restore() makes a kept one current.
  virtual void keep(bool above) = 0;
  virtual void restore(bool above) = 0;
  // The force (N) that `result`'s residual leaves undetermined.
  virtual double undetermined_force(const SolveResult& result) const = 0;
};

struct ApproachSearch {
  double target = 0.0;  // the total force (N, signed)
  double probe = 0.0;   // the first step (m): the approach over which the force changes (an adhesive law's range)
  double ceiling = std::numeric_limits<double>::infinity();  // the largest approach allowed (m)
  double force_tolerance = 1e-6;                             // relative to the forces of the state
  int max_steps = 60;                                        // displacement-controlled solves
};

// The search from `result`, the solve already made at `approach`. Returns
// the last solve, its iterations and operator products those of every
// solve; status breakdown with the reason when the target is beyond the
// pull-off force of the branch followed (the message gives the least force
// reached), lies in a jump of the force on every branch, or was not reached
// in max_steps; a failed inner solve's status and message otherwise.
SolveResult search_approach(ApproachDriven& driven, const ApproachSearch& search, double approach, SolveResult result);

}  // namespace halfspace::solvers
