// The stresses of one Fourier mode in a coated half-space
// (layered_fourier_stress.hpp): the homogeneous limit, the conditions on the
// surface and at the interface, the thick and thin layer limits, and the
// surface displacement against the independently derived layered kernel.
#include "halfspace/stress/layered_fourier_stress.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "halfspace/kernels/layered_fourier.hpp"

namespace halfspace::stress {
namespace {

LayeredMaterial coating(double t, double e1, double nu1, double e2, double nu2) {
  return LayeredMaterial{t, ElasticBody{e1, nu1}, ElasticBody{e2, nu2}};
}

// Soft on hard, hard on soft, an auxetic layer, a nearly incompressible one,
// and moduli a thousand times apart either way.
std::vector<LayeredMaterial> material_pairs(double t) {
  return {coating(t, 2e9, 0.4, 200e9, 0.3),  coating(t, 400e9, 0.25, 100e9, 0.35), coating(t, 50e9, -0.5, 70e9, 0.2),
          coating(t, 1e7, 0.4999, 1e9, 0.3), coating(t, 1e12, 0.3, 1e9, 0.3),      coating(t, 1e9, 0.3, 1e12, 0.5)};
}

// Wavevectors with |k| = q in three directions (along x, along y, oblique).
std::vector<std::array<double, 2>> wavevectors(double q) {
  return {{q, 0.0}, {0.0, -q}, {0.6 * q, -0.8 * q}};
}

// The in-plane strains (xx, yy, xy) of a stress by Hooke's law: continuous
// across a bonded interface.
std::array<std::complex<double>, 3> in_plane_strain(const std::array<std::complex<double>, kComponentCount>& s,
                                                    const ElasticBody& body) {
  const double e = body.youngs_modulus;
  const double nu = body.poissons_ratio;
  return {(s[0] - nu * (s[1] + s[2])) / e, (s[1] - nu * (s[0] + s[2])) / e, s[3] * (1.0 + nu) / e};
}

TEST(LayeredFourierStressTest, IdenticalMaterialsGiveTheHomogeneousStresses) {
  // Exact algebra on multipliers of size 1: a few hundred eps.
  constexpr double kRoundoff = 1e-13;
  const double t = 1e-6;
  for (const double nu : {0.3, -0.4, 0.5}) {
    const LayeredFourierStress layered(coating(t, 210e9, nu, 210e9, nu));
    for (const double s : {1e-5, 0.3, 1.0, 1.0001, 4.0, 60.0}) {
      const double q = s / t;
      const LayeredMode mode = layered.solve(q);
      double worst = 0.0;
      for (const double depth_ratio : {0.0, 0.25, 0.999, 1.0, 1.5, 7.0}) {
        const double z = depth_ratio * t;
        const Body body = layered.body_at(z);
        for (const auto& [kx, ky] : wavevectors(q)) {
          const auto expected = fourier_stress(kx, ky, z, nu);
          const auto got = layered.stress(kx, ky, layered.profile(mode, z, body), body);
          for (std::size_t c = 0; c < kComponentCount; ++c) worst = std::max(worst, std::abs(got[c] - expected[c]));
        }
      }
      EXPECT_LT(worst, kRoundoff) << "nu = " << nu << ", q t = " << s;
    }
  }
}

TEST(LayeredFourierStressTest, SurfaceDisplacementEqualsTheLayeredKernel) {
  // Two independent solutions of the same conditions (Stanley & Kato's closed
  // form and this 6 x 6 solve): round-off amplified by the system's condition,
  // largest for a stiff layer on a soft substrate at small q t.
  constexpr double kAgreement = 1e-11;  // measured 4e-14
  const double t = 2e-6;
  double worst = 0.0;
  for (const LayeredMaterial& material : material_pairs(t)) {
    const LayeredFourierStress layered(material);
    const kernels::LayeredKernel kernel(material);
    for (const double s : {1e-4, 1e-2, 0.5, 1.0, 1.01, 3.0, 20.0, 200.0}) {
      const double q = s / t;
      const double expected = kernel.spectrum(q);
      const double got = layered.surface_displacement(layered.solve(q));
      EXPECT_NEAR(got / expected, 1.0, kAgreement) << "E1 = " << material.layer.youngs_modulus
                                                   << ", E2 = " << material.substrate.youngs_modulus << ", q t = " << s;
      worst = std::max(worst, std::abs(got / expected - 1.0));
    }
  }
  std::printf("surface displacement against the layered kernel: largest relative difference %.3g\n", worst);
}

TEST(LayeredFourierStressTest, SurfaceIsLoadedByThePressureOnlyAndTheInterfaceIsBonded) {
  // The conditions the solve imposes, read back from the evaluated stresses:
  // round-off relative to the largest stress of the mode.
  constexpr double kRoundoff = 1e-10;
  const double t = 1e-6;
  for (const LayeredMaterial& material : material_pairs(t)) {
    const LayeredFourierStress layered(material);
    for (const double s : {1e-3, 0.2, 1.0, 2.5, 30.0}) {
      const double q = s / t;
      const LayeredMode mode = layered.solve(q);
      for (const auto& [kx, ky] : wavevectors(q)) {
        const auto top = layered.stress(kx, ky, layered.profile(mode, 0.0, Body::layer), Body::layer);
        EXPECT_NEAR(std::abs(top[2] + 1.0), 0.0, kRoundoff) << "sigma_zz = -p at q t = " << s;
        EXPECT_NEAR(std::abs(top[4]), 0.0, kRoundoff) << "sigma_xz = 0 at q t = " << s;
        EXPECT_NEAR(std::abs(top[5]), 0.0, kRoundoff) << "sigma_yz = 0 at q t = " << s;

        const auto above = layered.stress(kx, ky, layered.profile(mode, t, Body::layer), Body::layer);
        const auto below = layered.stress(kx, ky, layered.profile(mode, t, Body::substrate), Body::substrate);
        double scale = 0.0;
        for (std::size_t c = 0; c < kComponentCount; ++c)
          scale = std::max({scale, std::abs(above[c]), std::abs(below[c])});
        for (const std::size_t c : {2u, 4u, 5u}) {
          EXPECT_NEAR(std::abs(above[c] - below[c]), 0.0, kRoundoff * scale)
              << kComponentNames[c] << " continuous at q t = " << s << ", E1 = " << material.layer.youngs_modulus;
        }
        // The in-plane strain is continuous, so the in-plane stresses jump
        // with the moduli.
        const auto strain_above = in_plane_strain(above, material.layer);
        const auto strain_below = in_plane_strain(below, material.substrate);
        const double strain_scale = scale / std::min(material.layer.youngs_modulus, material.substrate.youngs_modulus);
        for (std::size_t c = 0; c < 3; ++c) {
          EXPECT_NEAR(std::abs(strain_above[c] - strain_below[c]), 0.0, kRoundoff * strain_scale)
              << "in-plane strain " << c << " at q t = " << s << ", E1 = " << material.layer.youngs_modulus;
        }
      }
    }
  }
}

TEST(LayeredFourierStressTest, ThickLayerIsTheLayerAndThinLayerIsTheSubstrate) {
  // t -> inf: the substrate's influence near the surface falls like
  // exp(-2 q t) (1e-35 at q t = 40): round-off. t -> 0: the layer's is of
  // order q t (1e-8 here) times the modulus contrast (100).
  constexpr double kRoundoff = 1e-13;
  constexpr double kThinLayer = 1e-5;
  const ElasticBody steel{210e9, 0.3};
  const ElasticBody polymer{2.1e9, 0.42};
  {
    const double q = 1e6;
    const double t = 40.0 / q;
    const LayeredFourierStress layered(LayeredMaterial{t, polymer, steel});
    const LayeredMode mode = layered.solve(q);
    for (const double z : {0.0, 0.3 / q, 2.0 / q, 6.0 / q}) {
      for (const auto& [kx, ky] : wavevectors(q)) {
        const auto expected = fourier_stress(kx, ky, z, polymer.poissons_ratio);
        const auto got = layered.stress(kx, ky, layered.profile(mode, z, Body::layer), Body::layer);
        for (std::size_t c = 0; c < kComponentCount; ++c) {
          EXPECT_NEAR(std::abs(got[c] - expected[c]), 0.0, kRoundoff) << kComponentNames[c] << " at q z = " << q * z;
        }
      }
    }
  }
  {
    const double q = 1e3;  // t = 1e-11 m, inside the accepted range
    const double t = 1e-8 / q;
    const LayeredFourierStress layered(LayeredMaterial{t, steel, polymer});
    const LayeredMode mode = layered.solve(q);
    for (const double z : {0.1 / q, 1.0 / q, 3.0 / q}) {
      for (const auto& [kx, ky] : wavevectors(q)) {
        const auto expected = fourier_stress(kx, ky, z, polymer.poissons_ratio);
        const auto got = layered.stress(kx, ky, layered.profile(mode, z, Body::substrate), Body::substrate);
        for (std::size_t c = 0; c < kComponentCount; ++c) {
          EXPECT_NEAR(std::abs(got[c] - expected[c]), 0.0, kThinLayer) << kComponentNames[c] << " at q z = " << q * z;
        }
      }
    }
  }
}

TEST(LayeredFourierStressTest, MeanModeIsTheConfinedBodyOfEachMaterial) {
  const LayeredFourierStress layered(coating(1e-6, 2e9, 0.4, 200e9, 0.25));
  const LayeredMode mode = layered.solve(0.0);
  for (const Body body : {Body::layer, Body::substrate}) {
    const double nu = body == Body::layer ? 0.4 : 0.25;
    const auto s = layered.stress(0.0, 0.0, layered.profile(mode, 2e-6, body), body);
    EXPECT_EQ(s[2], -1.0);
    EXPECT_DOUBLE_EQ(s[0].real(), -nu / (1.0 - nu));
    EXPECT_DOUBLE_EQ(s[1].real(), -nu / (1.0 - nu));
    EXPECT_EQ(s[3], 0.0);
  }
}

}  // namespace
}  // namespace halfspace::stress
