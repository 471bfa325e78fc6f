// The reproduction of Table 1 of the seed paper: the test data and their
// line-contact reading, agreement of Lemke, LCPquad and Polonsky-Keer on all
// four tests, force balance, and the Hertz peak and half-width on tests 1-3.
#include "halfspace/paper/table1.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "halfspace/error.hpp"
#include "halfspace/paper/reproduction.hpp"

namespace halfspace {
namespace {

// Agreement between methods, over the Hertz maximum (the figures):
// LCPquad stops at an interior-point tolerance; Lemke is exact to rounding
// and Polonsky-Keer runs to residual 1e-12.
constexpr double kLcpQuadAgreement = 1e-6;
constexpr double kLemkeVsPk = 1e-8;
// Force balance: an equality constraint (dense) or a rescaling (PK).
constexpr double kForceTolerance = 1e-10;  // relative
// Discretisation error of the peak with 40-150 nodes in contact.
constexpr double kPeakTolerance = 1e-3;  // relative to p_H

TEST(Table1Test, HoldsThePapersData) {
  const auto& tests = paper::table1();
  ASSERT_EQ(tests.size(), 4U);
  EXPECT_EQ(tests[0].nodes, 129U);
  EXPECT_EQ(tests[1].nodes, 500U);
  EXPECT_EQ(tests[2].nodes, 500U);
  EXPECT_EQ(tests[3].nodes, 7U);
  EXPECT_EQ(tests[2].radius2, 0.0005);
  EXPECT_EQ(tests[1].youngs_modulus, 82.7e9);
  EXPECT_EQ(tests[3].poissons_ratio, 0.293);
  EXPECT_THROW(paper::table1_test(5), InputError);
}

TEST(Table1Test, ReadsEachTestAsALineContact) {
  const paper::LineContact c = paper::line_contact(paper::table1_test(1), 1e5);
  // R = R1 R2 / (R1 + R2), E* = E / (2 (1 - nu^2)) for two equal bodies.
  EXPECT_DOUBLE_EQ(c.radius, 0.05 * 0.03 / 0.08);
  EXPECT_NEAR(c.e_star, 210e9 / (2.0 * (1.0 - 0.09)), 1e-6 * c.e_star);
  // Nodes at both ends of [-4e-4, 4e-4] m.
  EXPECT_DOUBLE_EQ(c.x.front(), -4e-4);
  EXPECT_NEAR(c.x.back(), 4e-4, 1e-18);
  EXPECT_DOUBLE_EQ(c.grid.dx(), 8e-4 / 128.0);
  EXPECT_NEAR(c.initial_gap[64], 0.0, 1e-24);  // the middle node is x = 0
  EXPECT_DOUBLE_EQ(c.initial_gap[0], 4e-4 * 4e-4 / (2.0 * c.radius));
  // Hertz: b = sqrt(4 W R / (pi E*)), p_H = 2 W / (pi b).
  const double b = std::sqrt(4.0 * 1e5 * c.radius / (std::numbers::pi * c.e_star));
  EXPECT_DOUBLE_EQ(c.hertz.half_width, b);
  EXPECT_DOUBLE_EQ(c.hertz.peak, 2.0 * 1e5 / (std::numbers::pi * b));
}

// Where two methods' pressures differ most (m).
double worst_x(const paper::TestReproduction& run, const SolveResult& a, const SolveResult& b) {
  Eigen::Index where = 0;
  (a.pressure - b.pressure).abs().maxCoeff(&where);
  return run.contact.x[static_cast<std::size_t>(where)];
}

class Table1Reproduction : public ::testing::TestWithParam<int> {};

TEST_P(Table1Reproduction, MethodsAgreeAndMatchHertz) {
  const paper::TestReproduction run = paper::reproduce(paper::table1_test(GetParam()), {});
  const paper::LineContact& c = run.contact;
  ASSERT_TRUE(run.all_converged()) << run.lemke.message << run.lcpquad.message << run.pk.message;
  const double p_h = c.hertz.peak;
  std::printf(
      "test %d: Lemke-LCPquad %.2e, Lemke-PK %.2e, LCPquad-PK %.2e; peak %.6f p_H; a - b = %.3f dx; "
      "%d pivots, %d IPM iterations\n",
      GetParam(), run.lemke_vs_lcpquad, run.lemke_vs_pk, run.lcpquad_vs_pk, run.lemke.max_pressure / p_h,
      (paper::contact_half_width(run.lemke, c.grid.dx()) - c.hertz.half_width) / c.grid.dx(),
      run.lemke_report.iterations, run.lcpquad_report.iterations);

  EXPECT_LE(run.lemke_vs_lcpquad, kLcpQuadAgreement) << "at x = " << worst_x(run, run.lemke, run.lcpquad);
  EXPECT_LE(run.lcpquad_vs_pk, kLcpQuadAgreement) << "at x = " << worst_x(run, run.lcpquad, run.pk);
  EXPECT_LE(run.lemke_vs_pk, kLemkeVsPk) << "at x = " << worst_x(run, run.lemke, run.pk);
  for (const SolveResult* result : {&run.lemke, &run.lcpquad, &run.pk}) {
    EXPECT_NEAR(result->total_force, c.load, kForceTolerance * c.load) << result->solver;
  }
  // Lemke reports a solution and its pivots, LCPquad an objective of zero.
  EXPECT_EQ(run.lemke_report.status, solvers::LcpStatus::solved);
  EXPECT_GT(run.lemke_report.iterations, 0);
  EXPECT_NEAR(run.lcpquad_report.objective, 0.0, kLcpQuadAgreement);

  if (GetParam() <= 3) {  // test 4 has 3 nodes in contact: no Hertz check
    for (const SolveResult* result : {&run.lemke, &run.lcpquad, &run.pk}) {
      EXPECT_NEAR(result->max_pressure, p_h, kPeakTolerance * p_h) << result->solver;
      EXPECT_LE(std::abs(paper::contact_half_width(*result, c.grid.dx()) - c.hertz.half_width), c.grid.dx())
          << result->solver;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllFourTests, Table1Reproduction, ::testing::Values(1, 2, 3, 4));

TEST(Table1Test, UnscaledQpWithTheLoadReturnsTheUniformPressure) {
  // docs/paper.md: in SI units the influence coefficients (1e-16 m/Pa) are
  // numerically invisible next to the load row, and the QP stays at the
  // uniform pressure W / L that satisfies the load: a flat curve.
  paper::ReproductionOptions options;
  options.unscaled_qp = true;
  const paper::TestReproduction run = paper::reproduce(paper::table1_test(3), options);
  ASSERT_EQ(run.extras.size(), 2U);
  const paper::ExtraPressure& si = run.extras[0];
  EXPECT_EQ(si.column, "p_lcpquad_si");
  const double uniform = run.contact.load / run.contact.grid.domain_area();
  const double spread = (si.pressure - uniform).abs().maxCoeff() / uniform;
  std::printf("SI LCPquad with load: %s, spread %.2e of W/L = %.4f p_H\n",
              std::string(to_string(si.lcp.status)).c_str(), spread, uniform / run.contact.hertz.peak);
  EXPECT_LT(spread, 1e-3);                            // flat to within 0.1 %
  EXPECT_GT(run.lemke.max_pressure, 10.0 * uniform);  // far from the solution
}

}  // namespace
}  // namespace halfspace
