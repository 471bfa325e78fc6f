// Polonsky-Keer on the free-boundary FFT operator against Hertz: point contact
// of a sphere (2D grid) and line contact of a cylinder (1D grid), with errors
// that must shrink under grid refinement.
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

class PolonskyKeerHertzTest : public ::testing::TestWithParam<SolverType> {};
using testing::field_from;

constexpr double kEStar = 1.1e11;       // Pa, steel on steel
constexpr double kSphereRadius = 0.01;  // m
constexpr double kForce = 10.0;         // N
// Force balance holds to rounding under load control.
constexpr double kForceBalanceTolerance = 1e-10;
// Peak pressure and approach: discretisation error of a ~20-cell contact radius.
constexpr double kHertzRelativeTolerance = 0.01;
// Contact gap: residual 1e-10 of the gap scale allows far less than this.
constexpr double kGapTolerance = 1e-6;  // relative to the approach

struct PointContactErrors {
  double radius_error_cells;
  double peak_error;      // relative
  double approach_error;  // relative
};

PointContactErrors solve_hertz_point(std::size_t n, SolverType type) {
  const auto hertz = testing::hertz_point(kForce, kSphereRadius, kEStar);
  const double size = 3.0 * hertz.radius;
  const Grid grid = Grid::plane(n, n, size / static_cast<double>(n), size / static_cast<double>(n), Boundary::free);
  const Eigen::ArrayXd gap0 =
      field_from(grid, [](double x, double y) { return (x * x + y * y) / (2 * kSphereRadius); });

  const auto solver = solvers::make_solver(grid, kEStar, test_options(type));
  const SolveResult result = solver->solve({gap0.data(), grid.size()}, Loading::force(kForce));
  EXPECT_TRUE(result.converged()) << result.message;
  EXPECT_NEAR(result.total_force, kForce, kForceBalanceTolerance * kForce);
  expect_contact_conditions(result, kGapTolerance * hertz.approach);

  const double contact_area = static_cast<double>((result.pressure > 0.0).count()) * grid.cell_area();
  const double radius = std::sqrt(contact_area / std::numbers::pi);
  PointContactErrors errors{std::abs(radius - hertz.radius) / grid.dx(),
                            std::abs(result.max_pressure - hertz.peak) / hertz.peak,
                            std::abs(result.approach - hertz.approach) / hertz.approach};
  std::printf(
      "Hertz point n=%zu: a/dx=%.1f, radius error %.3f cells, peak error %.2e, approach error %.2e, %d iterations\n", n,
      hertz.radius / grid.dx(), errors.radius_error_cells, errors.peak_error, errors.approach_error, result.iterations);
  return errors;
}

TEST_P(PolonskyKeerHertzTest, ReproducesHertzPointContactAndConvergesUnderRefinement) {
  const PointContactErrors coarse = solve_hertz_point(33, GetParam());
  const PointContactErrors fine = solve_hertz_point(65, GetParam());
  for (const auto& e : {coarse, fine}) {
    EXPECT_LE(e.radius_error_cells, 1.0);
    EXPECT_LE(e.peak_error, kHertzRelativeTolerance);
    EXPECT_LE(e.approach_error, kHertzRelativeTolerance);
  }
  EXPECT_LT(fine.peak_error, coarse.peak_error);
  EXPECT_LT(fine.approach_error, coarse.approach_error);
}

struct LineContactErrors {
  double half_width_error;  // relative
  double peak_error;        // relative
  double profile_error;     // relative L2
};

constexpr double kCylinderRadius = 0.01875;  // m, R1 = 0.05, R2 = 0.03 combined
constexpr double kLineLoad = 1e5;            // N/m

LineContactErrors solve_hertz_line(std::size_t n, SolverType type) {
  const auto hertz = testing::hertz_line(kLineLoad, kCylinderRadius, kEStar);
  const double size = 3.0 * hertz.half_width;
  const Grid grid = Grid::line(n, size / static_cast<double>(n), Boundary::free);
  const Eigen::ArrayXd gap0 = field_from(grid, [](double x, double) { return x * x / (2 * kCylinderRadius); });

  const auto solver = solvers::make_solver(grid, kEStar, test_options(type));
  const SolveResult result = solver->solve({gap0.data(), grid.size()}, Loading::force(kLineLoad));
  EXPECT_TRUE(result.converged()) << result.message;
  EXPECT_NEAR(result.total_force, kLineLoad, kForceBalanceTolerance * kLineLoad);
  expect_contact_conditions(result, kGapTolerance * hertz.half_width * hertz.half_width / kCylinderRadius);

  double error_sq = 0.0;
  double norm_sq = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double exact = hertz.pressure(centred_x(grid, i));
    error_sq += std::pow(result.pressure[static_cast<Eigen::Index>(i)] - exact, 2);
    norm_sq += exact * exact;
  }
  const double half_width = 0.5 * static_cast<double>((result.pressure > 0.0).count()) * grid.dx();
  LineContactErrors errors{std::abs(half_width - hertz.half_width) / hertz.half_width,
                           std::abs(result.max_pressure - hertz.peak) / hertz.peak, std::sqrt(error_sq / norm_sq)};
  std::printf(
      "Hertz line n=%zu: b/dx=%.1f, half-width error %.2e, peak error %.2e, profile error %.2e, %d iterations\n", n,
      hertz.half_width / grid.dx(), errors.half_width_error, errors.peak_error, errors.profile_error,
      result.iterations);
  return errors;
}

TEST_P(PolonskyKeerHertzTest, ReproducesHertzLineContactAndConvergesUnderRefinement) {
  const LineContactErrors coarse = solve_hertz_line(301, GetParam());
  const LineContactErrors fine = solve_hertz_line(1201, GetParam());
  for (const auto& e : {coarse, fine}) {
    EXPECT_LE(e.half_width_error, kHertzRelativeTolerance);
    EXPECT_LE(e.peak_error, kHertzRelativeTolerance);
    EXPECT_LE(e.profile_error, kHertzRelativeTolerance);
  }
  EXPECT_LT(fine.half_width_error, coarse.half_width_error);
  EXPECT_LT(fine.profile_error, coarse.profile_error);
}

INSTANTIATE_TEST_SUITE_P(Variants, PolonskyKeerHertzTest, testing::all_pk_solvers(), testing::solver_type_name);

}  // namespace
}  // namespace halfspace
