// Cerruti's rectangle and the tangentially loaded strip, in closed form.
//
// Rectangle. Cerruti's unit point force along x at the origin gives, with
// R = 1/rho, L = ln(rho + z) and W = z L - rho (all harmonic; W_z = L,
// L_z = R), the stresses (Johnson 1985, eq. 3.87, written as derivatives;
// fourier_shear_stress.cpp gives the same per Fourier mode)
//   2 pi sxx = 2 R_x - 2 nu W_xyy - z L_xxx
//   2 pi syy = -2 nu W_xxx - z L_xyy
//   2 pi szz = -z R_xz
//   2 pi sxy = R_y + 2 nu W_xxy - z L_xxy
//   2 pi sxz = R_z - z R_xx
//   2 pi syz = -z R_xy.
// Over the cell, int g(x - x', y - y') dA is the signed sum over its corners
// of a primitive G(s, t) with G_st = g (rectangle_stress.cpp). With
// W_x = -s/(rho + z), L_y = t/(rho (rho + z)) and the harmonic relations
// W_xx + W_yy = -R, L_xx + L_yy = -R_z, every primitive is elementary:
//   R_x: ln(rho + t)            R_y: ln(rho + s)
//   W_xyy: -t/(rho + z)         W_xxy: -s/(rho + z)
//   W_xxx: -ln(rho + t) + t/(rho + z)
//   L_xyy: t/(rho (rho + z))    L_xxy: s/(rho (rho + z))
//   L_xxx: -t/(rho (rho + z)) - z/(rho (rho + t))
//   R_z: -atan(s t/(z rho))     R_xx: s/(rho (rho + t))
//   R_xz: z/(rho (rho + t))     R_xy: 1/rho
// (each checked by differentiation). A shear along y exchanges x and y.
//
// Strip. The tangential line force (Flamant's along the surface) gives
// sxx = -(2/pi) s^3/r^4, szz = -(2/pi) s z^2/r^4, sxz = -(2/pi) s^2 z/r^4
// (r^2 = s^2 + z^2); integrated over s from x - a to x + a:
//   sxx = -[ln r^2 + z^2/r^2] / pi,   szz = [z^2/r^2] / pi,
//   sxz = -[atan(s/z) - s z/r^2] / pi   (differences between the ends).
// The antiplane line force along y (u_y = -(F/(pi G)) ln r) gives
// syz = -(1/pi) z/r^2 and sxy = -(1/pi) s/r^2, so
//   syz = -[atan(s/z)] / pi,   sxy = -[ln r^2] / (2 pi).
#include "halfspace/stress/rectangle_shear_stress.hpp"

#include <cmath>
#include <numbers>
#include <utility>

#include "corner_distance.hpp"

