// Surface statistics (rms height and slope) on one process: the sums of
// statistics_sums.hpp over all cells.
#include "halfspace/surface/statistics.hpp"

#include <algorithm>
#include <cmath>

#include "halfspace/error.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "statistics_sums.hpp"

namespace halfspace::surface {

double rms_height(std::span<const double> heights) {
  if (heights.empty()) throw InputError("rms_height: no heights given");
  return detail::rms_about_mean(linalg::serial_communicator(), heights, static_cast<double>(heights.size()));
}

double rms_slope(const Grid& grid, std::span<const double> heights) {
  check_field_size("rms_slope: the heights", heights.size(), grid);
  const linalg::Communicator& one = linalg::serial_communicator();
  if (!grid.periodic()) return std::sqrt(detail::difference_slope_square(one, grid, heights.data(), 0, grid.size()));
  RealFft fft = grid.dimension() == 1 ? RealFft(grid.nx(), FftPlanning::estimate)
                                      : RealFft(grid.ny(), grid.nx(), FftPlanning::estimate);
  std::copy(heights.begin(), heights.end(), fft.input().begin());
  fft.forward();
  const std::size_t columns = fft.spectrum_cols();
  return std::sqrt(detail::spectral_slope_square(one, grid, fft.spectrum(), [&](std::size_t k) {
    return std::pair{k % columns, k / columns};
  }));
}

SurfaceStatistics surface_statistics(const Grid& grid, std::span<const double> heights) {
  return {rms_height(heights), rms_slope(grid, heights)};
}

}  // namespace halfspace::surface
