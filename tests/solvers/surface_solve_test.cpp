// Tests of solve_surface and sweep_surface: the same bits as building the
// solver by hand on max(h) - h, and the errors for mismatched sizes.
#include "halfspace/solvers/surface_solve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "halfspace/analysis/load_sweep.hpp"
#include "halfspace/error.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/solvers/solver_factory.hpp"

namespace halfspace::solvers {
namespace {

TEST(SurfaceSolveTest, EqualsTheSolverBuiltByHand) {
  const Grid grid = Grid::plane(32, 32, 1e-5, 1e-5, Boundary::free);
  const Eigen::ArrayXd heights = geometry::make_surface_heights(grid, {geometry::SurfaceShape::sphere, 0.01, 0.0, 0.0});
  SolverOptions options;
  options.fft_planning = FftPlanning::estimate;
  const SolveResult front_door = solve_surface(grid, {heights.data(), grid.size()}, 1e9, Loading::force(0.05), options);
  const Eigen::ArrayXd gap = initial_gap(grid, {heights.data(), grid.size()});
  const SolveResult by_hand = make_solver(grid, 1e9, options)->solve({gap.data(), grid.size()}, Loading::force(0.05));
  ASSERT_TRUE(front_door.converged());
  EXPECT_TRUE((front_door.pressure == by_hand.pressure).all());
  EXPECT_EQ(front_door.iterations, by_hand.iterations);
  EXPECT_GT(front_door.wall_seconds, 0.0);
}

TEST(SurfaceSolveTest, RefusesHeightsOfAnotherSize) {
  const Grid grid = Grid::line(16, 1e-5, Boundary::free);
  const std::vector<double> heights(15, 0.0);
  EXPECT_THROW(solve_surface(grid, heights, 1e9, Loading::force(1.0), {}), InputError);
  EXPECT_THROW(analysis::sweep_surface(grid, heights, 1e9, ControlMode::force, std::vector<double>{1.0}, {}),
               InputError);
}

}  // namespace
}  // namespace halfspace::solvers
