// Tests of the surface statistics: rms height and slope against closed forms.
#include "halfspace/surface/statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "halfspace/error.hpp"

namespace halfspace::surface {
namespace {

// Closed forms evaluated with a few operations per cell, summed over <= 10^4 cells.
constexpr double kTolerance = 1e-12;

TEST(SurfaceStatisticsTest, RmsHeightIsAboutTheMean) {
  const std::vector<double> h{1.0, 2.0, 3.0, 4.0, 5.0};
  EXPECT_NEAR(rms_height(h), std::sqrt(2.0), kTolerance);
  const std::vector<double> shifted{1e3 + 1.0, 1e3 - 1.0};
  EXPECT_NEAR(rms_height(shifted), 1.0, 1e-12);
}

TEST(SurfaceStatisticsTest, PeriodicRmsSlopeOfSinusoidIsExact) {
  // h = A sin(qx x) cos(qy y): |grad h|^2 averages to A^2 (qx^2 + qy^2) / 4.
  const std::size_t nx = 64;
  const std::size_t ny = 48;
  const double dx = 1e-6;
  const double dy = 2e-6;
  const Grid grid = Grid::plane(nx, ny, dx, dy, Boundary::periodic);
  const double amplitude = 3e-8;
  const double qx = 2 * std::numbers::pi * 5 / (nx * dx);
  const double qy = 2 * std::numbers::pi * 3 / (ny * dy);
  std::vector<double> h(grid.size());
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      h[j * nx + i] = amplitude * std::sin(qx * i * dx) * std::cos(qy * j * dy);
    }
  }
  const double expected = amplitude * std::sqrt((qx * qx + qy * qy) / 4);
  EXPECT_NEAR(rms_slope(grid, h), expected, kTolerance * expected);

  // 1D: A sin(q x) has rms slope A q / sqrt(2).
  const Grid line = Grid::line(100, dx, Boundary::periodic);
  const double q = 2 * std::numbers::pi * 7 / (100 * dx);
  std::vector<double> profile(100);
  for (std::size_t i = 0; i < 100; ++i) profile[i] = amplitude * std::sin(q * i * dx);
  EXPECT_NEAR(rms_slope(line, profile), amplitude * q / std::sqrt(2.0), kTolerance * amplitude * q);
}

TEST(SurfaceStatisticsTest, PeriodicRmsSlopeIgnoresNyquistMode) {
  // The alternating surface (-1)^i is the Nyquist mode: its interpolant
  // cos(pi x / dx) has zero slope at every cell.
  const Grid grid = Grid::line(8, 1.0, Boundary::periodic);
  const std::vector<double> h{1, -1, 1, -1, 1, -1, 1, -1};
  EXPECT_NEAR(rms_slope(grid, h), 0.0, kTolerance);
}

TEST(SurfaceStatisticsTest, FreeRmsSlopeOfPlaneIsExact) {
  // Finite differences are exact on a plane: slope sqrt(a^2 + b^2).
  const Grid grid = Grid::plane(7, 5, 0.5, 0.25, Boundary::free);
  std::vector<double> h(grid.size());
  for (std::size_t j = 0; j < 5; ++j) {
    for (std::size_t i = 0; i < 7; ++i) h[j * 7 + i] = 0.3 * (i * 0.5) - 0.4 * (j * 0.25) + 2.0;
  }
  EXPECT_NEAR(rms_slope(grid, h), 0.5, kTolerance);
  EXPECT_THROW(rms_slope(grid, std::vector<double>(3, 0.0)), InputError);
}

}  // namespace
}  // namespace halfspace::surface
