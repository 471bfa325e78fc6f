// The coated half-space's tangential and coupling symbols
// (layered_tangential_fourier.hpp).
//
// In-plane: the Airy mode g of layered_fourier_stress.cpp, solved once with
// g(0) = 1, g'(0) = 0 (unit pressure) and once with g(0) = 0, g'(0) = 1 (a
// shear traction T along q, g = -i T gamma), gives the surface displacements
//   2 mu1 q u_z  = (1 - nu1) g'''(0) - (2 - nu1) g'(0),
//   2 mu1 q u_x' = -i ((1 - nu1) g''(0) + nu1 g(0)),
// so normal = (1 - nu1) g'''(0)/(2 mu1), longitudinal = -(1 - nu1)
// gamma''(0)/(2 mu1), and the coupling from the pressure -((1 - nu1) g''(0)
// + nu1)/mu1, from the shear ((1 - nu1) gamma'''(0) - (2 - nu1))/mu1 (Betti:
// the two agree). The body-frame signs of the coupling are the reverse of
// coupling_fourier.hpp's relative ones (there the traction is the one body 1
// exerts on body 2): D_eff is written in the latter's sign, which gives
// (1 - 2 nu)/G for a homogeneous body.
// Antiplane: u_y(0) = (T/(mu1 q)) (1 + k e^{-2 s})/(1 - k e^{-2 s}),
// k = (mu1 - mu2)/(mu1 + mu2), s = q t (1/mu2 for s -> 0, 1/mu1 for s -> inf),
// the surface value of the antiplane field of
// stress/layered_fourier_shear_stress.cpp.
#include "halfspace/kernels/layered_tangential_fourier.hpp"

#include <cmath>

#include "halfspace/kernels/coupling_fourier.hpp"
#include "halfspace/kernels/layered_fourier.hpp"
#include "halfspace/kernels/tangential_fourier.hpp"

namespace halfspace::kernels {

LayeredTangentialKernel::LayeredTangentialKernel(const LayeredMaterial& material)
    : modes_(material), antiplane_(material) {
  const ElasticBody& layer = material.layer;
  layer_shear_modulus_ = layer.youngs_modulus / (2.0 * (1.0 + layer.poissons_ratio));
  auto factors = [](const ElasticBody& body) {
    const double compliance = 2.0 * (1.0 + body.poissons_ratio) / body.youngs_modulus;  // 1/G
    return Factors{compliance, body.poissons_ratio * compliance, (1.0 - 2.0 * body.poissons_ratio) * compliance};
  };
  layer_ = factors(layer);
  substrate_ = factors(material.substrate);
}

// The closed-form part's symbols (cerruti_rectangle.hpp, coupling_rectangle.hpp)
// in the same factors: the layer's plus (substrate's - layer's) exp(-q h),
// the directional one with (1 + q h) exp(-q h). Each difference vanishes
// like q at q = 0 (the substrate's limit) except the directional part of
// the tangential one, whose O(q) term has a direction (q_a q_b/q^2).
LayeredTangentialKernel::Factors LayeredTangentialKernel::remainder(double q, double height) const {
  const LayeredModeCompliance c = mode_compliance(q);
  const double e = std::exp(-q * height);
  return {c.transverse - layer_.shear - (substrate_.shear - layer_.shear) * e,
          (c.transverse - c.longitudinal) - layer_.directional -
              (substrate_.directional - layer_.directional) * (1.0 + q * height) * e,
          c.coupling - layer_.coupling - (substrate_.coupling - layer_.coupling) * e};
}

void LayeredTangentialKernel::remainder_cell_spectrum(double qx, double qy, double dx, double dy, double height,
                                                      TangentialCoefficients& tangential,
                                                      CouplingCoefficients& coupling) const {
  const double t = material().thickness;
  tangential = {};
  coupling = {};
  auto add = [&](double kx, double ky, double shape) {
    const double q = std::hypot(kx, ky);
    TangentialCoefficients s;
    CouplingCoefficients odd;
    if (q == 0.0) {
      // Factors/q tend to finite limits (Richardson extrapolation of the
      // difference quotient, O(h^2) = 1e-8 relative); the mean over the
      // directions of q_a q_b/q^2 is delta_ab/2, of the odd coupling 0.
      constexpr double h = 1e-4;
      const Factors one = remainder(h / t, height);
      const Factors two = remainder(2.0 * h / t, height);
      const double shear = (2.0 * one.shear - 0.5 * two.shear) * t / h;
      const double directional = (2.0 * one.directional - 0.5 * two.directional) * t / h;
      s = {shear - 0.5 * directional, shear - 0.5 * directional, 0.0};
    } else {
      const Factors f = remainder(q, height);
      s = tangential_spectrum(kx, ky, f.shear, f.directional);
      odd = coupling_spectrum(kx, ky, f.coupling);
    }
    tangential.xx += s.xx * shape;
    tangential.yy += s.yy * shape;
    tangential.xy += s.xy * shape;
    coupling.x += odd.x * shape;
    coupling.y += odd.y * shape;
  };
  // Beyond q t = 40 the remainder is below e^-40 of its scale (as the normal one's).
  for_each_alias_image(qx, qy, dx, dy, false, LayeredKernel::kAliasImages, 40.0 / t, add);
}

LayeredModeCompliance LayeredTangentialKernel::mode_compliance(double q) const {
  const double nu1 = modes_.material().layer.poissons_ratio;
  const double mu1 = layer_shear_modulus_;
  const stress::SurfaceDerivatives pressure = modes_.surface_derivatives(modes_.solve(q, 1.0, 0.0));
  const stress::SurfaceDerivatives shear = modes_.surface_derivatives(modes_.solve_shear(q));
  LayeredModeCompliance c;
  c.normal = (1.0 - nu1) * pressure.third / (2.0 * mu1);
  c.longitudinal = -(1.0 - nu1) * shear.second / (2.0 * mu1);
  c.transverse = antiplane_.surface_displacement(q) / mu1;
  c.coupling = -((1.0 - nu1) * pressure.second + nu1) / mu1;
  c.coupling_transpose = ((1.0 - nu1) * shear.third - (2.0 - nu1)) / mu1;
  return c;
}

void LayeredTangentialKernel::symbols(double qx, double qy, TangentialCoefficients& tangential,
                                      CouplingCoefficients& coupling) const {
  const double q = std::hypot(qx, qy);
  if (q == 0.0) {
    tangential = {};
    coupling = {};
    return;
  }
  const LayeredModeCompliance c = mode_compliance(q);
  tangential = tangential_spectrum(qx, qy, c.transverse, c.transverse - c.longitudinal);
  coupling = coupling_spectrum(qx, qy, c.coupling);
}

TangentialCoefficients LayeredTangentialKernel::tangential(double qx, double qy) const {
  TangentialCoefficients t;
  CouplingCoefficients c;
  symbols(qx, qy, t, c);
  return t;
}

CouplingCoefficients LayeredTangentialKernel::coupling(double qx, double qy) const {
  TangentialCoefficients t;
  CouplingCoefficients c;
  symbols(qx, qy, t, c);
  return c;
}

}  // namespace halfspace::kernels
