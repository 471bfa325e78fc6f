// The bonded-layer kernel of a coated half-space. The compliance factor
//   M(s) = (1 + 4 kappa s e - lambda kappa e^2) / (1 - (lambda + kappa + 4 kappa s^2) e + lambda kappa e^2),
//   s = |q| t, e = exp(-2 s), g = mu1/mu2,
//   kappa = (g - 1)/(g + 3 - 4 nu1), lambda = 1 - 4 (1 - nu1)/(1 + g (3 - 4 nu2)),
// is the closed-form solution of the layer's plane-strain equations for one
// Fourier mode with zero surface shear and continuous displacements and
// tractions at the interface (O'Sullivan & King 1988, Stanley & Kato 1997);
// docs/theory.md, "Coated half-space", checks it against a direct solution
// of those equations. Its limits: kappa = lambda = 0 for identical
// materials (M = 1), M -> 1 for s -> inf, and M(0) = (1 - lambda kappa) /
// ((1 - lambda)(1 - kappa)) = E1*/E2*.
#include "halfspace/kernels/layered_fourier.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "halfspace/kernels/love_rectangle.hpp"
#include "halfspace/kernels/plane_strain_strip.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::kernels {
namespace {

// Antiderivative in X and Y of 1/sqrt(X^2 + Y^2 + s^2), s > 0: the potential of
// a uniform rectangle at height s. Y + rho is formed without cancellation for
// Y < 0.
double smoothed_potential_antiderivative(double x, double y, double s) {
  const double rho = std::sqrt(x * x + y * y + s * s);
  auto log_sum = [rho, s](double a, double other) {  // ln(a + rho)
    return a >= 0.0 ? std::log(a + rho) : std::log((other * other + s * s) / (rho - a));
  };
  return x * log_sum(y, x) + y * log_sum(x, y) - s * std::atan(x * y / (s * rho));
}

// The Bessel function J0(x), x >= 0, by the polynomial approximations of
// Abramowitz & Stegun 9.4.1 (x <= 3, error below 5e-8) and 9.4.3 (x > 3,
// modulus and phase to 1.6e-8 and 7e-8). The remainder's radial tables take
// millions of values; std::cyl_bessel_j's series cost 30 s a table for a
// stiff layer on a soft substrate (issue 32), these a hundredth of it, and
// their error is far below the tables' quadrature and interpolation error
// (1e-4 of the remainder).
double bessel_j0(double x) {
  if (x <= 3.0) {
    const double y = (x / 3.0) * (x / 3.0);
    return 1.0 +
           y * (-2.2499997 + y * (1.2656208 + y * (-0.3163866 + y * (0.0444479 + y * (-0.0039444 + y * 0.0002100)))));
  }
  const double y = 3.0 / x;
  const double modulus =
      0.79788456 +
      y * (-0.00000077 + y * (-0.00552740 + y * (-0.00009512 + y * (0.00137237 + y * (-0.00072805 + y * 0.00014476)))));
  const double phase =
      x - 0.78539816 +
      y * (-0.04166397 + y * (-0.00003954 + y * (0.00262573 + y * (-0.00054125 + y * (-0.00029333 + y * 0.00013558)))));
  return modulus * std::cos(phase) / std::sqrt(x);
}

}  // namespace

LayeredKernel::LayeredKernel(const LayeredMaterial& material)
    : material_(validated(material)),
      layer_modulus_(plane_strain_modulus(material.layer)),
      substrate_modulus_(plane_strain_modulus(material.substrate)) {
  const double nu1 = material.layer.poissons_ratio;
  const double nu2 = material.substrate.poissons_ratio;
  // Shear moduli mu = E / (2 (1 + nu)); their ratio g.
  const double g = (material.layer.youngs_modulus / (1.0 + nu1)) / (material.substrate.youngs_modulus / (1.0 + nu2));
  kappa_ = (g - 1.0) / (g + 3.0 - 4.0 * nu1);
  one_minus_kappa_ = 4.0 * (1.0 - nu1) / (g + 3.0 - 4.0 * nu1);
  one_minus_lambda_ = 4.0 * (1.0 - nu1) / (1.0 + g * (3.0 - 4.0 * nu2));
  lambda_ = 1.0 - one_minus_lambda_;
  split_height_ = find_split_height();
  // R(q) -> (2 t / E1*) d/ds [M - 1 - (c - 1) exp(-s)] at s = 0: Richardson
  // extrapolation of the difference quotient, O(h^2) = 1e-8 relative.
  constexpr double h = 1e-4;
  const double t = material_.thickness;
  remainder_at_zero_ = 2.0 * remainder(h / t) - remainder(2.0 * h / t);
}

