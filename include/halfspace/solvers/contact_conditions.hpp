// An independent check of a solved contact: "converged" must mean that the
// contact conditions hold, whatever the solver's own residual said. It
// recomputes u = K p from the result's pressure and checks the fields are
// finite, the pressure within its bounds, the gap's complementarity with
// it, and the force (or approach) the loading asked for.
#pragma once

#include <span>
#include <string>

#include "halfspace/operators/influence_operator.hpp"
#include "halfspace/solvers/loading.hpp"
#include "halfspace/solvers/pressure_bounds.hpp"
#include "halfspace/solvers/solve_result.hpp"

namespace halfspace::solvers {

struct ContactConditionTolerances {
  // Gaps (m) relative to the gap scale ptp(initial_gap) + max(ptp(K p),
  // max |K p|): the
  // largest interpenetration out of contact, |gap| in contact below the cap,
  // open gap at the cap, and |K p - result displacement|.
  double gap = 1e-6;
  // |total force - target| relative to the target (load control), and
  // |approach - imposed| relative to the gap scale (displacement control).
  double force = 1e-9;

  // The tolerances for a solve stopped at relative residual `tolerance`:
  // the residual is a mean over the cells, so a single cell may be off by
  // more; gap max(1e-6, sqrt(tolerance)).
  static ContactConditionTolerances for_solver_tolerance(double tolerance);
};

struct ContactConditionReport {
  bool holds = true;
  std::string violation;            // the first condition broken, with the numbers; empty if none
  double worst_gap = 0.0;           // largest gap violation over the gap scale
  double force_error = 0.0;         // relative force (or approach) error
  double displacement_error = 0.0;  // |K p - result.displacement| over the gap scale
};

// Checks `result` against the problem (initial_gap, loading) on `op`, the
// frictionless law with `bounds` ([0, inf) or [0, H]): the pressure may
// only be at zero, in (0, H) with a closed gap, or at H with gap <= 0.
// `scratch` (one entry per local cell) receives K p; op's communicator
// reduces across processes. A cohesive law (negative pressures) is not
// this check's: an adhesive solver would check its own law's traction-gap
// relation and call this with bounds {-inf, H} only for the finiteness,
// force and K p parts (see docs/solvers.md). Throws InputError on sizes
// that do not match the operator.
ContactConditionReport check_contact_conditions(InfluenceOperator& op, std::span<const double> initial_gap,
                                                const Loading& loading, const PressureBounds& bounds,
                                                const SolveResult& result, const ContactConditionTolerances& tolerances,
                                                std::span<double> scratch);

}  // namespace halfspace::solvers
