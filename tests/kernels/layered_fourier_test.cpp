// The coated half-space's kernel (layered_fourier.hpp): its compliance factor
// against a direct solution of the layer's elasticity equations, its limits,
// and the validation of the material.
#include "halfspace/kernels/layered_fourier.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <string>

#include "halfspace/error.hpp"
#include "support/layered_navier_solve.hpp"

namespace halfspace {
namespace {

using kernels::LayeredKernel;

LayeredMaterial coating(double t, double e1, double nu1, double e2, double nu2) {
  return LayeredMaterial{t, ElasticBody{e1, nu1}, ElasticBody{e2, nu2}};
}

// The compliance factor M = W(0) E1* q / (2 p) of the direct plane-strain
// solve (support/layered_navier_solve.hpp), q = 1/m, p = 1 Pa.
double direct_compliance_factor(double t, double e1, double nu1, double e2, double nu2) {
  const double surface_w = testing::layered_surface_displacement(coating(t, e1, nu1, e2, nu2), 1.0, 0.0)[1];
  return surface_w * e1 / (1 - nu1 * nu1) / 2.0;
}

// The direct 6 x 6 solve, condition number up to 1e5: 1e-11 at worst.
constexpr double kDirectSolveTolerance = 1e-10;

TEST(LayeredFourierTest, CompliancefactorMatchesDirectSolutionOfTheLayer) {
  const std::array<std::array<double, 4>, 5> materials = {{
      {1e9, 0.3, 2e11, 0.25},   // polymer on steel
      {4e11, 0.2, 1e11, 0.35},  // hard coating
      {1e7, 0.45, 2e11, 0.3},   // rubber on steel
      {1e9, -0.5, 3e9, 0.1},    // auxetic layer
      {2e11, 0.0, 7e10, 0.49},  // nearly incompressible substrate
  }};
  double worst = 0.0;
  for (const auto& m : materials) {
    for (const double s : {0.01, 0.1, 0.5, 1.0, 2.6, 5.0}) {
      const LayeredKernel kernel(coating(s, m[0], m[1], m[2], m[3]));
      const double direct = direct_compliance_factor(s, m[0], m[1], m[2], m[3]);
      const double error = std::abs(kernel.compliance_factor(1.0) - direct) / direct;
      worst = std::max(worst, error);
      EXPECT_LE(error, kDirectSolveTolerance) << "E1 = " << m[0] << ", E2 = " << m[2] << ", q t = " << s;
    }
  }
  std::printf("layered compliance factor: largest relative difference from the direct solution %.2e\n", worst);
}

// A few roundings in kappa, lambda and the quotient.
constexpr double kRoundingTolerance = 1e-15;

TEST(LayeredFourierTest, IdenticalMaterialsGiveTheHomogeneousKernel) {
  const LayeredKernel kernel(coating(1e-6, 2.1e11, 0.29, 2.1e11, 0.29));
  for (const double q : {1.0, 1e4, 1e6, 3e6, 1e8}) {
    EXPECT_NEAR(kernel.compliance_factor(q), 1.0, 4 * kRoundingTolerance) << "q = " << q;
    const double homogeneous = 2.0 / (kernel.layer_modulus() * q);
    EXPECT_NEAR(kernel.spectrum(q), homogeneous, 4 * kRoundingTolerance * homogeneous);
  }
  EXPECT_EQ(kernel.spectrum(0.0), 0.0);
}

TEST(LayeredFourierTest, ThickLayerIsTheLayerAndThinLayerIsTheSubstrate) {
  for (const auto& [e1, e2] : {std::array{1e9, 2e11}, std::array{4e11, 1e11}, std::array{1e5, 1e12}}) {
    const LayeredKernel kernel(coating(1e-6, e1, 0.3, e2, 0.25));
    const double ratio = kernel.layer_modulus() / kernel.substrate_modulus();
    // q t = 40: the layer terms are e^{-80} q t^2 small.
    EXPECT_NEAR(kernel.compliance_factor(4e7), 1.0, 4 * kRoundingTolerance);
    // q t = 1e-12: M = E1*/E2* + m1 q t, with |m1| = dM/ds(0) below 5 for
    // these pairs (0.41, -4.5, 0.41 in 50-digit arithmetic).
    EXPECT_NEAR(kernel.compliance_factor(1e-6), ratio, 5e-12 + 4 * kRoundingTolerance * ratio)
        << "E1 = " << e1 << ", E2 = " << e2;
    // The factor moves monotonically between the two limits.
    double previous = kernel.compliance_factor(1e-6);
    for (double q = 1e3; q <= 1e8; q *= 1.5) {
      const double m = kernel.compliance_factor(q);
      if (ratio < 1.0) {
        EXPECT_GE(m, previous * (1 - kRoundingTolerance));
      } else {
        EXPECT_LE(m, previous * (1 + kRoundingTolerance));
      }
      previous = m;
    }
  }
}

// M in 60-digit arithmetic (mpmath) for extreme pairs, E1/E2 = 1e-7 and 1e7,
// and a polymer on steel: the evaluation without cancellation near q t = 0.
struct ExactValue {
  double e1, nu1, e2, nu2, s, m;
};
constexpr ExactValue kExactValues[] = {
    {1e5, 0.49, 1e12, 0.2, 1e-9, 1.2637085881971053334e-7},   {1e5, 0.49, 1e12, 0.2, 1e-6, 1.6477907237594595439e-7},
    {1e5, 0.49, 1e12, 0.2, 1e-3, 0.000038573583646970415394}, {1e5, 0.49, 1e12, 0.2, 0.3, 0.025317025337580745837},
    {1e5, 0.49, 1e12, 0.2, 3, 0.89055668111023874956},        {1e12, 0.2, 1e5, 0.49, 1e-9, 7915577.571518613045},
    {1e12, 0.2, 1e5, 0.49, 1e-6, 7912762.3613052951231},      {1e12, 0.2, 1e5, 0.49, 1e-3, 7902004.1065452763904},
    {1e12, 0.2, 1e5, 0.49, 0.3, 226.27042695840727678},       {1e12, 0.2, 1e5, 0.49, 3, 1.1368110287243082632},
    {3e9, 0.35, 2.1e11, 0.29, 1e-9, 0.01491086726110808896},  {3e9, 0.35, 2.1e11, 0.29, 1e-6, 0.014911217152041388755},
    {3e9, 0.35, 2.1e11, 0.29, 1e-3, 0.015261104485206015563}, {3e9, 0.35, 2.1e11, 0.29, 0.3, 0.12183516444006413156},
    {3e9, 0.35, 2.1e11, 0.29, 3, 0.92634810310869284491},
};
// Rounding of kappa and lambda, amplified by the 1/((1 - lambda)(1 - kappa))
// of a 1e7 modulus ratio.
constexpr double kExtremePairTolerance = 1e-9;

TEST(LayeredFourierTest, MatchesHighPrecisionValuesForExtremeModulusRatios) {
  for (const ExactValue& v : kExactValues) {
    const LayeredKernel kernel(coating(1.0, v.e1, v.nu1, v.e2, v.nu2));
    EXPECT_NEAR(kernel.compliance_factor(v.s), v.m, kExtremePairTolerance * v.m)
        << "E1 = " << v.e1 << ", E2 = " << v.e2 << ", q t = " << v.s;
  }
}

void expect_input_error(const LayeredMaterial& material, const std::string& expected) {
  try {
    const LayeredKernel kernel(material);
    ADD_FAILURE() << "no error for " << expected;
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
  }
}

TEST(LayeredFourierTest, RefusesOutOfRangeMaterialNamingTheQuantity) {
  expect_input_error(coating(0.0, 1e9, 0.3, 2e11, 0.3),
                     "layer thickness t = 0 m is invalid: allowed range is [1e-12, 1000] m");
  expect_input_error(coating(NAN, 1e9, 0.3, 2e11, 0.3), "layer thickness t = nan m");
  expect_input_error(coating(1e-6, 10.0, 0.3, 2e11, 0.3),
                     "layer Young's modulus E1 = 10 Pa is invalid: allowed range is [1000, 1e+15] Pa");
  expect_input_error(coating(1e-6, 1e9, 0.6, 2e11, 0.3),
                     "layer Poisson's ratio nu1 = 0.6 is invalid: allowed range is (-1, 0.5]");
  expect_input_error(coating(1e-6, 1e9, 0.3, 1e16, 0.3), "substrate Young's modulus E2 = 1e+16 Pa is invalid");
  expect_input_error(coating(1e-6, 1e9, 0.3, 2e11, -1.0), "substrate Poisson's ratio nu2 = -1 is invalid");
}

}  // namespace
}  // namespace halfspace
