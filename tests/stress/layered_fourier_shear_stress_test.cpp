// The stresses of one Fourier mode in a coated half-space under a tangential
// surface traction (layered_fourier_shear_stress.hpp): the homogeneous limit
// (Cerruti, fourier_shear_stress.hpp), the conditions on the surface and at
// the interface, a direct solution of Navier's equations (plane strain and
// antiplane, tests/support/layered_navier_solve.hpp), and the surface
// displacement of the field against the friction solver's layered tangential
// and coupling compliances (layered_tangential_fourier.hpp).
#include "halfspace/stress/layered_fourier_shear_stress.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "halfspace/kernels/layered_tangential_fourier.hpp"
#include "halfspace/stress/fourier_shear_stress.hpp"
#include "support/gauss_legendre.hpp"
#include "support/layered_navier_solve.hpp"

namespace halfspace::stress {
namespace {

using Stress = std::array<std::complex<double>, kComponentCount>;

LayeredMaterial coating(double t, double e1, double nu1, double e2, double nu2) {
  return LayeredMaterial{t, ElasticBody{e1, nu1}, ElasticBody{e2, nu2}};
}

// Soft on hard, hard on soft, an auxetic layer, a nearly incompressible one,
// and moduli a thousand times apart either way.
std::vector<LayeredMaterial> material_pairs(double t) {
  return {coating(t, 2e9, 0.4, 200e9, 0.3),  coating(t, 400e9, 0.25, 100e9, 0.35), coating(t, 50e9, -0.5, 70e9, 0.2),
          coating(t, 1e7, 0.4999, 1e9, 0.3), coating(t, 1e12, 0.3, 1e9, 0.3),      coating(t, 1e9, 0.3, 1e12, 0.5)};
}

// Wavevectors with |k| = q: along x, along y, and two oblique ones.
std::vector<std::array<double, 2>> wavevectors(double q) {
  return {{q, 0.0}, {0.0, -q}, {0.6 * q, -0.8 * q}, {-0.28 * q, 0.96 * q}};
}

// The field of a unit shear along `direction` as the stress loop forms it:
// the mode's in-plane and antiplane parts at depth z in `body`.
class CoatedShear {
 public:
  explicit CoatedShear(const LayeredMaterial& material) : material_(material), modes_(material), antiplane_(material) {}

  Stress at(Traction direction, double kx, double ky, double z, Body body) const {
    const double q = std::hypot(kx, ky);
    const AiryProfile longitudinal = modes_.profile(modes_.solve_shear(q), z, body);
    const AntiplaneProfile transverse = q > 0.0 ? antiplane_.profile(q, z, body) : AntiplaneProfile{};
    return layered_shear_stress(direction, kx, ky, longitudinal, transverse, elastic(body).poissons_ratio);
  }
  Stress at(Traction direction, double kx, double ky, double z) const {
    return at(direction, kx, ky, z, modes_.body_at(z));
  }
  const ElasticBody& elastic(Body body) const { return body == Body::layer ? material_.layer : material_.substrate; }

