// One Fourier mode of a bonded layer on a substrate under a tangential
// surface traction, split in the frame of the wave vector: x' along k
// (q = |k|, c = kx/q, s = ky/q), y' across it.
//
// Along k (plane strain in x', z): the Airy mode of layered_fourier_stress.cpp
// with the surface conditions g(0) = 0 (no normal traction) and g'(0) = 1,
// gamma, scaled by -i T for a shear T along k (sigma_x'z(0) = -T), gives
//   sx'x' = -i T gamma'',  sy'y' = -i T nu (gamma'' - gamma),
//   szz = i T gamma,       sx'z = -T gamma';
// the interface conditions are those of the pressure's mode, so the same
// solver serves both (and the tangential kernel's longitudinal compliance
// reads the same gamma, layered_tangential_fourier.cpp).
// Across k (antiplane): u_y' = W(z) e^{i q x'} is harmonic in each body,
// sy'z = mu W', sx'y' = i q mu W. With F = mu1 q W / T, F'(0) = -1 on the
// surface, F = A cosh(zeta) - sinh(zeta) in the layer, C e^{-(zeta - s)} in
// the substrate, continuous W and mu W' at zeta = s give
//   A = (cosh s + r sinh s)/(sinh s + r cosh s),   r = mu2/mu1,
// written with k = (1 - r)/(1 + r) and D = 1 - k e^{-2s} as
//   layer:     F = (e^{-zeta} + k e^{-s} e^{zeta - s}) / D,
//   substrate: mu2 q W / T = (1 - k) e^{-zeta} / D,
// whose exponents are never positive (the cosh/sinh form overflows for
// large s); D is formed as (1 - e^{-2s}) + (1 - k) e^{-2s}, without the
// cancellation 1 - k suffers for a soft substrate. across = F (layer) and
// vertical = -F' give sx'y' = i T across, sy'z = -T vertical.
// A unit shear along x has the parts T = c along k and -s across it (along
// y: s and c); s_lab = R s' R^T turns them back into (x, y).
#include "halfspace/stress/layered_fourier_shear_stress.hpp"

#include <cmath>
#include <utility>

#include "halfspace/linalg/parallel.hpp"

namespace halfspace::stress {
namespace {

double shear_modulus(const ElasticBody& body) {
  return body.youngs_modulus / (2.0 * (1.0 + body.poissons_ratio));
}

}  // namespace

LayeredAntiplane::LayeredAntiplane(const LayeredMaterial& material) : thickness_(validated(material).thickness) {
  const double mu1 = shear_modulus(material.layer);
  const double mu2 = shear_modulus(material.substrate);
  reflection_ = (mu1 - mu2) / (mu1 + mu2);
  transmission_ = 2.0 * mu2 / (mu1 + mu2);
  substrate_stiffness_ = mu2 / mu1;
}

double LayeredAntiplane::surface_displacement(double q) const {
  const double s = std::abs(q) * thickness_;
  const double e = std::exp(-2.0 * s);
  return (1.0 + reflection_ * e) / (-std::expm1(-2.0 * s) + transmission_ * e);
}

AntiplaneProfile LayeredAntiplane::profile(double q, double z, Body body) const {
  const double s = std::abs(q) * thickness_;
  const double zeta = std::abs(q) * z;
  const double denominator = -std::expm1(-2.0 * s) + transmission_ * std::exp(-2.0 * s);
  if (body == Body::substrate) {
    const double value = transmission_ * std::exp(-zeta) / denominator;
    return {value, value};
  }
  const double down = std::exp(-zeta);
  const double reflected = reflection_ * std::exp(-s) * std::exp(zeta - s);
  return {(down + reflected) / denominator, (down - reflected) / denominator};
}

std::complex<double> layered_shear_stress_component(Component component, Traction direction, double kx, double ky,
                                                    const AiryProfile& longitudinal, const AntiplaneProfile& transverse,
                                                    double nu) {
  const double q2 = kx * kx + ky * ky;
  if (q2 == 0.0) {
    if (direction == Traction::shear_x) return component == Component::xz ? -1.0 : 0.0;
    return component == Component::yz ? -1.0 : 0.0;
  }
  const double q = std::sqrt(q2);
  const double c = kx / q;
  const double s = ky / q;
  // The shear along k and across it.
  const double along = direction == Traction::shear_x ? c : s;
  const double across = direction == Traction::shear_x ? -s : c;
  const std::complex<double> i(0.0, 1.0);
  const std::complex<double> xx = -i * along * longitudinal.g2;
  const std::complex<double> yy = -i * along * nu * (longitudinal.g2 - longitudinal.g);
  const std::complex<double> xy = i * across * transverse.across;
  const double xz = -along * longitudinal.g1;
  const double yz = -across * transverse.vertical;
  switch (component) {
    case Component::xx:
      return c * c * xx - 2.0 * c * s * xy + s * s * yy;
    case Component::yy:
      return s * s * xx + 2.0 * c * s * xy + c * c * yy;
    case Component::zz:
      return i * along * longitudinal.g;
    case Component::xy:
      return c * s * (xx - yy) + (c * c - s * s) * xy;
    case Component::xz:
      return c * xz - s * yz;
    case Component::yz:
      return s * xz + c * yz;
  }
  return 0.0;
}

std::array<std::complex<double>, kComponentCount> layered_shear_stress(Traction direction, double kx, double ky,
                                                                       const AiryProfile& longitudinal,
                                                                       const AntiplaneProfile& transverse, double nu) {
  std::array<std::complex<double>, kComponentCount> result;
  for (std::size_t k = 0; k < kComponentCount; ++k) {
    result[k] =
        layered_shear_stress_component(static_cast<Component>(k), direction, kx, ky, longitudinal, transverse, nu);
  }
  return result;
}

LayeredShearModes::LayeredShearModes(const LayeredMaterial& material, std::vector<double> kx, std::vector<double> ky)
    : modes_(material), antiplane_(material), kx_(std::move(kx)), ky_(std::move(ky)) {
  solved_.resize(kx_.size());
  longitudinal_.resize(kx_.size());
  transverse_.resize(kx_.size());
  linalg::for_each_index(kx_.size(),
                         [&](std::size_t k) { solved_[k] = modes_.solve_shear(std::hypot(kx_[k], ky_[k])); });
}

void LayeredShearModes::evaluate(double z, Body body) {
  linalg::for_each_index(kx_.size(), [&](std::size_t k) {
    const double q = solved_[k].q;
    longitudinal_[k] = modes_.profile(solved_[k], z, body);
    transverse_[k] = q > 0.0 ? antiplane_.profile(q, z, body) : AntiplaneProfile{};
  });
}

}  // namespace halfspace::stress
