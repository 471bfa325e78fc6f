// Load control of the adhesive solver: the secant search on the approach
// reproduces a displacement-controlled equilibrium, and a pull beyond the
// pull-off force is reported as not converged, not answered with a jump.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "halfspace/solvers/adhesive_contact_solver.hpp"

namespace halfspace {
namespace {

using solvers::AdhesiveContactSolver;
using solvers::AdhesiveSolverOptions;

// The force target is met to the search's relative tolerance 1e-6; the
// approach that carries it then agrees with the displacement-controlled one
// to the solver's tolerance (1e-6 of the pressure scale) over the contact
// stiffness, well inside 1e-4 of the approach unit.
constexpr double kApproachTolerance = 1e-4;

struct Case {
  Grid grid;
  std::vector<double> gap;
  AdhesionLaw law;
  double unit;  // ell^2 / R
};

// A paraboloid (R = 1 m, E* = 1 Pa) with the exponential law, w = 1e-4 J/m^2,
// rho = ell^2 / R: a DMT-like, smooth loading branch.
Case paraboloid(Boundary boundary) {
  const double ell = std::cbrt(std::numbers::pi * 1e-4 / (4.0 / 3.0));
  const std::size_t n = 48;
  const double dx = 4.0 * ell / static_cast<double>(n);
  Grid grid = Grid::plane(n, n, dx, dx, boundary);
  std::vector<double> gap(grid.size());
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t i = 0; i < n; ++i) {
      const double x = (static_cast<double>(i) + 0.5 - 0.5 * static_cast<double>(n)) * dx;
      const double y = (static_cast<double>(j) + 0.5 - 0.5 * static_cast<double>(n)) * dx;
      gap[j * n + i] = (x * x + y * y) / 2.0;
    }
  }
  return {grid, gap, AdhesionLaw::exponential(1e-4, ell * ell), ell * ell};
}

AdhesiveContactSolver make_solver(const Case& c) {
  AdhesiveSolverOptions options;
  options.law = c.law;
  return AdhesiveContactSolver(c.grid, 1.0, options);
}

void expect_force_control_matches_displacement_control(Boundary boundary) {
  const Case c = paraboloid(boundary);
  AdhesiveContactSolver reference_solver = make_solver(c);
  // The displacement-controlled path to 0.6 units, in steps.
  SolveResult reference;
  for (const double a : {0.0, 0.2, 0.4, 0.6}) {
    std::span<const double> start;
    if (reference.pressure.size() > 0) start = {reference.pressure.data(), c.grid.size()};
    reference = reference_solver.solve(c.gap, Loading::approach(a * c.unit), start);
    ASSERT_TRUE(reference.converged()) << reference.message;
  }
  AdhesiveContactSolver solver = make_solver(c);
  const SolveResult result = solver.solve(c.gap, Loading::force(reference.total_force));
  ASSERT_TRUE(result.converged()) << result.message;
  EXPECT_NEAR(result.total_force, reference.total_force, 1e-5 * std::abs(reference.total_force));
  EXPECT_NEAR(result.approach, reference.approach, kApproachTolerance * c.unit);
  // Mean pressure is the force over the domain.
  AdhesiveContactSolver again = make_solver(c);
  const SolveResult by_pressure = again.solve(c.gap, Loading::mean_pressure(reference.mean_pressure));
  ASSERT_TRUE(by_pressure.converged()) << by_pressure.message;
  EXPECT_NEAR(by_pressure.approach, reference.approach, kApproachTolerance * c.unit);
}

TEST(AdhesionLoadControlTest, ForceControlFindsTheDisplacementControlledStateFree) {
  expect_force_control_matches_displacement_control(Boundary::free);
}

TEST(AdhesionLoadControlTest, ForceControlFindsTheDisplacementControlledStatePeriodic) {
  expect_force_control_matches_displacement_control(Boundary::periodic);
}

TEST(AdhesionLoadControlTest, PullBeyondPullOffIsReportedNotSolved) {
  const Case c = paraboloid(Boundary::free);
  AdhesiveContactSolver solver = make_solver(c);
  // pi w R is the scale of any pull-off (JKR 1.5, DMT 2 of it): 5 pi w R is out of reach.
  const SolveResult result = solver.solve(c.gap, Loading::force(-5.0 * std::numbers::pi * c.law.work));
  EXPECT_FALSE(result.converged());
  EXPECT_NE(result.message.find("displacement control"), std::string::npos) << result.message;
}

}  // namespace
}  // namespace halfspace
