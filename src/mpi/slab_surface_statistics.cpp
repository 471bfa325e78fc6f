// Surface statistics on slabs: the sums of surface/statistics.cpp over the
// processes; the spectral slope from the slab transform's (transposed) half
// spectrum, the finite-difference slope with the neighbouring processes'
// edge rows (fetch_rows).
#include "halfspace/mpi/slab_surface_statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/mpi/row_exchange.hpp"

namespace halfspace::mpi {
namespace {

double signed_index(std::size_t k, std::size_t n) {
  return k <= n / 2 ? static_cast<double>(k) : static_cast<double>(k) - static_cast<double>(n);
}

bool is_nyquist(std::size_t k, std::size_t n) {
  return n % 2 == 0 && k == n / 2;
}

// The spectral slope of surface/statistics.cpp, over the transposed spectrum
// ([c * ny + r] for kx = first_column + c, ky = r).
double spectral_slope_sq(const Grid& grid, std::span<const double> heights, const MpiCommunicator& comm) {
  const std::size_t nx = grid.nx();
  const std::size_t ny = grid.ny();
  SlabRealFft fft(nx, ny, comm, FftPlanning::estimate);
  fft.forward(heights);
  const std::span<const std::complex<double>> spectrum = fft.spectrum();
  const std::size_t first_column = fft.layout().first_column;
  const std::size_t values = fft.layout().columns * ny;
  const double qx_unit = 2.0 * std::numbers::pi / (static_cast<double>(nx) * grid.dx());
  const double qy_unit = 2.0 * std::numbers::pi / (static_cast<double>(ny) * grid.dy());
  const double sum = linalg::sum(comm, values, [&](std::size_t k) {
    const std::size_t c = first_column + k / ny;
    const std::size_t r = k % ny;
    const double weight = (c == 0 || is_nyquist(c, nx)) ? 1.0 : 2.0;
    const double qx = is_nyquist(c, nx) ? 0.0 : qx_unit * static_cast<double>(c);
    const double qy = is_nyquist(r, ny) ? 0.0 : qy_unit * signed_index(r, ny);
    return weight * (qx * qx + qy * qy) * std::norm(spectrum[k]);
  });
  const double cells = static_cast<double>(grid.size());
  return sum / (cells * cells);
}

// numpy.gradient: central inside, one-sided at the grid's two ends.
double difference(const double* h, std::size_t position, std::size_t n, std::ptrdiff_t stride, double spacing) {
  if (position == 0) return (h[stride] - h[0]) / spacing;
  if (position == n - 1) return (h[0] - h[-stride]) / spacing;
  return (h[stride] - h[-stride]) / (2.0 * spacing);
}

double finite_difference_slope_sq(const Grid& grid, const SlabLayout& layout, std::span<const double> heights,
                                  const MpiCommunicator& comm) {
  const std::size_t nx = grid.nx();
  // This slab with the row above and the row below it, where the grid has them.
  const std::size_t first = layout.rows > 0 && layout.first_row > 0 ? layout.first_row - 1 : layout.first_row;
  const std::size_t end = layout.rows > 0 ? std::min(layout.first_row + layout.rows + 1, grid.ny()) : first;
  std::vector<double> extended((end - first) * nx);
  fetch_rows(comm, nx, RowRanges::gather(comm, layout.first_row, layout.rows), heights,
             RowRanges::gather(comm, first, end - first), extended);
  const auto stride = static_cast<std::ptrdiff_t>(nx);
  const double sum = linalg::sum(comm, layout.local_size(), [&](std::size_t k) {
    const std::size_t i = k % nx;
    const std::size_t j = layout.first_row + k / nx;
    const double* h = extended.data() + (layout.first_row - first) * nx + k;
    const double gx = difference(h, i, nx, 1, grid.dx());
    const double gy = difference(h, j, grid.ny(), stride, grid.dy());
    return gx * gx + gy * gy;
  });
  return sum / static_cast<double>(grid.size());
}

}  // namespace

surface::SurfaceStatistics slab_surface_statistics(const Grid& grid, const SlabLayout& layout,
                                                   std::span<const double> heights, const MpiCommunicator& comm) {
  if (grid.dimension() != 2 || heights.size() != layout.local_size()) {
    throw InputError(fmt::format("slab_surface_statistics: {} heights for {} rows of the {} grid", heights.size(),
                                 layout.rows, grid.shape_string()));
  }
  const double n = static_cast<double>(grid.size());
  const double mean = linalg::sum(comm, heights.size(), [&](std::size_t i) { return heights[i]; }) / n;
  const double square = linalg::sum(comm, heights.size(), [&](std::size_t i) {
    const double d = heights[i] - mean;
    return d * d;
  });
  const double slope_square = grid.periodic() ? spectral_slope_sq(grid, heights, comm)
                                              : finite_difference_slope_sq(grid, layout, heights, comm);
  return {std::sqrt(square / n), std::sqrt(slope_square)};
}

}  // namespace halfspace::mpi