double LayeredKernel::compliance_factor(double q) const {
  const double s = std::abs(q) * material_.thickness;
  const double e = std::exp(-2.0 * s);
  const double em1 = std::expm1(-2.0 * s);  // e - 1
  // 1 - lambda e = (1 - lambda) - lambda (e - 1), likewise for kappa: exact
  // near s = 0, where the denominator tends to (1 - lambda)(1 - kappa).
  const double denominator =
      (one_minus_lambda_ - lambda_ * em1) * (one_minus_kappa_ - kappa_ * em1) - 4.0 * kappa_ * s * s * e;
  const double one_minus_lambda_kappa = one_minus_lambda_ + lambda_ * one_minus_kappa_;
  const double numerator = one_minus_lambda_kappa - lambda_ * kappa_ * std::expm1(-4.0 * s) + 4.0 * kappa_ * s * e;
  return numerator / denominator;
}

// The height h of the closed-form part's smoothed substrate term (see the
// header): t, or longer where the compliance factor moves from E1*/E2* to 1
// over wavenumbers far below 1/t. That is a stiff layer on a soft substrate,
// a plate whose bending spreads a load over a length growing like
// t (E1*/E2*)^(1/3): with h = t the remainder then cancels most of the
// smoothed term near the load and is as large as it, and on a free grid
// the periodic images of its long tail made the operator indefinite (a
// negative self-influence from a ratio of about 1e3; issue 32). The h that
// matches exp(-q h) to (M - 1)/(E1*/E2* - 1) where the latter is 1/2 keeps
// the remainder a correction on the scale of the bending length. A factor
// within 2 of 1 keeps h = t (M is near 1 everywhere).
double LayeredKernel::find_split_height() const {
  const double t = material_.thickness;
  const double c = layer_modulus_ / substrate_modulus_;
  if (!(c > 2.0)) return t;
  // (M(s/t) - 1)/(c - 1) falls from 1 at s = 0 towards 0: bisection for 1/2.
  double low = 0.0;
  double high = 1.0;
  auto share = [&](double s) { return (compliance_factor(s / t) - 1.0) / (c - 1.0); };
  while (share(high) > 0.5 && high < 1e3) high *= 2.0;
  constexpr int kBisections = 60;
  for (int k = 0; k < kBisections; ++k) {
    const double middle = 0.5 * (low + high);
    (share(middle) > 0.5 ? low : high) = middle;
  }
  return std::max(t, t * std::numbers::ln2 / high);
}

double LayeredKernel::spectrum(double q) const {
  return q == 0.0 ? 0.0 : 2.0 * compliance_factor(q) / (layer_modulus_ * std::abs(q));
}

double LayeredKernel::remainder(double q) const {
  if (q == 0.0) return remainder_at_zero_;
  const double t = material_.thickness;
  const double s = std::abs(q) * t;
  const double split = std::abs(q) * split_height_;
  const double c = layer_modulus_ / substrate_modulus_;
  double bracket;  // M - 1 - (c - 1) exp(-q h), divided by s
  if (s < 1.0) {
    // (M - c) + (c - 1)(1 - exp(-q h)): both terms vanish like s.
    bracket = ((compliance_factor(q) - c) - (c - 1.0) * std::expm1(-split)) / s;
  } else {
    // M - 1 = e (lambda + kappa + 4 kappa s (1 + s) - 2 lambda kappa e) / D,
    // free of the cancellation of M - 1 when M is close to 1.
    const double e = std::exp(-2.0 * s);
    const double em1 = std::expm1(-2.0 * s);
    const double denominator =
        (one_minus_lambda_ - lambda_ * em1) * (one_minus_kappa_ - kappa_ * em1) - 4.0 * kappa_ * s * s * e;
    const double m_minus_one =
        e * (lambda_ + kappa_ + 4.0 * kappa_ * s * (1.0 + s) - 2.0 * lambda_ * kappa_ * e) / denominator;
    bracket = (m_minus_one - (c - 1.0) * std::exp(-split)) / s;
  }
  return 2.0 * t * bracket / layer_modulus_;
}

double LayeredKernel::near_rectangle_displacement(double x, double y, double hx, double hy) const {
  // 2 exp(-q h)/(E |q|) is, in real space, 1/(pi E sqrt(r^2 + h^2)): its cell
  // integral is the rectangle potential at height h.
  const double t = split_height_;
  const double smoothed =
      smoothed_potential_antiderivative(x + hx, y + hy, t) - smoothed_potential_antiderivative(x + hx, y - hy, t) -
      smoothed_potential_antiderivative(x - hx, y + hy, t) + smoothed_potential_antiderivative(x - hx, y - hy, t);
  const double weight = (1.0 / substrate_modulus_ - 1.0 / layer_modulus_) / std::numbers::pi;
  return love_rectangle_displacement(x, y, hx, hy, layer_modulus_) + weight * smoothed;
}

