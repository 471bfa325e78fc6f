// A load of a whole number of cells at the cap (F / (H dx dy) an integer),
// the round input users type: every contact cell could sit at the cap, which
// fixes no approach, and the iteration once cycled there or broke down
// (issue 32, defect 1). Each Polonsky-Keer solver must converge to the
// capped contact conditions and all must agree; the largest load, H times
// the domain, puts every cell at the cap.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <string>

#include "halfspace/solvers/solver_factory.hpp"
#include "hardness_checks.hpp"
#include "support/grid_fields.hpp"
#include "support/pk_solvers.hpp"

namespace halfspace {
namespace {

using solvers::SolverType;
using testing::field_from;

constexpr std::size_t kCells = 64;  // per side
constexpr double kSide = 1e-3;      // m
constexpr double kRadius = 1e-2;    // sphere radius (m)
constexpr double kHardness = 2e8;   // Pa
constexpr double kSolveTolerance = 1e-10;
// A few tens of iterations suffice; on the broken solver the cycle ran to
// any limit, so a tight one keeps the failure quick.
constexpr int kMaxIterations = 300;
// Force balance: the load is restored exactly at every iterate, to rounding.
constexpr double kForceTolerance = 1e-12;
// Gaps, relative to the sphere's height range over the grid.
constexpr double kGapTolerance = 1e-8;
// Pressures of two solvers of the same discrete problem, relative to H.
constexpr double kSolverAgreement = 1e-7;

Grid sphere_grid() {
  return Grid::plane(kCells, kCells, kSide / kCells, kSide / kCells, Boundary::free);
}

Eigen::ArrayXd sphere_gap(const Grid& grid) {
  return field_from(grid, [](double x, double y) { return (x * x + y * y) / (2.0 * kRadius); });
}

SolveResult solve_capped(SolverType type, double e_star, double force) {
  const Grid grid = sphere_grid();
  const Eigen::ArrayXd gap0 = sphere_gap(grid);
  solvers::SolverOptions options = testing::test_options(type, kSolveTolerance);
  options.max_iterations = kMaxIterations;
  options.interface_law.hardness = kHardness;
  return solvers::make_solver(grid, e_star, options)->solve({gap0.data(), grid.size()}, Loading::force(force));
}

struct WholeCellsCase {
  double e_star;        // Pa
  double capped_cells;  // the load over H dx dy
};

class HardnessWholeCellsTest : public ::testing::TestWithParam<SolverType> {};

// E* = 1e11 cycled to the iteration limit (every contact cell at the cap,
// then every one just below it); 1e12 broke down with t.Kt = 0 or NaN.
TEST_P(HardnessWholeCellsTest, LoadOfAWholeNumberOfCellsAtTheCapConverges) {
  const Grid grid = sphere_grid();
  const double range = sphere_gap(grid).maxCoeff();
  for (const WholeCellsCase c : {WholeCellsCase{1e11, 2048}, WholeCellsCase{1e11, 1024}, WholeCellsCase{1e12, 2048},
                                 WholeCellsCase{1e13, 2048}}) {
    const double force = c.capped_cells * kHardness * grid.cell_area();
    const SolveResult result = solve_capped(GetParam(), c.e_star, force);
    SCOPED_TRACE(::testing::Message() << "E* = " << c.e_star << " Pa, F = " << force << " N = " << c.capped_cells
                                      << " cells at the cap");
    std::printf("E* %.0e, F %g N (%g cells at H): %s after %d iterations, plastic %g cells, contact %g cells\n",
                c.e_star, force, c.capped_cells, std::string(to_string(result.status)).c_str(), result.iterations,
                result.plastic_fraction * static_cast<double>(grid.size()),
                result.contact_fraction * static_cast<double>(grid.size()));
    ASSERT_TRUE(result.converged()) << result.message;
    EXPECT_NEAR(result.total_force, force, kForceTolerance * force);
    testing::expect_capped_contact_conditions(result, kHardness, kGapTolerance * range);
  }
}

INSTANTIATE_TEST_SUITE_P(AllSolvers, HardnessWholeCellsTest, testing::all_pk_solvers(), testing::solver_type_name);

TEST(HardnessWholeCellsAgreementTest, EverySolverFindsTheSamePressure) {
  const Grid grid = sphere_grid();
  const double force = 2048.0 * kHardness * grid.cell_area();
  const SolveResult reference = solve_capped(SolverType::pk, 1e11, force);
  ASSERT_TRUE(reference.converged()) << reference.message;
  for (const SolverType type : {SolverType::pk_fourier, SolverType::pk_multilevel}) {
    const SolveResult result = solve_capped(type, 1e11, force);
    ASSERT_TRUE(result.converged()) << to_string(type) << ": " << result.message;
    Eigen::Index worst = 0;
    const double difference = (result.pressure - reference.pressure).abs().maxCoeff(&worst) / kHardness;
    std::printf("%s against pk: |dp| / H = %.2e at cell %ld\n", std::string(to_string(type)).c_str(), difference,
                static_cast<long>(worst));
    EXPECT_LE(difference, kSolverAgreement) << to_string(type);
  }
}

// At F = H times the domain every cell is at the cap, which the approach
// then leaves free below the lowest surface point: the solve must converge
// there, and a load a little above is refused naming the largest.
TEST(HardnessWholeCellsEdgeTest, LoadOfTheWholeDomainAtTheCapPutsEveryCellThere) {
  const Grid grid = sphere_grid();
  const double largest = kHardness * grid.domain_area();
  for (const SolverType type : {SolverType::pk, SolverType::pk_fourier, SolverType::pk_multilevel}) {
    const SolveResult full = solve_capped(type, 1e11, largest);
    ASSERT_TRUE(full.converged()) << to_string(type) << ": " << full.message;
    EXPECT_EQ(full.plastic_fraction, 1.0) << to_string(type);
    EXPECT_NEAR(full.total_force, largest, kForceTolerance * largest) << to_string(type);
    try {
      solve_capped(type, 1e11, largest * (1.0 + 1e-9));
      FAIL() << to_string(type) << " accepted a load above H times the domain area";
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("infeasible"), std::string::npos) << message;
      EXPECT_NE(message.find("= 200 N (the largest force"), std::string::npos) << message;
    }
  }
}

}  // namespace
}  // namespace halfspace
