// Stress influence coefficients of a shear: the exact stress inside an
// elastic half-space under a unit uniform tangential traction (1 Pa) on one
// grid cell, a rectangle in 3D (Cerruti's point force integrated in closed
// form) or a strip in plane strain (the tangential line force, Johnson 1985,
// sec. 2.2). Compression is negative; z > 0 is the depth (m) below the
// surface; at the surface sigma_xz = -q_x, sigma_yz = -q_y (surface_traction.hpp).
#pragma once

#include "halfspace/stress/stress_tensor.hpp"
#include "halfspace/stress/surface_traction.hpp"

namespace halfspace::stress {

// Stress at (x, y, z) (m, x and y relative to the rectangle's centre, z > 0)
// under 1 Pa of shear along `direction` (Traction::shear_x or shear_y) on
// |x'| <= half_width_x, |y'| <= half_width_y, for Poisson's ratio nu. The
// parities are those of odd_in_x(component, direction), odd_in_y(...).
StressTensor rectangle_shear_stress(Traction direction, double x, double y, double z, double half_width_x,
                                    double half_width_y, double nu);

// The strip |x'| <= half_width (x relative to its centre, z > 0): a shear
// along x gives the plane-strain xx, zz, xz and yy = nu (xx + zz); a shear
// along y the antiplane xy, yz (the rest zero).
StressTensor strip_shear_stress(Traction direction, double x, double z, double half_width, double nu);

}  // namespace halfspace::stress
