// Spence's stick zone (Spence 1975; Johnson 1985, sec. 5.6, Fig. 5.14): a
// cylinder or a sphere pressed monotonically into a dissimilar body with
// friction mu keeps a central stick zone |x| < c, r < c, whose ratio c/a is
// a function of |beta|/mu alone (Dundurs' beta), the pressure taken as
// Hertz's (the shear's effect on it neglected, as in Spence's analysis).
// Derived in docs/theory.md ("The stick zone of a pressed contact") from
// the self-similar stick condition (a stuck point keeps the relative
// tangential displacement it had when the growing stick zone reached it),
// bounded shear at the stick edge and no square-root term there (the edge
// advances):
//   plane:          |beta|/mu = K'(k)/K(k)
//   axisymmetric:   |beta|/mu = [2 k f(k) + 4 int_k^1 f(t) dt] / artanh(k),
//                   f(t) = E(1 - t^2) - K(1 - t^2)/2
// with k = c/a and K, E the complete elliptic integrals (parameter m = k^2
// in K(k) above; f's argument is the parameter).
#pragma once

#include <cmath>
#include <stdexcept>

#include "support/gauss_legendre.hpp"

namespace halfspace::testing {

// Complete elliptic integrals of the parameter m = k^2.
inline double elliptic_k(double m) {
  return std::comp_ellint_1(std::sqrt(m));
}
inline double elliptic_e(double m) {
  return std::comp_ellint_2(std::sqrt(m));
}

// |beta|/mu for a stick ratio k = c/a in (0, 1); both decrease with k.
inline double spence_plane_beta_over_mu(double k) {
  return elliptic_k(1.0 - k * k) / elliptic_k(k * k);
}

inline double spence_axisymmetric_beta_over_mu(double k) {
  const auto f = [](double t) { return elliptic_e(1.0 - t * t) - 0.5 * elliptic_k(1.0 - t * t); };
  // f is smooth on [k, 1] (its logarithm sits at t = 0): 64 Gauss-Legendre
  // panels of 8 points, graded towards t = k for small k.
  static const QuadratureRule rule = gauss_legendre(8);
  double integral = 0.0;
  const int panels = 64;
  for (int i = 0; i < panels; ++i) {
    // t = k + (1 - k) s^2 on panels of s: finer near k.
    const double s0 = static_cast<double>(i) / panels;
    const double s1 = static_cast<double>(i + 1) / panels;
    for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
      const double s = 0.5 * (s0 + s1) + 0.5 * (s1 - s0) * rule.nodes[j];
      const double t = k + (1.0 - k) * s * s;
      integral += 0.5 * (s1 - s0) * rule.weights[j] * f(t) * 2.0 * (1.0 - k) * s;
    }
  }
  return (2.0 * k * f(k) + 4.0 * integral) / std::atanh(k);
}

// c/a for a given |beta|/mu > 0 (bisection: both relations are monotone).
template <class Relation>
double spence_stick_ratio(double beta_over_mu, Relation relation) {
  if (!(beta_over_mu > 0.0)) throw std::invalid_argument("spence_stick_ratio: beta/mu must be > 0");
  double lo = 1e-12;        // relation(lo) is large
  double hi = 1.0 - 1e-15;  // relation(hi) is near 0
  for (int i = 0; i < 200 && hi - lo > 1e-14; ++i) {
    const double mid = 0.5 * (lo + hi);
    (relation(mid) > beta_over_mu ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

inline double spence_plane_stick_ratio(double beta_over_mu) {
  return spence_stick_ratio(beta_over_mu, spence_plane_beta_over_mu);
}
inline double spence_axisymmetric_stick_ratio(double beta_over_mu) {
  return spence_stick_ratio(beta_over_mu, spence_axisymmetric_beta_over_mu);
}

}  // namespace halfspace::testing
