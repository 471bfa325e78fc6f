// Surface statistics on slabs: the sums of surface/statistics.cpp over the
// processes; the spectral slope from the slab transform's (transposed) half
// spectrum, the finite-difference slope with the neighbouring processes'
// edge rows.
#include "halfspace/mpi/slab_surface_statistics.hpp"

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"

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

// This slab with the row above and the row below it (where the grid has
// them), from the processes that hold them.
std::vector<double> with_neighbour_rows(const Grid& grid, const SlabLayout& layout, std::span<const double> heights,
                                        const MpiCommunicator& comm) {
  const std::size_t nx = grid.nx();
  const auto processes = static_cast<std::size_t>(comm.size());
  std::vector<unsigned long long> ranges(2 * processes);
  const unsigned long long mine[2] = {layout.first_row, layout.rows};
  check(MPI_Allgather(mine, 2, MPI_UNSIGNED_LONG_LONG, ranges.data(), 2, MPI_UNSIGNED_LONG_LONG, comm.get()),
        "MPI_Allgather");
  const auto owner = [&](std::size_t row) {
    for (std::size_t p = 0; p < processes; ++p) {
      if (ranges[2 * p + 1] > 0 && row >= ranges[2 * p] && row < ranges[2 * p] + ranges[2 * p + 1]) {
        return static_cast<int>(p);
      }
    }
    return MPI_PROC_NULL;
  };
  std::vector<double> extended((layout.rows + 2) * nx, 0.0);
  std::copy(heights.begin(), heights.end(), extended.begin() + static_cast<std::ptrdiff_t>(nx));
  if (layout.rows == 0) return extended;
  const int above = layout.first_row > 0 ? owner(layout.first_row - 1) : MPI_PROC_NULL;
  const int below = layout.first_row + layout.rows < grid.ny() ? owner(layout.first_row + layout.rows) : MPI_PROC_NULL;
  const int count = static_cast<int>(nx);
  MPI_Request requests[4];
  check(MPI_Irecv(extended.data(), count, MPI_DOUBLE, above, 2, comm.get(), &requests[0]), "MPI_Irecv");
  check(MPI_Irecv(extended.data() + (layout.rows + 1) * nx, count, MPI_DOUBLE, below, 1, comm.get(), &requests[1]),
        "MPI_Irecv");
  check(MPI_Isend(heights.data(), count, MPI_DOUBLE, above, 1, comm.get(), &requests[2]), "MPI_Isend");
  check(MPI_Isend(heights.data() + (layout.rows - 1) * nx, count, MPI_DOUBLE, below, 2, comm.get(), &requests[3]),
        "MPI_Isend");
  check(MPI_Waitall(4, requests, MPI_STATUSES_IGNORE), "MPI_Waitall");
  return extended;
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
  const std::vector<double> extended = with_neighbour_rows(grid, layout, heights, comm);
  const auto stride = static_cast<std::ptrdiff_t>(nx);
  const double sum = linalg::sum(comm, layout.local_size(), [&](std::size_t k) {
    const std::size_t i = k % nx;
    const std::size_t j = layout.first_row + k / nx;
    const double* h = extended.data() + nx + k;
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
