// The hardness cap on rough surfaces, on every Polonsky-Keer solver, 1D and
// 2D, free and periodic: force balance and the capped contact conditions at
// every load, a plastic fraction that rises with the load; and the
// rigid-plastic limit (E* -> infinity), where the contact is the bearing
// area of the surface at the level that carries the force at the hardness.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include "halfspace/solvers/solver_factory.hpp"
#include "hardness_checks.hpp"
#include "support/pk_solvers.hpp"
#include "support/rough_gap.hpp"

namespace halfspace {
namespace {

using solvers::SolverType;
using testing::test_options;

constexpr double kSpacing = 1e-6;  // m
constexpr double kEStar = 1e9;     // Pa
// H / E* = 0.02, as for a hard steel against steel.
constexpr double kHardness = 2e7;  // Pa
// Force balance: the load is restored exactly at every iterate, to rounding.
constexpr double kForceTolerance = 1e-12;
// Gaps at a residual of 1e-10, relative to the height range.
constexpr double kGapTolerance = 1e-7;

enum class Shape { line_free, line_periodic, plane_free, plane_periodic };

Grid make_grid(Shape shape) {
  switch (shape) {
    case Shape::line_free:
      return Grid::line(1024, kSpacing, Boundary::free);
    case Shape::line_periodic:
      return Grid::line(1024, kSpacing, Boundary::periodic);
    case Shape::plane_free:
      return Grid::plane(64, 64, kSpacing, kSpacing, Boundary::free);
    case Shape::plane_periodic:
      break;
  }
  return Grid::plane(64, 64, kSpacing, kSpacing, Boundary::periodic);
}

class HardnessRoughTest : public ::testing::TestWithParam<std::tuple<SolverType, Shape>> {};

TEST_P(HardnessRoughTest, PlasticFractionRisesWithTheLoadAndTheForceBalances) {
  const auto [type, shape] = GetParam();
  const Grid grid = make_grid(shape);
  const Eigen::ArrayXd gap0 = testing::self_affine_gap(grid, 11);
  const double range = gap0.maxCoeff() - gap0.minCoeff();
  solvers::SolverOptions options = test_options(type);
  options.interface_law.hardness = kHardness;
  const auto solver = solvers::make_solver(grid, kEStar, options);
  double previous_plastic = 0.0;
  double previous_contact = 0.0;
  for (const double fraction : {0.02, 0.05, 0.1, 0.2, 0.4}) {
    const double mean_pressure = fraction * kHardness;
    const SolveResult result = solver->solve({gap0.data(), grid.size()}, Loading::mean_pressure(mean_pressure));
    ASSERT_TRUE(result.converged()) << "p/H = " << fraction << ": " << result.message;
    EXPECT_NEAR(result.mean_pressure, mean_pressure, kForceTolerance * mean_pressure);
    testing::expect_capped_contact_conditions(result, kHardness, kGapTolerance * range);
    std::printf("%s %s p/H = %.2f: contact %.4f, plastic %.4f, %d iterations\n", std::string(to_string(type)).c_str(),
                grid.shape_string().c_str(), fraction, result.contact_fraction, result.plastic_fraction,
                result.iterations);
    EXPECT_GT(result.plastic_fraction, previous_plastic) << "p/H = " << fraction;
    EXPECT_GT(result.contact_fraction, previous_contact) << "p/H = " << fraction;
    // The cap carries at most the load: H times the plastic area.
    EXPECT_LE(result.plastic_fraction * kHardness, mean_pressure * (1.0 + kForceTolerance));
    previous_plastic = result.plastic_fraction;
    previous_contact = result.contact_fraction;
  }
}

INSTANTIATE_TEST_SUITE_P(AllSolversAndGrids, HardnessRoughTest,
                         ::testing::Combine(testing::all_pk_solvers(),
                                            ::testing::Values(Shape::line_free, Shape::line_periodic, Shape::plane_free,
                                                              Shape::plane_periodic)),
                         [](const ::testing::TestParamInfo<std::tuple<SolverType, Shape>>& info) {
                           static const char* shapes[] = {"LineFree", "LinePeriodic", "PlaneFree", "PlanePeriodic"};
                           return testing::solver_type_name({std::get<0>(info.param), info.index}) +
                                  shapes[static_cast<int>(std::get<1>(info.param))];
                         });

// E* -> infinity: the elastic deflections vanish against the heights, so
// the contact is the k lowest cells of the initial gap (the bearing area at
// the level that carries F at H, k = F / (H A_cell)) and one partial cell.
class HardnessRigidPlasticTest : public ::testing::TestWithParam<SolverType> {};

TEST_P(HardnessRigidPlasticTest, ContactTendsToTheBearingAreaAtFOverH) {
  const Grid grid = Grid::plane(64, 64, kSpacing, kSpacing, Boundary::periodic);
  const Eigen::ArrayXd gap0 = testing::self_affine_gap(grid, 12);
  const double mean_pressure = 0.1 * kHardness;
  const double bearing_cells = mean_pressure * static_cast<double>(grid.size()) / kHardness;
  std::vector<double> sorted(gap0.data(), gap0.data() + gap0.size());
  std::sort(sorted.begin(), sorted.end());
  double previous_error = 1.0;
  for (const double e_star : {1e9, 1e11, 1e13, 1e15}) {
    solvers::SolverOptions options = test_options(GetParam());
    options.interface_law.hardness = kHardness;
    const SolveResult result = solvers::make_solver(grid, e_star, options)
                                   ->solve({gap0.data(), grid.size()}, Loading::mean_pressure(mean_pressure));
    ASSERT_TRUE(result.converged()) << "E* = " << e_star << ": " << result.message;
    const double contact_cells = result.contact_fraction * static_cast<double>(grid.size());
    const double error = std::abs(contact_cells - bearing_cells) / bearing_cells;
    std::printf("E* = %.0e: contact %.0f cells (F/H: %.1f), plastic %.0f, %d iterations\n", e_star, contact_cells,
                bearing_cells, result.plastic_fraction * static_cast<double>(grid.size()), result.iterations);
    EXPECT_LE(error, previous_error) << "E* = " << e_star;
    previous_error = error;
    if (e_star == 1e15) {
      // F / H in cells, and the contact is the lowest cells of g0.
      EXPECT_GE(contact_cells, std::floor(bearing_cells));
      EXPECT_LE(contact_cells, std::floor(bearing_cells) + 1.0);
      const double level = sorted[static_cast<std::size_t>(contact_cells) - 1];
      for (Eigen::Index i = 0; i < gap0.size(); ++i) {
        EXPECT_EQ(result.pressure[i] > 0.0, gap0[i] <= level) << "cell " << i;
      }
    }
  }
  EXPECT_LE(previous_error, 1.0 / bearing_cells);
}

INSTANTIATE_TEST_SUITE_P(AllSolvers, HardnessRigidPlasticTest, testing::all_pk_solvers(), testing::solver_type_name);

}  // namespace
}  // namespace halfspace
