// The EHL GMRES's multigrid preconditioner (src/lubrication/film_multigrid.hpp)
// on its own: one V-cycle as a stationary iteration x += M (b - A x) on model
// Reynolds operators (diffusion with an upwind convection along x, the
// diffusion switched off where the film is piezoviscous), whose residual it
// must contract at a rate that does not grow with the grid.
#include "lubrication/film_multigrid.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/threads.hpp"
#include "lubrication/banded_lu.hpp"

namespace halfspace::lubrication::detail {
namespace {

// The finite-volume Reynolds operator with diffusion (Poiseuille)
// conductance `diffusion(x, y)` and a first-order upwind convection
// (Couette) of unit speed along +x, per unit cell; edges held fixed
// (identity rows) unless the grid is periodic.
template <class Diffusion>
CsrMatrix model_operator(const Grid& grid, Diffusion diffusion, double convection) {
  const std::size_t nx = grid.nx(), ny = grid.ny();
  CsrMatrix a;
  a.rows = nx * ny;
  a.start.push_back(0);
  for (std::size_t y = 0; y < ny; ++y) {
    for (std::size_t x = 0; x < nx; ++x) {
      const std::size_t k = y * nx + x;
      std::vector<std::pair<int, double>> row;
      const bool edge = x == 0 || y == 0 || x + 1 == nx || y + 1 == ny;
      if (edge && !grid.periodic()) {
        row.emplace_back(static_cast<int>(k), 1.0);
      } else {
        const auto wrap = [&](long i, long n) { return static_cast<std::size_t>((i + n) % n); };
        const std::size_t xw = wrap(static_cast<long>(x) - 1, static_cast<long>(nx));
        const std::size_t xe = wrap(static_cast<long>(x) + 1, static_cast<long>(nx));
        const std::size_t ys = wrap(static_cast<long>(y) - 1, static_cast<long>(ny));
        const std::size_t yn = wrap(static_cast<long>(y) + 1, static_cast<long>(ny));
        // Face conductances the mean of the two nodes' (the Reynolds
        // stencil's), so that the diffusion is conservative and symmetric.
        const double d = diffusion(x, y);
        const double west = 0.5 * (d + diffusion(xw, y)), east = 0.5 * (d + diffusion(xe, y));
        const double south = 0.5 * (d + diffusion(x, ys)), north = 0.5 * (d + diffusion(x, yn));
        row = {{static_cast<int>(k), west + east + south + north + convection},
               {static_cast<int>(y * nx + xw), -west - convection},
               {static_cast<int>(y * nx + xe), -east},
               {static_cast<int>(ys * nx + x), -south},
               {static_cast<int>(yn * nx + x), -north}};
        std::sort(row.begin(), row.end());
      }
      for (const auto& [column, value] : row) {
        a.column.push_back(column);
        a.value.push_back(value);
      }
      a.start.push_back(static_cast<int>(a.column.size()));
    }
  }
  return a;
}

// The mean contraction of the residual's norm per V-cycle over `cycles`
// cycles from x = 0 with a random right-hand side.
double contraction(FilmMultigrid& multigrid, const CsrMatrix& a, int cycles) {
  std::string message;
  EXPECT_TRUE(multigrid.factorise(a, message)) << message;
  const auto n = static_cast<Eigen::Index>(a.rows);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd b(n), x = Eigen::VectorXd::Zero(n), r(n), correction(n);
  for (Eigen::Index i = 0; i < n; ++i) b[i] = uniform(random);
  a.residual(b, x, r);
  const double first = r.norm();
  for (int c = 0; c < cycles; ++c) {
    multigrid.apply(r, correction);
    x += correction;
    a.residual(b, x, r);
  }
  return std::pow(r.norm() / first, 1.0 / cycles);
}

// One V-cycle (a forward and a backward line sweep around the coarse
// correction) contracts these residuals by 0.14-0.18 from 64^2 to 512^2
// (measured, 2026-11-29); 0.3 leaves room and would still fail a cycle
// whose rate grows with the grid (or diverges, as with unscaled columns or
// interpolation into fixed edges).
constexpr double kLargestContraction = 0.3;
constexpr int kCycles = 8;

// The Reynolds operator's cases: diffusion-dominated (an inlet), a jump of
// eight decades from 100 to 1e-6 (the pressure-viscosity's film) with the
// convection alone downstream, and the reverse.
struct ModelCase {
  const char* name;
  double upstream, downstream;  // the diffusion on either half of the grid (x < n / 2 and beyond)
};
constexpr ModelCase kModelCases[] = {{"uniform", 1.0, 1.0}, {"piezoviscous", 100.0, 1e-6}, {"reversed", 1e-6, 100.0}};

TEST(FilmMultigridTest, VCycleContractsModelReynoldsOperatorsAtEveryGridSize) {
  for (const std::size_t n : {64, 256}) {
    const Grid grid = Grid::plane(n, n, 1.0, 1.0, Boundary::free);
    FilmMultigrid multigrid(grid, 0, false);
    EXPECT_EQ(multigrid.levels(), n == 64 ? 2U : 4U);  // down to 32^2, solved by the sparse LU
    for (const ModelCase& c : kModelCases) {
      const CsrMatrix a = model_operator(
          grid, [&](std::size_t x, std::size_t) { return x < n / 2 ? c.upstream : c.downstream; }, 1.0);
      const double rate = contraction(multigrid, a, kCycles);
      EXPECT_LT(rate, kLargestContraction) << c.name << " on " << n << "^2";
    }
  }
}

// Columns scaled apart by five decades on every other line (as the
// cavitated nodes' d balance / d theta against the pressurised ones' d
// balance / dp p_scale): with the diagonal scaling the EHL solve uses, the
// V-cycle contracts as on the unscaled operator.
TEST(FilmMultigridTest, DiagonalScalingUndoesTheScaleOfTheUnknowns) {
  const std::size_t n = 128;
  const Grid grid = Grid::plane(n, n, 1.0, 1.0, Boundary::free);
  CsrMatrix a = model_operator(
      grid, [](std::size_t, std::size_t) { return 1.0; }, 1.0);
  for (std::size_t e = 0; e < a.entries(); ++e) {
    if ((a.column[e] / static_cast<int>(n)) % 2 == 1) a.value[e] *= 1e5;
  }
  FilmMultigrid scaled(grid, 0, true);
  EXPECT_LT(contraction(scaled, a, kCycles), kLargestContraction);
}

// Entrainment along y: lines along y, the model operator transposed in
// space (its convection along +y).
TEST(FilmMultigridTest, LinesFollowTheEntrainmentAlongY) {
  const std::size_t n = 128;
  const Grid grid = Grid::plane(n, n, 1.0, 1.0, Boundary::free);
  const CsrMatrix along_x = model_operator(
      grid, [&](std::size_t x, std::size_t) { return x < n / 2 ? 100.0 : 1e-6; }, 1.0);
  // Node (x, y) of the transposed operator is node (y, x) of this one.
  CsrMatrix along_y;
  along_y.rows = along_x.rows;
  along_y.start.push_back(0);
  const auto swap = [n](int k) {
    return static_cast<int>((k % static_cast<int>(n)) * static_cast<int>(n) + k / static_cast<int>(n));
  };
  for (std::size_t k = 0; k < along_x.rows; ++k) {
    const auto source = static_cast<std::size_t>(swap(static_cast<int>(k)));
    std::vector<std::pair<int, double>> row;
    for (int e = along_x.start[source]; e < along_x.start[source + 1]; ++e) {
      row.emplace_back(swap(along_x.column[e]), along_x.value[e]);
    }
    std::sort(row.begin(), row.end());
    for (const auto& [column, value] : row) {
      along_y.column.push_back(column);
      along_y.value.push_back(value);
    }
    along_y.start.push_back(static_cast<int>(along_y.column.size()));
  }
  FilmMultigrid lines_along_y(grid, 1, false);
  EXPECT_LT(contraction(lines_along_y, along_y, kCycles), kLargestContraction);
}

// A periodic grid (no fixed edges; a small reaction term, the compressible
// film's d rho / dp, keeps the operator regular).
TEST(FilmMultigridTest, VCycleContractsOnAPeriodicGrid) {
  const std::size_t n = 128;
  const Grid grid = Grid::plane(n, n, 1.0, 1.0, Boundary::periodic);
  CsrMatrix a = model_operator(
      grid, [&](std::size_t x, std::size_t) { return x < n / 2 ? 100.0 : 1e-6; }, 1.0);
  for (std::size_t k = 0; k < a.rows; ++k) {
    for (int e = a.start[k]; e < a.start[k + 1]; ++e) {
      if (a.column[e] == static_cast<int>(k)) a.value[e] += 1e-2;
    }
  }
  FilmMultigrid multigrid(grid, 0, false);
  EXPECT_LT(contraction(multigrid, a, kCycles), kLargestContraction);
}

// Grids of at least 256^2 nodes are swept in chains of lines, those of one
// colour on different threads (film_multigrid.cpp): the V-cycle must be the
// same linear map, to the bit, on one thread and on three, and still
// contract; on a periodic grid whose 9 chains of 32 lines are made 8 (an odd
// count would put two of one colour side by side across the wrap), and on
// a free one.
TEST(FilmMultigridTest, ChainedSweepsAreTheSameMapOnAnyThreadCount) {
  const int original = threads();
  for (const Boundary boundary : {Boundary::periodic, Boundary::free}) {
    const std::size_t n = boundary == Boundary::periodic ? 288 : 272;
    const Grid grid = Grid::plane(n, n, 1.0, 1.0, boundary);
    CsrMatrix a = model_operator(
        grid, [&](std::size_t x, std::size_t) { return x < n / 2 ? 100.0 : 1e-6; }, 1.0);
    for (std::size_t k = 0; k < a.rows; ++k) {
      for (int e = a.start[k]; e < a.start[k + 1]; ++e) {
        if (a.column[e] == static_cast<int>(k)) a.value[e] += 1e-2;
      }
    }
    Eigen::VectorXd in(static_cast<Eigen::Index>(a.rows));
    std::mt19937 random(11);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (Eigen::Index i = 0; i < in.size(); ++i) in[i] = uniform(random);
    std::vector<Eigen::VectorXd> out;
    for (const int count : {1, 3}) {
      set_threads(count);
      FilmMultigrid multigrid(grid, 0, false);
      std::string message;
      ASSERT_TRUE(multigrid.factorise(a, message)) << message;
      out.emplace_back();
      multigrid.apply(in, out.back());
      if (count == 3) {
        EXPECT_LT(contraction(multigrid, a, kCycles), kLargestContraction) << n << "^2";
      }
    }
    set_threads(original);
    ASSERT_EQ(out[0].size(), out[1].size());
    EXPECT_TRUE(out[0] == out[1]) << n << "^2: largest difference " << (out[0] - out[1]).cwiseAbs().maxCoeff();
  }
}

// The coarse operator is P^T A P (film_multigrid.cpp forms it as P^T (A
// P), row by row) for P built here from the header's rule alone: 3/4 from a
// node's own coarse cell and 1/4 from the next one on its side (the own
// cell alone at a free edge, wrapped on a periodic grid), fixed rows left
// out of both transfers, and a coarse node whose children are all fixed
// held by an identity row. A random operator reaching 2 cells each way
// (the mixed film's mass rows with the preconditioner's truncated K),
// identity rows on the free grid's edges; rounding is the only difference.
TEST(FilmMultigridTest, CoarseOperatorIsTheGalerkinProductOfAReach2Operator) {
  for (const Boundary boundary : {Boundary::free, Boundary::periodic}) {
    const std::size_t nx = 48, ny = 40, n = nx * ny;  // one coarsening: 24 x 20 <= kDirectNodes
    const Grid grid = Grid::plane(nx, ny, 1.0, 1.0, boundary);
    const bool periodic = boundary == Boundary::periodic;
    std::mt19937 random(5);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    CsrMatrix a;
    a.clear();
    std::vector<std::pair<int, double>> row;
    std::vector<char> fixed(n, 0);
    for (std::size_t y = 0; y < ny; ++y) {
      for (std::size_t x = 0; x < nx; ++x) {
        const std::size_t k = y * nx + x;
        if (!periodic && (x == 0 || y == 0 || x + 1 == nx || y + 1 == ny)) {
          fixed[k] = 1;
          row.emplace_back(static_cast<int>(k), 1.0);
        } else {
          for (long dy = -2; dy <= 2; ++dy) {
            for (long dx = -2; dx <= 2; ++dx) {
              const long jx = static_cast<long>(x) + dx, jy = static_cast<long>(y) + dy;
              const auto wrap = [](long i, std::size_t m) { return (i + static_cast<long>(m)) % static_cast<long>(m); };
              if (!periodic && (jx < 0 || jy < 0 || jx >= static_cast<long>(nx) || jy >= static_cast<long>(ny)))
                continue;
              const double value = dx == 0 && dy == 0 ? 30.0 : uniform(random);
              row.emplace_back(static_cast<int>(wrap(jy, ny) * static_cast<long>(nx) + wrap(jx, nx)), value);
            }
          }
        }
        a.append_row(row);
      }
    }
    FilmMultigrid multigrid(grid, 0, false);
    std::string message;
    ASSERT_TRUE(multigrid.factorise(a, message)) << message;
    ASSERT_EQ(multigrid.levels(), 2U);
    // P (n x nc), dense.
    const std::size_t cx = nx / 2, cy = ny / 2, nc = cx * cy;
    const auto axis_weights = [&](std::size_t i, std::size_t coarse) {
      std::vector<std::pair<std::size_t, double>> weights;
      const long own = static_cast<long>(i / 2);
      long other = i % 2 == 0 ? own - 1 : own + 1;
      if (periodic) other = (other + static_cast<long>(coarse)) % static_cast<long>(coarse);
      if (other < 0 || other >= static_cast<long>(coarse)) {
        weights.emplace_back(static_cast<std::size_t>(own), 1.0);
      } else {
        weights.emplace_back(static_cast<std::size_t>(own), 0.75);
        weights.emplace_back(static_cast<std::size_t>(other), 0.25);
      }
      return weights;
    };
    Eigen::MatrixXd p = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(nc));
    for (std::size_t k = 0; k < n; ++k) {
      if (fixed[k]) continue;
      for (const auto& [px, wx] : axis_weights(k % nx, cx)) {
        for (const auto& [py, wy] : axis_weights(k / nx, cy)) {
          p(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(py * cx + px)) += wx * wy;
        }
      }
    }
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    for (std::size_t k = 0; k < n; ++k) {
      for (int e = a.start[k]; e < a.start[k + 1]; ++e) dense(static_cast<Eigen::Index>(k), a.column[e]) += a.value[e];
    }
    Eigen::MatrixXd expected = p.transpose() * dense * p;
    for (Eigen::Index c = 0; c < expected.rows(); ++c) {
      if (p.col(c).isZero()) expected(c, c) = 1.0;  // every child fixed
    }
    const CsrMatrix& coarse = multigrid.level_matrix(1);
    ASSERT_EQ(coarse.rows, nc);
    Eigen::MatrixXd formed = Eigen::MatrixXd::Zero(expected.rows(), expected.cols());
    for (std::size_t k = 0; k < nc; ++k) {
      for (int e = coarse.start[k]; e < coarse.start[k + 1]; ++e) {
        EXPECT_EQ(formed(static_cast<Eigen::Index>(k), coarse.column[e]), 0.0) << "a column twice in row " << k;
        formed(static_cast<Eigen::Index>(k), coarse.column[e]) = coarse.value[e];
      }
    }
    EXPECT_LE((formed - expected).cwiseAbs().maxCoeff(), 1e-13 * expected.cwiseAbs().maxCoeff())
        << (periodic ? "periodic" : "free");
    EXPECT_GT(expected.cwiseAbs().maxCoeff(), 1.0);
  }
}

// The line solves: a band that needs row interchanges (zero diagonal
// entries) against Eigen's dense partial-pivot LU, to rounding.
TEST(BandedLuTest, SolvesABandThatNeedsPivoting) {
  constexpr double kRounding = 1e-12;  // relative to the solution's largest entry
  const int n = 12, kl = 2, ku = 1;
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  std::vector<double> band(static_cast<std::size_t>(n) * banded_lu_stride(kl, ku), 0.0);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int i = 0; i < n; ++i) {
    for (int j = std::max(0, i - kl); j <= std::min(n - 1, i + ku); ++j) {
      const double value = i == j && i % 3 == 0 ? 0.0 : uniform(random);
      dense(i, j) = value;
      band[banded_index(kl, ku, static_cast<std::size_t>(i), static_cast<std::size_t>(j))] = value;
    }
  }
  Eigen::VectorXd rhs(n);
  for (int i = 0; i < n; ++i) rhs[i] = uniform(random);
  const Eigen::VectorXd expected = dense.partialPivLu().solve(rhs);
  std::vector<int> pivots(static_cast<std::size_t>(n));
  ASSERT_TRUE(banded_lu_factorise(band, pivots, kl, ku));
  std::vector<double> x(rhs.data(), rhs.data() + n);
  banded_lu_solve(band, pivots, kl, ku, x);
  for (int i = 0; i < n; ++i) {
    EXPECT_NEAR(x[static_cast<std::size_t>(i)], expected[i], kRounding * expected.cwiseAbs().maxCoeff())
        << "entry " << i;
  }
}

TEST(BandedLuTest, ReportsASingularBand) {
  std::vector<double> band(3 * banded_lu_stride(1, 1), 0.0);
  std::vector<int> pivots(3);
  EXPECT_FALSE(banded_lu_factorise(band, pivots, 1, 1));
}

}  // namespace
}  // namespace halfspace::lubrication::detail
