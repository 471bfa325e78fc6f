// SpectralTransforms::apply_pair: the serial transforms' fused path (each
// few kx columns forward, multiplied and back while in cache) against the
// plain one (both forward, the multiplier on the whole spectra, both back),
// with a multiplier that couples the two spectra as the tangential symbol
// does; and the plain path taken where the caller's arrays cannot be
// transformed directly.
#include "halfspace/operators/spectral_transforms.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <span>
#include <vector>

#include "halfspace/grid.hpp"

namespace halfspace {
namespace {

using operators::SpectralTransforms;

std::vector<double> random_values(std::size_t n, unsigned seed) {
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<double> values(n);
  for (double& v : values) v = uniform(engine);
  return values;
}

// (x, y) <- (a x + b y, b x - a y) with a, b depending on the entry.
SpectralTransforms::BlockMultiply mixing(SpectralTransforms& transforms) {
  return [&transforms](std::size_t first, std::size_t count) {
    const std::span<std::complex<double>> x = transforms.spectrum(0);
    const std::span<std::complex<double>> y = transforms.spectrum(1);
    const std::size_t length = transforms.spectrum_length();
    for (std::size_t k = first * length; k < (first + count) * length; ++k) {
      const double a = 1.0 + 0.01 * static_cast<double>(k % 17);
      const double b = 0.3 - 0.02 * static_cast<double>(k % 5);
      const std::complex<double> u = x[k];
      const std::complex<double> v = y[k];
      x[k] = a * u + b * v;
      y[k] = b * u - a * v;
    }
  };
}

TEST(SpectralTransformsTest, FusedPairEqualsThePlainOne) {
  for (const auto& [ny, nx] : std::vector<std::pair<std::size_t, std::size_t>>{{24, 40}, {17, 30}, {64, 16}}) {
    const Grid grid = Grid::plane(nx, ny, 1e-6, 1e-6, Boundary::periodic);
    const std::size_t n = grid.size();
    auto transforms = operators::make_serial_transforms(grid, FftPlanning::estimate);
    ASSERT_TRUE(transforms->transposed());
    const std::vector<double> x = random_values(n, 3);
    const std::vector<double> y = random_values(n, 4);
    std::vector<double> fused_x(n), fused_y(n), plain_x(n), plain_y(n);
    transforms->apply_pair(x, y, fused_x, fused_y, mixing(*transforms));
    transforms->operators::SpectralTransforms::apply_pair(x, y, plain_x, plain_y, mixing(*transforms));
    double scale = 0.0;
    double difference = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      scale = std::max({scale, std::abs(plain_x[i]), std::abs(plain_y[i])});
      difference = std::max({difference, std::abs(fused_x[i] - plain_x[i]), std::abs(fused_y[i] - plain_y[i])});
    }
    EXPECT_LE(difference, 1e-13 * scale) << ny << "x" << nx;
    // In place, and through arrays a double off the transforms' alignment
    // (the plain path, with copies): the same.
    std::vector<double> inplace_x = x;
    std::vector<double> inplace_y = y;
    transforms->apply_pair(inplace_x, inplace_y, inplace_x, inplace_y, mixing(*transforms));
    std::vector<double> offset_x(n + 1), offset_y(n + 1);
    std::copy(x.begin(), x.end(), offset_x.begin() + 1);
    std::copy(y.begin(), y.end(), offset_y.begin() + 1);
    const std::span<double> shifted_x(offset_x.data() + 1, n);
    const std::span<double> shifted_y(offset_y.data() + 1, n);
    transforms->apply_pair(shifted_x, shifted_y, shifted_x, shifted_y, mixing(*transforms));
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_LE(std::abs(inplace_x[i] - plain_x[i]), 1e-13 * scale) << i;
      ASSERT_LE(std::abs(inplace_y[i] - plain_y[i]), 1e-13 * scale) << i;
      ASSERT_LE(std::abs(shifted_x[i] - plain_x[i]), 1e-13 * scale) << i;
      ASSERT_LE(std::abs(shifted_y[i] - plain_y[i]), 1e-13 * scale) << i;
    }
  }
}

}  // namespace
}  // namespace halfspace
