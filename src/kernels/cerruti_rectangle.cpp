// Cerruti's solution over a rectangle: each term of the point-load kernel has
// a primitive H with d2H/dx dy equal to it, and the cell's coefficient is H's
// signed sum over the four corners, as in Love's formula (Kalker 1990):
//   1/rho:       s asinh(t/|s|) + t asinh(s/|t|)
//   s^2/rho^3:   t asinh(s/|t|)
//   t^2/rho^3:   s asinh(t/|s|)
//   s t/rho^3:   -rho
// Away from the cell these sums cancel (cell_integration.hpp) and the tensor
// Gauss rule of the point-load kernel is used instead.
// At a height h > 0 (rho^2 = s^2 + t^2 + h^2) the same four terms have
//   1/rho:       s asinh(t/sqrt(s^2 + h^2)) + t asinh(s/sqrt(t^2 + h^2)) - h atan(s t/(h rho))
//   s^2/rho^3:   t asinh(s/sqrt(t^2 + h^2)) - h atan(s t/(h rho))
// (and t^2/rho^3 the mirror; s t/rho^3 still -rho), which tend to the above
// for h -> 0; the Gauss rule takes over at a distance sqrt(x^2 + y^2 + h^2)
// from the singular point below the cell.
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

// sqrt(s^2 + t^2 + h^2), rounded as before for h = 0.
double radius(double s, double t, double h) {
  return h == 0.0 ? std::hypot(s, t) : std::hypot(s, t, h);
}

// t asinh(s/sqrt(t^2 + h^2)) (signed_asinh_term for h = 0): the primitive of
// s^2/rho^3 without its atan term.
double height_asinh_term(double t, double s, double h) {
  return h == 0.0 ? signed_asinh_term(t, s) : t * std::asinh(s / std::hypot(t, h));
}

CellIntegrals corner_sums(double x, double y, double a, double b, double h) {
  CellIntegrals total;
  const double xs[2] = {x + a, x - a};
  const double ys[2] = {y + b, y - b};
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const double sign = i == j ? 1.0 : -1.0;
      const double s = xs[i];
      const double t = ys[j];
      const double rho = radius(s, t, h);
      const double angle = h == 0.0 ? 0.0 : h * std::atan(s * t / (h * rho));
      const double along_x = height_asinh_term(t, s, h);  // primitive of s^2/rho^3, + angle
      const double along_y = height_asinh_term(s, t, h);  // primitive of t^2/rho^3, + angle
      total.inverse += sign * (along_x + along_y - angle);
      total.xx += sign * (along_x - angle);
      total.yy += sign * (along_y - angle);
      total.xy -= sign * rho;
    }
  }
  return total;
}

CellIntegrals gauss_sums(double x, double y, double a, double b, double h, const CellGaussRule& rule) {
  CellIntegrals total;
  total.xx = cell_gauss_integral(x, y, a, b, rule, [h](double s, double t) {
    const double r = radius(s, t, h);
    return s * s / (r * r * r);
  });
  total.yy = cell_gauss_integral(x, y, a, b, rule, [h](double s, double t) {
    const double r = radius(s, t, h);
    return t * t / (r * r * r);
  });
  total.xy = cell_gauss_integral(x, y, a, b, rule, [h](double s, double t) {
    const double r = radius(s, t, h);
    return s * t / (r * r * r);
  });
  total.inverse =
      h == 0.0 ? total.xx + total.yy
               : cell_gauss_integral(x, y, a, b, rule, [h](double s, double t) { return 1.0 / radius(s, t, h); });
  return total;
}

}  // namespace

TangentialCoefficients cerruti_rectangle_displacement(double x, double y, double half_width_x, double half_width_y,
                                                      double shear, double directional, double height) {
  // xx and yy are even in x and y, xy odd in each: evaluate on the folded
  // offset, so that the coefficients are exactly (anti)symmetric bit for bit.
  const double sign_xy = (x < 0.0) != (y < 0.0) ? -1.0 : 1.0;
  x = std::abs(x);
  y = std::abs(y);
  const CellGaussRule* rule = far_field_rule(std::hypot(x, height), y, half_width_x, half_width_y);
  const CellIntegrals cell = rule ? gauss_sums(x, y, half_width_x, half_width_y, height, *rule)
                                  : corner_sums(x, y, half_width_x, half_width_y, height);
  const double scale = 1.0 / (2.0 * std::numbers::pi);
  const double isotropic = shear - directional;
  return {scale * (isotropic * cell.inverse + directional * cell.xx),
          scale * (isotropic * cell.inverse + directional * cell.yy), sign_xy * scale * directional * cell.xy};
}

}  // namespace halfspace::kernels
