// The FFT convolution operator against the assembled dense matrix (all four
// kernels, odd and even sizes, dx != dy), the exact periodic response to a
// Fourier mode, self-influence, repeatability, in-place application and
// thread independence.
#include "halfspace/operators/fft_influence_operator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <span>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/operators/dense_influence_operator.hpp"
#include "halfspace/threads.hpp"
#include "operators/operator_test_support.hpp"

namespace halfspace {
namespace {

using testing::max_error;
using testing::random_field;

constexpr double kEStar = 1.1e11;  // Pa
constexpr double kPi = std::numbers::pi;
// FFT against direct matrix-vector product: both exact up to rounding, which
// grows like eps log N in the FFT.
constexpr double kDenseMatchTolerance = 1e-12;
// Single Fourier mode: the FFT reproduces the analytic 2/(E* q) to rounding.
constexpr double kModeTolerance = 1e-13;
// Periodic self-influence: the same sum over the spectrum in another order.
constexpr double kSelfInfluenceTolerance = 1e-13;
// 1 vs 2 threads: FFTW may split the transform differently; rounding only.
constexpr double kThreadTolerance = 1e-14;

std::vector<double> apply_to(InfluenceOperator& op, const std::vector<double>& pressure) {
  std::vector<double> displacement(pressure.size());
  op.apply(pressure, displacement);
  return displacement;
}

// Largest relative error of the FFT operator against the dense matrix on one
// grid, printed with its location.
double fft_versus_dense(const Grid& grid, unsigned seed) {
  FftInfluenceOperator fft(grid, kEStar);
  DenseInfluenceOperator dense(grid, kEStar);
  const std::vector<double> pressure = random_field(grid.size(), seed);
  const auto error = max_error(apply_to(fft, pressure), apply_to(dense, pressure));
  std::printf("FFT vs dense, %s %s: largest relative error %.2e at cell (%zu, %zu)\n",
              std::string(to_string(grid.boundary())).c_str(), grid.shape_string().c_str(), error.relative,
              error.index % grid.nx(), error.index / grid.nx());
  return error.relative;
}

void expect_matches_dense(const std::vector<Grid>& grids) {
  unsigned seed = 1;
  for (const Grid& grid : grids) {
    EXPECT_LE(fft_versus_dense(grid, seed++), kDenseMatchTolerance)
        << to_string(grid.boundary()) << " grid " << grid.shape_string();
  }
}

std::vector<Grid> line_grids(Boundary boundary) {
  std::vector<Grid> grids;
  for (const std::size_t n : {7u, 8u, 15u, 16u, 255u}) grids.push_back(Grid::line(n, 2e-6, boundary));
  return grids;
}

std::vector<Grid> plane_grids(Boundary boundary) {
  // (nx, ny) odd/even mixes with dx != dy; 100x4 reaches Love's far-field branch.
  return {Grid::plane(9, 6, 1e-6, 1.7e-6, boundary), Grid::plane(8, 12, 1.3e-6, 1e-6, boundary),
          Grid::plane(15, 10, 1e-6, 1e-6, boundary), Grid::plane(16, 7, 2e-6, 0.5e-6, boundary),
          Grid::plane(100, 4, 1e-6, 1e-6, boundary)};
}

TEST(FftInfluenceOperatorTest, MatchesDenseMatrixPeriodic1D) {
  expect_matches_dense(line_grids(Boundary::periodic));
}
TEST(FftInfluenceOperatorTest, MatchesDenseMatrixFree1D) {
  expect_matches_dense(line_grids(Boundary::free));
}
TEST(FftInfluenceOperatorTest, MatchesDenseMatrixPeriodic2D) {
  expect_matches_dense(plane_grids(Boundary::periodic));
}
TEST(FftInfluenceOperatorTest, MatchesDenseMatrixFree2D) {
  expect_matches_dense(plane_grids(Boundary::free));
}

// u = 2/(E* q) cos(q . x) for p = cos(q . x), to rounding.
// Mode m on n points is the wave 2 pi m' / (n h) with m' = m or m - n,
// whichever is nearer zero (aliasing).
double mode_wavenumber(std::size_t m, std::size_t n, double h) {
  const double nearest = 2 * m <= n ? static_cast<double>(m) : static_cast<double>(m) - static_cast<double>(n);
  return 2.0 * kPi * nearest / (static_cast<double>(n) * h);
}

void expect_mode_response(const Grid& grid, std::size_t mx, std::size_t my) {
  const double qx = mode_wavenumber(mx, grid.nx(), grid.dx());
  const double qy = grid.dimension() == 1 ? 0.0 : mode_wavenumber(my, grid.ny(), grid.dy());
  std::vector<double> pressure(grid.size());
  for (std::size_t j = 0; j < grid.ny(); ++j) {
    for (std::size_t i = 0; i < grid.nx(); ++i) {
      const double phase = 2.0 * kPi *
                           (static_cast<double>((mx * i) % grid.nx()) / static_cast<double>(grid.nx()) +
                            static_cast<double>((my * j) % grid.ny()) / static_cast<double>(grid.ny()));
      pressure[j * grid.nx() + i] = std::cos(phase);
    }
  }
  FftInfluenceOperator op(grid, kEStar);
  const std::vector<double> displacement = apply_to(op, pressure);
  const double gain = 2.0 / (kEStar * std::hypot(qx, qy));
  std::vector<double> expected(pressure.size());
  for (std::size_t k = 0; k < pressure.size(); ++k) expected[k] = gain * pressure[k];
  const auto error = max_error(displacement, expected);
  EXPECT_LE(error.relative, kModeTolerance)
      << grid.shape_string() << " mode (" << mx << ", " << my << "): at cell " << error.index;
}

TEST(FftInfluenceOperatorTest, PeriodicFourierModeIsExact1D) {
  const Grid grid = Grid::line(16, 3e-6, Boundary::periodic);
  expect_mode_response(grid, 3, 0);
  expect_mode_response(grid, 8, 0);  // Nyquist
  expect_mode_response(Grid::line(15, 3e-6, Boundary::periodic), 7, 0);
}

TEST(FftInfluenceOperatorTest, PeriodicFourierModeIsExact2D) {
  const Grid grid = Grid::plane(12, 10, 1e-6, 1.6e-6, Boundary::periodic);
  expect_mode_response(grid, 2, 3);
  expect_mode_response(grid, 0, 5);
  expect_mode_response(grid, 6, 1);
  expect_mode_response(grid, 11, 9);
  // An odd number of rows: the kernel stores rows 0..ny/2 and folds the rest.
  const Grid odd = Grid::plane(8, 7, 1e-6, 1.3e-6, Boundary::periodic);
  expect_mode_response(odd, 1, 3);
  expect_mode_response(odd, 3, 4);
  expect_mode_response(odd, 5, 6);
}

TEST(FftInfluenceOperatorTest, PeriodicOutputHasZeroMean) {
  for (const Grid& grid :
       {Grid::line(15, 1e-6, Boundary::periodic), Grid::plane(9, 8, 1e-6, 2e-6, Boundary::periodic)}) {
    FftInfluenceOperator op(grid, kEStar);
    const std::vector<double> displacement = apply_to(op, random_field(grid.size(), 7));
    double sum = 0.0;
    double largest = 0.0;
    for (const double u : displacement) {
      sum += u;
      largest = std::max(largest, std::abs(u));
    }
    EXPECT_LE(std::abs(sum) / static_cast<double>(grid.size()), kDenseMatchTolerance * largest) << grid.shape_string();
  }
}

TEST(FftInfluenceOperatorTest, SelfInfluenceEqualsDenseDiagonal) {
  for (const Boundary boundary : {Boundary::periodic, Boundary::free}) {
    for (const Grid& grid : {Grid::line(16, 2e-6, boundary), Grid::plane(9, 6, 1e-6, 1.7e-6, boundary)}) {
      const FftInfluenceOperator fft(grid, kEStar);
      const DenseInfluenceOperator dense(grid, kEStar);
      const double expected = dense.matrix()(0, 0);
      EXPECT_NEAR(fft.self_influence(), expected, kSelfInfluenceTolerance * expected)
          << to_string(boundary) << " " << grid.shape_string();
      EXPECT_GT(fft.self_influence(), 0.0);
    }
  }
}

TEST(FftInfluenceOperatorTest, RepeatedApplyIsIdentical) {
  // The zero padding must survive each apply: a second pressure field must not
  // leak into a later result.
  for (const Boundary boundary : {Boundary::periodic, Boundary::free}) {
    for (const Grid& grid : {Grid::line(33, 1e-6, boundary), Grid::plane(10, 9, 1e-6, 1e-6, boundary)}) {
      FftInfluenceOperator op(grid, kEStar);
      const std::vector<double> first = random_field(grid.size(), 11);
      const std::vector<double> before = apply_to(op, first);
      apply_to(op, random_field(grid.size(), 12));
      EXPECT_EQ(apply_to(op, first), before) << to_string(boundary) << " " << grid.shape_string();
    }
  }
}

TEST(FftInfluenceOperatorTest, MisalignedArraysGiveTheSameResult) {
  // Periodic grids transform the caller's arrays directly; arrays FFTW cannot
  // use (here one double off its alignment) go through the owned buffers.
  for (const Grid& grid :
       {Grid::line(64, 1e-6, Boundary::periodic), Grid::plane(12, 10, 1e-6, 1e-6, Boundary::periodic)}) {
    FftInfluenceOperator op(grid, kEStar);
    const std::vector<double> pressure = random_field(grid.size(), 21);
    const std::vector<double> aligned = apply_to(op, pressure);
    std::vector<double> shifted_pressure(grid.size() + 1, 0.0);
    std::copy(pressure.begin(), pressure.end(), shifted_pressure.begin() + 1);
    std::vector<double> shifted_displacement(grid.size() + 1, 0.0);
    op.apply(std::span<const double>(shifted_pressure).subspan(1), std::span<double>(shifted_displacement).subspan(1));
    EXPECT_EQ(std::vector<double>(shifted_displacement.begin() + 1, shifted_displacement.end()), aligned)
        << grid.shape_string();
  }
}

TEST(FftInfluenceOperatorTest, InPlaceApplyGivesTheSameResult) {
  // The deflated solver applies K to a field in place (one field less): the
  // forward transform must have read all of it before the backward one
  // writes, on the padded path and on the caller's arrays alike.
  for (const Boundary boundary : {Boundary::periodic, Boundary::free}) {
    for (const Grid& grid : {Grid::line(64, 1e-6, boundary), Grid::plane(12, 10, 1e-6, 1.3e-6, boundary)}) {
      FftInfluenceOperator op(grid, kEStar);
      std::vector<double> field = random_field(grid.size(), 31);
      const std::vector<double> expected = apply_to(op, field);
      op.apply(field, field);
      EXPECT_EQ(field, expected) << to_string(boundary) << " " << grid.shape_string();
    }
  }
}

TEST(FftInfluenceOperatorTest, SameResultWithOneAndTwoThreads) {
  const int original = threads();
  for (const Boundary boundary : {Boundary::periodic, Boundary::free}) {
    for (const Grid& grid : {Grid::line(1000, 1e-6, boundary), Grid::plane(96, 80, 1e-6, 1.2e-6, boundary)}) {
      const std::vector<double> pressure = random_field(grid.size(), 5);
      set_threads(1);
      FftInfluenceOperator one(grid, kEStar);
      const std::vector<double> serial = apply_to(one, pressure);
      set_threads(2);
      FftInfluenceOperator two(grid, kEStar);
      const auto error = max_error(apply_to(two, pressure), serial);
      EXPECT_LE(error.relative, kThreadTolerance)
          << to_string(boundary) << " " << grid.shape_string() << ": at cell " << error.index;
    }
  }
  set_threads(original);
}

TEST(FftInfluenceOperatorTest, PlanningLevelsAgree) {
  // One thread: measuring threaded plans is slow on a loaded machine.
  const int original = threads();
  set_threads(1);
  const Grid grid = Grid::plane(24, 18, 1e-6, 1e-6, Boundary::free);
  const std::vector<double> pressure = random_field(grid.size(), 9);
  FftInfluenceOperator estimate(grid, kEStar, FftPlanning::estimate);
  FftInfluenceOperator measure(grid, kEStar, FftPlanning::measure);
  const auto error = max_error(apply_to(measure, pressure), apply_to(estimate, pressure));
  EXPECT_LE(error.relative, kDenseMatchTolerance) << "at cell " << error.index;
  set_threads(original);
}

TEST(FftInfluenceOperatorTest, RejectsInvalidModulus) {
  EXPECT_THROW(FftInfluenceOperator(Grid::line(8, 1e-6, Boundary::free), -1.0), InputError);
}

}  // namespace
}  // namespace halfspace
