// The dry contact a mixed film's solves start from (dry_contact_memo.hpp):
// Polonsky–Keer preconditioned on a homogeneous half-space's 2D grid, free
// or periodic, finds the plain solve's contact in fewer iterations, and is
// the plain solve itself on a line; a kept solve is handed out only for
// the same operator, grid, gap values and loading, and it is the dry
// contact's own solve to the bit.
#include "lubrication/dry_contact_memo.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>

#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/solvers/polonsky_keer.hpp"

namespace halfspace::lubrication {
namespace {

constexpr double kEStar = 1.1e11;  // Pa
constexpr double kRadius = 0.01;   // m
constexpr std::size_t kCells = 32;
constexpr double kSpacing = 5e-6;  // m
constexpr double kForce = 2.0;     // N: a Hertz radius of about 8 cells

// A ball's gap on the free kCells^2 grid.
Eigen::ArrayXd ball_gap() {
  Eigen::ArrayXd gap(static_cast<Eigen::Index>(kCells * kCells));
  const double centre = 0.5 * static_cast<double>(kCells - 1);
  for (std::size_t j = 0; j < kCells; ++j) {
    for (std::size_t i = 0; i < kCells; ++i) {
      const double x = (static_cast<double>(i) - centre) * kSpacing;
      const double y = (static_cast<double>(j) - centre) * kSpacing;
      gap[static_cast<Eigen::Index>(j * kCells + i)] = (x * x + y * y) / (2.0 * kRadius);
    }
  }
  return gap;
}

Grid ball_grid() {
  return Grid::plane(kCells, kCells, kSpacing, kSpacing, Boundary::free);
}

// The ball with waves of 0.1 um along both axes: a few dozen contact spots.
Eigen::ArrayXd rough_ball_gap() {
  Eigen::ArrayXd gap = ball_gap();
  for (std::size_t j = 0; j < kCells; ++j) {
    for (std::size_t i = 0; i < kCells; ++i) {
      gap[static_cast<Eigen::Index>(j * kCells + i)] +=
          5e-8 * (std::sin(1.3 * static_cast<double>(i)) + std::sin(0.9 * static_cast<double>(j) + 0.4));
    }
  }
  return gap - gap.minCoeff();
}

// The preconditioned solve is the plain one within the solvers' tolerance
// (1e-10 in the residual; the pressures to 1e-6 of the peak, the approach
// to 1e-9 of itself), in fewer iterations, on the free and the periodic
// grid; on a line it is the plain solve to the bit.
TEST(DryContactMemoTest, DryContactIsPreconditionedPolonskyKeerOnA2dHalfSpace) {
  const Eigen::ArrayXd gap = rough_ball_gap();
  const std::size_t n = gap.size();
  for (const Boundary boundary : {Boundary::free, Boundary::periodic}) {
    FftInfluenceOperator op(Grid::plane(kCells, kCells, kSpacing, kSpacing, boundary), kEStar);
    const solvers::SolveResult plain =
        solvers::PolonskyKeer(op).solve({gap.data(), n}, solvers::Loading::force(kForce));
    const solvers::SolveResult dry = detail::solve_dry_contact(op, gap, solvers::Loading::force(kForce));
    ASSERT_TRUE(plain.converged()) << plain.message;
    ASSERT_TRUE(dry.converged()) << dry.message;
    EXPECT_LT(dry.iterations, plain.iterations);
    EXPECT_GT(dry.preconditioner_applications, 0);
    EXPECT_LE((dry.pressure - plain.pressure).abs().maxCoeff(), 1e-6 * plain.max_pressure);
    EXPECT_NEAR(dry.approach, plain.approach, 1e-9 * std::abs(plain.approach));
    EXPECT_NEAR(dry.total_force, kForce, 1e-9 * kForce);
  }
  constexpr double kLineForce = 4e3;  // N/m: a Hertz half-width of about 4 cells
  const Grid line = Grid::line(kCells, kSpacing, Boundary::free);
  FftInfluenceOperator line_op(line, kEStar);
  const Eigen::ArrayXd profile = gap.head(kCells);
  const solvers::SolveResult plain =
      solvers::PolonskyKeer(line_op).solve({profile.data(), kCells}, solvers::Loading::force(kLineForce));
  const solvers::SolveResult dry = detail::solve_dry_contact(line_op, profile, solvers::Loading::force(kLineForce));
  ASSERT_TRUE(dry.converged()) << dry.message;
  EXPECT_EQ(dry.preconditioner_applications, 0);
  EXPECT_EQ(dry.iterations, plain.iterations);
  EXPECT_TRUE((dry.pressure == plain.pressure).all());
}

TEST(DryContactMemoTest, HandsOutTheKeptSolveOnlyForTheSameProblem) {
  FftInfluenceOperator op(ball_grid(), kEStar);
  const Eigen::ArrayXd gap = ball_gap();
  const std::size_t n = op.grid().size();
  detail::DryContactMemo memo;
  const solvers::SolveResult& first = memo.solve(op, gap, solvers::Loading::force(kForce));
  ASSERT_TRUE(first.converged()) << first.message;
  EXPECT_EQ(memo.solves(), 1);

  // The dry contact's own solve, to the bit.
  const solvers::SolveResult fresh = detail::solve_dry_contact(op, gap, solvers::Loading::force(kForce));
  ASSERT_EQ(fresh.pressure.size(), first.pressure.size());
  EXPECT_TRUE((fresh.pressure == first.pressure).all());
  EXPECT_EQ(fresh.approach, first.approach);
  EXPECT_EQ(fresh.max_pressure, first.max_pressure);

  // The same values in another array: kept.
  const Eigen::ArrayXd copy = gap;
  const solvers::SolveResult& again = memo.solve(op, copy, solvers::Loading::force(kForce));
  EXPECT_EQ(&again, &first);
  EXPECT_EQ(memo.solves(), 1);

  // Another load, another gap value, another loading mode: solved anew.
  const solvers::SolveResult& heavier = memo.solve(op, gap, solvers::Loading::force(2.0 * kForce));
  EXPECT_EQ(memo.solves(), 2);
  EXPECT_NEAR(heavier.total_force, 2.0 * kForce, 1e-6 * kForce);
  Eigen::ArrayXd moved = gap;
  moved[static_cast<Eigen::Index>(n / 2)] += 1e-9;
  memo.solve(op, moved, solvers::Loading::force(2.0 * kForce));
  EXPECT_EQ(memo.solves(), 3);
  const double approach = fresh.approach;
  const solvers::SolveResult& by_approach = memo.solve(op, moved, solvers::Loading::approach(approach));
  EXPECT_EQ(memo.solves(), 4);
  EXPECT_NEAR(by_approach.approach, approach, 1e-12 * approach);

  // Another operator on a grid of the same shape (a softer body): solved
  // anew, in the first operator's place (one kept solve per grid shape).
  FftInfluenceOperator softer(ball_grid(), 0.5 * kEStar);
  const solvers::SolveResult& soft = memo.solve(softer, gap, solvers::Loading::force(kForce));
  EXPECT_EQ(memo.solves(), 5);
  EXPECT_GT(soft.approach, 1.5 * fresh.approach);
  memo.solve(op, moved, solvers::Loading::approach(approach));
  EXPECT_EQ(memo.solves(), 6);

  // A grid of another shape is kept beside it.
  const Grid coarse = Grid::plane(kCells / 2, kCells / 2, 2.0 * kSpacing, 2.0 * kSpacing, Boundary::free);
  FftInfluenceOperator coarse_op(coarse, kEStar);
  Eigen::ArrayXd coarse_gap(static_cast<Eigen::Index>(coarse.size()));
  for (std::size_t j = 0; j < kCells / 2; ++j) {
    for (std::size_t i = 0; i < kCells / 2; ++i) {
      coarse_gap[static_cast<Eigen::Index>(j * kCells / 2 + i)] =
          gap[static_cast<Eigen::Index>(2 * j * kCells + 2 * i)];
    }
  }
  memo.solve(coarse_op, coarse_gap, solvers::Loading::force(kForce));
  EXPECT_EQ(memo.solves(), 7);
  memo.solve(op, moved, solvers::Loading::approach(approach));
  memo.solve(coarse_op, coarse_gap, solvers::Loading::force(kForce));
  EXPECT_EQ(memo.solves(), 7);
}

}  // namespace
}  // namespace halfspace::lubrication
