// Fourier-space kernel of a coated half-space: an elastic layer of thickness t
// (E1, nu1) perfectly bonded to an elastic substrate (E2, nu2), normal load,
// no shear on the surface (O'Sullivan & King 1988; Stanley & Kato 1997):
//   u(q) = 2 p(q) M(q t) / (E1* |q|),  E1* = E1 / (1 - nu1^2),
// with the bonded-layer compliance factor M (docs/theory.md, "Coated
// half-space"): M = 1 for identical materials or t -> inf, E1*/E2* for t -> 0.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "halfspace/layered_material.hpp"

namespace halfspace::kernels {

// sin(x)/x: a cell's transform over its width at x = q dx/2.
inline double cell_sinc(double x) {
  return x == 0.0 ? 1.0 : std::sin(x) / x;
}

// The alias images K = (qx + 2 pi m/dx, qy + 2 pi n/dy), |m|, |n| <= images
// (n = 0 on a line), with |K| <= q_negligible: term(Kx, Ky, shape), shape the
// cell's transform over its area, sinc(Kx dx/2) sinc(Ky dy/2) (a line: the
// first factor). Summed, a kernel's transform times the shape over them is
// the DFT at (qx, qy) of its cell coefficients on a grid of spacing (dx, dy)
// (collocation at cell centres: on grid points the images coincide).
template <class Term>
void for_each_alias_image(double qx, double qy, double dx, double dy, bool line, int images, double q_negligible,
                          Term&& term) {
  const double period_x = 2.0 * std::numbers::pi / dx;
  const double period_y = 2.0 * std::numbers::pi / dy;
  const int images_y = line ? 0 : images;
  for (int my = -images_y; my <= images_y; ++my) {
    const double ky = line ? 0.0 : qy + my * period_y;
    if (std::abs(ky) > q_negligible) continue;
    const double shape_y = line ? 1.0 : cell_sinc(0.5 * ky * dy);
    for (int mx = -images; mx <= images; ++mx) {
      const double kx = qx + mx * period_x;
      if (std::hypot(kx, ky) > q_negligible) continue;
      term(kx, ky, cell_sinc(0.5 * kx * dx) * shape_y);
    }
  }
}

class LayeredKernel {
 public:
  // Throws InputError naming the quantity if `material` is out of range
  // (validated(), layered_material.hpp).
  explicit LayeredKernel(const LayeredMaterial& material);

  const LayeredMaterial& material() const { return material_; }
  double layer_modulus() const { return layer_modulus_; }          // E1*, Pa
  double substrate_modulus() const { return substrate_modulus_; }  // E2*, Pa
  // The height h (m) of the smoothed substrate term of the free grids' split
  // below: the thickness t, or for a stiff layer on a soft substrate (E1*/E2*
  // above 2) the longer length over which the layer spreads a load, where
  // (M(q t) - 1)/(E1*/E2* - 1) = exp(-q h) = 1/2 (about 11 t at 2e4).
  double split_height() const { return split_height_; }

  // M(q t), dimensionless, for |q| (rad/m); finite and positive for all q.
  double compliance_factor(double q) const;
  // The kernel 2 M(q t) / (E1* |q|) (m/Pa per unit spectral amplitude), 0 at
  // q = 0 (the mean mode is set by the load or approach, as for the
  // homogeneous kernel).
  double spectrum(double q) const;

  // Free grids, in two parts (docs/theory.md, "Coated half-space"):
  // near_rectangle_displacement is the displacement (m) at (x, y) under unit
  // pressure on the rectangle |x'| <= hx, |y'| <= hy of the closed-form part
  // of the kernel, 2/(E1* q) + 2 (1/E2* - 1/E1*) exp(-q h)/q: Love's
  // rectangle for E1* plus a smoothed point-load term, so that it has the
  // substrate's 1/(pi E2* r) far away and the layer's Love coefficients near.
  double near_rectangle_displacement(double x, double y, double hx, double hy) const;
  // Free 1D (plane strain) grids, the same split: the displacement (m) at
  // distance x from the centre of the strip |x'| <= h under unit pressure of
  // the same closed-form part, the strip for E1* plus (1/E2* - 1/E1*) times
  // the cell integral of -(1/pi) ln(x^2 + h^2) (the line-load counterpart of
  // the smoothed term; lengths in metres, datum at 1 m as for the strip).
  double near_strip_displacement(double x, double h) const;
  // The rest, R(q) = 2 (M(q t) - 1 - (E1*/E2* - 1) exp(-q h)) / (E1* |q|),
  // which is finite at q = 0 and decays exponentially for q t >> 1, times the
  // transform of a dx x dy cell divided by its area, summed over the alias
  // images (qx + 2 pi m / dx, qy + 2 pi n / dy), |m|, |n| <= kAliasImages: the
  // DFT, at wavenumber (qx, qy) of a grid of spacing (dx, dy), of this part's
  // cell coefficients times the grid's period area over dx dy.
  double remainder_cell_spectrum(double qx, double qy, double dx, double dy) const;
  // The same on a 1D grid: images qx + 2 pi m / dx only, the cell's
  // transform sinc(qx dx/2).
  double remainder_strip_spectrum(double qx, double dx) const;
  static constexpr int kAliasImages = 2;
  // The same part in real space, for free grids whose domain is not large
  // against t (the DFT above would fold in its periodic images): the
  // displacement (m) at distances 0, step, 2 step, ... <= r_max (m) under a
  // point force of 1 N,
  //   (1/(pi E1*)) int_0^inf (M(q t) - 1 - (E1*/E2* - 1) exp(-q h)) J0(q r) dq,
  // by composite Simpson quadrature (the integrand decays like exp(-q t)).
  std::vector<double> remainder_point_table(double r_max, double step) const;
  // Its plane-strain counterpart, under a line load of 1 N/m:
  //   (1/pi) int_0^inf R(q) cos(q x) dq at x = 0, step, ... <= x_max.
  std::vector<double> remainder_line_table(double x_max, double step) const;

 private:
  double remainder(double q) const;  // R(q) above, with its limit at q = 0
  double find_split_height() const;  // h above, once

  LayeredMaterial material_;
  double layer_modulus_;
  double substrate_modulus_;
  double kappa_;              // (g - 1)/(g + 3 - 4 nu1), g = mu1/mu2
  double lambda_;             // 1 - 4 (1 - nu1)/(1 + g (3 - 4 nu2))
  double one_minus_kappa_;    // 1 - kappa, formed without cancellation
  double one_minus_lambda_;   // 1 - lambda, likewise
  double remainder_at_zero_;  // lim R(q), q -> 0
  double split_height_;       // h, m
};

}  // namespace halfspace::kernels
