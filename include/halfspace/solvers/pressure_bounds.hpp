// The admissible contact pressures. Frictionless contact without adhesion
// admits p >= 0; Polonsky-Keer projects every iterate onto the bounds here
// and nowhere else, so that a further bound (e.g. a hardness cap p <= H)
// is added here rather than in the iteration.
#pragma once

#include <algorithm>

namespace halfspace::solvers {

struct PressureBounds {
  double lower = 0.0;  // Pa

  // The admissible pressure nearest to p.
  double project(double p) const { return std::max(p, lower); }
};

}  // namespace halfspace::solvers
