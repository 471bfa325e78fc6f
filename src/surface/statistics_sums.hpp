// The sums behind the surface statistics, over the cells or spectrum entries
// held here and reduced over `comm`: shared by the serial statistics
// (statistics.cpp, one process) and the slab ones (MPI builds), so that both
// add the same terms. Sums go through linalg::sums (fixed blocking, so the
// same bits for any thread count).
#pragma once

#include <cmath>
#include <complex>
#include <cstddef>
#include <numbers>
#include <span>
#include <utility>

#include "halfspace/grid.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::surface::detail {

// sqrt(<(h - <h>)^2>) over the `cells` heights of all processes.
inline double rms_about_mean(const linalg::Communicator& comm, std::span<const double> heights, double cells) {
  const double mean = linalg::sum(comm, heights.size(), [&](std::size_t i) { return heights[i]; }) / cells;
  const double square = linalg::sum(comm, heights.size(), [&](std::size_t i) {
    const double d = heights[i] - mean;
    return d * d;
  });
  return std::sqrt(square / cells);
}

// <|grad h|^2> by Parseval from the half spectrum of the heights (the
// unnormalised r2c DFT): (1/N^2) sum weight |q|^2 |H(q)|^2 over the entries
// held here, entry(k) being the (column, row) = (kx >= 0, ky index) of
// spectrum[k]. Columns 1 .. (nx-1)/2 stand for themselves and their mirror
// images (weight 2); the Nyquist mode of an even axis has no slope along it.
template <class Entry>
double spectral_slope_square(const linalg::Communicator& comm, const Grid& grid,
                             std::span<const std::complex<double>> spectrum, Entry&& entry) {
  const std::size_t nx = grid.nx();
  const std::size_t ny = grid.ny();
  const auto nyquist = [](std::size_t k, std::size_t n) { return n % 2 == 0 && k == n / 2; };
  const double qx_unit = 2.0 * std::numbers::pi / (static_cast<double>(nx) * grid.dx());
  const double qy_unit = grid.dimension() == 1 ? 0.0 : 2.0 * std::numbers::pi / (static_cast<double>(ny) * grid.dy());
  const double sum = linalg::sum(comm, spectrum.size(), [&](std::size_t k) {
    const auto [c, r] = entry(k);
    const double weight = (c == 0 || nyquist(c, nx)) ? 1.0 : 2.0;
    const double qx = nyquist(c, nx) ? 0.0 : qx_unit * static_cast<double>(c);
    const double ky = r <= ny / 2 ? static_cast<double>(r) : static_cast<double>(r) - static_cast<double>(ny);
    const double qy = nyquist(r, ny) ? 0.0 : qy_unit * ky;
    return weight * (qx * qx + qy * qy) * std::norm(spectrum[k]);
  });
  const double cells = static_cast<double>(grid.size());
  return sum / (cells * cells);
}

// <|grad h|^2> by numpy.gradient's differences (central inside, one-sided at
// the grid's ends) over the `cells` cells held here from row `first_row` on,
// heights[k] being cell k of them; the rows next to them, where the grid has
// them, must be readable at heights[k -+ nx].
inline double difference_slope_square(const linalg::Communicator& comm, const Grid& grid, const double* heights,
                                      std::size_t first_row, std::size_t cells) {
  const std::size_t nx = grid.nx();
  const auto difference = [](const double* h, std::size_t position, std::size_t n, std::ptrdiff_t stride,
                             double spacing) {
    if (position == 0) return (h[stride] - h[0]) / spacing;
    if (position == n - 1) return (h[0] - h[-stride]) / spacing;
    return (h[stride] - h[-stride]) / (2.0 * spacing);
  };
  const auto stride = static_cast<std::ptrdiff_t>(nx);
  const double sum = linalg::sum(comm, cells, [&](std::size_t k) {
    const double* h = heights + k;
    const double gx = difference(h, k % nx, nx, 1, grid.dx());
    const double gy = grid.dimension() == 1 ? 0.0 : difference(h, first_row + k / nx, grid.ny(), stride, grid.dy());
    return gx * gx + gy * gy;
  });
  return sum / static_cast<double>(grid.size());
}

}  // namespace halfspace::surface::detail