namespace halfspace::stress {
namespace {

// Corner primitives at corner (s, t), depth z.
struct CornerTerms {
  double log_t = 0.0;       // ln(rho + t)
  double log_s = 0.0;       // ln(rho + s)
  double t_over = 0.0;      // t / (rho + z)
  double s_over = 0.0;      // s / (rho + z)
  double t_over_rho = 0.0;  // t / (rho (rho + z))
  double s_over_rho = 0.0;  // s / (rho (rho + z))
  double r_z = 0.0;         // -atan(s t / (z rho))
  double r_xx = 0.0;        // s / (rho (rho + t))
  double r_xz = 0.0;        // z / (rho (rho + t))
  double r_xy = 0.0;        // 1 / rho
};

CornerTerms corner_terms(double s, double t, double z) {
  const double s2 = s * s;
  const double t2 = t * t;
  const double z2 = z * z;
  const double rho = std::sqrt(s2 + t2 + z2);
  const double over_rho_plus_z = 1.0 / (rho + z);
  CornerTerms c;
  c.log_t = log_rho_plus(rho, t, s2 + z2);
  c.log_s = log_rho_plus(rho, s, t2 + z2);
  c.t_over = t * over_rho_plus_z;
  c.s_over = s * over_rho_plus_z;
  c.t_over_rho = c.t_over / rho;
  c.s_over_rho = c.s_over / rho;
  c.r_z = -std::atan(s * t / (z * rho));
  const double over_rho_plus_t = inverse_rho_plus(rho, t, s2 + z2);
  c.r_xx = s * over_rho_plus_t / rho;
  c.r_xz = z * over_rho_plus_t / rho;
  c.r_xy = 1.0 / rho;
  return c;
}

void add_corner(CornerTerms& sum, const CornerTerms& c, double sign) {
  sum.log_t += sign * c.log_t;
  sum.log_s += sign * c.log_s;
  sum.t_over += sign * c.t_over;
  sum.s_over += sign * c.s_over;
  sum.t_over_rho += sign * c.t_over_rho;
  sum.s_over_rho += sign * c.s_over_rho;
  sum.r_z += sign * c.r_z;
  sum.r_xx += sign * c.r_xx;
  sum.r_xz += sign * c.r_xz;
  sum.r_xy += sign * c.r_xy;
}

StressTensor rectangle_shear_x_stress(double x, double y, double z, double a, double b, double nu) {
  CornerTerms sum;
  add_corner(sum, corner_terms(x + a, y + b, z), 1.0);
  add_corner(sum, corner_terms(x - a, y - b, z), 1.0);
  add_corner(sum, corner_terms(x + a, y - b, z), -1.0);
  add_corner(sum, corner_terms(x - a, y + b, z), -1.0);
  const double scale = 1.0 / (2.0 * std::numbers::pi);
  StressTensor s;
  s.xx = scale * (2.0 * sum.log_t + 2.0 * nu * sum.t_over + z * (sum.t_over_rho + sum.r_xz));
  s.yy = scale * (2.0 * nu * (sum.log_t - sum.t_over) - z * sum.t_over_rho);
  s.zz = -scale * z * sum.r_xz;
  s.xy = scale * (sum.log_s - 2.0 * nu * sum.s_over - z * sum.s_over_rho);
  s.xz = scale * (sum.r_z - z * sum.r_xx);
  s.yz = -scale * z * sum.r_xy;
  return s;
}

}  // namespace

StressTensor rectangle_shear_stress(Traction direction, double x, double y, double z, double half_width_x,
                                    double half_width_y, double nu) {
  if (direction != Traction::shear_y) return rectangle_shear_x_stress(x, y, z, half_width_x, half_width_y, nu);
  StressTensor s = rectangle_shear_x_stress(y, x, z, half_width_y, half_width_x, nu);
  std::swap(s.xx, s.yy);
  std::swap(s.xz, s.yz);
  return s;
}

StressTensor strip_shear_stress(Traction direction, double x, double z, double half_width, double nu) {
  const double s1 = x - half_width;
  const double s2 = x + half_width;
  const double z2 = z * z;
  const double r1 = s1 * s1 + z2;
  const double r2 = s2 * s2 + z2;
  // atan(s2/z) - atan(s1/z) as one arctangent (strip_stress in rectangle_stress.cpp).
  const double angle = std::atan2(z * (s2 - s1), z2 + s1 * s2);
  const double log_ratio = std::log(r2 / r1);
  const double inverse_pi = 1.0 / std::numbers::pi;
  StressTensor s;
  if (direction == Traction::shear_y) {
    s.yz = -inverse_pi * angle;
    s.xy = -0.5 * inverse_pi * log_ratio;
    return s;
  }
  const double z2_ratio = z2 / r2 - z2 / r1;
  s.xx = -inverse_pi * (log_ratio + z2_ratio);
  s.zz = inverse_pi * z2_ratio;
  s.xz = -inverse_pi * (angle - z * (s2 / r2 - s1 / r1));
  s.yy = nu * (s.xx + s.zz);
  return s;
}

}  // namespace halfspace::stress
