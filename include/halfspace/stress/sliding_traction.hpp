// The shear tractions of gross sliding: every contact cell at the Coulomb
// limit, q = mu p along the sliding direction, what the stresses below a
// sliding sphere or cylinder take beside its pressure.
#pragma once

#include <span>
#include <vector>

namespace halfspace::stress {

struct SlidingShear {
  std::vector<double> x;  // q_x, Pa, one per cell like the pressure
  std::vector<double> y;  // q_y, Pa
};

// q = mu p (cos, sin) with (cos, sin) the unit vector of (direction_x,
// direction_y): the traction body 1 exerts on body 2 when body 1 slides
// along that direction relative to body 2 (the friction library's sign,
// solvers/tangential_result.hpp; the same as TangentialSolver's gross
// sliding under a force of mu P along it). Throws InputError naming the
// value unless mu is finite and >= 0, the direction finite and not zero, and
// every pressure finite and >= 0 (Pa).
SlidingShear gross_sliding_shear(std::span<const double> pressure, double friction_coefficient, double direction_x,
                                 double direction_y = 0.0);

}  // namespace halfspace::stress
