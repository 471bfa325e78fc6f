// Cerruti's unit tangential point force on the surface of a half-space
// (Johnson 1985, eq. 3.87): the independent reference for the shear stress
// coefficients. Force along +x acting on the body at the origin; z > 0 into
// the body; compression negative.
#pragma once

#include <cmath>
#include <numbers>

#include "halfspace/stress/stress_tensor.hpp"

namespace halfspace::testing {

inline stress::StressTensor cerruti_point_force_stress(double x, double y, double z, double nu) {
  const double rho = std::sqrt(x * x + y * y + z * z);
  const double rho2 = rho * rho;
  const double rho3 = rho2 * rho;
  const double rho5 = rho3 * rho2;
  const double rz = rho + z;
  const double rz2 = rz * rz;
  const double rz3 = rz2 * rz;
  const double m = 1.0 - 2.0 * nu;
  const double scale = 1.0 / (2.0 * std::numbers::pi);
  stress::StressTensor s;
  s.xx = scale * (-3.0 * x * x * x / rho5 +
                  m * (x / rho3 - 3.0 * x / (rho * rz2) + x * x * x / (rho3 * rz2) + 2.0 * x * x * x / (rho2 * rz3)));
  s.yy = scale * (-3.0 * x * y * y / rho5 +
                  m * (x / rho3 - x / (rho * rz2) + x * y * y / (rho3 * rz2) + 2.0 * x * y * y / (rho2 * rz3)));
  s.zz = -3.0 * scale * x * z * z / rho5;
  s.xy = scale *
         (-3.0 * x * x * y / rho5 + m * (-y / (rho * rz2) + x * x * y / (rho3 * rz2) + 2.0 * x * x * y / (rho2 * rz3)));
  s.xz = -3.0 * scale * x * x * z / rho5;
  s.yz = -3.0 * scale * x * y * z / rho5;
  return s;
}

}  // namespace halfspace::testing
