// A progress callback that returns IterationDecision::stop ends every
// iterative solver at that iteration with status `stopped` (never
// converged, the reason in the message); a sweep ends at the step it
// stopped; an exception thrown by the callback still passes through.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "friction/friction_checks.hpp"
#include "halfspace/analysis/load_sweep.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/solvers/tangential_solver.hpp"
#include "halfspace/surface/self_affine.hpp"
#include "support/pk_solvers.hpp"

namespace halfspace::solvers {
namespace {

constexpr int kStopAt = 3;
// Far below what a few iterations reach, so that only the callback ends them.
constexpr double kUnreachableTolerance = 1e-14;

// A callback stopping at iteration `at` that records every iteration it saw.
ProgressCallback stop_at(int at, std::vector<int>& seen) {
  return [at, &seen](int iteration, double) {
    seen.push_back(iteration);
    return iteration == at ? IterationDecision::stop : IterationDecision::proceed;
  };
}

void expect_stopped_at(const SolveResult& result, const std::vector<int>& seen, int at) {
  EXPECT_EQ(result.status, SolveStatus::stopped) << result.message;
  EXPECT_FALSE(result.converged());
  EXPECT_EQ(result.iterations, at);
  EXPECT_EQ(seen.back(), at);
  EXPECT_NE(result.message.find("stopped by the caller"), std::string::npos) << result.message;
  EXPECT_EQ(result.pressure.size(), result.gap.size());  // the fields of the last iterate are there
}

// A rough surface: no solver reaches kUnreachableTolerance on it in a few iterations.
Eigen::ArrayXd rough_heights(const Grid& grid) {
  surface::SelfAffineSpec spec;
  spec.rms_slope = 0.1;
  spec.seed = 7;
  return surface::make_self_affine_surface(grid, spec);
}

class PolonskyKeerStopTest : public ::testing::TestWithParam<SolverType> {};

TEST_P(PolonskyKeerStopTest, StopsAtTheIterationTheCallbackSays) {
  const Grid grid = Grid::plane(64, 64, 1e-5, 1e-5, Boundary::periodic);
  const Eigen::ArrayXd heights = rough_heights(grid);
  SolverOptions options = testing::test_options(GetParam(), kUnreachableTolerance);
  std::vector<int> seen;
  options.progress = stop_at(kStopAt, seen);
  const SolveResult result =
      solve_surface(grid, {heights.data(), grid.size()}, 1e9, Loading::mean_pressure(1e7), options);
  expect_stopped_at(result, seen, kStopAt);
  EXPECT_EQ(seen.size(), static_cast<std::size_t>(kStopAt + 1));  // iterations 0 (the start) to kStopAt
  EXPECT_EQ(result.residual_history.size(), seen.size());
}

INSTANTIATE_TEST_SUITE_P(AllForms, PolonskyKeerStopTest, testing::all_pk_solvers(), testing::solver_type_name);

TEST(ProgressStopTest, StopsTheAdhesiveSolver) {
  const Grid grid = Grid::plane(64, 64, 1e-8, 1e-8, Boundary::periodic);
  // A sphere of radius 1 um; Maugis-Dugdale with w = 0.01 J/m^2 and h0 = 2 nm
  // (sigma0 = 5 MPa: the cohesive zone spans many 10 nm cells at E* = 1 GPa).
  const Eigen::ArrayXd heights = geometry::make_surface_heights(grid, {geometry::SurfaceShape::sphere, 1e-6, 0.0, 0.0});
  SolverOptions options = testing::test_options(SolverType::pk);
  options.adhesion = SolverOptions::Adhesion{AdhesionLaw::maugis_dugdale(0.01, 2e-9), kUnreachableTolerance};
  std::vector<int> seen;
  options.progress = stop_at(kStopAt, seen);
  const SolveResult result = solve_surface(grid, {heights.data(), grid.size()}, 1e9, Loading::approach(1e-9), options);
  expect_stopped_at(result, seen, kStopAt);
}

TEST(ProgressStopTest, StopsTheTangentialSolver) {
  const ElasticPair pair = ElasticPair::similar({2.1e11, 0.3});
  const auto [grid, contact] = testing::hertz_sphere_contact(pair, 10.0, 0.01, 32);
  ASSERT_TRUE(contact.converged());
  TangentialOperator op(grid, pair);
  TangentialOptions options;
  options.friction_coefficient = 0.3;
  options.tolerance = kUnreachableTolerance;
  std::vector<int> seen;
  options.progress = stop_at(kStopAt, seen);
  TangentialSolver solver(op, options);
  const TangentialResult result = solver.solve({contact.pressure.data(), grid.size()}, TangentialLoading::force(1.0),
                                               TangentialState::unloaded(grid.size()));
  EXPECT_EQ(result.status, SolveStatus::stopped) << result.message;
  EXPECT_EQ(result.iterations, kStopAt);
  EXPECT_EQ(seen.back(), kStopAt);
}

TEST(ProgressStopTest, EndsASweepAtTheStoppedStep) {
  const Grid grid = Grid::plane(32, 32, 1e-5, 1e-5, Boundary::periodic);
  const Eigen::ArrayXd heights = rough_heights(grid);
  SolverOptions options = testing::test_options(SolverType::pk_fourier);
  int solves = 0;
  options.progress = [&solves](int iteration, double) {
    if (iteration == 0) ++solves;
    return solves == 2 && iteration == 1 ? IterationDecision::stop : IterationDecision::proceed;
  };
  const std::vector<double> loads{1e7, 2e7, 3e7};
  const std::vector<analysis::SweepStep> steps =
      analysis::sweep_surface(grid, {heights.data(), grid.size()}, 1e9, ControlMode::mean_pressure, loads, options);
  ASSERT_EQ(steps.size(), 2U);
  EXPECT_TRUE(steps[0].result.converged()) << steps[0].result.message;
  EXPECT_EQ(steps[1].result.status, SolveStatus::stopped);
  EXPECT_EQ(steps[1].result.iterations, 1);
}

TEST(ProgressStopTest, ExceptionsOfTheCallbackPassThrough) {
  const Grid grid = Grid::plane(32, 32, 1e-5, 1e-5, Boundary::periodic);
  const Eigen::ArrayXd heights = rough_heights(grid);
  SolverOptions options = testing::test_options(SolverType::pk);
  options.progress = [](int iteration, double) {
    if (iteration == 2) throw std::runtime_error("stop");
    return IterationDecision::proceed;
  };
  EXPECT_THROW(solve_surface(grid, {heights.data(), grid.size()}, 1e9, Loading::mean_pressure(1e7), options),
               std::runtime_error);
}

}  // namespace
}  // namespace halfspace::solvers
