// Polonsky-Keer with the block-deflation coarse correction: the same
// solutions as without it on rough contacts, periodic and free, under load
// and displacement control, from coarse-grid and cold starts, in no more
// iterations; and the solvers and grids it refuses.
#include <gtest/gtest.h>

#include <cstdio>
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

// `name` with the correction on B x B blocks, or none for B = 0.
SolverOptions settings(const std::string& name, std::size_t block) {
  SolverOptions s = testing::test_options(parse_solver_type(name), 1e-12);
  s.deflation.mode = block > 0 ? DeflationOptions::Mode::on : DeflationOptions::Mode::off;
  if (block > 0) s.deflation.block = block;
  return s;
}

struct Case {
  std::string solver;
  Loading loading;
};

class DeflatedSolverTest : public ::testing::TestWithParam<Boundary> {};

TEST_P(DeflatedSolverTest, MatchesTheUndeflatedSolutionInNoMoreIterations) {
  const Grid grid = Grid::plane(256, 256, 1.0, 1.0, GetParam());
  const Eigen::ArrayXd gap = self_affine_gap(grid, 3);
  // About 8 % contact; the approach of the same load from a first solve.
  const Loading load = Loading::mean_pressure(0.004);
  const SolveResult loaded =
      make_solver(grid, kEStar, settings("pk-fourier", 0))->solve({gap.data(), grid.size()}, load);
  ASSERT_TRUE(loaded.converged()) << loaded.message;
  const Loading approach = Loading::approach(loaded.approach);
  for (const Case& c : {Case{"pk-multilevel", load}, Case{"pk-multilevel", approach}, Case{"pk-fourier", load}}) {
    const SolveResult plain =
        make_solver(grid, kEStar, settings(c.solver, 0))->solve({gap.data(), grid.size()}, c.loading);
    const SolveResult deflated =
        make_solver(grid, kEStar, settings(c.solver, 32))->solve({gap.data(), grid.size()}, c.loading);
    ASSERT_TRUE(plain.converged()) << plain.message;
    ASSERT_TRUE(deflated.converged()) << c.solver << ": " << deflated.message;
    expect_contact_conditions(deflated, 1e-9 * gap.maxCoeff());
    const double difference = (deflated.pressure - plain.pressure).abs().maxCoeff() / plain.max_pressure;
    std::printf(
        "%s, %s, %s control: %d iterations (%d K, %d M^-1) deflated against %d (%d K, %d M^-1), max |dp| %.1e\n",
        std::string(to_string(grid.boundary())).c_str(), c.solver.c_str(),
        c.loading.load_controlled() ? "load" : "displacement", deflated.iterations, deflated.operator_applications,
        deflated.preconditioner_applications, plain.iterations, plain.operator_applications,
        plain.preconditioner_applications, difference);
    EXPECT_LE(difference, kSameSolution) << c.solver;
    EXPECT_LE(deflated.iterations, plain.iterations) << c.solver;
    // It joins where the settled iteration is slow without it (pk-multilevel's
    // fine solves here); otherwise the fast rate is reported (pk-fourier's
    // cold solve settles late, at about 0.5 per iteration).
    if (c.solver == "pk-multilevel") {
      EXPECT_GT(deflated.deflation.deflated_iterations, 0);
    }
    EXPECT_TRUE(deflated.deflation.deflated_iterations > 0 ||
                (deflated.deflation.fast_rate > 0.0 && deflated.deflation.fast_rate <= 0.55))
        << c.solver;
  }
}

