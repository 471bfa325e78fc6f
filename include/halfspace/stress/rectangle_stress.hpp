// Stress influence coefficients: the exact stress inside an elastic half-space
// under unit uniform pressure (1 Pa) on one grid cell, a rectangle in 3D
// (Love 1929) or a strip in plane strain (Johnson 1985, sec. 2.3). Compression
// is negative; z > 0 is the depth (m) below the surface.
#pragma once

#include "halfspace/stress/stress_tensor.hpp"

namespace halfspace::stress {

// Stress at (x, y, z) (m, x and y relative to the rectangle's centre, z > 0)
// under 1 Pa on |x'| <= half_width_x, |y'| <= half_width_y, for Poisson's
// ratio nu. Even in x and y except xz (odd in x), yz (odd in y) and xy (odd
// in both).
StressTensor rectangle_stress(double x, double y, double z, double half_width_x, double half_width_y, double nu);

// Plane-strain stress at (x, z) (x relative to the strip's centre, z > 0)
// under 1 Pa on |x'| <= half_width: xx, zz, xz from the strip solution and
// yy = nu (xx + zz); xy = yz = 0.
StressTensor strip_stress(double x, double z, double half_width, double nu);

}  // namespace halfspace::stress
