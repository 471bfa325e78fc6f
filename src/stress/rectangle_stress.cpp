// Love's (1929) rectangle and the plane-strain strip, in closed form.
//
// Rectangle. For a normal surface load p the stresses follow from two
// potentials (Johnson 1985, eq. 3.9 with the tangential loads zero):
//   psi = int p / rho dA,   F = int p ln(rho + z) dA,
//   sxx = [2 nu psi_z - z psi_xx - (1 - 2 nu) F_xx] / 2 pi
//   syy = [2 nu psi_z - z psi_yy - (1 - 2 nu) F_yy] / 2 pi
//   szz = [psi_z - z psi_zz] / 2 pi
//   sxy = -[(1 - 2 nu) F_xy + z psi_xy] / 2 pi
//   sxz = -z psi_xz / 2 pi,   syz = -z psi_yz / 2 pi
// (checked against the Fourier-space solution of fourier_stress.cpp and, in
// the tests, against the integral of Boussinesq's point-load stresses,
// Johnson eq. 3.21). Over the rectangle, int g(x - x', y - y') dA is the
// signed sum over its corners of a primitive G(s, t) with G_st = g, where
// s = x -+ a and t = y -+ b; derivatives in x and y act on s and t. Each term
// below is that corner primitive of one derivative, written so that it is
// finite for z > 0 on the cell's edges and corners and never cancels
// catastrophically (rho - z and rho + t are rewritten where they would).
//
// Strip. Integrating Flamant's line load over |x'| <= a with
// s = x - x' = z tan(theta) gives, between theta1 = atan((x - a)/z) and
// theta2 = atan((x + a)/z) (Johnson 1985, sec. 2.3):
//   szz = -[2 (theta2 - theta1) + sin 2theta2 - sin 2theta1] / 2 pi
//   sxx = -[2 (theta2 - theta1) - sin 2theta2 + sin 2theta1] / 2 pi
//   sxz = -[cos 2theta1 - cos 2theta2] / 2 pi
#include "halfspace/stress/rectangle_stress.hpp"

#include <cmath>
#include <numbers>

#include "corner_distance.hpp"

namespace halfspace::stress {
namespace {

// Corner primitives of the derivatives of psi and F at corner (s, t), depth z.
struct CornerTerms {
  double psi_z;   // -atan(s t / (z rho))
  double psi_zz;  // s t (rho^2 + z^2) / (rho (s^2 + z^2) (t^2 + z^2))
  double psi_xx;  // s / (rho (rho + t))
  double psi_yy;  // t / (rho (rho + s))
  double psi_xy;  // 1 / rho
  double psi_xz;  // z / (rho (rho + t))
  double psi_yz;  // z / (rho (rho + s))
  double f_xx;    // atan(s t (rho - z) / (s^2 rho + t^2 z))
  double f_yy;    // atan(s t (rho - z) / (t^2 rho + s^2 z))
  double f_xy;    // ln(rho + z)
};

CornerTerms corner_terms(double s, double t, double z) {
  const double s2 = s * s;
  const double t2 = t * t;
  const double z2 = z * z;
  const double rho = std::sqrt(s2 + t2 + z2);
  const double rho_minus_z = (s2 + t2) / (rho + z);
  const double over_rho_plus_t = inverse_rho_plus(rho, t, s2 + z2);
  const double over_rho_plus_s = inverse_rho_plus(rho, s, t2 + z2);
  CornerTerms c{};
  c.psi_z = -std::atan(s * t / (z * rho));
  c.psi_zz = s * t * (rho * rho + z2) / (rho * (s2 + z2) * (t2 + z2));
  c.psi_xx = s * over_rho_plus_t / rho;
  c.psi_yy = t * over_rho_plus_s / rho;
  c.psi_xy = 1.0 / rho;
  c.psi_xz = z * over_rho_plus_t / rho;
  c.psi_yz = z * over_rho_plus_s / rho;
  const double st = s * t * rho_minus_z;
  // At s = t = 0 both fractions are 0/0 with the limit 0.
  const double xx_denominator = s2 * rho + t2 * z;
  const double yy_denominator = t2 * rho + s2 * z;
  c.f_xx = xx_denominator > 0.0 ? std::atan(st / xx_denominator) : 0.0;
  c.f_yy = yy_denominator > 0.0 ? std::atan(st / yy_denominator) : 0.0;
  c.f_xy = std::log(rho + z);
  return c;
}

void add_corner(CornerTerms& sum, const CornerTerms& c, double sign) {
  sum.psi_z += sign * c.psi_z;
  sum.psi_zz += sign * c.psi_zz;
  sum.psi_xx += sign * c.psi_xx;
  sum.psi_yy += sign * c.psi_yy;
  sum.psi_xy += sign * c.psi_xy;
  sum.psi_xz += sign * c.psi_xz;
  sum.psi_yz += sign * c.psi_yz;
  sum.f_xx += sign * c.f_xx;
  sum.f_yy += sign * c.f_yy;
  sum.f_xy += sign * c.f_xy;
}

}  // namespace

StressTensor rectangle_stress(double x, double y, double z, double half_width_x, double half_width_y, double nu) {
  const double a = half_width_x;
  const double b = half_width_y;
  // int_{-a}^{a} f(x - x') dx' = G(x + a) - G(x - a): corners (x + a, y + b)
  // and (x - a, y - b) count +1, the other two -1.
  CornerTerms sum{};
  add_corner(sum, corner_terms(x + a, y + b, z), 1.0);
  add_corner(sum, corner_terms(x - a, y - b, z), 1.0);
  add_corner(sum, corner_terms(x + a, y - b, z), -1.0);
  add_corner(sum, corner_terms(x - a, y + b, z), -1.0);

  const double scale = 1.0 / (2.0 * std::numbers::pi);
  const double m = 1.0 - 2.0 * nu;
  StressTensor s;
  s.xx = scale * (2.0 * nu * sum.psi_z - z * sum.psi_xx - m * sum.f_xx);
  s.yy = scale * (2.0 * nu * sum.psi_z - z * sum.psi_yy - m * sum.f_yy);
  s.zz = scale * (sum.psi_z - z * sum.psi_zz);
  s.xy = -scale * (m * sum.f_xy + z * sum.psi_xy);
  s.xz = -scale * z * sum.psi_xz;
  s.yz = -scale * z * sum.psi_yz;
  return s;
}

StressTensor strip_stress(double x, double z, double half_width, double nu) {
  const double s1 = x - half_width;
  const double s2 = x + half_width;
  const double z2 = z * z;
  // theta2 - theta1 as one arctangent of a difference, exact for z > 0 since
  // the product of the tangents' denominators z^2 + s1 s2 may be negative:
  // atan2 keeps the quadrant.
  const double angle = std::atan2(z * (s2 - s1), z2 + s1 * s2);
  const double r1 = s1 * s1 + z2;
  const double r2 = s2 * s2 + z2;
  const double sin_difference = 2.0 * z * (s2 / r2 - s1 / r1);              // sin 2theta2 - sin 2theta1
  const double cos_difference = (z2 - s1 * s1) / r1 - (z2 - s2 * s2) / r2;  // cos 2theta1 - cos 2theta2
  const double scale = 1.0 / (2.0 * std::numbers::pi);
  StressTensor s;
  s.zz = -scale * (2.0 * angle + sin_difference);
  s.xx = -scale * (2.0 * angle - sin_difference);
  s.xz = -scale * cos_difference;
  s.yy = nu * (s.xx + s.zz);
  return s;
}

}  // namespace halfspace::stress
