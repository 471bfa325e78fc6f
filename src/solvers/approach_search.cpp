// Load control by a search on the approach (approach_search.hpp).
#include "halfspace/solvers/approach_search.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace halfspace::solvers {

// The search (approach_search.hpp). F(delta) is not one function: the contact edge of a
// cohesive law is trapped by the grid (a cell snaps in or out of contact at
// a finite jump of the force), so the state at an approach depends on the
// path to it, and a loaded state and an unloaded one at the same approach
// differ. The search therefore follows one path: every trial solve starts
// from the `base`, the last state on the side of the target the search
// came from, moving the approach one way (towards more force when the
// force is too small, less when too large). It expands its steps (secant
// steps where the force grows with the approach, doubling ones otherwise)
// until the target is bracketed, then closes the bracket by secant steps
// safeguarded by bisection (the base following the near side). A bracket
// closing on a jump (the target between the force before and after a
// snap) is left from its other end, along that branch in the other
// direction (after a snap-in the contact is larger, and unloading it
// reaches the target: the state load control snaps to). Unloading past the
// force minimum detaches the surfaces (the force rises again): then the
// target is beyond the pull-off force of the branch, which is reported.
// The force tolerance is the requested relative one or the force the inner
// solve's residual leaves undetermined, whichever is larger.
SolveResult search_approach(ApproachDriven& driven, const ApproachSearch& search, double approach, SolveResult result) {
  const double target = search.target;
  const double probe = search.probe;
  int iterations = result.iterations;
  int products = result.operator_applications;
  // The force tolerance: the requested relative one, or the force the inner
  // solve leaves undetermined.
  const auto tolerance = [&](const SolveResult& r) {
    const double scale = std::max(
        {std::abs(target), std::abs(r.adhesion.adhesive_force), std::abs(r.total_force - r.adhesion.adhesive_force)});
    return std::max(search.force_tolerance * scale, driven.undetermined_force(r));
  };
  // The two ends of the bracket: approaches with the force below and above
  // the target (their states kept by `driven`).
  struct End {
    bool set = false;
    double approach = 0.0;
    double force = 0.0;
  };
  End low;
  End high;
  const auto keep = [&](End& end) {
    end = {true, approach, result.total_force};
    driven.keep(&end == &high);
  };
  bool loading = true;  // the base is `low` (the search raises the approach) or `high`
  double step_size = probe;
  double least_force = std::numeric_limits<double>::infinity();  // the least force solved, and where
  double least_at = approach;
  bool base_in_contact = false;
  int reversals = 0;  // brackets closed on a jump and left from their other end
  double least_slope = std::numeric_limits<double>::infinity();  // |dF / d delta| across the bracket
  int streak = 0;                     // the Illinois modification: how often the same end moved
  bool previous_slope_valid = false;  // the expansion's last base state, for its secant
  double previous_approach = 0.0;
  double previous_force = 0.0;
  constexpr int kMaxReversals = 3;
  std::string failure;
  int step = 0;
  for (; step < search.max_steps; ++step) {
    if (!result.converged()) {
      failure =
          fmt::format("the displacement-controlled solve at approach {:.6g} m failed: {}", approach, result.message);
      break;
    }
    const double force = result.total_force;
    if (std::abs(force - target) <= tolerance(result)) break;
    if (step == 0) loading = force < target;
    End& base = loading ? low : high;
    End& far = loading ? high : low;
    // File the state just solved.
    const bool on_base_side = loading ? force < target : force > target;
    if (!loading && on_base_side && base.set && base_in_contact && result.contact_fraction == 0.0) {
      // Unloading, and the surfaces came apart: the force minimum (the
      // pull-off) lies between the base and this approach. Back towards the
      // base with half the step; where the step vanishes, the target is
      // beyond the pull-off force.
      const double half = 0.5 * (approach - base.approach);
      step_size = std::abs(half);
      if (step_size <= 1e-2 * probe) {
        failure = fmt::format(
            "the force {:.6g} is beyond the pull-off force of this branch: unloading reached no less than {:.6g} "
            "(at approach {:.6g} m) before the surfaces came apart; load control has no equilibrium there: use "
            "displacement control (an approach sweep)",
            target, least_force, least_at);
        break;
      }
      if ((loading ? low : high).set) driven.restore(!loading);
      approach = base.approach + half;
      result = driven.solve_at(approach);
      iterations += result.iterations;
      products += result.operator_applications;
      continue;
    }
    if (!on_base_side) {
      keep(far);
    } else {
      keep(base);
      base_in_contact = result.contact_fraction > 0.0;
    }
    // +k: the low end moved k times in a row, -k: the high end.
    streak = force < target ? (streak > 0 ? streak + 1 : 1) : (streak < 0 ? streak - 1 : -1);
    if (force < least_force) {
      least_force = force;
      least_at = approach;
    }
    const double direction = loading ? 1.0 : -1.0;
    double next = 0.0;
    if (!far.set) {
      // Expanding: a secant step from the last two base states where the
      // force changes the right way, else doubling steps.
      next = base.approach + direction * step_size;
      if (previous_slope_valid && base.approach != previous_approach) {
        const double slope = (base.force - previous_force) / (base.approach - previous_approach);
        if (slope > 0.0 && std::isfinite(slope)) {
          const double secant = (target - base.force) / slope;
          next = base.approach + std::clamp(secant, -4.0 * step_size, 4.0 * step_size);
        }
      }
      step_size = std::abs(next - base.approach) * 2.0;
      previous_slope_valid = true;
      previous_approach = base.approach;
      previous_force = base.force;
    } else {
      const double width = std::abs(high.approach - low.approach);
      // A jump: the bracket is narrow against the law's range and its
      // force difference has stopped shrinking with it (the mean slope
      // across it 100 times the least seen in this bracket; on a steep but
      // continuous stretch of a rough contact it stays put), or the
      // bracket is at rounding.
      const double slope_across = std::abs(high.force - low.force) / width;
      least_slope = std::min(least_slope, slope_across);
      const bool narrow = width <= 1e-4 * probe && slope_across >= 100.0 * least_slope;
      if (narrow || width <= 1e-13 * std::max(std::abs(approach), probe)) {
        // Closed on a jump: leave the bracket from its other end, along
        // that end's branch the other way.
        if (++reversals > kMaxReversals) {
          failure = fmt::format(
              "the force jumps from {:.6g} to {:.6g} at approach {:.6g} m (cells snapping into or out of contact on "
              "this grid) and the target {:.6g} lies in the jump on every branch followed ({} reversals)",
              low.force, high.force, approach, target, kMaxReversals);
          break;
        }
        loading = !loading;
        (loading ? high : low).set = false;
        least_slope = std::numeric_limits<double>::infinity();
        previous_slope_valid = false;
        step_size = probe;
        streak = 0;
        next = (loading ? low : high).approach + (loading ? 1.0 : -1.0) * step_size;
      } else {
        // Regula falsi inside the bracket with the Illinois modification
        // (the retained end's residual halved while the other end moves,
        // Dowell & Jarratt 1971, BIT 11, 168), bisection where it leaves
        // the bracket's interior.
        const double weight = std::ldexp(1.0, -std::min(60, std::max(0, std::abs(streak) - 1)));
        const double f_low = (low.force - target) * (streak < 0 ? weight : 1.0);
        const double f_high = (high.force - target) * (streak > 0 ? weight : 1.0);
        next = low.approach - f_low * (high.approach - low.approach) / (f_high - f_low);
        const double lo = std::min(low.approach, high.approach);
        const double hi = std::max(low.approach, high.approach);
        if (!(next > lo + 1e-3 * width && next < hi - 1e-3 * width)) next = 0.5 * (low.approach + high.approach);
      }
    }
    // Every trial starts from the base (the path the search follows).
    if ((loading ? low : high).set) driven.restore(!loading);
    approach = std::min(next, search.ceiling);
    result = driven.solve_at(approach);
    iterations += result.iterations;
    products += result.operator_applications;
  }
  if (failure.empty() && step >= search.max_steps) {
    // breakdown, not iteration_limit: the last inner solve converged, and
    // the reason (the force missed) is the message, which front ends show
    // for a breakdown.
    result.status = SolveStatus::breakdown;
    failure = fmt::format(
        "the force {:.6g} was not reached in {} approach steps (last: {:.6g} at approach {:.6g} m{})", target,
        search.max_steps, result.total_force, approach,
        low.set && high.set ? fmt::format("; bracket [{:.6g}, {:.6g}] m", low.approach, high.approach) : std::string());
  }
  if (!failure.empty()) {
    if (result.converged()) result.status = SolveStatus::breakdown;
    result.message = failure;
  }
  result.iterations = iterations;
  result.operator_applications = products;
  return result;
}

}  // namespace halfspace::solvers
