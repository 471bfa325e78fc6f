// Block deflation: its coarse matrix against Z^T K Z assembled from FFT
// products, exact where every block pair is a neighbour pair and close
// (point loads beyond the neighbours) on a larger grid, periodic and free;
// the correction it adds; and the input it refuses.
#include "halfspace/solvers/block_deflation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "operators/operator_test_support.hpp"
#include "support/boundary_param.hpp"

namespace halfspace::solvers {
namespace {

using testing::random_field;

constexpr double kEStar = 1e9;  // Pa

// A random search set covering about `share` of the cells.
std::vector<std::uint8_t> random_set(std::size_t n, double share, unsigned seed) {
  std::mt19937 generator(seed);
  std::bernoulli_distribution in(share);
  std::vector<std::uint8_t> set(n);
  for (auto& s : set) s = in(generator) ? 1 : 0;
  return set;
}

struct Fixture {
  Grid grid;
  std::size_t block;
  FftInfluenceOperator op;
  BlockDeflation deflation;
  std::vector<std::uint8_t> set;

  Fixture(std::size_t nx, std::size_t ny, std::size_t b, double share, Boundary boundary = Boundary::periodic)
      : grid(Grid::plane(nx, ny, 1e-6, 1.5e-6, boundary)),
        block(b),
        op(grid, kEStar),
        deflation(grid, BlockDeflationOptions{b, 1e9}),
        set(random_set(grid.size(), share, 7)) {
    std::vector<double> unit(grid.size(), 0.0);
    std::vector<double> response(grid.size());
    unit[0] = 1.0;
    op.apply(unit, response);
    deflation.set_kernel(response);
    deflation.update([&](std::size_t i) { return set[i] != 0; });
    EXPECT_TRUE(deflation.ready());
  }

  std::size_t owner(std::size_t i) const {
    const std::size_t row = i / grid.nx();
    const std::size_t col = i % grid.nx();
    return (row / block) * (grid.nx() / block) + col / block;
  }

  // Column J of Z^T K Z by one product of Z e_J.
  std::vector<double> galerkin_column(std::size_t J) {
    std::vector<double> field(grid.size(), 0.0);
    std::vector<double> image(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i) field[i] = (set[i] && owner(i) == J) ? 1.0 : 0.0;
    op.apply(field, image);
    std::vector<double> column(deflation.coarse_size(), 0.0);
    for (std::size_t i = 0; i < grid.size(); ++i) {
      if (set[i]) column[owner(i)] += image[i];
    }
    return column;
  }

