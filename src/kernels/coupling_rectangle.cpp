// The coupling kernel over a rectangle: s/rho^2 (s = x - x', t = y - y') has
// the primitive
//   H(s, t) = t ln(rho)  + s atan(t/s)      (d2H/ds dt = s/rho^2),
// up to terms linear in t alone that the corner sum cancels, and the cell's
// coefficient is H's signed sum over the four corners (as Love's formula,
// Johnson 1985 sec. 3.2; Kalker 1990). The y component is the same with the
// axes exchanged. Away from the cell the corner sums cancel and the tensor
// Gauss rule of the point kernel is used (cell_integration.hpp; the kernel
// is as smooth on the cell as Cerruti's).
// At a height h > 0 the kernel s/(rho (rho + h)), rho^2 = s^2 + t^2 + h^2,
// has the primitive
//   H(s, t) = t ln(rho + h) + h asinh(t/sqrt(s^2 + h^2)) + s (atan(t/s) - atan(t h/(s rho))),
// which tends to the above for h -> 0.
#include "halfspace/kernels/coupling_rectangle.hpp"

#include <cmath>
#include <numbers>

#include "cell_integration.hpp"

namespace halfspace::kernels {
namespace {

// t ln(rho) + s atan(t/s), exact at s = 0 (limit 0 for the second term) and
// at t = 0.
double primitive(double s, double t, double h) {
  if (h > 0.0) {
    const double rho = std::hypot(s, t, h);
    const double angle_term = s == 0.0 ? 0.0 : s * (std::atan(t / s) - std::atan(t * h / (s * rho)));
    return t * std::log(rho + h) + h * std::asinh(t / std::hypot(s, h)) + angle_term;
  }
  const double log_term = t == 0.0 ? 0.0 : 0.5 * t * std::log(s * s + t * t);
  const double angle_term = s == 0.0 ? 0.0 : s * std::atan(t / s);
  return log_term + angle_term;
}

// The integral of s/(rho (rho + h)) over the cell at the folded offset x, y >= 0.
double along_first_axis(double x, double y, double a, double b, double h) {
  if (const CellGaussRule* rule = far_field_rule(std::hypot(x, h), y, a, b)) {
    return cell_gauss_integral(x, y, a, b, *rule, [h](double s, double t) {
      if (h == 0.0) return s / (s * s + t * t);
      const double rho = std::hypot(s, t, h);
      return s / (rho * (rho + h));
    });
  }
  return primitive(x + a, y + b, h) - primitive(x + a, y - b, h) - primitive(x - a, y + b, h) +
         primitive(x - a, y - b, h);
}

}  // namespace

CouplingCoefficients coupling_rectangle_displacement(double x, double y, double half_width_x, double half_width_y,
                                                     double coupling, double height) {
  const double scale = coupling / (4.0 * std::numbers::pi);
  const double ax = std::abs(x);
  const double ay = std::abs(y);
  const double along_x = scale * along_first_axis(ax, ay, half_width_x, half_width_y, height);
  const double along_y = scale * along_first_axis(ay, ax, half_width_y, half_width_x, height);
  return {x < 0.0 ? -along_x : along_x, y < 0.0 ? -along_y : along_y};
}

}  // namespace halfspace::kernels
