// One Fourier mode of a bonded layer on a substrate under normal pressure.
//
// The mode is a plane-strain problem in the frame whose x' axis is k (the
// normal load excites no antiplane motion), so sigma_y'y' = nu (sigma_x'x' +
// sigma_zz) and sigma_x'y' = sigma_y'z = 0; rotating back to (x, y) gives the
// six components. The Airy function phi = (p/q^2) g(zeta) e^{i q x'},
// zeta = q z, gives sigma_zz = -p g, sigma_x'x' = p g'', sigma_x'z = -i p g',
// and g solves g'''' - 2 g'' + g = 0 in each body (Johnson 1985, sec. 2.6;
// Timoshenko & Goodier 1951, sec. 25). With s = q t:
//   substrate:  g = (a2 + b2 eta) e^{-eta},  eta = zeta - s (decaying only);
//   layer:      g = (a + b zeta) e^{-zeta} + (c + d eta) e^{eta}   (s > 1), or
//               g = g(0) Phi0 + g'(0) Phi1 + g''(0) Phi2 + g'''(0) Phi3   (s <= 1),
// with Phi_j the solutions of unit j-th initial derivative (Phi0 = cosh -
// zeta sinh/2, Phi1 = (3 sinh - zeta cosh)/2, Phi2 = zeta sinh/2, Phi3 =
// (zeta cosh - sinh)/2), which stay
// well conditioned as s -> 0, where the exponential basis degenerates; the
// exponential one keeps every term bounded by 1 + s for large s, where
// Phi_j grow like e^s and would cancel.
// Conditions: on the surface g(0) = 1 (sigma_zz = -p) and g'(0) = 0 (no
// shear), or, for a shear traction (docs/theory.md, "Tangential compliance
// of a coated half-space"), other values of the two; at zeta = s, g and g'
// continuous (sigma_zz, sigma_xz), and u_x and u_z continuous. For one mode these are the continuity of
//   2 mu eps_x'x' / p = (1 - nu) g'' + nu g            (u_x' = eps_x'x' / (i q))
//   2 mu q u_z / p    = (1 - nu) g''' - (2 - nu) g'    (from eps_x'z and eps_x'x')
// divided by mu; the surface displacement is then u_z = (1 - nu1) g'''(0) p /
// (2 mu1 q), i.e. the layered kernel's M(q t) = g'''(0)/2.
#include "halfspace/stress/layered_fourier_stress.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace halfspace::stress {
namespace {

// The substrate's g, g', g'', g''' at eta = 0 per unit a2 and b2.
constexpr double kSubstrateValues[4][2] = {{1.0, 0.0}, {-1.0, 1.0}, {1.0, -2.0}, {-1.0, 3.0}};

}  // namespace

LayeredFourierStress::LayeredFourierStress(const LayeredMaterial& material) : material_(validated(material)) {
  const ElasticBody& layer = material_.layer;
  const ElasticBody& substrate = material_.substrate;
  shear_modulus_ratio_ = (layer.youngs_modulus / (1.0 + layer.poissons_ratio)) /
                         (substrate.youngs_modulus / (1.0 + substrate.poissons_ratio));
}

double LayeredFourierStress::poisson_ratio(Body body) const {
  return body == Body::layer ? material_.layer.poissons_ratio : material_.substrate.poissons_ratio;
}

