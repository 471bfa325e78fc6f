// The hardness cap on the dense path: LCPquad's box-constrained energy QP
// against Polonsky-Keer on the FFT operator, on small grids (1D and 2D,
// free and periodic, sphere and rough patch), and the refusals: Lemke
// (which solves the plain LCP only), a load above H times the domain area,
// a hardness out of range.
#include <gtest/gtest.h>

#include <cstdio>
#include <limits>
#include <span>
#include <string>

#include "halfspace/error.hpp"
#include "halfspace/solvers/lcp_quad.hpp"
#include "halfspace/solvers/lemke.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "hardness_checks.hpp"
#include "support/grid_fields.hpp"
#include "support/pk_solvers.hpp"
#include "support/rough_gap.hpp"

namespace halfspace {
namespace {

using solvers::SolverType;
using testing::field_from;
using testing::test_options;

constexpr double kSpacing = 1e-6;  // m
constexpr double kEStar = 1e11;    // Pa
constexpr double kHardness = 2e9;  // Pa
// Polonsky-Keer at residual 1e-12 against the interior-point method at its
// 1e-12 stopping tolerance (as for the elastic comparison, dense_vs_fft_test).
constexpr double kPkTolerance = 1e-12;
constexpr double kDenseVsPk = 1e-6;  // of the hardness
// Approaches, relative to the height range.
constexpr double kApproachTolerance = 1e-6;

Eigen::ArrayXd sphere_gap(const Grid& grid) {
  return field_from(grid, [](double x, double y) { return (x * x + y * y) / (2.0 * 1e-4); });
}

struct Case {
  const char* what;
  Grid grid;
  Eigen::ArrayXd gap;
  Loading loading;
};

void expect_dense_agrees_with_pk(const Case& c) {
  const std::span<const double> g0(c.gap.data(), c.grid.size());
  solvers::LcpQuad lcpquad(c.grid, kEStar, solvers::LcpQuadOptions{}, {}, solvers::InterfaceLaw{kHardness});
  const SolveResult dense = lcpquad.solve(g0, c.loading);
  solvers::SolverOptions options = test_options(SolverType::pk, kPkTolerance);
  options.interface_law.hardness = kHardness;
  const SolveResult fft = solvers::make_solver(c.grid, kEStar, options)->solve(g0, c.loading);
  ASSERT_TRUE(dense.converged()) << c.what << ": " << dense.message;
  ASSERT_TRUE(fft.converged()) << c.what << ": " << fft.message;
  Eigen::Index worst = 0;
  const double difference = (dense.pressure - fft.pressure).abs().maxCoeff(&worst) / kHardness;
  const double range = c.gap.maxCoeff() - c.gap.minCoeff();
  std::printf("%s: contact %.3f, plastic %.3f (dense %.3f), %d IPM iterations; |LCPquad-PK| / H = %.2e at cell %ld\n",
              c.what, fft.contact_fraction, fft.plastic_fraction, dense.plastic_fraction, dense.iterations, difference,
              static_cast<long>(worst));
  EXPECT_LE(difference, kDenseVsPk) << c.what;
  EXPECT_NEAR(dense.approach, fft.approach, kApproachTolerance * range) << c.what;
  EXPECT_EQ(dense.plastic_fraction, fft.plastic_fraction) << c.what;
  EXPECT_TRUE(dense.hardness.has_value());
  testing::expect_capped_contact_conditions(dense, kHardness, kApproachTolerance * range);
  // The comparison says little unless the cap acts on part of the contact.
  EXPECT_GT(fft.plastic_fraction, 0.0) << c.what;
  EXPECT_LT(fft.plastic_fraction, fft.contact_fraction) << c.what;
}

TEST(HardnessDenseTest, SphereOnFreeGrid) {
  const Grid grid = Grid::plane(16, 16, kSpacing, kSpacing, Boundary::free);
  expect_dense_agrees_with_pk({"free sphere, force", grid, sphere_gap(grid), Loading::force(0.1)});
}

TEST(HardnessDenseTest, SphereOnFreeGridUnderDisplacementControl) {
  const Grid grid = Grid::plane(16, 16, kSpacing, kSpacing, Boundary::free);
  expect_dense_agrees_with_pk({"free sphere, approach", grid, sphere_gap(grid), Loading::approach(2e-7)});
}

TEST(HardnessDenseTest, RoughPatchOnPeriodicGrid) {
  const Grid grid = Grid::plane(16, 16, kSpacing, kSpacing, Boundary::periodic);
  expect_dense_agrees_with_pk(
      {"periodic rough patch", grid, 10.0 * testing::self_affine_gap(grid, 3), Loading::mean_pressure(3e8)});
}

TEST(HardnessDenseTest, RoughProfileOnFreeLine) {
  const Grid grid = Grid::line(256, kSpacing, Boundary::free);
  expect_dense_agrees_with_pk(
      {"free rough line", grid, 10.0 * testing::self_affine_gap(grid, 4), Loading::mean_pressure(3e8)});
}

TEST(HardnessDenseTest, LemkeRefusesAHardness) {
  solvers::SolverOptions options;
  options.type = SolverType::lemke;
  options.interface_law.hardness = kHardness;
  try {
    options.validate();
    FAIL() << "lemke accepted a hardness";
  } catch (const solvers::SolverOptionError& error) {
    EXPECT_EQ(error.option(), "hardness");
    EXPECT_NE(std::string(error.what()).find("lcpquad"), std::string::npos) << error.what();
  }
}

TEST(HardnessDenseTest, LoadAboveTheHardnessTimesTheAreaIsRefused) {
  const Grid grid = Grid::plane(16, 16, kSpacing, kSpacing, Boundary::periodic);
  const Eigen::ArrayXd gap = sphere_gap(grid);
  for (const SolverType type : {SolverType::pk, SolverType::pk_multilevel, SolverType::lcpquad}) {
    solvers::SolverOptions options = test_options(type);
    options.interface_law.hardness = kHardness;
    const auto solver = solvers::make_solver(grid, kEStar, options);
    try {
      solver->solve({gap.data(), grid.size()}, Loading::mean_pressure(1.01 * kHardness));
      FAIL() << to_string(type) << " accepted an infeasible load";
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("infeasible"), std::string::npos) << message;
      // Six significant digits, not the round trip of the product H A.
      EXPECT_NE(message.find("hardness = 2e+09 Pa"), std::string::npos) << message;
      EXPECT_NE(message.find("2.56e-10 m^2 = 0.512 N"), std::string::npos) << message;
    }
    // At exactly H times the area every cell is at the cap (LCPquad's
    // interior point stopped with 4 of 256 cells just below it).
    const SolveResult full = solver->solve({gap.data(), grid.size()}, Loading::mean_pressure(kHardness));
    ASSERT_TRUE(full.converged()) << to_string(type) << ": " << full.message;
    EXPECT_EQ(full.plastic_fraction, 1.0) << to_string(type);
    EXPECT_EQ(full.pressure.minCoeff(), kHardness) << to_string(type);
  }
}

// Every solver checks the law it is given when it is made (ContactSolver),
// the dense ones as Polonsky-Keer.
TEST(HardnessDenseTest, HardnessOutOfRangeIsRefused) {
  const Grid grid = Grid::plane(8, 8, kSpacing, kSpacing, Boundary::free);
  for (const double hardness : {0.0, -1e9, 10.0, 1e14, std::numeric_limits<double>::infinity()}) {
    solvers::SolverOptions options;
    options.type = SolverType::lcpquad;
    options.interface_law.hardness = hardness;
    try {
      solvers::make_solver(grid, kEStar, options);
      FAIL() << "hardness " << hardness << " accepted";
    } catch (const solvers::SolverOptionError& error) {
      EXPECT_EQ(error.option(), "hardness");
      EXPECT_NE(std::string(error.what()).find("allowed range is 1000 to 1e+13 Pa"), std::string::npos) << error.what();
    }
  }
}

}  // namespace
}  // namespace halfspace
