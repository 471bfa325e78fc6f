// Love's (1929) exact surface displacement of an elastic half-space under
// uniform pressure on a rectangle (Johnson, Contact Mechanics, 1985, sec. 3.2).
#pragma once

namespace halfspace::kernels {

// Normal displacement (m) at (x, y) (m, relative to the rectangle's centre)
// under unit pressure (1 Pa) on |x'| <= half_width_x, |y'| <= half_width_y,
// for composite modulus e_star (Pa). Finite everywhere, including on the
// rectangle's edges and corners.
double love_rectangle_displacement(double x, double y, double half_width_x, double half_width_y, double e_star);

}  // namespace halfspace::kernels
