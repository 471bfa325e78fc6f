// pk-multilevel: the coarse-grid start changes the path, not the answer, and
// it is used exactly when it can be (even sides, large enough grid, no warm
// start close to the load). The physics validation (Hertz, Westergaard,
// round trips) runs on it through the suites of support/pk_solvers.hpp.
#include "halfspace/solvers/multilevel_solver.hpp"

#include <gtest/gtest.h>

#include <cstdio>

#include "halfspace/error.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/threads.hpp"
#include "support/contact_checks.hpp"
#include "support/pk_solvers.hpp"
#include "support/rough_gap.hpp"

namespace halfspace::solvers {
namespace {

using testing::expect_contact_conditions;
using testing::self_affine_gap;

constexpr double kEStar = 1.0;
// Two converged solutions at residual 1e-12 differ by rounding-level amounts
// relative to the largest pressure.
constexpr double kSameSolution = 1e-8;

SolverOptions settings(const std::string& name) {
  return testing::test_options(parse_solver_type(name), 1e-12);
}

TEST(MultilevelSolverTest, MatchesTheSingleGridSolverAndUsesTheCoarseGrids) {
  const int original = threads();
  set_threads(1);
  for (const Boundary boundary : {Boundary::periodic, Boundary::free}) {
    const Grid grid = Grid::plane(128, 128, 1.0, 1.0, boundary);
    const Eigen::ArrayXd gap = self_affine_gap(grid, 7);
    const Loading loading = Loading::mean_pressure(0.004);  // about 8% contact
    const SolveResult single =
        make_solver(grid, kEStar, settings("pk-fourier"))->solve({gap.data(), grid.size()}, loading);
    const SolveResult multi =
        make_solver(grid, kEStar, settings("pk-multilevel"))->solve({gap.data(), grid.size()}, loading);
    ASSERT_TRUE(single.converged()) << single.message;
    ASSERT_TRUE(multi.converged()) << multi.message;
    expect_contact_conditions(multi, 1e-9 * gap.maxCoeff());
    const double difference = (multi.pressure - single.pressure).abs().maxCoeff() / single.max_pressure;
    std::printf("%s 128^2: pk-fourier %d iterations, pk-multilevel %d (+%d on %d coarser grids), max |dp| %.1e\n",
                std::string(to_string(boundary)).c_str(), single.iterations, multi.iterations, multi.coarse.iterations,
                multi.coarse.levels, difference);
    EXPECT_LE(difference, kSameSolution);
    EXPECT_EQ(multi.coarse.levels, 2) << "128 -> 64 -> 32 cells per side";
    EXPECT_GT(multi.coarse.iterations, 0);
    EXPECT_GT(multi.coarse.operator_work, 0.0);
    EXPECT_LT(multi.coarse.operator_work, multi.operator_applications) << "coarse work is weighted by grid size";
    EXPECT_EQ(multi.solver, "multilevel-polonsky-keer");
    EXPECT_NEAR(multi.total_force, single.total_force, 1e-12 * single.total_force);
  }
  set_threads(original);
}

TEST(MultilevelSolverTest, SkipsTheCoarseGridsWhenItCannotOrNeedNotUseThem) {
  // Odd side: no coarser grid of the same domain.
  const Grid odd = Grid::plane(65, 64, 1.0, 1.0, Boundary::periodic);
  const Eigen::ArrayXd odd_gap = self_affine_gap(odd, 3);
  const SolveResult odd_result = make_solver(odd, kEStar, settings("pk-multilevel"))
                                     ->solve({odd_gap.data(), odd.size()}, Loading::mean_pressure(0.004));
  ASSERT_TRUE(odd_result.converged()) << odd_result.message;
  EXPECT_EQ(odd_result.coarse.levels, 0);

  // A warm start (a sweep's previous step) is used as it is.
  const Grid grid = Grid::plane(64, 64, 1.0, 1.0, Boundary::periodic);
  const Eigen::ArrayXd gap = self_affine_gap(grid, 4);
  auto solver = make_solver(grid, kEStar, settings("pk-multilevel"));
  const SolveResult cold = solver->solve({gap.data(), grid.size()}, Loading::mean_pressure(0.004));
  ASSERT_TRUE(cold.converged()) << cold.message;
  EXPECT_EQ(cold.coarse.levels, 1);
  const SolveResult warm =
      solver->solve({gap.data(), grid.size()}, Loading::mean_pressure(0.005), {cold.pressure.data(), grid.size()});
  ASSERT_TRUE(warm.converged()) << warm.message;
  EXPECT_EQ(warm.coarse.levels, 0);
  EXPECT_EQ(warm.solver, "multilevel-polonsky-keer");

  // A warm start whose force is more than 1.5x off the target (here 2x) is
  // set aside for the coarse grids; under displacement control any is kept.
  const SolveResult far =
      solver->solve({gap.data(), grid.size()}, Loading::mean_pressure(0.008), {cold.pressure.data(), grid.size()});
  ASSERT_TRUE(far.converged()) << far.message;
  EXPECT_EQ(far.coarse.levels, 1);
  EXPECT_NEAR(far.mean_pressure, 0.008, 1e-12);
  const SolveResult approach =
      solver->solve({gap.data(), grid.size()}, Loading::approach(far.approach), {cold.pressure.data(), grid.size()});
  ASSERT_TRUE(approach.converged()) << approach.message;
  EXPECT_EQ(approach.coarse.levels, 0);
}

TEST(MultilevelSolverTest, RefusesBadInputBeforeAnyCoarseSolve) {
  const Grid grid = Grid::plane(64, 64, 1.0, 1.0, Boundary::periodic);
  auto solver = make_solver(grid, kEStar, settings("pk-multilevel"));
  const Eigen::ArrayXd gap = self_affine_gap(grid, 5);
  EXPECT_THROW(solver->solve({gap.data(), 100}, Loading::mean_pressure(0.004)), InputError);
  EXPECT_THROW(solver->solve({gap.data(), grid.size()}, Loading::force(-1.0)), InputError);
  MultilevelOptions bad;
  bad.coarse_tolerance = 2.0;
  EXPECT_THROW(bad.validate(), InputError);
  bad = {};
  bad.min_cells_per_axis = 1;
  EXPECT_THROW(bad.validate(), InputError);
  bad = {};
  bad.warm_start_max_load_ratio = 0.9;
  EXPECT_THROW(bad.validate(), InputError);
}

}  // namespace
}  // namespace halfspace::solvers
