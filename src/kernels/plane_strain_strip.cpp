// Plane-strain influence coefficient of a strip: the logarithmic line-load
// displacement -(2/(pi E*)) ln|t| (Johnson 1985, sec. 2.2) integrated over one cell.
#include "halfspace/kernels/plane_strain_strip.hpp"

#include <cmath>
#include <numbers>

namespace halfspace::kernels {
namespace {

// F(t) = t ln|t| - t, the primitive of ln|t|, with its limit F(0) = 0.
double log_primitive(double t) {
  return t == 0.0 ? 0.0 : t * std::log(std::abs(t)) - t;
}

// F(d + h) - F(d - h) for d >= 0. Away from the strip (d > 2h) it is rewritten
// as 2 d atanh(h/d) + h ln((d - h)(d + h)) - 2h, whose terms stay O(h ln d): the
// direct difference of two O(d ln d) values would lose digits growing with d.
// Closer in, atanh(h/d) would be ill-conditioned and the direct form is fine.
double strip_integral(double d, double h) {
  if (d <= 2.0 * h) return log_primitive(d + h) - log_primitive(d - h);
  return 2.0 * d * std::atanh(h / d) + h * std::log((d - h) * (d + h)) - 2.0 * h;
}

}  // namespace

double plane_strain_strip_displacement(double d, double width, double e_star) {
  // Even in d; folding makes K(d) == K(-d) bit for bit (symmetric matrix, real
  // DC-FFT spectrum).
  const double h = 0.5 * width;
  return -2.0 / (std::numbers::pi * e_star) * strip_integral(std::abs(d), h);
}

}  // namespace halfspace::kernels
