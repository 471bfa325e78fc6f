// Tests of solve_surface and sweep_surface: the same bits as building the
// solver by hand on max(h) - h (on -h under load control, the approach then
// measured from max(h)), the heights lent to the solve given back bit for
// bit, and the errors for mismatched sizes.
#include "halfspace/solvers/surface_solve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "halfspace/analysis/load_sweep.hpp"
#include "halfspace/error.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/surface/self_affine.hpp"

namespace halfspace::solvers {
namespace {

TEST(SurfaceSolveTest, EqualsTheSolverBuiltByHand) {
  const Grid grid = Grid::plane(32, 32, 1e-5, 1e-5, Boundary::free);
  const Eigen::ArrayXd heights = geometry::make_surface_heights(grid, {geometry::SurfaceShape::sphere, 0.01, 0.0, 0.0});
  SolverOptions options;
  options.fft_planning = FftPlanning::estimate;
  // Load control: the solver on -h, its approach shifted by max(h).
  ASSERT_TRUE(initial_gap_in_heights(Loading::force(0.05), options));
  const SolveResult front_door = solve_surface(grid, {heights.data(), grid.size()}, 1e9, Loading::force(0.05), options);
  const Eigen::ArrayXd negated = -heights;
  const SolveResult by_hand =
      make_solver(grid, 1e9, options)->solve({negated.data(), grid.size()}, Loading::force(0.05));
  ASSERT_TRUE(front_door.converged());
  EXPECT_TRUE((front_door.pressure == by_hand.pressure).all());
  EXPECT_EQ(front_door.iterations, by_hand.iterations);
  EXPECT_EQ(front_door.approach, by_hand.approach + heights.maxCoeff());
  EXPECT_GT(front_door.wall_seconds, 0.0);
  // The same contact on max(h) - h: the same solution to the tolerance.
  const Eigen::ArrayXd gap = initial_gap(grid, {heights.data(), grid.size()});
  const SolveResult on_gap = make_solver(grid, 1e9, options)->solve({gap.data(), grid.size()}, Loading::force(0.05));
  EXPECT_LE((front_door.pressure - on_gap.pressure).abs().maxCoeff(), 1e-6 * on_gap.pressure.maxCoeff());
  EXPECT_NEAR(front_door.approach, on_gap.approach, 1e-6 * on_gap.approach);

  // Displacement control: on max(h) - h itself.
  const Loading approach = Loading::approach(0.5 * on_gap.approach);
  ASSERT_FALSE(initial_gap_in_heights(approach, options));
  const SolveResult displaced = solve_surface(grid, {heights.data(), grid.size()}, 1e9, approach, options);
  const SolveResult displaced_by_hand = make_solver(grid, 1e9, options)->solve({gap.data(), grid.size()}, approach);
  ASSERT_TRUE(displaced.converged());
  EXPECT_TRUE((displaced.pressure == displaced_by_hand.pressure).all());
}

TEST(SurfaceSolveTest, LentHeightsComeBackBitForBitWithTheSameSolution) {
  const Grid grid = Grid::plane(64, 64, 1e-6, 1e-6, Boundary::periodic);
  surface::SelfAffineSpec spec;
  spec.rms_slope = 0.1;
  spec.seed = 3;
  const Eigen::ArrayXd heights = surface::make_self_affine_surface(grid, spec);
  SolverOptions options;
  options.fft_planning = FftPlanning::estimate;
  for (const Loading& loading : {Loading::mean_pressure(1e7), Loading::approach(0.2 * (heights.maxCoeff()))}) {
    Eigen::ArrayXd lent = heights;
    const SolveResult copied = solve_surface(grid, {heights.data(), grid.size()}, 1e9, loading, options);
    const SolveResult in_place = solve_surface_in_place(grid, {lent.data(), grid.size()}, 1e9, loading, options);
    ASSERT_TRUE(in_place.converged()) << to_string(loading.mode);
    EXPECT_TRUE((lent == heights).all()) << to_string(loading.mode);
    EXPECT_TRUE((in_place.pressure == copied.pressure).all()) << to_string(loading.mode);
    EXPECT_TRUE((in_place.gap == copied.gap).all()) << to_string(loading.mode);
    EXPECT_EQ(in_place.approach, copied.approach) << to_string(loading.mode);
  }
}

TEST(SurfaceSolveTest, LentHeightsComeBackWhenTheSolveThrows) {
  const Grid grid = Grid::plane(32, 32, 1e-6, 1e-6, Boundary::periodic);
  surface::SelfAffineSpec spec;
  spec.rms_slope = 0.1;
  const Eigen::ArrayXd heights = surface::make_self_affine_surface(grid, spec);
  SolverOptions options;
  options.fft_planning = FftPlanning::estimate;
  options.progress = [](int iteration, double) -> IterationDecision {
    if (iteration == 2) throw std::runtime_error("stopped by the test");
    return IterationDecision::proceed;
  };
  Eigen::ArrayXd lent = heights;
  EXPECT_THROW(solve_surface_in_place(grid, {lent.data(), grid.size()}, 1e9, Loading::mean_pressure(1e7), options),
               std::runtime_error);
  EXPECT_TRUE((lent == heights).all());
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
