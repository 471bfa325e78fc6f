// Cerruti's solution over a rectangle: each term of the point-load kernel has
// a primitive H with d2H/dx dy equal to it, and the cell's coefficient is H's
// signed sum over the four corners, as in Love's formula (Kalker 1990):
//   1/rho:       s asinh(t/|s|) + t asinh(s/|t|)
//   s^2/rho^3:   t asinh(s/|t|)
//   t^2/rho^3:   s asinh(t/|s|)
//   s t/rho^3:   -rho
// Away from the cell these sums cancel (cell_integration.hpp) and the tensor
// Gauss rule of the point-load kernel is used instead.
#include "halfspace/kernels/cerruti_rectangle.hpp"

#include <cmath>
#include <numbers>

#include "cell_integration.hpp"

namespace halfspace::kernels {
namespace {

// The four integrals over the cell of 1/rho, x^2/rho^3, y^2/rho^3, x y/rho^3.
struct CellIntegrals {
  double inverse = 0.0;
  double xx = 0.0;
  double yy = 0.0;
  double xy = 0.0;
};

CellIntegrals corner_sums(double x, double y, double a, double b) {
  CellIntegrals total;
  const double xs[2] = {x + a, x - a};
  const double ys[2] = {y + b, y - b};
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const double sign = i == j ? 1.0 : -1.0;
      const double s = xs[i];
      const double t = ys[j];
      const double along_x = signed_asinh_term(t, s);  // primitive of s^2/rho^3
      const double along_y = signed_asinh_term(s, t);  // primitive of t^2/rho^3
      total.inverse += sign * (along_x + along_y);
      total.xx += sign * along_x;
      total.yy += sign * along_y;
      total.xy -= sign * std::hypot(s, t);
    }
  }
  return total;
}

CellIntegrals gauss_sums(double x, double y, double a, double b, const CellGaussRule& rule) {
  CellIntegrals total;
  total.xx = cell_gauss_integral(x, y, a, b, rule, [](double s, double t) {
    const double r = std::hypot(s, t);
    return s * s / (r * r * r);
  });
  total.yy = cell_gauss_integral(x, y, a, b, rule, [](double s, double t) {
    const double r = std::hypot(s, t);
    return t * t / (r * r * r);
  });
  total.xy = cell_gauss_integral(x, y, a, b, rule, [](double s, double t) {
    const double r = std::hypot(s, t);
    return s * t / (r * r * r);
  });
  total.inverse = total.xx + total.yy;
  return total;
}

}  // namespace

TangentialCoefficients cerruti_rectangle_displacement(double x, double y, double half_width_x, double half_width_y,
                                                      double shear, double directional) {
  // xx and yy are even in x and y, xy odd in each: evaluate on the folded
  // offset, so that the coefficients are exactly (anti)symmetric bit for bit.
  const double sign_xy = (x < 0.0) != (y < 0.0) ? -1.0 : 1.0;
  x = std::abs(x);
  y = std::abs(y);
  const CellGaussRule* rule = far_field_rule(x, y, half_width_x, half_width_y);
  const CellIntegrals cell =
      rule ? gauss_sums(x, y, half_width_x, half_width_y, *rule) : corner_sums(x, y, half_width_x, half_width_y);
  const double scale = 1.0 / (2.0 * std::numbers::pi);
  const double isotropic = shear - directional;
  return {scale * (isotropic * cell.inverse + directional * cell.xx),
          scale * (isotropic * cell.inverse + directional * cell.yy), sign_xy * scale * directional * cell.xy};
}

}  // namespace halfspace::kernels
