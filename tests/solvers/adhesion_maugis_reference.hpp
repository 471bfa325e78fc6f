// Maugis's (1992, J. Colloid Interface Sci. 150, 243) solution of the
// adhesive sphere with a Dugdale cohesive zone, in Johnson & Greenwood's
// (1997, J. Colloid Interface Sci. 192, 326) dimensionless form, as an
// independent reference for the adhesive solver's tests. With K = 4E*/3,
// contact radius a, cohesive-zone radius c = m a and the Dugdale stress
// sigma0 acting over a gap h0 = w / sigma0:
//
//   A = a (K / (pi w R^2))^(1/3),   P = F / (pi w R),
//   lambda = 2 sigma0 (R / (pi w K^2))^(1/3),   s = sqrt(m^2 - 1),
//
//   (lambda A^2 / 2) [s + (m^2 - 2) atan s] + (4 lambda^2 A / 3) [s atan s - m + 1] = 1,
//   P = A^3 - lambda A^2 [s + m^2 atan s].
//
// lambda -> infinity gives JKR (P = A^3 - sqrt(6 A^3), pull-off -3/2),
// lambda -> 0 gives DMT (pull-off -2).
#pragma once

#include <algorithm>
#include <cmath>

namespace halfspace::testing::maugis {

// m = c/a > 1 at dimensionless contact radius `a_bar` (the root of the
// first equation, increasing in m), by bisection.
inline double zone_ratio(double lambda, double a_bar) {
  const auto lhs = [&](double m) {
    const double s = std::sqrt(m * m - 1.0);
    const double t = std::atan(s);
    return 0.5 * lambda * a_bar * a_bar * (s + (m * m - 2.0) * t) +
           4.0 / 3.0 * lambda * lambda * a_bar * (s * t - m + 1.0);
  };
  double low = 1.0;
  double high = 2.0;
  while (lhs(high) < 1.0) high *= 2.0;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (low + high);
    (lhs(mid) < 1.0 ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

// P = F / (pi w R) at dimensionless contact radius a_bar.
inline double load(double lambda, double a_bar) {
  const double m = zone_ratio(lambda, a_bar);
  const double s = std::sqrt(m * m - 1.0);
  return a_bar * a_bar * a_bar - lambda * a_bar * a_bar * (s + m * m * std::atan(s));
}

// The pull-off force over pi w R: the smallest load on the curve, found on a
// grid of contact radii and refined by golden sections.
inline double pull_off(double lambda) {
  double best_a = 1e-4;
  double best = load(lambda, best_a);
  for (double a = 1e-4; a < 3.0; a *= 1.02) {
    const double p = load(lambda, a);
    if (p < best) {
      best = p;
      best_a = a;
    }
  }
  double low = std::max(1e-5, best_a / 1.02);
  double high = best_a * 1.02;
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int k = 0; k < 100; ++k) {
    const double x1 = high - golden * (high - low);
    const double x2 = low + golden * (high - low);
    (load(lambda, x1) < load(lambda, x2) ? high : low) = (load(lambda, x1) < load(lambda, x2) ? x2 : x1);
  }
  return std::min(best, load(lambda, 0.5 * (low + high)));
}

}  // namespace halfspace::testing::maugis