// A Hertz contact converges fast without the correction (a few tenths per
// iteration), where it would cost more products than it saves: it stays
// off, the rate is reported, and the solve is the undeflated one.
TEST(DeflatedSolverRateTest, StaysOffWhereTheIterationIsFastWithoutIt) {
  const Grid grid = Grid::plane(256, 256, 1e-6 / 3.0, 1e-6 / 3.0, Boundary::free);
  geometry::SurfaceSpec sphere;
  sphere.radius = 1e-4;
  const Eigen::ArrayXd heights = geometry::make_surface_heights(grid, sphere);
  const Eigen::ArrayXd gap = solvers::initial_gap(grid, {heights.data(), grid.size()});
  // Contact radius (3 F R / 4 E*)^(1/3) = 25 um: a third of the domain.
  const Loading load = Loading::force(2.1e-10);
  const SolveResult plain =
      make_solver(grid, kEStar, settings("pk-multilevel", 0))->solve({gap.data(), grid.size()}, load);
  const SolveResult deflated =
      make_solver(grid, kEStar, settings("pk-multilevel", 32))->solve({gap.data(), grid.size()}, load);
  ASSERT_TRUE(plain.converged()) << plain.message;
  ASSERT_TRUE(deflated.converged()) << deflated.message;
  EXPECT_GT(deflated.contact_fraction, 0.1);
  std::printf("Hertz: %d iterations, rate without the correction %.2f\n", deflated.iterations,
              deflated.deflation.fast_rate);
  EXPECT_EQ(deflated.deflation.deflated_iterations, 0);
  EXPECT_GT(deflated.deflation.fast_rate, 0.0);
  EXPECT_LE(deflated.deflation.fast_rate, 0.55);
  EXPECT_EQ(deflated.iterations, plain.iterations);
  EXPECT_EQ(deflated.operator_applications, plain.operator_applications) << "not even K e_0 for the coarse matrix";
  EXPECT_LE((deflated.pressure - plain.pressure).abs().maxCoeff(), 1e-12 * plain.max_pressure);
}

INSTANTIATE_TEST_SUITE_P(Boundaries, DeflatedSolverTest, ::testing::Values(Boundary::periodic, Boundary::free),
                         testing::boundary_param_name);

TEST(DeflatedSolverRefusalTest, RefusesSolversAndGridsWithoutIt) {
  EXPECT_THROW(make_solver(Grid::plane(128, 128, 1.0, 1.0, Boundary::periodic), kEStar, settings("pk", 32)),
               InputError);
  EXPECT_THROW(make_solver(Grid::plane(128, 128, 1.0, 1.0, Boundary::periodic), kEStar, settings("lemke", 32)),
               InputError);
  EXPECT_THROW(make_solver(Grid::plane(128, 64, 1.0, 1.0, Boundary::free), kEStar, settings("pk-fourier", 32)),
               InputError);
  EXPECT_THROW(make_solver(Grid::line(1024, 1.0, Boundary::periodic), kEStar, settings("pk-multilevel", 32)),
               InputError);
  EXPECT_THROW(make_solver(Grid::plane(96, 80, 1.0, 1.0, Boundary::periodic), kEStar, settings("pk-fourier", 32)),
               InputError);
}

TEST(DeflatedSolverDefaultTest, JoinsFrom2048SquaredCellsOnBothBoundaries) {
  // The automatic rule follows the measured break-even
  // (DeflationOptions::kAutomaticFromCells): 2048^2 cells and beyond, either
  // boundary, any shape the block divides.
  const DeflationOptions automatic;
  auto default_deflation = [&](const Grid& grid) { return automatic.automatic_applies(grid); };
  for (const Boundary boundary : {Boundary::periodic, Boundary::free}) {
    EXPECT_TRUE(default_deflation(Grid::plane(2048, 2048, 1e-6, 1e-6, boundary)));
    EXPECT_TRUE(default_deflation(Grid::plane(16384, 256, 1e-6, 1e-6, boundary)));
    EXPECT_FALSE(default_deflation(Grid::plane(1024, 1024, 1e-6, 1e-6, boundary)));
    EXPECT_FALSE(default_deflation(Grid::plane(2048, 2016, 1e-6, 1e-6, boundary)));  // 63 blocks of 32, too few cells
    EXPECT_TRUE(default_deflation(Grid::plane(2080, 2080, 1e-6, 1e-6, boundary)));   // 65 blocks of 32
    EXPECT_FALSE(default_deflation(Grid::plane(2050, 2050, 1e-6, 1e-6, boundary)));  // 32 does not divide 2050
    EXPECT_FALSE(default_deflation(Grid::plane(65536, 64, 1e-6, 1e-6, boundary)));   // 2 blocks across
  }
  EXPECT_FALSE(default_deflation(Grid::line(std::size_t{1} << 23, 1e-6, Boundary::periodic)));
}

}  // namespace
}  // namespace halfspace::solvers
