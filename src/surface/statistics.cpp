// Surface and contact statistics. Sums go through linalg::sums (fixed
// blocking, so the same bits for any thread count); the cluster labelling is
// a serial union-find, linear in the number of cells.
#include "halfspace/surface/statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <numeric>

#include "halfspace/error.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::surface {
namespace {

void check_size(std::string_view what, std::size_t size, const Grid& grid) {
  if (size != grid.size()) {
    throw InputError(
        fmt::format("{} has {} values but the grid has {} cells ({})", what, size, grid.size(), grid.shape_string()));
  }
}

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

// Union-find over cell indices with path halving and union by size.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n), size_(n, 1) { std::iota(parent_.begin(), parent_.end(), 0); }

  std::size_t find(std::size_t a) {
    while (parent_[a] != a) {
      parent_[a] = parent_[parent_[a]];
      a = parent_[a];
    }
    return a;
  }

  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }

  std::int64_t size_of_root(std::size_t root) const { return size_[root]; }

 private:
  std::vector<std::size_t> parent_;
  std::vector<std::int64_t> size_;
};

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
  check_size("rms_slope: the heights", heights.size(), grid);
  const double square = grid.periodic() ? spectral_slope_sq(grid, heights) : finite_difference_slope_sq(grid, heights);
  return std::sqrt(square);
}

SurfaceStatistics surface_statistics(const Grid& grid, std::span<const double> heights) {
  return {rms_height(heights), rms_slope(grid, heights)};
}

std::vector<std::int64_t> contact_cluster_sizes(const Grid& grid, std::span<const double> pressure) {
  check_size("contact_cluster_sizes: the pressure", pressure.size(), grid);
  const std::size_t nx = grid.nx();
  const std::size_t ny = grid.ny();
  const bool wrap = grid.periodic();
  DisjointSets sets(grid.size());
  const auto join = [&](std::size_t a, std::size_t b) {
    if (pressure[a] > 0.0 && pressure[b] > 0.0) sets.unite(a, b);
  };
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t k = j * nx + i;
      if (!(pressure[k] > 0.0)) continue;
      // Right and lower neighbours; with wrap-around the last column meets
      // the first and the last row the first. A 1D grid has only one row.
      if (i + 1 < nx) {
        join(k, k + 1);
      } else if (wrap) {
        join(k, j * nx);
      }
      if (grid.dimension() == 2) {
        if (j + 1 < ny) {
          join(k, k + nx);
        } else if (wrap) {
          join(k, i);
        }
      }
    }
  }
  std::vector<std::int64_t> sizes;
  for (std::size_t k = 0; k < grid.size(); ++k) {
    if (pressure[k] > 0.0 && sets.find(k) == k) sizes.push_back(sets.size_of_root(k));
  }
  std::sort(sizes.begin(), sizes.end(), std::greater<>());
  return sizes;
}

ContactStatistics contact_statistics(const Grid& grid, std::span<const double> pressure, std::span<const double> gap) {
  check_size("contact_statistics: the pressure", pressure.size(), grid);
  check_size("contact_statistics: the gap", gap.size(), grid);
  const double* p = pressure.data();
  const double* g = gap.data();
  const auto [contact, gap_sum, gap_square] = linalg::sums<3>(grid.size(), [&](std::size_t i) {
    const double gap = std::max(g[i], 0.0);
    return std::array<double, 3>{p[i] > 0.0 ? 1.0 : 0.0, gap, gap * gap};
  });
  const double cells = static_cast<double>(grid.size());
  ContactStatistics statistics;
  statistics.contact_fraction = contact / cells;
  statistics.mean_gap = gap_sum / cells;
  statistics.rms_gap = std::sqrt(gap_square / cells);
  statistics.free_volume = gap_sum * grid.cell_area();
  statistics.cluster_sizes = contact_cluster_sizes(grid, {p, grid.size()});
  return statistics;
}

}  // namespace halfspace::surface
