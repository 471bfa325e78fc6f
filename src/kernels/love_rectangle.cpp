// Love's (1929) influence coefficient of a rectangular cell: the closed form of
// Johnson (1985, sec. 3.2) near the cell, Gauss-Legendre quadrature of the same
// integral beyond two half-diagonals, where the closed form loses digits.
#include "halfspace/kernels/love_rectangle.hpp"

#include <cmath>
#include <cstddef>
#include <numbers>

#include "cell_integration.hpp"

namespace halfspace::kernels {
namespace {

// Antiderivative of 1/sqrt(s^2 + t^2) in both s and t (d2H/ds dt = 1/r), odd in
// each argument; Love's formula is its signed sum over the four corners.
double corner_primitive(double s, double t) {
  return signed_asinh_term(s, t) + signed_asinh_term(t, s);
}

// The tensor Gauss rule of 1/r over the cell away from it (cell_gauss_rules.hpp).
double gauss_integral(double x, double y, double a, double b, const CellGaussRule& rule) {
  return cell_gauss_integral(x, y, a, b, rule, [](double u, double v) { return 1.0 / std::hypot(u, v); });
}

}  // namespace

double love_rectangle_displacement(double x, double y, double half_width_x, double half_width_y, double e_star) {
  // The displacement is even in x and y; folding makes the coefficients exactly
  // symmetric (K(d) == K(-d) bit for bit), which keeps the DC-FFT spectrum real
  // and the dense matrix symmetric.
  x = std::abs(x);
  y = std::abs(y);
  const double a = half_width_x;
  const double b = half_width_y;
  const double scale = 1.0 / (std::numbers::pi * e_star);

  if (const CellGaussRule* rule = far_field_rule(x, y, a, b)) return scale * gauss_integral(x, y, a, b, *rule);

  // Love (1929), Johnson (1985) sec. 3.2: the signed corner sum of the primitive.
  const double xp = x + a;
  const double xm = x - a;
  const double yp = y + b;
  const double ym = y - b;
  return scale *
         (corner_primitive(xp, yp) - corner_primitive(xp, ym) - corner_primitive(xm, yp) + corner_primitive(xm, ym));
}

}  // namespace halfspace::kernels
