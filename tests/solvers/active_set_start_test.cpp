// pk-multilevel with the primal-dual active-set phase on its finest grid
// (active_set_start.hpp): the same solutions as the default solver on rough
// contacts, periodic and free, under load and displacement control and near
// full contact, the phase's work counted in the result; Hertz against the
// analytic contact radius; capped contacts and 1D grids left to
// Polonsky-Keer alone; its options checked.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "halfspace/error.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "support/boundary_param.hpp"
#include "support/contact_checks.hpp"
#include "support/pk_solvers.hpp"
#include "support/rough_gap.hpp"

namespace halfspace::solvers {
namespace {

using testing::expect_contact_conditions;
using testing::self_affine_gap;

constexpr double kEStar = 1.0;
// Two solutions converged to residual 1e-12 differ by rounding-level amounts
// relative to the largest pressure.
constexpr double kSameSolution = 1e-8;

using ActiveSet = MultilevelOptions::ActiveSet;

SolverOptions settings(bool active_set) {
  SolverOptions s = testing::test_options(SolverType::pk_multilevel, 1e-12);
  s.multilevel.active_set = active_set ? ActiveSet::on : ActiveSet::off;
  return s;
}

struct Case {
  const char* what;
  Loading loading;
};

class ActiveSetStartTest : public ::testing::TestWithParam<Boundary> {};

TEST_P(ActiveSetStartTest, MatchesTheDefaultSolverAndCountsItsWork) {
  const Grid grid = Grid::plane(256, 256, 1.0, 1.0, GetParam());
  const Eigen::ArrayXd gap = self_affine_gap(grid, 3);
  // About 8 % contact, and near full contact; the approach of the first
  // load from the default solve.
  const Loading load = Loading::mean_pressure(0.004);
  const SolveResult loaded = make_solver(grid, kEStar, settings(false))->solve({gap.data(), grid.size()}, load);
  ASSERT_TRUE(loaded.converged()) << loaded.message;
  for (const Case& c : {Case{"8 % contact, load control", load},
                        Case{"8 % contact, displacement control", Loading::approach(loaded.approach)},
                        Case{"near full contact", Loading::mean_pressure(0.2)}}) {
    const SolveResult plain = make_solver(grid, kEStar, settings(false))->solve({gap.data(), grid.size()}, c.loading);
    const SolveResult active = make_solver(grid, kEStar, settings(true))->solve({gap.data(), grid.size()}, c.loading);
    ASSERT_TRUE(plain.converged()) << plain.message;
    ASSERT_TRUE(active.converged()) << c.what << ": " << active.message;
    expect_contact_conditions(active, 1e-9 * gap.maxCoeff());
    const double difference = (active.pressure - plain.pressure).abs().maxCoeff() / plain.max_pressure;
    std::printf(
        "%s, %s: %d iterations (%d in %d set updates; %d K, %d M^-1) against %d (%d K, %d M^-1), "
        "contact %.3f, max |dp| %.1e\n",
        std::string(to_string(grid.boundary())).c_str(), c.what, active.iterations, active.active_set_inner,
        active.active_set_outer, active.operator_applications, active.preconditioner_applications, plain.iterations,
        plain.operator_applications, plain.preconditioner_applications, active.contact_fraction, difference);
    EXPECT_LE(difference, kSameSolution) << c.what;
    // The phase ran from the coarse start, and its iterations and products
    // are part of the result's.
    EXPECT_GE(active.active_set_outer, 1) << c.what;
    EXPECT_GE(active.active_set_inner, 1) << c.what;
    // Each set update follows a linear solve of at least min_inner steps.
    EXPECT_GE(active.active_set_inner, ActiveSetOptions{}.min_inner * active.active_set_outer) << c.what;
    EXPECT_GT(active.iterations, active.active_set_inner) << c.what << ": Polonsky-Keer finishes";
    EXPECT_GE(active.operator_applications, active.active_set_inner + active.active_set_outer) << c.what;
  }
}

INSTANTIATE_TEST_SUITE_P(Boundaries, ActiveSetStartTest, ::testing::Values(Boundary::periodic, Boundary::free),
                         testing::boundary_param_name);

// Whether block deflation pays is measured in the phase; Polonsky-Keer,
// finishing on the same contact, keeps that verdict instead of spending
// undeflated iterations measuring it again.
TEST(ActiveSetStartDeflationTest, PolonskyKeerKeepsThePhasesVerdict) {
  const Grid grid = Grid::plane(256, 256, 1.0, 1.0, Boundary::periodic);
  const Eigen::ArrayXd gap = self_affine_gap(grid, 3);
  SolverOptions options = settings(true);
  options.deflation.mode = DeflationOptions::Mode::on;
  const SolveResult result =
      make_solver(grid, kEStar, options)->solve({gap.data(), grid.size()}, Loading::mean_pressure(0.004));
  ASSERT_TRUE(result.converged()) << result.message;
  const int finish = result.iterations - result.active_set_inner;
  std::printf("%d iterations (%d in %d set updates), Polonsky-Keer %d, of them deflated %d, fast rate %g\n",
              result.iterations, result.active_set_inner, result.active_set_outer, finish,
              result.deflation.deflated_iterations, result.deflation.fast_rate);
  ASSERT_EQ(result.deflation.fast_rate, 0.0) << "the correction pays on this contact";
  EXPECT_EQ(result.deflation.deflated_iterations, finish) << "every Polonsky-Keer iteration deflated";
}

// Hertz on a free grid: the contact radius (3 F R / 4 E*)^(1/3) within the
// discretisation error, as the default solver has it.
TEST(ActiveSetStartHertzTest, ReproducesTheHertzContactRadius) {
  const double cell = 1e-6 / 3.0;
  const Grid grid = Grid::plane(256, 256, cell, cell, Boundary::free);
  geometry::SurfaceSpec sphere;
  sphere.radius = 1e-4;
  const Eigen::ArrayXd heights = geometry::make_surface_heights(grid, sphere);
  const Eigen::ArrayXd gap = solvers::initial_gap(grid, {heights.data(), grid.size()});
  const double force = 2.1e-10;
  const SolveResult result =
      make_solver(grid, kEStar, settings(true))->solve({gap.data(), grid.size()}, Loading::force(force));
  ASSERT_TRUE(result.converged()) << result.message;
  expect_contact_conditions(result, 1e-9 * gap.maxCoeff());
  const double radius = std::cbrt(3.0 * force * sphere.radius / (4.0 * kEStar));
  const double area = result.contact_fraction * grid.domain_area();
  const double measured = std::sqrt(area / std::numbers::pi);
  // The contact edge is resolved to a cell: the area's radius within two cells.
  constexpr double kEdgeCells = 2.0;
  std::printf("Hertz: radius %.4e m against %.4e m analytic, %d iterations (%d in %d set updates)\n", measured, radius,
              result.iterations, result.active_set_inner, result.active_set_outer);
  EXPECT_NEAR(measured, radius, kEdgeCells * cell);
}

TEST(ActiveSetStartScopeTest, CappedContactsAndLinesRunPolonskyKeerAlone) {
  // In SI units: the hardness has a physical range. H/E* = 0.1.
  const Grid plane = Grid::plane(128, 128, 1e-6, 1e-6, Boundary::periodic);
  const Eigen::ArrayXd gap = self_affine_gap(plane, 5);
  SolverOptions capped = settings(true);
  capped.interface_law.hardness = 1e8;
  const SolveResult result =
      make_solver(plane, 1e9, capped)->solve({gap.data(), plane.size()}, Loading::mean_pressure(4e6));
  ASSERT_TRUE(result.converged()) << result.message;
  EXPECT_EQ(result.active_set_outer, 0);

  const Grid line = Grid::line(1024, 1.0, Boundary::periodic);
  Eigen::ArrayXd line_gap(static_cast<Eigen::Index>(line.size()));
  for (std::size_t i = 0; i < line.size(); ++i) {
    line_gap[static_cast<Eigen::Index>(i)] = 1.0 - std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / 1024.0);
  }
  const SolveResult one_d =
      make_solver(line, kEStar, settings(true))->solve({line_gap.data(), line.size()}, Loading::mean_pressure(0.01));
  ASSERT_TRUE(one_d.converged()) << one_d.message;
  EXPECT_EQ(one_d.active_set_outer, 0);
}

// The automatic rule (MultilevelOptions::active_set_applies): on from
// 4096^2 cells for a homogeneous, uncapped, periodic 2D contact, where it
// was measured to pay (on one process and on slabs alike: the rule knows no
// layout); off below, on free and 1D grids, with a cap or a coating; on and
// off as asked.
TEST(ActiveSetRuleTest, AutomaticRunsThePhaseWhereItPays) {
  MultilevelOptions options;
  EXPECT_EQ(options.active_set, ActiveSet::automatic);
  const Grid large = Grid::plane(4096, 4096, 1e-6, 1e-6, Boundary::periodic);
  const Grid large_free = Grid::plane(4096, 4096, 1e-6, 1e-6, Boundary::free);
  const Grid oblong = Grid::plane(8192, 2048, 1e-6, 1e-6, Boundary::periodic);
  const Grid below = Grid::plane(4096, 2048, 1e-6, 1e-6, Boundary::periodic);
  const Grid small = Grid::plane(256, 256, 1e-6, 1e-6, Boundary::periodic);
  const Grid line = Grid::line(std::size_t{1} << 24, 1e-6, Boundary::periodic);
  EXPECT_TRUE(options.active_set_applies(large, false, false));
  EXPECT_FALSE(options.active_set_applies(large_free, false, false)) << "free grid";
  EXPECT_TRUE(options.active_set_applies(oblong, false, false));
  EXPECT_FALSE(options.active_set_applies(below, false, false));
  EXPECT_FALSE(options.active_set_applies(small, false, false));
  EXPECT_FALSE(options.active_set_applies(line, false, false));
  EXPECT_FALSE(options.active_set_applies(large, true, false)) << "hardness cap";
  EXPECT_FALSE(options.active_set_applies(large, false, true)) << "coating";

  options.active_set = ActiveSet::off;
  EXPECT_FALSE(options.active_set_applies(large, false, false));

  options.active_set = ActiveSet::on;
  EXPECT_TRUE(options.active_set_applies(small, false, false));
  EXPECT_TRUE(options.active_set_applies(small, false, true)) << "asked for on a coating";
  EXPECT_TRUE(options.active_set_applies(large_free, false, false)) << "asked for on a free grid";
  EXPECT_FALSE(options.active_set_applies(small, true, false)) << "hardness cap";
  EXPECT_FALSE(options.active_set_applies(line, false, false));

  EXPECT_EQ(parse_active_set("automatic"), ActiveSet::automatic);
  EXPECT_EQ(to_string(ActiveSet::on), "on");
  EXPECT_THROW(parse_active_set("yes"), SolverOptionError);
}

// Below the threshold the default (automatic) is the solve without the
// phase, product for product; asked for, the phase runs there too.
TEST(ActiveSetRuleTest, TheDefaultBelowTheThresholdIsTheSolveWithoutThePhase) {
  const Grid grid = Grid::plane(256, 256, 1.0, 1.0, Boundary::periodic);
  const Eigen::ArrayXd gap = self_affine_gap(grid, 3);
  const Loading load = Loading::mean_pressure(0.004);
  SolverOptions automatic = testing::test_options(SolverType::pk_multilevel, 1e-12);
  ASSERT_EQ(automatic.multilevel.active_set, ActiveSet::automatic);
  const SolveResult by_default = make_solver(grid, kEStar, automatic)->solve({gap.data(), grid.size()}, load);
  const SolveResult off = make_solver(grid, kEStar, settings(false))->solve({gap.data(), grid.size()}, load);
  const SolveResult on = make_solver(grid, kEStar, settings(true))->solve({gap.data(), grid.size()}, load);
  ASSERT_TRUE(by_default.converged() && off.converged() && on.converged()) << by_default.message;
  EXPECT_EQ(by_default.active_set_outer, 0);
  EXPECT_EQ(by_default.iterations, off.iterations);
  EXPECT_EQ(by_default.operator_applications, off.operator_applications);
  EXPECT_EQ(by_default.preconditioner_applications, off.preconditioner_applications);
  EXPECT_GE(on.active_set_outer, 1);
}

TEST(ActiveSetOptionsTest, NamesTheOptionItRefuses) {
  auto message_of = [](const ActiveSetOptions& options) {
    try {
      options.validate();
    } catch (const SolverOptionError& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  ActiveSetOptions options;
  EXPECT_EQ(message_of(options), "accepted");
  options.inner_reduction = 1.0;
  EXPECT_NE(message_of(options).find("active_set.inner_reduction"), std::string::npos) << message_of(options);
  options = {};
  options.min_inner = 0;
  EXPECT_NE(message_of(options).find("active_set.min_inner"), std::string::npos) << message_of(options);
  options = {};
  options.max_inner = 0;
  EXPECT_NE(message_of(options).find("active_set.max_inner"), std::string::npos);
  options = {};
  options.max_inner = 1;  // below min_inner, 2
  EXPECT_NE(message_of(options).find("at least active_set.min_inner (2)"), std::string::npos) << message_of(options);
  options = {};
  options.max_outer = 0;
  EXPECT_NE(message_of(options).find("active_set.max_outer"), std::string::npos);
  options = {};
  options.settled_changes = -0.1;
  EXPECT_NE(message_of(options).find("active_set.settled_changes"), std::string::npos);
  SolverOptions solver = settings(true);
  solver.multilevel.active_set_options.max_outer = 0;
  EXPECT_THROW(solver.validate(), SolverOptionError);
}

}  // namespace
}  // namespace halfspace::solvers
