// The admissible contact pressures. Frictionless contact without adhesion
// admits p >= 0; an elastic-perfectly plastic surface of hardness H admits
// 0 <= p <= H (interface_law.hpp). Polonsky-Keer projects every iterate
// onto the bounds here and nowhere else.
#pragma once

#include <algorithm>
#include <limits>

namespace halfspace::solvers {

struct PressureBounds {
  double lower = 0.0;                                      // Pa
  double upper = std::numeric_limits<double>::infinity();  // Pa; infinite without a cap

  // Relative distance below the cap within which a pressure is on it.
  static constexpr double kSnap = 1e-13;

  // Bounds with the cap p <= hardness (Pa).
  static PressureBounds capped_at(double hardness) { return {0.0, hardness}; }

  bool capped() const { return upper < std::numeric_limits<double>::infinity(); }
  // The admissible pressure nearest to p.
  double project(double p) const { return std::min(std::max(p, lower), upper); }
  // Whether p is at the cap (a plastic cell). Iterates are put on the cap
  // exactly (project, snap), so this compares without a tolerance.
  bool at_cap(double p) const { return p >= upper; }
  // p, or the cap itself if p is within rounding of it (a few ulps): a
  // pressure projected onto the cap and then rescaled by the load must stay
  // exactly on it.
  double snap(double p) const { return p >= upper * (1.0 - kSnap) ? upper : p; }
};

}  // namespace halfspace::solvers
