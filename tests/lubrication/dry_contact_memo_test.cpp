// The dry contact kept for a mixed film's solves (dry_contact_memo.hpp): a
// kept solve is handed out only for the same operator, grid, gap values and
// loading, and it is Polonsky–Keer's own solve to the bit.
#include "lubrication/dry_contact_memo.hpp"

#include <gtest/gtest.h>

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

TEST(DryContactMemoTest, HandsOutTheKeptSolveOnlyForTheSameProblem) {
  FftInfluenceOperator op(ball_grid(), kEStar);
  const Eigen::ArrayXd gap = ball_gap();
  const std::size_t n = op.grid().size();
  detail::DryContactMemo memo;
  const solvers::SolveResult& first = memo.solve(op, gap, solvers::Loading::force(kForce));
  ASSERT_TRUE(first.converged()) << first.message;
  EXPECT_EQ(memo.solves(), 1);

  // Polonsky–Keer's own solve, to the bit.
  solvers::PolonskyKeer solver(op);
  const solvers::SolveResult fresh = solver.solve({gap.data(), n}, solvers::Loading::force(kForce));
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
