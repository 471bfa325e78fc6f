// The stress field of a coated half-space (an elastic layer bonded to an
// elastic substrate, layered_material.hpp) under a normal surface traction,
// for one Fourier mode: the periodic grids' solution below a coating.
#pragma once

#include <array>
#include <complex>

#include "halfspace/layered_material.hpp"
#include "halfspace/stress/fourier_stress.hpp"

namespace halfspace::stress {

// Which body a depth lies in: depths z <= t are in the layer (the interface
// itself is evaluated with the layer's constants unless asked otherwise).
enum class Body { layer, substrate };

// The Airy function of one mode, phi = (p / q^2) g(q z) exp(i k.x), in
// dimensionless form: the layer's two unknowns and the substrate's two, which
// fix g in each body (docs/theory.md, "Stresses in a coated half-space").
struct LayeredMode {
  double q = 0.0;                     // |k|, rad/m
  bool thin = false;                  // s = q t <= 1: the layer in the basis of its initial values
  std::array<double, 4> layer{};      // thin: (g''(0), g'''(0), 0, 0); else (a, b, c, d)
  std::array<double, 2> substrate{};  // (a2, b2)
  // The surface conditions it was solved for: g(0) (the normal traction,
  // sigma_zz = -g) and g'(0) (the shear, sigma_x'z = -i g'); (1, 0) is a
  // unit pressure without shear.
  double surface_value = 1.0;
  double surface_slope = 0.0;
};

// g''(0) and g'''(0) of a solved mode: what its surface displacements need.
struct SurfaceDerivatives {
  double second = 0.0;
  double third = 0.0;
};

// g, g' and g'' (derivatives in q z) at one depth: sigma_zz = -g p,
// sigma_x'x' = g'' p and sigma_x'z = -i g' p in the frame whose x' axis is k.
struct AiryProfile {
  double g = 0.0;
  double g1 = 0.0;
  double g2 = 0.0;
};

// One component of LayeredFourierStress::stress for a body of Poisson's ratio
// nu: the form the periodic stress loop evaluates for each wavevector.
std::complex<double> layered_stress_component(Component component, double kx, double ky, const AiryProfile& profile,
                                              double nu);

class LayeredFourierStress {
 public:
  // Throws InputError naming the quantity if `material` is out of range.
  explicit LayeredFourierStress(const LayeredMaterial& material);

  const LayeredMaterial& material() const { return material_; }
  double thickness() const { return material_.thickness; }

  // Solves the mode of wavenumber q (rad/m, > 0): the six conditions (zero
  // shear and unit pressure on the surface, continuous displacements and
  // tractions at z = t) for the four coefficients of the layer and the two of
  // the substrate.
  LayeredMode solve(double q) const { return solve(q, 1.0, 0.0); }
  // The same mode under the surface conditions g(0) = value and g'(0) =
  // slope: a normal traction sigma_zz = -value and a shear traction
  // sigma_x'z = -i slope per unit of the spectrum's scale (a shear traction
  // T on the surface along k, whose outward normal is -z, is slope = -i T).
  LayeredMode solve(double q, double value, double slope) const;
  // The mode of a unit shear along k, g(0) = 0 and g'(0) = 1 (its stresses
  // are -i T times this mode's for a shear T along k:
  // layered_fourier_shear_stress.hpp).
  LayeredMode solve_shear(double q) const { return solve(q, 0.0, 1.0); }
  // g''(0) and g'''(0) of `mode`.
  SurfaceDerivatives surface_derivatives(const LayeredMode& mode) const;

  // g, g', g'' of `mode` at depth z (m, >= 0) in `body`.
  AiryProfile profile(const LayeredMode& mode, double z, Body body) const;

  // The six stress multipliers (Component order) of a mode of wavevector
  // (kx, ky) solved as `mode` (|k| = mode.q), at depth z in `body`, per unit
  // pressure spectrum; compression negative. The mean mode (q = 0) is the
  // laterally confined body under uniform pressure, as for the homogeneous
  // half-space, with the Poisson's ratio of `body`.
  std::array<std::complex<double>, kComponentCount> stress(double kx, double ky, const AiryProfile& profile,
                                                           Body body) const;

  // The body of depth z (m): the layer for z <= t.
  Body body_at(double z) const { return z <= material_.thickness ? Body::layer : Body::substrate; }

  // The surface displacement per unit pressure of the solved mode,
  // (1 - nu1) g'''(0) / (2 mu1 q) (m/Pa): equals the layered kernel's
  // 2 M(q t) / (E1* q), an independent check of the solution.
  double surface_displacement(const LayeredMode& mode) const;

 private:
  double poisson_ratio(Body body) const;

  LayeredMaterial material_;
  double shear_modulus_ratio_;  // mu1 / mu2
};

}  // namespace halfspace::stress
