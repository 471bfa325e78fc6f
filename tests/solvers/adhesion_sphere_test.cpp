// The adhesive sphere under displacement control (free boundary): pull-off
// forces against Maugis's curve (adhesion_maugis_reference.hpp) and its DMT
// and JKR limits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "halfspace/analysis/adhesion_sweep.hpp"
#include "halfspace/analysis/load_sweep.hpp"
#include "halfspace/solvers/adhesive_contact_solver.hpp"
#include "solvers/adhesion_maugis_reference.hpp"
#include "solvers/adhesive_sphere.hpp"

namespace halfspace {
namespace {

using solvers::AdhesiveContactSolver;
using solvers::AdhesiveSolverOptions;
using testing::AdhesiveSphere;
using testing::sphere_gap;

constexpr double kPi = std::numbers::pi;

// The pull-off force (in pi w R) of a displacement-controlled sweep over
// `approaches` (in ell^2 / R) on a free grid of `cells_per_ell` cells per
// ell spanning `width` ell: the smallest force of the unloading branch,
// refined by the parabola through it and its neighbours (the force is
// smooth at its minimum).
double pull_off(const AdhesiveSphere& sphere, double cells_per_ell, double width, const std::vector<double>& approaches,
                bool precondition = false) {
  const double dx = sphere.ell() / cells_per_ell;
  const auto n = static_cast<std::size_t>(std::lround(width * cells_per_ell));
  const Grid grid = Grid::plane(n, n, dx, dx, Boundary::free);
  AdhesiveSolverOptions options;
  options.law = sphere.law();
  options.precondition = precondition;
  AdhesiveContactSolver solver(grid, sphere.e_star, options);
  const std::vector<double> gap = sphere_gap(grid, sphere.radius);
  std::vector<double> values;
  for (const double a : approaches) values.push_back(a * sphere.approach_unit());
  analysis::LoadSweepOptions sweep;
  sweep.signed_loads = true;
  const std::vector<analysis::SweepStep> steps =
      analysis::run_load_sweep(solver, grid, gap, ControlMode::approach, values, sweep);
  for (const analysis::SweepStep& step : steps) {
    EXPECT_TRUE(step.result.converged()) << "approach " << step.loading.value << ": " << step.result.message;
  }
  // The unloading branch: from the deepest approach on.
  const auto deepest =
      static_cast<std::size_t>(std::max_element(approaches.begin(), approaches.end()) - approaches.begin());
  std::vector<double> at;
  std::vector<double> forces;
  for (std::size_t k = deepest; k < steps.size(); ++k) {
    at.push_back(approaches[k]);
    forces.push_back(steps[k].result.total_force / sphere.force_unit());
  }
  const double least = analysis::pull_off_force(steps) / sphere.force_unit();
  EXPECT_NEAR(*std::min_element(forces.begin(), forces.end()), least, 1e-12 * std::abs(least));
  return testing::refined_minimum(at, forces);
}

// DMT side, lambda = 0.05: the attraction acts out to c = ell sqrt(4 /
// (pi lambda)) = 5 ell, which 6 cells per ell over 12 ell resolve; the
// pull-off (at the loss of contact) then agrees with Maugis's -1.981 to
// 0.3 % and with DMT's -2 (the lambda -> 0 limit) to 1.3 %.
constexpr double kDmtLambda = 0.05;
constexpr double kDmtMaugisTolerance = 0.015;  // relative: the attracted disc's area on a 6-per-ell grid
constexpr double kDmtLimitTolerance =
    0.03;  // relative: Maugis's own distance from DMT at lambda = 0.05, 1 %, plus the above

void expect_dmt_pull_off(bool precondition) {
  const AdhesiveSphere sphere{kDmtLambda};
  const std::vector<double> approaches{0.0, 0.5, 0.3, 0.1, -0.1, -0.2, -0.3, -0.35, -0.4, -0.5, -0.7};
  const double force = pull_off(sphere, 6.0, 12.0, approaches, precondition);
  const double maugis = testing::maugis::pull_off(kDmtLambda);
  EXPECT_NEAR(force, maugis, kDmtMaugisTolerance * std::abs(maugis)) << "pull-off " << force << " pi w R";
  EXPECT_NEAR(force, -2.0, kDmtLimitTolerance * 2.0) << "DMT: -2 pi w R";
}

TEST(AdhesionSphereTest, PullOffApproachesDmtAtSmallTaborParameter) {
  expect_dmt_pull_off(false);
}
TEST(AdhesionSphereTest, PullOffApproachesDmtAtSmallTaborParameterConjugateGradients) {
  expect_dmt_pull_off(true);
}

// JKR side, lambda = 2 (Maugis -1.535, within 2.3 % of JKR's -3/2). The
// cohesive zone is (3/4) ell / lambda^2 = 0.19 ell wide there; a grid that
// does not resolve it traps the crack edge and overestimates the pull-off,
// by how much depends on the path: on this sweep's steps of 0.05-0.2
// ell^2 / R, SPG -1.644 and -1.568 pi w R at 16 and 32 cells per ell (+7.1 %
// and +2.2 %), the conjugate gradients -1.768 and -1.651 (+15 %, +7.6 %);
// on a quasi-static sweep (steps of 0.01) both give +7-8.5 % on 32 cells per
// ell (SPG -1.643, conjugate gradients -1.665): SPG's long non-monotone
// steps jump over trapped states that a small step keeps, so its closer
// value on this sweep is the path's, not the method's (docs/solvers.md).
// The test checks the convergence and the fine grid against Maugis and
// JKR. (At lambda = 3 the zone is 0.08 ell, and 32 cells per ell still
// leave +8 %: docs/theory.md, "Adhesion".)
constexpr double kJkrLambda = 2.0;
// Relative tolerances against Maugis's value and against -3/2 (Maugis's own
// 2.3 % plus the grid's error), per solver, from the values above.
struct JkrTolerances {
  double maugis;
  double limit;
};
constexpr JkrTolerances kJkrSpg{0.04, 0.06};
constexpr JkrTolerances kJkrConjugateGradients{0.10, 0.13};

void expect_jkr_pull_off(bool precondition, JkrTolerances tolerance) {
  const AdhesiveSphere sphere{kJkrLambda};
  const std::vector<double> approaches{0.2, 0.0, -0.2, -0.4, -0.5, -0.55, -0.6, -0.65, -0.7, -0.75, -0.8, -0.9, -1.0};
  const double coarse = pull_off(sphere, 16.0, 4.0, approaches, precondition);
  const double fine = pull_off(sphere, 32.0, 4.0, approaches, precondition);
  const double maugis = testing::maugis::pull_off(kJkrLambda);
  EXPECT_LT(std::abs(fine - maugis), 0.6 * std::abs(coarse - maugis))
      << "coarse " << coarse << ", fine " << fine << ", Maugis " << maugis;
  EXPECT_NEAR(fine, maugis, tolerance.maugis * std::abs(maugis)) << "coarse " << coarse << ", fine " << fine;
  EXPECT_NEAR(fine, -1.5, tolerance.limit * 1.5) << "JKR: -3/2 pi w R";
}

TEST(AdhesionSphereTest, PullOffConvergesTowardsJkrAtLargerTaborParameter) {
  expect_jkr_pull_off(false, kJkrSpg);
}
TEST(AdhesionSphereTest, PullOffConvergesTowardsJkrAtLargerTaborParameterConjugateGradients) {
  expect_jkr_pull_off(true, kJkrConjugateGradients);
}

// The load-contact-radius relation on the loading branch at lambda = 2: a
// sweep from first touch (approach 0) to 1.5 ell^2 / R in steps of 0.1,
// the force P (in pi w R) at approaches 0.5, 1 and 1.5 against Maugis's
// P(A) at the contact radius A = sqrt(area / pi) / ell of the cells at the
// wall (A = 1.45-1.88 here). JKR's F(a) = 4 E* a^3 / (3R) - sqrt(8 pi w E*
// a^3), P = A^3 - sqrt(6 A^3) in these units, is Maugis's curve as lambda
// -> infinity (checked on the reference below); at lambda = 2 the curve
// still lies 0.3-0.5 pi w R above JKR. Directly at larger lambda the
// Maugis-Dugdale zone (0.75 ell / lambda^2) is below a cell of a unit
// test's grid and traps the edge (at lambda = 5, P 0.6-0.7 pi w R off JKR's
// F(a) at 32 and 64 cells per ell, bench/adhesion_jkr_sphere.py);
// adhesion_jkr_sphere_test.cpp tests JKR directly with the exponential law,
// which converges at about a cell per zone, and the 1D cylinder
// (adhesion_cylinder_test.cpp) with Maugis-Dugdale. The error here is
// dominated by the contact radius the discrete wall set gives: dP/dA is
// about 4, so a radius off by a third of a cell at 16 cells per ell moves P
// by 0.1. Measured largest |P - P_Maugis(A)| over the three steps: 0.51
// and 0.26 pi w R at 8 and 16 cells per ell (adhesive-pcg; SPG 0.51 and
// 0.23).
constexpr double kLoadingBranchTolerance = 0.35;  // pi w R, absolute: the 16-per-ell grid's 0.26 plus margin

// The loading branch of a displacement-controlled sweep from first touch
// (approach 0) to 1.5 ell^2 / R in steps of `step` ell^2 / R on a free grid
// of `cells_per_ell` cells per ell spanning 4 ell: at approaches 0.5, 1 and
// 1.5, the force P (in pi w R) and the contact radius A = sqrt(area / pi) /
// ell of the cells at the wall; the largest |P - reference(A)| over them.
template <class Reference>
double loading_branch_error(const AdhesiveSphere& sphere, double cells_per_ell, double step, Reference&& reference) {
  const double dx = sphere.ell() / cells_per_ell;
  const auto n = static_cast<std::size_t>(std::lround(4.0 * cells_per_ell));
  const Grid grid = Grid::plane(n, n, dx, dx, Boundary::free);
  AdhesiveSolverOptions options;
  options.law = sphere.law();
  AdhesiveContactSolver solver(grid, sphere.e_star, options);
  const std::vector<double> gap = sphere_gap(grid, sphere.radius);
  const auto steps_per_half = static_cast<int>(std::lround(0.5 / step));
  std::vector<double> values;
  for (int k = 0; k <= 3 * steps_per_half; ++k) values.push_back(k * step * sphere.approach_unit());
  analysis::LoadSweepOptions sweep;
  sweep.signed_loads = true;
  const std::vector<analysis::SweepStep> steps =
      analysis::run_load_sweep(solver, grid, gap, ControlMode::approach, values, sweep);
  double worst = 0.0;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const SolveResult& r = steps[k].result;
    EXPECT_TRUE(r.converged()) << "approach " << steps[k].loading.value << ": " << r.message;
    if (k == 0 || k % static_cast<std::size_t>(steps_per_half) != 0) continue;
    const double a = std::sqrt(r.contact_fraction * grid.domain_area() / kPi) / sphere.ell();
    const double p = r.total_force / sphere.force_unit();
    // In contact: the loading branch has jumped in.
    EXPECT_GT(a, 1.0) << "approach " << steps[k].loading.value;
    worst = std::max(worst, std::abs(p - reference(a)));
  }
  return worst;
}

TEST(AdhesionSphereTest, LoadAgainstContactRadiusFollowsMaugisOnLoading) {
  const AdhesiveSphere sphere{kJkrLambda};
  const auto maugis = [&](double a) { return testing::maugis::load(sphere.lambda, a); };
  const double coarse = loading_branch_error(sphere, 8.0, 0.1, maugis);
  const double fine = loading_branch_error(sphere, 16.0, 0.1, maugis);
  EXPECT_LT(fine, 0.8 * coarse) << "coarse " << coarse << ", fine " << fine << " pi w R";
  EXPECT_LT(fine, kLoadingBranchTolerance) << "coarse " << coarse << ", fine " << fine << " pi w R";
}

TEST(AdhesionMaugisReferenceTest, ReachesTheJkrAndDmtLimits) {
  // Independent of the solver: the reference itself, at its two ends.
  EXPECT_NEAR(testing::maugis::pull_off(100.0), -1.5, 1e-3);
  EXPECT_NEAR(testing::maugis::pull_off(1e-3), -2.0, 1e-3);
  // JKR's load at contact radius A: A^3 - sqrt(6 A^3).
  EXPECT_NEAR(testing::maugis::load(1000.0, 1.2), testing::jkr_load(1.2), 1e-2);
}

}  // namespace
}  // namespace halfspace