  std::vector<double> coarse_column(std::size_t J) {
    std::vector<double> unit(deflation.coarse_size(), 0.0);
    std::vector<double> column(deflation.coarse_size());
    unit[J] = 1.0;
    deflation.apply_coarse(unit, column);
    return column;
  }
};

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// 3 x 3 blocks: every pair is a neighbour pair (across the period), so A is
// the exact Galerkin matrix up to rounding.
TEST(BlockDeflationTest, CoarseMatrixIsExactWhenAllBlocksAreNeighbours) {
  Fixture f(24, 24, 8, 0.3);
  for (std::size_t J = 0; J < f.deflation.coarse_size(); ++J) {
    const std::vector<double> exact = f.galerkin_column(J);
    const std::vector<double> built = f.coarse_column(J);
    const double scale = max_abs(exact);
    for (std::size_t I = 0; I < exact.size(); ++I) {
      EXPECT_NEAR(built[I], exact[I], 1e-10 * scale) << "block " << I << ", column " << J;
    }
  }
}

// 8 x 6 blocks: the neighbours (across the period on a periodic grid)
// exact, the others point loads between block centres, which for 8-cell
// blocks two or more blocks apart are within a few percent of the diagonal's
// scale.
void expect_near_exact_and_far_close(Fixture& f) {
  const auto bx = static_cast<long>(f.grid.nx() / f.block);
  const auto by = static_cast<long>(f.grid.ny() / f.block);
  const bool periodic = f.grid.periodic();
  for (std::size_t J : {std::size_t{0}, std::size_t{13}, std::size_t{47}}) {
    const std::vector<double> exact = f.galerkin_column(J);
    const std::vector<double> built = f.coarse_column(J);
    const double diagonal = exact[J];
    for (std::size_t I = 0; I < exact.size(); ++I) {
      const long dy = std::labs(static_cast<long>(I) / bx - static_cast<long>(J) / bx);
      const long dx = std::labs(static_cast<long>(I) % bx - static_cast<long>(J) % bx);
      const bool near_y = dy <= 1 || (periodic && dy == by - 1);
      const bool near_x = dx <= 1 || (periodic && dx == bx - 1);
      const double tolerance = near_x && near_y ? 1e-10 : 0.03;
      EXPECT_NEAR(built[I], exact[I], tolerance * diagonal) << "block " << I << ", column " << J;
    }
  }
}

TEST(BlockDeflationTest, CoarseMatrixMatchesGalerkinNearAndApproximatesItFar) {
  Fixture f(64, 48, 8, 0.3);
  expect_near_exact_and_far_close(f);
}

// The same on a free grid: the neighbours stop at the edges (no wrap), and
// the far field is a linear convolution: blocks at opposite edges interact
// by their true distance (with wrapping, the test's 3 % would fail there by
// far).
TEST(BlockDeflationTest, FreeGridCoarseMatrixMatchesGalerkinNearAndApproximatesItFar) {
  Fixture f(64, 48, 8, 0.3, Boundary::free);
  expect_near_exact_and_far_close(f);
}

// y read back from a prolonged field Z y, and Z^T g, by block.
struct Coarse {
  std::vector<double> y;
  std::vector<double> rhs;
  std::vector<double> counts;
};

Coarse read_back(Fixture& f, const std::vector<double>& field, const std::vector<double>& g) {
  const std::size_t m = f.deflation.coarse_size();
  Coarse c{std::vector<double>(m, 0.0), std::vector<double>(m, 0.0), std::vector<double>(m, 0.0)};
  for (std::size_t i = 0; i < f.grid.size(); ++i) {
    if (f.set[i]) {
      c.y[f.owner(i)] = field[i];
      c.rhs[f.owner(i)] += g[i];
      c.counts[f.owner(i)] += 1.0;
    } else {
      EXPECT_EQ(field[i], 0.0) << "cell " << i << " is outside the set";
    }
  }
  return c;
}

// pre_correction solves A y = Z^T g and writes Z y: y on the set's cells of
// each block, zero elsewhere.
class BlockDeflationBoundaryTest : public ::testing::TestWithParam<Boundary> {};

TEST_P(BlockDeflationBoundaryTest, PreCorrectionSolvesTheCoarseSystemOnTheSet) {
  Fixture f(48, 48, 8, 0.4, GetParam());
  const std::vector<double> g = random_field(f.grid.size(), 3);
  std::vector<double> field(f.grid.size(), 0.5);
  f.deflation.pre_correction(g, field, false);
  const Coarse c = read_back(f, field, g);
  std::vector<double> image(c.y.size());
  f.deflation.apply_coarse(c.y, image);
  for (std::size_t I = 0; I < c.y.size(); ++I) EXPECT_NEAR(image[I], c.rhs[I], 1e-7 * max_abs(c.rhs)) << "block " << I;
  EXPECT_EQ(f.deflation.stats().unconverged_coarse_solves, 0);
}

// Under a fixed load the correction moves no load (n^T y = 0) and solves A y
// = Z^T g up to a multiple of n, the coarse multiplier.
TEST_P(BlockDeflationBoundaryTest, FixedLoadCorrectionMovesNoLoad) {
  Fixture f(48, 48, 8, 0.4, GetParam());
  const std::vector<double> g = random_field(f.grid.size(), 5);
  std::vector<double> field(f.grid.size());
  f.deflation.pre_correction(g, field, true);
  const Coarse c = read_back(f, field, g);
  double load = 0.0;
  double scale = 0.0;
  for (std::size_t I = 0; I < c.y.size(); ++I) {
    load += c.counts[I] * c.y[I];
    scale += c.counts[I] * std::abs(c.y[I]);
  }
  EXPECT_LE(std::abs(load), 1e-10 * scale);
  std::vector<double> image(c.y.size());
  f.deflation.apply_coarse(c.y, image);
  // The multiplier: the least-squares lambda of rhs - A y = lambda n.
  double along = 0.0;
  double norm = 0.0;
  for (std::size_t I = 0; I < c.y.size(); ++I) {
    along += c.counts[I] * (c.rhs[I] - image[I]);
    norm += c.counts[I] * c.counts[I];
  }
  const double lambda = along / norm;
  for (std::size_t I = 0; I < c.y.size(); ++I) {
    EXPECT_NEAR(image[I] + lambda * c.counts[I], c.rhs[I], 1e-6 * max_abs(c.rhs)) << "block " << I;
  }
}

// Cells leaving and entering: A updated by the changed cells equals the
// Galerkin matrix of the new set; a large change rebuilds it; no change
// leaves it. (3 x 3 blocks: on a free grid the corner blocks are not
// neighbours, so there the far entries are checked at the far tolerance.)
TEST_P(BlockDeflationBoundaryTest, UpdatesByTheChangedCells) {
  Fixture f(24, 24, 8, 0.4, GetParam());
  const bool periodic = GetParam() == Boundary::periodic;
  auto tolerance = [&](std::size_t I, std::size_t J) {
    const auto dy = static_cast<long>(I / 3) - static_cast<long>(J / 3);
    const auto dx = static_cast<long>(I % 3) - static_cast<long>(J % 3);
    return periodic || (std::labs(dy) <= 1 && std::labs(dx) <= 1) ? 1e-10 : 0.03;
  };
  std::mt19937 generator(11);
  std::bernoulli_distribution flip(0.1);
  for (auto& s : f.set) {
    if (flip(generator)) s = s ? 0 : 1;
  }
  f.deflation.update([&](std::size_t i) { return f.set[i] != 0; });
  EXPECT_EQ(f.deflation.stats().rebuilds, 1);
  EXPECT_EQ(f.deflation.stats().updates, 1);
  for (std::size_t J = 0; J < f.deflation.coarse_size(); ++J) {
    const std::vector<double> exact = f.galerkin_column(J);
    const std::vector<double> built = f.coarse_column(J);
    for (std::size_t I = 0; I < exact.size(); ++I) {
      EXPECT_NEAR(built[I], exact[I], tolerance(I, J) * max_abs(exact)) << "block " << I << ", column " << J;
    }
  }
  f.deflation.update([&](std::size_t i) { return f.set[i] != 0; });
  EXPECT_EQ(f.deflation.stats().updates, 1) << "no change, no update";
  for (auto& s : f.set) s = s ? 0 : 1;
  f.deflation.update([&](std::size_t i) { return f.set[i] != 0; });
  EXPECT_EQ(f.deflation.stats().rebuilds, 2);
  const std::vector<double> exact = f.galerkin_column(4);
  const std::vector<double> built = f.coarse_column(4);
  for (std::size_t I = 0; I < exact.size(); ++I) EXPECT_NEAR(built[I], exact[I], tolerance(I, 4) * max_abs(exact));
}

INSTANTIATE_TEST_SUITE_P(Boundaries, BlockDeflationBoundaryTest, ::testing::Values(Boundary::periodic, Boundary::free),
                         testing::boundary_param_name);

// A full build whose pair sums exceed the budget is not made.
TEST(BlockDeflationTest, DeclinesDenseContacts) {
  const Grid grid = Grid::plane(48, 48, 1.0, 1.0, Boundary::periodic);
  BlockDeflationOptions options{8};
  // Per cell 9 n_B: 576 at full contact, about 52 at 30 %.
  options.max_pair_terms = 288.0;
  BlockDeflation deflation(grid, options);
  // The same decision before the kernel is known.
  EXPECT_TRUE(deflation.decline_if_dense([](std::size_t) { return true; }));
  EXPECT_EQ(deflation.stats().declined, 1);
  const std::vector<std::uint8_t> sparse_set = random_set(grid.size(), 0.3, 9);
  EXPECT_FALSE(deflation.decline_if_dense([&](std::size_t i) { return sparse_set[i] != 0; }));
  EXPECT_EQ(deflation.stats().declined, 1);
  FftInfluenceOperator op(grid, kEStar);
  std::vector<double> unit(grid.size(), 0.0);
  std::vector<double> response(grid.size());
  unit[0] = 1.0;
  op.apply(unit, response);
  deflation.set_kernel(response);
  deflation.update([](std::size_t) { return true; });
  EXPECT_FALSE(deflation.ready());
  EXPECT_EQ(deflation.stats().declined, 2);
  const std::vector<std::uint8_t> sparse = random_set(grid.size(), 0.3, 9);
  deflation.update([&](std::size_t i) { return sparse[i] != 0; });
  EXPECT_TRUE(deflation.ready());
}

TEST(BlockDeflationTest, RefusesGridsItCannotCover) {
  EXPECT_TRUE(BlockDeflation::covers(Grid::plane(64, 64, 1e-6, 1e-6, Boundary::free), 8));
  EXPECT_THROW(BlockDeflation(Grid::plane(64, 16, 1e-6, 1e-6, Boundary::free), {8}), InputError);
  EXPECT_THROW(BlockDeflation(Grid::line(64, 1e-6, Boundary::periodic), {8}), InputError);
  EXPECT_THROW(BlockDeflation(Grid::plane(60, 64, 1e-6, 1e-6, Boundary::periodic), {8}), InputError);
  EXPECT_THROW(BlockDeflation(Grid::plane(16, 64, 1e-6, 1e-6, Boundary::periodic), {8}), InputError);
  EXPECT_THROW(BlockDeflation(Grid::plane(64, 64, 1e-6, 1e-6, Boundary::periodic), {0}), InputError);
}

// A slab of rows is for a distributed grid (the MPI build's tests solve
// those): on one process the correction holds every row.
TEST(BlockDeflationTest, OneProcessHoldsEveryRow) {
  const Grid grid = Grid::plane(64, 64, 1e-6, 1e-6, Boundary::periodic);
  const linalg::Communicator& one = linalg::serial_communicator();
  EXPECT_EQ(BlockDeflation(grid, {8}, 0, 64, one).local_size(), grid.size());
  EXPECT_THROW(BlockDeflation(grid, {8}, 0, 32, one), InputError);
  EXPECT_THROW(BlockDeflation(grid, {8}, 32, 32, one), InputError);
  EXPECT_THROW(BlockDeflation(grid, {8}, 32, 64, one), InputError);
}

}  // namespace
}  // namespace halfspace::solvers
