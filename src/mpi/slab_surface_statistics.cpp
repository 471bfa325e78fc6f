// Surface statistics on slabs: the sums of surface/statistics_sums.hpp over
// the processes; the spectral slope from the slab transform's (transposed)
// half spectrum, the finite-difference slope with the neighbouring
// processes' edge rows (fetch_rows).
#include "halfspace/mpi/slab_surface_statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <utility>
#include <vector>

#include "../surface/statistics_sums.hpp"
#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/mpi/row_exchange.hpp"

namespace halfspace::mpi {

surface::SurfaceStatistics slab_surface_statistics(const Grid& grid, const SlabLayout& layout,
                                                   std::span<const double> heights, const MpiCommunicator& comm) {
  if (grid.dimension() != 2 || heights.size() != layout.local_size()) {
    throw InputError(fmt::format("slab_surface_statistics: {} heights for {} rows of the {} grid", heights.size(),
                                 layout.rows, grid.shape_string()));
  }
  const double rms_height = surface::detail::rms_about_mean(comm, heights, static_cast<double>(grid.size()));
  if (grid.periodic()) {
    // The transposed spectrum: [c * ny + r] for kx = first_column + c, ky = r.
    SlabRealFft fft(grid.nx(), grid.ny(), comm, FftPlanning::estimate);
    fft.forward(heights);
    const std::size_t first_column = fft.layout().first_column;
    const std::size_t ny = grid.ny();
    const double slope_square = surface::detail::spectral_slope_square(
        comm, grid, fft.spectrum().first(fft.layout().columns * ny), [&](std::size_t k) {
          return std::pair{first_column + k / ny, k % ny};
        });
    return {rms_height, std::sqrt(slope_square)};
  }
  // This slab with the row above and the row below it, where the grid has them.
  const std::size_t nx = grid.nx();
  const std::size_t first = layout.rows > 0 && layout.first_row > 0 ? layout.first_row - 1 : layout.first_row;
  const std::size_t end = layout.rows > 0 ? std::min(layout.first_row + layout.rows + 1, grid.ny()) : first;
  std::vector<double> extended((end - first) * nx);
  fetch_rows(comm, nx, RowRanges::gather(comm, layout.first_row, layout.rows), heights,
             RowRanges::gather(comm, first, end - first), extended);
  const double slope_square = surface::detail::difference_slope_square(
      comm, grid, extended.data() + (layout.first_row - first) * nx, layout.first_row, layout.local_size());
  return {rms_height, std::sqrt(slope_square)};
}

}  // namespace halfspace::mpi
