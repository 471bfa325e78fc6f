// Contact statistics. Sums go through linalg::sums (fixed blocking, so the
// same bits for any thread count); the cluster labelling is a serial
// union-find, linear in the number of cells.
#include "halfspace/analysis/contact_statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numeric>
#include <utility>

#include "halfspace/analysis/disjoint_sets.hpp"
#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::analysis {
namespace {

void check_size(std::string_view what, std::size_t size, const Grid& grid) {
  if (size != grid.size()) {
    throw InputError(
        fmt::format("{} has {} values but the grid has {} cells ({})", what, size, grid.size(), grid.shape_string()));
  }
}

}  // namespace

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
  return contact_statistics(grid, pressure, gap, linalg::serial_communicator(), contact_cluster_sizes(grid, pressure));
}

ContactStatistics contact_statistics(const Grid& grid, std::span<const double> pressure, std::span<const double> gap,
                                     const linalg::Communicator& comm, std::vector<std::int64_t> cluster_sizes) {
  const double* p = pressure.data();
  const double* g = gap.data();
  const auto [contact, gap_sum, gap_square] = linalg::sums<3>(comm, pressure.size(), [&](std::size_t i) {
    const double clipped = std::max(g[i], 0.0);
    return std::array<double, 3>{p[i] > 0.0 ? 1.0 : 0.0, clipped, clipped * clipped};
  });
  const double cells = static_cast<double>(grid.size());
  ContactStatistics statistics;
  statistics.contact_fraction = contact / cells;
  statistics.mean_gap = gap_sum / cells;
  statistics.rms_gap = std::sqrt(gap_square / cells);
  statistics.free_volume = gap_sum * grid.cell_area();
  statistics.cluster_sizes = std::move(cluster_sizes);
  return statistics;
}

}  // namespace halfspace::analysis