double LayeredKernel::near_strip_displacement(double x, double h) const {
  // int_{x-h}^{x+h} ln(s^2 + t^2) ds = G(x + h) - G(x - h), G(s) = s ln(s^2 +
  // t^2) - 2 s + 2 t atan(s/t), written as x ln(A/B) + h ln(A B) - 4 h + 2 t
  // (atan((x+h)/t) - atan((x-h)/t)), A, B = (x +- h)^2 + t^2, so that far
  // away no two large terms cancel; t here is the split height h.
  const double t = split_height_;
  const double a = (x + h) * (x + h) + t * t;
  const double b = (x - h) * (x - h) + t * t;
  const double integral = x * std::log1p(4.0 * x * h / b) + h * std::log(a * b) - 4.0 * h +
                          2.0 * t * std::atan2(2.0 * h * t, t * t + x * x - h * h);
  const double weight = (1.0 / substrate_modulus_ - 1.0 / layer_modulus_) / std::numbers::pi;
  return plane_strain_strip_displacement(x, 2.0 * h, layer_modulus_) - weight * integral;
}

double LayeredKernel::remainder_strip_spectrum(double qx, double dx) const {
  double sum = 0.0;
  for_each_alias_image(qx, 0.0, dx, dx, true, kAliasImages, 40.0 / material_.thickness,
                       [&](double kx, double /*ky*/, double shape) { sum += remainder(std::abs(kx)) * shape; });
  return sum;
}

double LayeredKernel::remainder_cell_spectrum(double qx, double qy, double dx, double dy) const {
  // Collocation at cell centres of a piecewise-constant pressure; beyond
  // q t = 40 the remainder is below e^-40 of its scale: skipped.
  double sum = 0.0;
  for_each_alias_image(qx, qy, dx, dy, false, kAliasImages, 40.0 / material_.thickness,
                       [&](double kx, double ky, double shape) { sum += remainder(std::hypot(kx, ky)) * shape; });
  return sum;
}

std::vector<double> LayeredKernel::remainder_point_table(double r_max, double step) const {
  const double t = material_.thickness;
  const double c = layer_modulus_ / substrate_modulus_;
  // Up to q t = 40 (the integrand has fallen by e^-40 of its scale); steps
  // that resolve both the decay (t/40) and J0's period at r_max (2 pi / r_max)
  // with Simpson's error far below 1e-6.
  const double q_max = 40.0 / t;
  const double h_max = std::min(0.02 / t, 0.2 / std::max(r_max, t));
  const auto intervals = 2 * static_cast<std::size_t>(std::ceil(0.5 * q_max / h_max));
  const double h = q_max / static_cast<double>(intervals);
  std::vector<double> weighted(intervals + 1);  // Simpson weight times integrand, without J0
  for (std::size_t k = 0; k <= intervals; ++k) {
    const double q = static_cast<double>(k) * h;
    const double f = k == 0 ? 0.0 : (compliance_factor(q) - 1.0) - (c - 1.0) * std::exp(-q * split_height_);
    const double w = (k == 0 || k == intervals) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    weighted[k] = w * f * h / 3.0;
  }
  const auto entries = static_cast<std::size_t>(std::floor(r_max / step)) + 2;
  std::vector<double> table(entries);
  linalg::for_each_row(entries, intervals, [&](std::size_t i) {
    const double r = static_cast<double>(i) * step;
    double sum = 0.0;
    for (std::size_t k = 0; k <= intervals; ++k) sum += weighted[k] * bessel_j0(static_cast<double>(k) * h * r);
    table[i] = sum / (std::numbers::pi * layer_modulus_);
  });
  return table;
}

std::vector<double> LayeredKernel::remainder_line_table(double x_max, double step) const {
  // As remainder_point_table, with cos(q x) for J0 and R itself (finite at
  // q = 0) as the integrand.
  const double t = material_.thickness;
  const double q_max = 40.0 / t;
  const double h_max = std::min(0.02 / t, 0.2 / std::max(x_max, t));
  const auto intervals = 2 * static_cast<std::size_t>(std::ceil(0.5 * q_max / h_max));
  const double h = q_max / static_cast<double>(intervals);
  std::vector<double> weighted(intervals + 1);
  for (std::size_t k = 0; k <= intervals; ++k) {
    const double w = (k == 0 || k == intervals) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    weighted[k] = w * remainder(static_cast<double>(k) * h) * h / 3.0;
  }
  const auto entries = static_cast<std::size_t>(std::floor(x_max / step)) + 2;
  std::vector<double> table(entries);
  linalg::for_each_row(entries, intervals, [&](std::size_t i) {
    const double x = static_cast<double>(i) * step;
    double sum = 0.0;
    for (std::size_t k = 0; k <= intervals; ++k) sum += weighted[k] * std::cos(static_cast<double>(k) * h * x);
    table[i] = sum / std::numbers::pi;
  });
  return table;
}

}  // namespace halfspace::kernels
