// Surface statistics (rms height and slope). Sums go through linalg::sums
// (fixed blocking, so the same bits for any thread count).
#include "halfspace/surface/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "halfspace/error.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::surface {
namespace {

// Signed wavenumber index of DFT bin k of an axis of n points: 0, 1, ...,
// n/2, -(n-1)/2, ..., -1 (the Nyquist bin of an even axis counts as +n/2).
double signed_index(std::size_t k, std::size_t n) {
  return k <= n / 2 ? static_cast<double>(k) : static_cast<double>(k) - static_cast<double>(n);
}

bool is_nyquist(std::size_t k, std::size_t n) {
  return n % 2 == 0 && k == n / 2;
}

// sum over the half spectrum of the squared spectral gradient, Parseval-weighted.
double spectral_slope_sq(const Grid& grid, std::span<const double> heights) {
  const std::size_t nx = grid.nx();
  const std::size_t ny = grid.ny();
  RealFft fft = grid.dimension() == 1 ? RealFft(nx, FftPlanning::estimate) : RealFft(ny, nx, FftPlanning::estimate);
  std::copy(heights.begin(), heights.end(), fft.input().begin());
  fft.forward();
  const std::span<const std::complex<double>> spectrum = fft.spectrum();
  const std::size_t columns = fft.spectrum_cols();
  const double qx_unit = 2.0 * std::numbers::pi / (static_cast<double>(nx) * grid.dx());
  const double qy_unit = grid.dimension() == 1 ? 0.0 : 2.0 * std::numbers::pi / (static_cast<double>(ny) * grid.dy());
  const double sum = linalg::sum(spectrum.size(), [&](std::size_t k) {
    const std::size_t r = k / columns;
    const std::size_t c = k % columns;
    // Columns 1 .. (nx-1)/2 stand for themselves and their mirror images.
    const double weight = (c == 0 || is_nyquist(c, nx)) ? 1.0 : 2.0;
    const double qx = is_nyquist(c, nx) ? 0.0 : qx_unit * static_cast<double>(c);
    const double qy = is_nyquist(r, ny) ? 0.0 : qy_unit * signed_index(r, ny);
    return weight * (qx * qx + qy * qy) * std::norm(spectrum[k]);
  });
  const double cells = static_cast<double>(grid.size());
  return sum / (cells * cells);
}

// numpy.gradient along one axis: central inside, one-sided at the two ends.
double difference(std::span<const double> h, std::size_t index, std::size_t position, std::size_t n, std::size_t stride,
                  double spacing) {
  if (position == 0) return (h[index + stride] - h[index]) / spacing;
  if (position == n - 1) return (h[index] - h[index - stride]) / spacing;
  return (h[index + stride] - h[index - stride]) / (2.0 * spacing);
}

double finite_difference_slope_sq(const Grid& grid, std::span<const double> heights) {
  const std::size_t nx = grid.nx();
  const std::size_t ny = grid.ny();
  const double sum = linalg::sum(grid.size(), [&](std::size_t k) {
    const std::size_t i = k % nx;
    const std::size_t j = k / nx;
    const double gx = difference(heights, k, i, nx, 1, grid.dx());
    const double gy = grid.dimension() == 1 ? 0.0 : difference(heights, k, j, ny, nx, grid.dy());
    return gx * gx + gy * gy;
  });
  return sum / static_cast<double>(grid.size());
}

}  // namespace

double rms_height(std::span<const double> heights) {
  if (heights.empty()) throw InputError("rms_height: no heights given");
  const double n = static_cast<double>(heights.size());
  const double mean = linalg::sum(heights.size(), [&](std::size_t i) { return heights[i]; }) / n;
  const double square = linalg::sum(heights.size(), [&](std::size_t i) {
    const double d = heights[i] - mean;
    return d * d;
  });
  return std::sqrt(square / n);
}

double rms_slope(const Grid& grid, std::span<const double> heights) {
  check_field_size("rms_slope: the heights", heights.size(), grid);
  const double square = grid.periodic() ? spectral_slope_sq(grid, heights) : finite_difference_slope_sq(grid, heights);
  return std::sqrt(square);
}

SurfaceStatistics surface_statistics(const Grid& grid, std::span<const double> heights) {
  return {rms_height(heights), rms_slope(grid, heights)};
}

}  // namespace halfspace::surface