 private:
  LayeredMaterial material_;
  LayeredFourierStress modes_;
  LayeredAntiplane antiplane_;
};

// Hooke's law: the strains (xx, yy, zz, xy) of a stress in `body`.
std::array<std::complex<double>, 4> strain(const Stress& s, const ElasticBody& body) {
  const double e = body.youngs_modulus;
  const double nu = body.poissons_ratio;
  return {(s[0] - nu * (s[1] + s[2])) / e, (s[1] - nu * (s[0] + s[2])) / e, (s[2] - nu * (s[0] + s[1])) / e,
          s[3] * (1.0 + nu) / e};
}

double largest(const Stress& s) {
  double m = 0.0;
  for (const auto& v : s) m = std::max(m, std::abs(v));
  return m;
}

constexpr std::array<Traction, 2> kShears = {Traction::shear_x, Traction::shear_y};

TEST(LayeredFourierShearStressTest, IdenticalMaterialsGiveCerrutisStresses) {
  // Exact algebra on multipliers of size 1 (both bases of the layer's mode,
  // either side of q t = 1): a few hundred eps (measured 1.3e-15).
  constexpr double kRoundoff = 1e-13;
  const double t = 1e-6;
  double worst = 0.0;
  for (const double nu : {0.3, -0.4, 0.5}) {
    const CoatedShear coated(coating(t, 210e9, nu, 210e9, nu));
    for (const double s : {0.0, 1e-5, 0.3, 1.0, 1.0001, 4.0, 60.0}) {
      const double q = s / t;
      for (const double depth_ratio : {0.0, 0.25, 0.999, 1.0, 1.5, 7.0}) {
        const double z = depth_ratio * t;
        for (const auto& [kx, ky] : wavevectors(q)) {
          for (const Traction direction : kShears) {
            const Stress expected = fourier_shear_stress(direction, kx, ky, z, nu);
            const Stress got = coated.at(direction, kx, ky, z);
            for (std::size_t c = 0; c < kComponentCount; ++c) {
              const double error = std::abs(got[c] - expected[c]);
              worst = std::max(worst, error);
              EXPECT_LT(error, kRoundoff)
                  << kComponentNames[c] << ", nu = " << nu << ", q t = " << s << ", z/t = " << depth_ratio;
            }
          }
        }
      }
    }
  }
  std::printf("coated shear stresses, identical materials vs Cerruti: worst %.2e\n", worst);
}

TEST(LayeredFourierShearStressTest, SurfaceIsShearedOnlyAndTheInterfaceIsBonded) {
  // The conditions the solves impose, read back from the evaluated stresses:
  // round-off relative to the largest stress (and strain) of the mode
  // (measured 5e-14 on the surface).
  constexpr double kRoundoff = 1e-10;
  const double t = 1e-6;
  double worst = 0.0;
  for (const LayeredMaterial& material : material_pairs(t)) {
    const CoatedShear coated(material);
    for (const double s : {1e-3, 0.2, 1.0, 2.5, 30.0}) {
      const double q = s / t;
      for (const auto& [kx, ky] : wavevectors(q)) {
        for (const Traction direction : kShears) {
          const Stress top = coated.at(direction, kx, ky, 0.0, Body::layer);
          const double xz = direction == Traction::shear_x ? -1.0 : 0.0;
          const double yz = direction == Traction::shear_y ? -1.0 : 0.0;
          const double surface = std::max({std::abs(top[2]), std::abs(top[4] - xz), std::abs(top[5] - yz)});
          worst = std::max(worst, surface);
          EXPECT_LT(surface, kRoundoff) << "sigma_zz = 0, sigma_xz = -q_x, sigma_yz = -q_y at q t = " << s;

          const Stress above = coated.at(direction, kx, ky, t, Body::layer);
          const Stress below = coated.at(direction, kx, ky, t, Body::substrate);
          const double scale = std::max(largest(above), largest(below));
          for (const std::size_t c : {2u, 4u, 5u}) {
            EXPECT_NEAR(std::abs(above[c] - below[c]), 0.0, kRoundoff * scale)
                << kComponentNames[c] << " continuous at q t = " << s << ", E1 = " << material.layer.youngs_modulus;
          }
          // Continuous u_x, u_y: continuous in-plane strains (xx, yy, xy).
          const auto strain_above = strain(above, material.layer);
          const auto strain_below = strain(below, material.substrate);
          const double strain_scale =
              scale / std::min(material.layer.youngs_modulus, material.substrate.youngs_modulus);
          for (const std::size_t c : {0u, 1u, 3u}) {
            EXPECT_NEAR(std::abs(strain_above[c] - strain_below[c]), 0.0, kRoundoff * strain_scale)
                << "in-plane strain " << c << " at q t = " << s << ", E1 = " << material.layer.youngs_modulus;
          }
        }
      }
    }
  }
  std::printf("coated shear stresses, surface conditions: worst %.2e\n", worst);
}

// The Navier solution of a unit shear along k (plane strain, traction
// sin(q x')) and across it (antiplane) as complex multipliers of exp(i q
// x') in the frame of k: a field A sin + B cos is the multiplier A + i B.
Eigen::Matrix3cd navier_stress(const LayeredMaterial& m, double z, bool in_layer, double along, double across) {
  const std::complex<double> i(0.0, 1.0);
  // (U, W, szz, sxz, sxx, syy); the shear parts are sin, the normal ones cos.
  const auto plane = testing::solve_layered_navier(m, 0.0, 1.0).at(z, in_layer);
  // (V, syz, sxy).
  const auto anti = testing::solve_layered_antiplane(m, 1.0).at(z, in_layer);
  Eigen::Matrix3cd s;
  const std::complex<double> xx = i * plane[4] * along;
  const std::complex<double> yy = i * plane[5] * along;
  const std::complex<double> zz = i * plane[2] * along;
  const std::complex<double> xz = plane[3] * along;
  const std::complex<double> xy = i * anti[2] * across;
  const std::complex<double> yz = anti[1] * across;
  s << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  return s;
}

TEST(LayeredFourierShearStressTest, AgreesWithADirectSolutionOfNaviersEquations) {
  // Two solutions of the same conditions, the reference a 6 x 6 system of
  // condition number up to 1e5 (layered_navier_solve.hpp): 1e-10 of the
  // traction.
  constexpr double kAgreement = 1e-10;  // measured 1e-14
  constexpr std::array<std::array<double, 4>, 5> kMaterials = {{
      {1e9, 0.3, 2e11, 0.25},   // polymer on steel
      {4e11, 0.2, 1e11, 0.35},  // hard coating
      {1e7, 0.45, 2e11, 0.3},   // rubber on steel
      {1e9, -0.5, 3e9, 0.1},    // auxetic layer
      {2e11, 0.0, 7e10, 0.49},  // nearly incompressible substrate
  }};
  double worst = 0.0;
  for (const auto& [e1, nu1, e2, nu2] : kMaterials) {
    for (const double t : {0.01, 0.3, 1.0, 2.6, 5.0}) {  // q t at q = 1/m
      const LayeredMaterial material = coating(t, e1, nu1, e2, nu2);
      const CoatedShear coated(material);
      for (const double depth_ratio : {0.0, 0.4, 1.0, 1.7}) {
        const double z = depth_ratio * t;
        const bool in_layer = z <= t;
        const Body body = in_layer ? Body::layer : Body::substrate;
        for (const auto& [kx, ky] : wavevectors(1.0)) {
          // The lab frame from the frame of k: x' = (c, s), y' = (-s, c).
          Eigen::Matrix3cd rotation;
          rotation << kx, -ky, 0.0, ky, kx, 0.0, 0.0, 0.0, 1.0;
          for (const Traction direction : kShears) {
            const bool along_x = direction == Traction::shear_x;
            const Eigen::Matrix3cd primed = navier_stress(material, z, in_layer, along_x ? kx : ky, along_x ? -ky : kx);
            const Eigen::Matrix3cd lab = rotation * primed * rotation.transpose();
            const std::array<std::complex<double>, kComponentCount> expected = {lab(0, 0), lab(1, 1), lab(2, 2),
                                                                                lab(0, 1), lab(0, 2), lab(1, 2)};
            const Stress got = coated.at(direction, kx, ky, z, body);
            for (std::size_t c = 0; c < kComponentCount; ++c) {
              const double error = std::abs(got[c] - expected[c]);
              worst = std::max(worst, error);
              EXPECT_LT(error, kAgreement) << kComponentNames[c] << " at E1 = " << e1 << ", q t = " << t
                                           << ", z/t = " << depth_ratio << ", k = (" << kx << ", " << ky << ")";
            }
          }
        }
      }
    }
  }
  std::printf("coated shear stresses vs Navier solve: worst %.2e (of a unit traction)\n", worst);
}

// u_z(0) = -int_0^inf eps_zz dz (u_z positive into the body, zero at depth),
// by composite Gauss-Legendre on panels of a quarter decay length, to 60
// decay lengths below the interface.
std::complex<double> surface_normal_displacement(const CoatedShear& coated, const LayeredMaterial& material,
                                                 Traction direction, double kx, double ky) {
  static const testing::QuadratureRule rule = testing::gauss_legendre(16);
  const double q = std::hypot(kx, ky);
  std::complex<double> sum = 0.0;
  const auto integrate = [&](double from, double to, Body body) {
    const int panels = std::max(1, static_cast<int>(std::ceil((to - from) * q / 0.25)));
    const double h = (to - from) / panels;
    for (int p = 0; p < panels; ++p) {
      for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
        const double z = from + h * (p + 0.5 * (1.0 + rule.nodes[j]));
        sum += 0.5 * h * rule.weights[j] * strain(coated.at(direction, kx, ky, z, body), coated.elastic(body))[2];
      }
    }
  };
  integrate(0.0, material.thickness, Body::layer);
  integrate(material.thickness, material.thickness + 60.0 / q, Body::substrate);
  return -sum;
}

TEST(LayeredFourierShearStressTest, SurfaceDisplacementIsTheFrictionSolversCompliance) {
  // The field's surface displacement, from its strains: u_x = eps_xx/(i kx),
  // u_y = eps_yy/(i ky) at z = 0 (Hooke's law with the layer's constants)
  // and u_z = -int eps_zz dz over both bodies, against the symbols the
  // friction solver uses: the tangential block, and the normal displacement
  // -i D_eff k_a/(2 q^2) per unit shear along a on this body (D_eff from the
  // pressure's mode, by Betti's reciprocity; coupling_fourier.hpp's +i is
  // for the traction body 1 exerts on body 2, i.e. minus the coated body's).
  // Round-off (tangential) and the quadrature's error (normal) relative to
  // the compliance's scale: measured 5e-15 and 1e-14.
  constexpr double kTangential = 1e-12;
  constexpr double kNormal = 1e-11;
  const double t = 1e-6;
  double worst_tangential = 0.0;
  double worst_normal = 0.0;
  for (const LayeredMaterial& material : material_pairs(t)) {
    const CoatedShear coated(material);
    const kernels::LayeredTangentialKernel kernel(material);
    for (const double s : {1e-3, 0.2, 1.0, 2.5, 30.0}) {
      const double q = s / t;
      const kernels::LayeredModeCompliance compliance = kernel.mode_compliance(q);
      const double scale = std::max({std::abs(compliance.longitudinal), std::abs(compliance.transverse),
                                     std::abs(compliance.coupling)}) /
                           q;
      for (const auto& [kx, ky] :
           {std::array<double, 2>{0.6 * q, -0.8 * q}, std::array<double, 2>{-0.28 * q, 0.96 * q}}) {
        const kernels::TangentialCoefficients symbol = kernel.tangential(kx, ky);
        for (const Traction direction : kShears) {
          const bool along_x = direction == Traction::shear_x;
          const std::complex<double> i(0.0, 1.0);
          const auto e = strain(coated.at(direction, kx, ky, 0.0, Body::layer), material.layer);
          const std::complex<double> ux = e[0] / (i * kx);
          const std::complex<double> uy = e[1] / (i * ky);
          const double expected_x = along_x ? symbol.xx : symbol.xy;
          const double expected_y = along_x ? symbol.xy : symbol.yy;
          const double tangential = std::max(std::abs(ux - expected_x), std::abs(uy - expected_y)) / scale;
          worst_tangential = std::max(worst_tangential, tangential);
          EXPECT_LT(tangential, kTangential) << "E1 = " << material.layer.youngs_modulus << ", q t = " << s;
          // The shear strain agrees with the two: 2 eps_xy = i (kx u_y + ky u_x).
          EXPECT_LT(std::abs(2.0 * e[3] - i * (kx * uy + ky * ux)) / (q * scale), kTangential);

          const std::complex<double> uz = surface_normal_displacement(coated, material, direction, kx, ky);
          const std::complex<double> expected_z = -i * compliance.coupling * (along_x ? kx : ky) / (2.0 * q * q);
          const double normal = std::abs(uz - expected_z) / scale;
          worst_normal = std::max(worst_normal, normal);
          EXPECT_LT(normal, kNormal) << "E1 = " << material.layer.youngs_modulus << ", q t = " << s;
        }
      }
    }
  }
  std::printf("coated shear surface displacement vs friction compliance: tangential %.2e, normal %.2e\n",
              worst_tangential, worst_normal);
}

}  // namespace
}  // namespace halfspace::stress