namespace {

// The layer's g, g', g'', g''' at zeta = s as linear functions of its
// unknowns x: g^(j)(s) = values[j] . x + constants[j].
struct LayerInterface {
  int unknowns = 0;
  double values[4][4] = {};
  double constants[4] = {};
};

LayerInterface layer_interface(double s, bool thin, double value, double slope) {
  LayerInterface layer;
  if (thin) {
    layer.unknowns = 2;  // g''(0), g'''(0); g(0) and g'(0) are built in
    const double c = std::cosh(s);
    const double sh = std::sinh(s);
    const double phi0[4] = {c - 0.5 * s * sh, 0.5 * (sh - s * c), -0.5 * s * sh, -0.5 * (sh + s * c)};
    const double phi1[4] = {0.5 * (3.0 * sh - s * c), c - 0.5 * s * sh, 0.5 * (sh - s * c), -0.5 * s * sh};
    const double phi2[4] = {0.5 * s * sh, 0.5 * (sh + s * c), c + 0.5 * s * sh, 0.5 * (3.0 * sh + s * c)};
    const double phi3[4] = {0.5 * (s * c - sh), 0.5 * s * sh, 0.5 * (sh + s * c), c + 0.5 * s * sh};
    for (int j = 0; j < 4; ++j) {
      layer.constants[j] = value * phi0[j] + slope * phi1[j];
      layer.values[j][0] = phi2[j];
      layer.values[j][1] = phi3[j];
    }
  } else {
    layer.unknowns = 4;  // a, b, c, d
    const double e = std::exp(-s);
    const double b_terms[4] = {s * e, (1.0 - s) * e, (s - 2.0) * e, (3.0 - s) * e};
    for (int j = 0; j < 4; ++j) {
      layer.values[j][0] = (j % 2 == 0 ? 1.0 : -1.0) * e;
      layer.values[j][1] = b_terms[j];
      layer.values[j][2] = 1.0;
      layer.values[j][3] = static_cast<double>(j);
    }
  }
  return layer;
}

// The weights of g, g', g'', g''' in the four interface conditions (g, g',
// in-plane strain, vertical displacement) of a body of Poisson's ratio nu,
// the last two times `weight` (its 1/mu, scaled).
struct ConditionRows {
  double weights[4][4];
};

ConditionRows condition_rows(double nu, double weight) {
  return {{{1.0, 0.0, 0.0, 0.0},
           {0.0, 1.0, 0.0, 0.0},
           {weight * nu, 0.0, weight * (1.0 - nu), 0.0},
           {0.0, weight * (2.0 - nu), 0.0, -weight * (1.0 - nu)}}};
}

}  // namespace

LayeredMode LayeredFourierStress::solve(double q, double value, double slope) const {
  LayeredMode mode;
  mode.q = std::abs(q);
  mode.surface_value = value;
  mode.surface_slope = slope;
  if (mode.q == 0.0) return mode;
  const double s = mode.q * material_.thickness;
  mode.thin = s <= 1.0;
  // 1. The layer's values at the interface over its unknowns.
  const LayerInterface layer = layer_interface(s, mode.thin, value, slope);
  const int n = layer.unknowns + 2;

  // 2. The interface conditions. The strain and displacement rows are
  // (layer)/mu1 = (substrate)/mu2, scaled so that neither side's
  // coefficients exceed their own size when mu1/mu2 is extreme.
  const double g = shear_modulus_ratio_;
  const ConditionRows layer_rows = condition_rows(material_.layer.poissons_ratio, 1.0 / std::max(g, 1.0));
  const ConditionRows substrate_rows = condition_rows(material_.substrate.poissons_ratio, std::min(g, 1.0));
  Eigen::Matrix<double, 6, 6> matrix = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
  for (int row = 0; row < 4; ++row) {
    for (int j = 0; j < 4; ++j) {
      const double w = layer_rows.weights[row][j];
      for (int k = 0; k < layer.unknowns; ++k) matrix(row, k) += w * layer.values[j][k];
      rhs(row) -= w * layer.constants[j];
      for (int k = 0; k < 2; ++k) {
        matrix(row, layer.unknowns + k) -= substrate_rows.weights[row][j] * kSubstrateValues[j][k];
      }
    }
  }
  // 3. The surface, in the exponential basis (the other has it built in):
  // g(0) = a + (c - d s) e^{-s} = value, g'(0) = b - a + (c + d - d s)
  // e^{-s} = slope.
  if (!mode.thin) {
    const double e = std::exp(-s);
    matrix(4, 0) = 1.0;
    matrix(4, 2) = e;
    matrix(4, 3) = -s * e;
    rhs(4) = value;
    matrix(5, 0) = -1.0;
    matrix(5, 1) = 1.0;
    matrix(5, 2) = e;
    matrix(5, 3) = (1.0 - s) * e;
    rhs(5) = slope;
  }
  // 4. Full-pivoting LU of the 4 x 4 or 6 x 6 system.
  Eigen::Matrix<double, 6, 1> x;
  if (n == 4) {
    const Eigen::Matrix4d m4 = matrix.topLeftCorner<4, 4>();
    const Eigen::Vector4d r4 = rhs.head<4>();
    x.head<4>() = m4.fullPivLu().solve(r4);
  } else {
    x = matrix.fullPivLu().solve(rhs);
  }
  for (int k = 0; k < layer.unknowns; ++k) mode.layer[static_cast<std::size_t>(k)] = x(k);
  mode.substrate = {x(layer.unknowns), x(layer.unknowns + 1)};
  return mode;
}

