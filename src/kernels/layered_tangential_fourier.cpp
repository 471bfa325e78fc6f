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
#include "halfspace/kernels/tangential_fourier.hpp"

namespace halfspace::kernels {

LayeredTangentialKernel::LayeredTangentialKernel(const LayeredMaterial& material)
    : modes_(material), antiplane_(material) {
  const ElasticBody& layer = material.layer;
  layer_shear_modulus_ = layer.youngs_modulus / (2.0 * (1.0 + layer.poissons_ratio));
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
