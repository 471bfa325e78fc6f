// The coated half-space's tangential and coupling symbols
// (layered_tangential_fourier.hpp): against a direct solution of Navier's
// equations per mode (plane strain and antiplane), Betti's reciprocity, the
// normal kernel's closed form, and the homogeneous Cerruti symbols in the
// limits t -> 0, t -> inf and equal moduli.
#include "halfspace/kernels/layered_tangential_fourier.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "halfspace/kernels/coupling_fourier.hpp"
#include "halfspace/kernels/layered_fourier.hpp"
#include "halfspace/kernels/tangential_fourier.hpp"
#include "support/layered_navier_solve.hpp"

namespace halfspace {
namespace {

using kernels::LayeredTangentialKernel;

LayeredMaterial coating(double t, double e1, double nu1, double e2, double nu2) {
  return LayeredMaterial{t, ElasticBody{e1, nu1}, ElasticBody{e2, nu2}};
}

double shear_modulus(double e, double nu) {
  return e / (2.0 * (1.0 + nu));
}

// The antiplane mode's u_y(0) (m) under a unit shear across q (q = 1/m).
double direct_antiplane_displacement(const LayeredMaterial& m) {
  return testing::solve_layered_antiplane(m, 1.0).at(0.0, true)[0];
}

// A homogeneous body's four compliances times q (layered_tangential_fourier.hpp).
kernels::LayeredModeCompliance homogeneous(const ElasticBody& b) {
  const double g = shear_modulus(b.youngs_modulus, b.poissons_ratio);
  const double nu = b.poissons_ratio;
  return {(1 - nu) / g, (1 - nu) / g, 1 / g, (1 - 2 * nu) / g, (1 - 2 * nu) / g};
}

double relative_error(const kernels::LayeredModeCompliance& a, const kernels::LayeredModeCompliance& b) {
  const double scale = std::max({std::abs(b.normal), std::abs(b.longitudinal), std::abs(b.transverse)});
  return std::max({std::abs(a.normal - b.normal), std::abs(a.longitudinal - b.longitudinal),
                   std::abs(a.transverse - b.transverse), std::abs(a.coupling - b.coupling),
                   std::abs(a.coupling_transpose - b.coupling_transpose)}) /
         scale;
}

constexpr std::array<std::array<double, 4>, 5> kMaterials = {{
    {1e9, 0.3, 2e11, 0.25},   // polymer on steel
    {4e11, 0.2, 1e11, 0.35},  // hard coating
    {1e7, 0.45, 2e11, 0.3},   // rubber on steel
    {1e9, -0.5, 3e9, 0.1},    // auxetic layer
    {2e11, 0.0, 7e10, 0.49},  // nearly incompressible substrate
}};
constexpr std::array<double, 7> kThicknesses = {1e-3, 0.01, 0.1, 0.5, 1.0, 2.6, 5.0};  // q t at q = 1/m

// The direct 6 x 6 solve's condition number reaches 1e5 (as in
// layered_fourier_test): 1e-10 of the compliance scale.
constexpr double kDirectSolveTolerance = 1e-10;

TEST(LayeredTangentialFourierTest, DirectSolverGivesCerrutiForAHomogeneousBody) {
  // The reference's own sign convention, fixed on the homogeneous body:
  // W(0) = (1 - nu)/G per p, U(0) = (1 - nu)/G per shear, and the cross
  // terms -(1 - 2 nu)/(2 G) (Johnson 1985, sec. 2.2, 3.2; its x axis is
  // the reverse of coupling_fourier.hpp's relative sense).
  const ElasticBody b{2e11, 0.3};
  const double g = shear_modulus(b.youngs_modulus, b.poissons_ratio);
  const auto pressure =
      testing::layered_surface_displacement(coating(0.5, b.youngs_modulus, 0.3, b.youngs_modulus, 0.3), 1, 0);
  const auto shear =
      testing::layered_surface_displacement(coating(0.5, b.youngs_modulus, 0.3, b.youngs_modulus, 0.3), 0, 1);
  EXPECT_NEAR(pressure[1], 0.7 / g, kDirectSolveTolerance / g);
  EXPECT_NEAR(shear[0], 0.7 / g, kDirectSolveTolerance / g);
  EXPECT_NEAR(pressure[0], -0.2 / g, kDirectSolveTolerance / g);
  EXPECT_NEAR(shear[1], -0.2 / g, kDirectSolveTolerance / g);
}

TEST(LayeredTangentialFourierTest, ModeCompliancesMatchADirectSolutionOfNavierEquations) {
  double worst = 0.0;
  double worst_betti = 0.0;
  for (const auto& m : kMaterials) {
    for (const double t : kThicknesses) {
      const LayeredMaterial material = coating(t, m[0], m[1], m[2], m[3]);
      const LayeredTangentialKernel kernel(material);
      const kernels::LayeredModeCompliance c = kernel.mode_compliance(1.0);
      const auto pressure = testing::layered_surface_displacement(material, 1.0, 0.0);
      const auto shear = testing::layered_surface_displacement(material, 0.0, 1.0);
      // The cross terms in the reference's convention are -D_eff/2 (see the homogeneous test).
      const kernels::LayeredModeCompliance direct{pressure[1], shear[0], direct_antiplane_displacement(material),
                                                  -2.0 * pressure[0], -2.0 * shear[1]};
      worst = std::max(worst, relative_error(c, direct));
      worst_betti = std::max(worst_betti, std::abs(c.coupling - c.coupling_transpose) / c.normal);
      // The normal part is the closed form of layered_fourier.hpp.
      const kernels::LayeredKernel normal(material);
      EXPECT_NEAR(c.normal, normal.spectrum(1.0), kDirectSolveTolerance * c.normal);
    }
  }
  std::printf("coated mode compliances: worst error against the direct solve %.2e, Betti asymmetry %.2e\n", worst,
              worst_betti);
  EXPECT_LE(worst, kDirectSolveTolerance);
  EXPECT_LE(worst_betti, kDirectSolveTolerance);
}

// t -> inf: the layer's half-space; t -> 0: the substrate's; equal moduli:
// the common body's, to rounding (1e-12 relative), or to the O(q t E2/E1)
// the thin layer leaves (q t = 1e-12, E2/E1 up to 2e4: 1e-7).
constexpr double kRoundingTolerance = 1e-12;
constexpr double kThinLayerTolerance = 1e-7;

TEST(LayeredTangentialFourierTest, LimitsAreTheHomogeneousCerrutiSymbols) {
  for (const auto& m : kMaterials) {
    const ElasticBody layer{m[0], m[1]};
    const ElasticBody substrate{m[2], m[3]};
    const LayeredTangentialKernel thick(coating(40.0, m[0], m[1], m[2], m[3]));
    EXPECT_LE(relative_error(thick.mode_compliance(1.0), homogeneous(layer)), kRoundingTolerance);
    const LayeredTangentialKernel thin(coating(1e-12, m[0], m[1], m[2], m[3]));
    EXPECT_LE(relative_error(thin.mode_compliance(1.0), homogeneous(substrate)), kThinLayerTolerance);
    for (const double t : kThicknesses) {
      const LayeredTangentialKernel same(coating(t, m[0], m[1], m[0], m[1]));
      EXPECT_LE(relative_error(same.mode_compliance(1.0), homogeneous(layer)), kRoundingTolerance);
    }
  }
  // The 2x2 and coupling symbols at an oblique wave vector against
  // tangential_fourier and coupling_fourier for the body on a rigid one.
  const ElasticBody steel{2.1e11, 0.3};
  const double g = shear_modulus(steel.youngs_modulus, steel.poissons_ratio);
  const LayeredTangentialKernel same(coating(1e-4, steel.youngs_modulus, 0.3, steel.youngs_modulus, 0.3));
  for (const auto& [qx, qy] : {std::array{3e3, -4e3}, std::array{1e5, 2e4}, std::array{0.0, 7e2}}) {
    const kernels::TangentialCoefficients t = same.tangential(qx, qy);
    const kernels::TangentialCoefficients h = kernels::tangential_spectrum(qx, qy, 1 / g, 0.3 / g);
    const kernels::CouplingCoefficients c = same.coupling(qx, qy);
    const kernels::CouplingCoefficients hc = kernels::coupling_spectrum(qx, qy, 0.4 / g);
    const double scale = std::abs(h.xx) + std::abs(h.yy);
    EXPECT_NEAR(t.xx, h.xx, kRoundingTolerance * scale);
    EXPECT_NEAR(t.yy, h.yy, kRoundingTolerance * scale);
    EXPECT_NEAR(t.xy, h.xy, kRoundingTolerance * scale);
    EXPECT_NEAR(c.x, hc.x, kRoundingTolerance * scale);
    EXPECT_NEAR(c.y, hc.y, kRoundingTolerance * scale);
  }
  const kernels::TangentialCoefficients zero = same.tangential(0.0, 0.0);
  EXPECT_EQ(zero.xx, 0.0);
  EXPECT_EQ(zero.yy, 0.0);
}

}  // namespace
}  // namespace halfspace
