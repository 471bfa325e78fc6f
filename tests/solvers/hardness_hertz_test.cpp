// A Hertz sphere under a hardness cap, on every Polonsky-Keer solver: the
// capped solution's force balance, contact conditions and plastic core, its
// agreement between the solvers, the elastic solution when the cap lies
// above the elastic peak, and displacement control against load control.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "halfspace/solvers/interface_law.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "hardness_checks.hpp"
#include "support/analytic_solutions.hpp"
#include "support/grid_fields.hpp"
#include "support/pk_solvers.hpp"

namespace halfspace {
namespace {

using solvers::SolverType;
using testing::field_from;
using testing::test_options;

constexpr std::size_t kCells = 96;  // per side; the Hertz radius spans 20 of them
constexpr double kSpacing = 1e-6;   // m
constexpr double kEStar = 1e11;     // Pa
constexpr double kRadius = 1e-3;    // sphere radius (m)
constexpr double kHertzRadius = 20.0 * kSpacing;
// The force whose Hertz radius is kHertzRadius, and its Hertz peak.
const double kForce = 4.0 * kEStar * std::pow(kHertzRadius, 3) / (3.0 * kRadius);
const double kPeak = testing::hertz_point(kForce, kRadius, kEStar).peak;
// Tolerances. The solves stop at a relative residual of 1e-12.
constexpr double kSolveTolerance = 1e-12;
// Force balance: the load is restored exactly at every iterate, to rounding.
constexpr double kForceTolerance = 1e-12;
// Gaps, relative to the sphere's height range over the grid.
constexpr double kGapTolerance = 1e-8;
// Pressures of two solvers of the same discrete problem, relative to H.
constexpr double kSolverAgreement = 1e-7;

Grid sphere_grid() {
  return Grid::plane(kCells, kCells, kSpacing, kSpacing, Boundary::free);
}

Eigen::ArrayXd sphere_gap(const Grid& grid) {
  return field_from(grid, [](double x, double y) { return (x * x + y * y) / (2.0 * kRadius); });
}

solvers::SolverOptions capped_options(SolverType type, double hardness) {
  solvers::SolverOptions options = test_options(type, kSolveTolerance);
  options.interface_law.hardness = hardness;
  return options;
}

class HardnessHertzTest : public ::testing::TestWithParam<SolverType> {};

TEST_P(HardnessHertzTest, CappedPeakBalancesTheForceAndFormsAPlasticCore) {
  const Grid grid = sphere_grid();
  const Eigen::ArrayXd gap0 = sphere_gap(grid);
  const double hardness = 0.7 * kPeak;
  const auto solver = solvers::make_solver(grid, kEStar, capped_options(GetParam(), hardness));
  const SolveResult result = solver->solve({gap0.data(), grid.size()}, Loading::force(kForce));
  ASSERT_TRUE(result.converged()) << result.message;

  EXPECT_NEAR(result.total_force, kForce, kForceTolerance * kForce);
  EXPECT_EQ(result.max_pressure, hardness);
  ASSERT_TRUE(result.hardness.has_value());
  EXPECT_EQ(*result.hardness, hardness);
  testing::expect_capped_contact_conditions(result, hardness, kGapTolerance * gap0.maxCoeff());

  // The plastic core: a disc at the centre, inside the contact, which the
  // cap makes wider than Hertz's (the load moves outwards).
  const double plastic = testing::plastic_cells(result, hardness);
  EXPECT_DOUBLE_EQ(result.plastic_fraction, plastic / static_cast<double>(grid.size()));
  const double core_radius = std::sqrt(plastic * grid.cell_area() / std::numbers::pi);
  const double contact_radius =
      std::sqrt(result.contact_fraction * static_cast<double>(grid.size()) * grid.cell_area() / std::numbers::pi);
  std::printf("%s: core radius %.2f cells, contact radius %.2f cells (Hertz %.2f), %d iterations\n",
              std::string(solver->name()).c_str(), core_radius / kSpacing, contact_radius / kSpacing,
              kHertzRadius / kSpacing, result.iterations);
  EXPECT_GT(core_radius, 3.0 * kSpacing);
  EXPECT_LT(core_radius, contact_radius - 2.0 * kSpacing);
  EXPECT_GT(contact_radius, kHertzRadius);
  // The core is centred: the centre's four cells are plastic.
  const std::size_t centre = (kCells / 2) * kCells + kCells / 2;
  EXPECT_EQ(result.pressure[static_cast<Eigen::Index>(centre)], hardness);
  EXPECT_EQ(result.pressure[static_cast<Eigen::Index>(centre - kCells - 1)], hardness);

  // The plastic displacement is the overlap at the plastic cells: positive
  // there, largest at the centre, zero elsewhere.
  const Eigen::ArrayXd plastic_displacement =
      solvers::plastic_displacement({result.pressure.data(), grid.size()}, {result.gap.data(), grid.size()}, hardness);
  EXPECT_EQ((plastic_displacement > 0.0).count(), static_cast<Eigen::Index>(plastic));
  Eigen::Index deepest = 0;
  plastic_displacement.maxCoeff(&deepest);
  const double dx = testing::centred_x(grid, static_cast<std::size_t>(deepest) % kCells);
  const double dy = testing::centred_y(grid, static_cast<std::size_t>(deepest) / kCells);
  EXPECT_LE(std::hypot(dx, dy), 1.0 * kSpacing);
}

TEST_P(HardnessHertzTest, HardnessAboveTheElasticPeakGivesTheElasticSolution) {
  const Grid grid = sphere_grid();
  const Eigen::ArrayXd gap0 = sphere_gap(grid);
  const SolveResult elastic = solvers::make_solver(grid, kEStar, test_options(GetParam(), kSolveTolerance))
                                  ->solve({gap0.data(), grid.size()}, Loading::force(kForce));
  ASSERT_TRUE(elastic.converged()) << elastic.message;
  const double hardness = 1.2 * elastic.max_pressure;
  const SolveResult capped = solvers::make_solver(grid, kEStar, capped_options(GetParam(), hardness))
                                 ->solve({gap0.data(), grid.size()}, Loading::force(kForce));
  ASSERT_TRUE(capped.converged()) << capped.message;
  EXPECT_EQ(capped.plastic_fraction, 0.0);
  EXPECT_EQ(capped.contact_fraction, elastic.contact_fraction);
  const double difference = (capped.pressure - elastic.pressure).abs().maxCoeff() / elastic.max_pressure;
  std::printf("capped above the peak: |p - p_elastic| / p_max = %.2e (%d against %d iterations)\n", difference,
              capped.iterations, elastic.iterations);
  EXPECT_LE(difference, kSolverAgreement);
}

// Displacement control at the approach the force gave returns the force.
TEST_P(HardnessHertzTest, DisplacementControlMatchesLoadControl) {
  const Grid grid = sphere_grid();
  const Eigen::ArrayXd gap0 = sphere_gap(grid);
  const double hardness = 0.7 * kPeak;
  const auto solver = solvers::make_solver(grid, kEStar, capped_options(GetParam(), hardness));
  const SolveResult by_force = solver->solve({gap0.data(), grid.size()}, Loading::force(kForce));
  ASSERT_TRUE(by_force.converged()) << by_force.message;
  const SolveResult by_approach = solver->solve({gap0.data(), grid.size()}, Loading::approach(by_force.approach));
  ASSERT_TRUE(by_approach.converged()) << by_approach.message;
  EXPECT_NEAR(by_approach.total_force, kForce, kSolverAgreement * kForce);
  EXPECT_EQ(by_approach.max_pressure, hardness);
  testing::expect_capped_contact_conditions(by_approach, hardness, kGapTolerance * gap0.maxCoeff());
  EXPECT_LE((by_approach.pressure - by_force.pressure).abs().maxCoeff() / hardness, kSolverAgreement);
}

// The preconditioned solvers against the published form on the same capped
// problem.
TEST(HardnessHertzAgreementTest, PreconditionedSolversAgreeWithThePublishedForm) {
  const Grid grid = sphere_grid();
  const Eigen::ArrayXd gap0 = sphere_gap(grid);
  const double hardness = 0.7 * kPeak;
  const SolveResult reference = solvers::make_solver(grid, kEStar, capped_options(SolverType::pk, hardness))
                                    ->solve({gap0.data(), grid.size()}, Loading::force(kForce));
  ASSERT_TRUE(reference.converged()) << reference.message;
  for (const SolverType type : {SolverType::pk_fourier, SolverType::pk_multilevel}) {
    const SolveResult result = solvers::make_solver(grid, kEStar, capped_options(type, hardness))
                                   ->solve({gap0.data(), grid.size()}, Loading::force(kForce));
    ASSERT_TRUE(result.converged()) << result.message;
    Eigen::Index worst = 0;
    const double difference = (result.pressure - reference.pressure).abs().maxCoeff(&worst) / hardness;
    std::printf("%s: |p - p_pk| / H = %.2e at cell %ld\n", std::string(to_string(type)).c_str(), difference,
                static_cast<long>(worst));
    EXPECT_LE(difference, kSolverAgreement) << to_string(type);
    EXPECT_NEAR(result.approach, reference.approach, kGapTolerance * gap0.maxCoeff()) << to_string(type);
  }
}

INSTANTIATE_TEST_SUITE_P(AllSolvers, HardnessHertzTest, testing::all_pk_solvers(), testing::solver_type_name);

}  // namespace
}  // namespace halfspace
