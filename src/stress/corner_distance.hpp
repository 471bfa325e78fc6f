// Sums rho + u at a rectangle's corner, rho = sqrt(u^2 + w2) with w2 > 0,
// shared by the closed-form stresses under a uniform pressure
// (rectangle_stress.cpp) and a uniform shear (rectangle_shear_stress.cpp):
// for u < 0 the sum cancels, so rho + u = w2 / (rho - u) is used instead.
#pragma once

#include <cmath>

namespace halfspace::stress {

// 1 / (rho + u).
inline double inverse_rho_plus(double rho, double u, double w2) {
  return u >= 0.0 ? 1.0 / (rho + u) : (rho - u) / w2;
}

// ln(rho + u).
inline double log_rho_plus(double rho, double u, double w2) {
  return u >= 0.0 ? std::log(rho + u) : std::log(w2) - std::log(rho - u);
}

}  // namespace halfspace::stress