AiryProfile LayeredFourierStress::profile(const LayeredMode& mode, double z, Body body) const {
  if (mode.q == 0.0) return {mode.surface_value, 0.0, 0.0};
  const double zeta = mode.q * z;
  const double s = mode.q * material_.thickness;
  if (body == Body::substrate) {
    const double eta = zeta - s;
    const double e = std::exp(-eta);
    const auto [a2, b2] = mode.substrate;
    return {(a2 + b2 * eta) * e, (b2 - a2 - b2 * eta) * e, (a2 - 2.0 * b2 + b2 * eta) * e};
  }
  if (mode.thin) {
    const double c = std::cosh(zeta);
    const double sh = std::sinh(zeta);
    const double value = mode.surface_value;
    const double slope = mode.surface_slope;
    const double second = mode.layer[0];
    const double third = mode.layer[1];
    return {value * (c - 0.5 * zeta * sh) + slope * 0.5 * (3.0 * sh - zeta * c) + second * 0.5 * zeta * sh +
                third * 0.5 * (zeta * c - sh),
            value * 0.5 * (sh - zeta * c) + slope * (c - 0.5 * zeta * sh) + second * 0.5 * (sh + zeta * c) +
                third * 0.5 * zeta * sh,
            value * -0.5 * zeta * sh + slope * 0.5 * (sh - zeta * c) + second * (c + 0.5 * zeta * sh) +
                third * 0.5 * (sh + zeta * c)};
  }
  const auto [a, b, c, d] = mode.layer;
  const double eta = zeta - s;
  const double down = std::exp(-zeta);
  const double up = std::exp(eta);
  return {(a + b * zeta) * down + (c + d * eta) * up, (b - a - b * zeta) * down + (c + d + d * eta) * up,
          (a - 2.0 * b + b * zeta) * down + (c + 2.0 * d + d * eta) * up};
}

std::array<std::complex<double>, kComponentCount> LayeredFourierStress::stress(double kx, double ky,
                                                                               const AiryProfile& profile,
                                                                               Body body) const {
  std::array<std::complex<double>, kComponentCount> result;
  for (std::size_t c = 0; c < kComponentCount; ++c) {
    result[c] = layered_stress_component(static_cast<Component>(c), kx, ky, profile, poisson_ratio(body));
  }
  return result;
}

SurfaceDerivatives LayeredFourierStress::surface_derivatives(const LayeredMode& mode) const {
  if (mode.thin) return {mode.layer[0], mode.layer[1]};
  const double s = mode.q * material_.thickness;
  const auto [a, b, c, d] = mode.layer;
  const double e = std::exp(-s);
  return {a - 2.0 * b + (c + 2.0 * d - d * s) * e, 3.0 * b - a + (c + 3.0 * d - d * s) * e};
}

double LayeredFourierStress::surface_displacement(const LayeredMode& mode) const {
  const double third = surface_derivatives(mode).third;
  const ElasticBody& layer = material_.layer;
  const double mu1 = layer.youngs_modulus / (2.0 * (1.0 + layer.poissons_ratio));
  return (1.0 - layer.poissons_ratio) * third / (2.0 * mu1 * mode.q);
}

std::complex<double> layered_stress_component(Component component, double kx, double ky, const AiryProfile& profile,
                                              double nu) {
  const double q2 = kx * kx + ky * ky;
  if (q2 == 0.0) return confined_mean_stress(component, nu);
  const double q = std::sqrt(q2);
  const double along = profile.g2;                      // sigma_x'x'
  const double across = nu * (profile.g2 - profile.g);  // sigma_y'y', plane strain
  switch (component) {
    case Component::xx:
      return (kx * kx * along + ky * ky * across) / q2;
    case Component::yy:
      return (ky * ky * along + kx * kx * across) / q2;
    case Component::zz:
      return -profile.g;
    case Component::xy:
      return kx * ky * (along - across) / q2;
    case Component::xz:
      return {0.0, -kx / q * profile.g1};
    case Component::yz:
      return {0.0, -ky / q * profile.g1};
  }
  return 0.0;
}

}  // namespace halfspace::stress
