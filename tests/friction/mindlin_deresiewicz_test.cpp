// A fretting cycle of a sphere (Mindlin & Deresiewicz 1953; Johnson 1985,
// sec. 7.4): loading to Q*, unloading to -Q*, reloading to Q*, similar
// materials. The unloading and reloading branches against Masing's rule
// applied to Cattaneo-Mindlin's loading curve, the energy dissipated per
// cycle against the area of that analytic loop, and the state closing on
// itself after the cycle.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "friction/friction_checks.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/solvers/tangential_solver.hpp"
#include "support/analytic_solutions.hpp"
#include "support/grid_fields.hpp"
#include "support/pk_solvers.hpp"

namespace halfspace {
namespace {

constexpr ElasticBody kSteel{2.1e11, 0.3};
constexpr double kSphereRadius = 0.01;  // m
constexpr double kForce = 10.0;         // N
constexpr double kMu = 0.3;
constexpr double kAmplitude = 0.6;  // Q*/(mu P)
constexpr int kStepsPerBranch = 12;

TEST(MindlinDeresiewicz, FrettingLoopFollowsMasingAndDissipatesItsArea) {
  const ElasticPair pair = ElasticPair::similar(kSteel);
  const auto hertz = testing::hertz_point(kForce, kSphereRadius, pair.composite_modulus());
  const auto [grid, contact] = testing::hertz_sphere_contact(pair, kForce, kSphereRadius, 32);
  ASSERT_TRUE(contact.converged());
  TangentialOperator op(grid, pair);
  solvers::TangentialOptions options;
  options.friction_coefficient = kMu;
  options.max_iterations = 20000;
  TangentialSolver solver(op, options);

  // Cattaneo-Mindlin's loading curve and Masing's branches (Johnson 1985,
  // eqs. 7.42, 7.56-7.57).
  const double limit = kMu * kForce;
  const double g = kSteel.youngs_modulus / (2.0 * (1.0 + kSteel.poissons_ratio));
  const double k = 3.0 * limit / (16.0 * hertz.radius) * 2.0 * (2.0 - kSteel.poissons_ratio) / g;
  auto loading = [&](double q) { return k * (1.0 - std::pow(1.0 - q / limit, 2.0 / 3.0)); };
  const double peak = kAmplitude * limit;
  const double peak_delta = loading(peak);
  auto unloading = [&](double q) { return peak_delta - 2.0 * loading(0.5 * (peak - q)); };
  auto reloading = [&](double q) { return -peak_delta + 2.0 * loading(0.5 * (peak + q)); };
  // The loop's area by Simpson's rule on the analytic branches.
  const int m = 2000;
  double area = 0.0;
  for (int i = 0; i <= m; ++i) {
    const double q = -peak + 2.0 * peak * i / m;
    const double w = i == 0 || i == m ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    area += w * (unloading(q) - reloading(q));
  }
  area *= 2.0 * peak / m / 3.0;

  TangentialState state = TangentialState::unloaded(grid.size());
  const std::span<const double> pressure{contact.pressure.data(), grid.size()};
  TangentialResult first = solver.solve(pressure, TangentialLoading::force(peak), state);
  ASSERT_TRUE(first.converged()) << first.message;
  const TangentialState at_peak = first.state;
  state = first.state;
  double dissipated = 0.0;
  double worst_branch = 0.0;
  int iterations = 0;
  for (int branch = 0; branch < 2; ++branch) {
    for (int step = 1; step <= kStepsPerBranch; ++step) {
      const double fraction = static_cast<double>(step) / kStepsPerBranch;
      const double q = branch == 0 ? peak - 2.0 * peak * fraction : -peak + 2.0 * peak * fraction;
      const TangentialResult r = solver.solve(pressure, TangentialLoading::force(q), state);
      ASSERT_TRUE(r.converged()) << r.message;
      testing::expect_coulomb_conditions(op, contact.pressure, kMu, state, r, 1e-5 * peak_delta, 1e-2);
      const double exact = branch == 0 ? unloading(q) : reloading(q);
      worst_branch = std::max(worst_branch, std::abs(r.state.approach_x - exact) / peak_delta);
      dissipated += r.dissipated_energy;
      iterations += r.iterations;
      state = r.state;
    }
  }
  const double closing = (state.shear_x - at_peak.shear_x).abs().maxCoeff() / (kMu * hertz.peak);
  std::printf(
      "Mindlin-Deresiewicz: branch error %.2e of delta*, dissipated %.4e J against loop area %.4e J "
      "(%.2e), state closes to %.2e mu p0, %.0f iterations per step\n",
      worst_branch, dissipated, area, std::abs(dissipated - area) / area, closing,
      static_cast<double>(iterations) / (2 * kStepsPerBranch));
  // Tolerances: Mindlin's closed form at nu = 0.3 and a/dx = 13 (the
  // loading curve is met to 4e-4 at these cells), and the steps' backward
  // Euler dissipation (ds times the traction at the step's end).
  EXPECT_LE(worst_branch, 5e-3);
  EXPECT_NEAR(dissipated, area, 0.05 * area);
  EXPECT_LE(closing, 1e-3);
}

}  // namespace
}  // namespace halfspace
