// Coarsening, block averages, piecewise-constant and bilinear prolongation
// between a grid and the grid of twice its spacing (the coarse-grid start of
// pk-multilevel, the EHL film's grid sequencing).
#include "halfspace/solvers/grid_transfer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace halfspace::solvers {
namespace {

TEST(GridTransferTest, CoarserGridKeepsTheDomain) {
  const Grid plane = Grid::plane(64, 32, 1e-6, 2e-6, Boundary::periodic);
  const std::optional<Grid> coarse = coarser_grid(plane, 8);
  ASSERT_TRUE(coarse.has_value());
  EXPECT_EQ(coarse->nx(), 32u);
  EXPECT_EQ(coarse->ny(), 16u);
  EXPECT_DOUBLE_EQ(coarse->dx(), 2e-6);
  EXPECT_DOUBLE_EQ(coarse->dy(), 4e-6);
  EXPECT_DOUBLE_EQ(coarse->domain_area(), plane.domain_area());
  EXPECT_EQ(coarse->boundary(), Boundary::periodic);

  const std::optional<Grid> line = coarser_grid(Grid::line(100, 1e-6, Boundary::free), 8);
  ASSERT_TRUE(line.has_value());
  EXPECT_EQ(line->dimension(), 1);
  EXPECT_EQ(line->nx(), 50u);
  EXPECT_EQ(line->boundary(), Boundary::free);
}

TEST(GridTransferTest, NoCoarserGridForOddSidesOrBelowTheMinimum) {
  EXPECT_FALSE(coarser_grid(Grid::plane(63, 64, 1e-6, 1e-6, Boundary::periodic), 8));
  EXPECT_FALSE(coarser_grid(Grid::plane(64, 30, 1e-6, 1e-6, Boundary::periodic), 16));  // 15 rows < 16
  EXPECT_FALSE(coarser_grid(Grid::line(33, 1e-6, Boundary::free), 2));
  EXPECT_TRUE(coarser_grid(Grid::plane(64, 32, 1e-6, 1e-6, Boundary::periodic), 16));
}

TEST(GridTransferTest, RestrictionAveragesBlocks) {
  const Grid fine = Grid::plane(4, 2, 1.0, 1.0, Boundary::free);
  // Rows (y) of 4 cells: the 2x2 blocks average to 3.5 and 5.5.
  const std::vector<double> values{1, 2, 3, 4, 5, 6, 7, 8};
  std::vector<double> coarse(2);
  restrict_by_average(fine, values, coarse);
  EXPECT_DOUBLE_EQ(coarse[0], (1 + 2 + 5 + 6) / 4.0);
  EXPECT_DOUBLE_EQ(coarse[1], (3 + 4 + 7 + 8) / 4.0);

  const Grid line = Grid::line(6, 1.0, Boundary::periodic);
  std::vector<double> line_coarse(3);
  restrict_by_average(line, std::vector<double>{1, 3, 5, 7, 9, 11}, line_coarse);
  EXPECT_EQ(line_coarse, (std::vector<double>{2, 6, 10}));
}

TEST(GridTransferTest, ProlongationCopiesEachCoarseValueToItsBlockAndRestrictionUndoesIt) {
  const Grid fine = Grid::plane(6, 4, 1.0, 1.0, Boundary::periodic);
  const std::vector<double> coarse{1, 2, 3, 4, 5, 6};  // 3 x 2
  std::vector<double> values(fine.size());
  prolong_constant(fine, coarse, values);
  for (std::size_t j = 0; j < 4; ++j) {
    for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(values[j * 6 + i], coarse[(j / 2) * 3 + i / 2]) << j << "," << i;
  }
  std::vector<double> back(coarse.size());
  restrict_by_average(fine, values, back);
  EXPECT_EQ(back, coarse);
}

// A coarse field linear in the node indices comes back exact wherever the
// fine node lies between coarse nodes (coarse coordinates i/2 - 1/4, j/2 -
// 1/4) and held at the edge value beyond; on a periodic grid the weights of
// every fine node sum to one, so a constant stays constant.
TEST(GridTransferTest, BilinearProlongationIsExactForLinearFields) {
  const Grid fine = Grid::plane(8, 6, 1.0, 1.0, Boundary::free);
  const std::size_t cx = 4, cy = 3;
  std::vector<double> coarse(cx * cy);
  const auto linear = [](double x, double y) { return 1.0 + 2.0 * x - 3.0 * y; };
  for (std::size_t j = 0; j < cy; ++j) {
    for (std::size_t i = 0; i < cx; ++i) coarse[j * cx + i] = linear(static_cast<double>(i), static_cast<double>(j));
  }
  std::vector<double> values(fine.size());
  prolong_bilinear(fine, coarse, values);
  for (std::size_t j = 0; j < fine.ny(); ++j) {
    for (std::size_t i = 0; i < fine.nx(); ++i) {
      const double x = std::clamp(0.5 * static_cast<double>(i) - 0.25, 0.0, static_cast<double>(cx - 1));
      const double y = std::clamp(0.5 * static_cast<double>(j) - 0.25, 0.0, static_cast<double>(cy - 1));
      EXPECT_NEAR(values[j * fine.nx() + i], linear(x, y), 1e-12) << "node " << i << ", " << j;
    }
  }
  const Grid periodic = Grid::plane(8, 6, 1.0, 1.0, Boundary::periodic);
  std::vector<double> constant(cx * cy, 2.5);
  prolong_bilinear(periodic, constant, values);
  for (double v : values) EXPECT_NEAR(v, 2.5, 1e-14);
}

}  // namespace
}  // namespace halfspace::solvers
