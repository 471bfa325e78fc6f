// Polonsky-Keer on periodic grids against exact solutions: Westergaard's 1D
// wave (partial contact) and the 2D wave of Johnson, Greenwood & Higginson
// (full contact, where the pressure field is exactly linear in the heights).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "halfspace/solvers/solver_factory.hpp"
#include "support/analytic_solutions.hpp"
#include "support/contact_checks.hpp"
#include "support/grid_fields.hpp"
#include "support/pk_solvers.hpp"

namespace halfspace {
namespace {

using solvers::SolverType;
using testing::centred_x;
using testing::expect_contact_conditions;
using testing::test_options;

class PolonskyKeerPeriodicTest : public ::testing::TestWithParam<SolverType> {};
using testing::field_from;

constexpr double kEStar = 2.0e9;      // Pa
constexpr double kWavelength = 1e-4;  // m
constexpr double kAmplitude = 1e-6;   // m
// Westergaard half-width and profile: the bound, met at 4096 cells.
constexpr double kWestergaardTolerance = 0.005;
// Full contact: one Fourier mode, so the discrete solution is exact to rounding.
constexpr double kFullContactTolerance = 1e-8;

TEST_P(PolonskyKeerPeriodicTest, ReproducesWestergaardHalfWidthAndProfile) {
  const std::size_t n = 4096;
  const Grid grid = Grid::line(n, kWavelength / static_cast<double>(n), Boundary::periodic);
  const testing::Westergaard exact{kWavelength, kAmplitude, kEStar};
  const Eigen::ArrayXd gap0 = field_from(
      grid, [](double x, double) { return kAmplitude * (1.0 - std::cos(2.0 * std::numbers::pi * x / kWavelength)); });
  const auto solver = solvers::make_solver(grid, kEStar, test_options(GetParam()));

  for (const double fraction : {0.05, 0.3, 0.7}) {
    const double mean_pressure = fraction * exact.full_contact_pressure();
    const SolveResult result = solver->solve({gap0.data(), n}, Loading::mean_pressure(mean_pressure));
    ASSERT_TRUE(result.converged()) << result.message;
    expect_contact_conditions(result, 1e-8 * kAmplitude);

    const double half_width = 0.5 * static_cast<double>((result.pressure > 0.0).count()) * grid.dx();
    const double half_width_error =
        std::abs(half_width - exact.half_width(mean_pressure)) / exact.half_width(mean_pressure);
    double error_sq = 0.0;
    double norm_sq = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double p = exact.pressure(centred_x(grid, i), mean_pressure);
      error_sq += std::pow(result.pressure[static_cast<Eigen::Index>(i)] - p, 2);
      norm_sq += p * p;
    }
    const double profile_error = std::sqrt(error_sq / norm_sq);
    std::printf("Westergaard p/p*=%.2f: half-width error %.2e, profile error %.2e, %d iterations\n", fraction,
                half_width_error, profile_error, result.iterations);
    EXPECT_LE(half_width_error, kWestergaardTolerance) << "p/p* = " << fraction;
    EXPECT_LE(profile_error, kWestergaardTolerance) << "p/p* = " << fraction;
    EXPECT_NEAR(result.mean_pressure, mean_pressure, 1e-12 * mean_pressure);
  }
}

TEST_P(PolonskyKeerPeriodicTest, TwoDimensionalWaveIsInFullContactAtAndAboveCriticalPressure) {
  const std::size_t n = 64;
  const double h = kWavelength / static_cast<double>(n);
  const Grid grid = Grid::plane(n, n, h, h, Boundary::periodic);
  const double k = 2.0 * std::numbers::pi / kWavelength;
  const Eigen::ArrayXd wave = field_from(grid, [&](double x, double y) { return std::cos(k * x) * std::cos(k * y); });
  const Eigen::ArrayXd gap0 = kAmplitude * (1.0 - wave);
  const double critical = std::numbers::sqrt2 * std::numbers::pi * kEStar * kAmplitude / kWavelength;

  const auto solver = solvers::make_solver(grid, kEStar, test_options(GetParam()));
  for (const double ratio : {1.0, 1.5}) {
    const double mean_pressure = ratio * critical;
    const SolveResult result = solver->solve({gap0.data(), grid.size()}, Loading::mean_pressure(mean_pressure));
    ASSERT_TRUE(result.converged()) << result.message;
    const Eigen::ArrayXd exact = mean_pressure + critical * wave;
    Eigen::Index worst = 0;
    const double error = (result.pressure - exact).abs().maxCoeff(&worst) / critical;
    std::printf("2D wave p/p*=%.1f: max pressure error %.2e of p* at cell %ld, max |gap| %.2e m, %d iterations\n",
                ratio, error, static_cast<long>(worst), result.gap.abs().maxCoeff(), result.iterations);
    EXPECT_LE(error, kFullContactTolerance);
    EXPECT_LE(result.gap.abs().maxCoeff(), kFullContactTolerance * kAmplitude) << "not in full contact";
    if (ratio > 1.0) {
      EXPECT_EQ(result.contact_fraction, 1.0);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Variants, PolonskyKeerPeriodicTest, testing::all_pk_solvers(), testing::solver_type_name);

}  // namespace
}  // namespace halfspace
