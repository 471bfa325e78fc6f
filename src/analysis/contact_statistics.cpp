// Contact statistics. Sums go through linalg::sums (fixed blocking, so the
// same bits for any thread count); the cluster labelling is a serial
// union-find, linear in the number of cells.
#include "halfspace/analysis/contact_statistics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

#include "halfspace/analysis/disjoint_sets.hpp"
#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::analysis {
namespace {}  // namespace

std::vector<std::int64_t> contact_cluster_sizes(const Grid& grid, std::span<const double> pressure) {
  check_field_size("contact_cluster_sizes: the pressure", pressure.size(), grid);
  // Row by row (Hoshen & Kopelman 1976): a cell in contact takes the label
  // of its left or upper neighbour in contact (joining the two labels when
  // both are), or a new one; only the labels are united, so that the memory
  // is three rows of labels and the labels' sets, not a set per cell (the
  // program's peak after a large solve). With wrap-around the last column
  // meets the first and the last row the first. A 1D grid has one row.
  const std::size_t nx = grid.nx();
  const std::size_t ny = grid.dimension() == 1 ? 1 : grid.ny();
  const bool wrap = grid.periodic();
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  DisjointSets labels(0);
  std::vector<std::size_t> first_row(nx, kNone);
  std::vector<std::size_t> previous(nx, kNone);
  std::vector<std::size_t> current(nx, kNone);
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      if (!(pressure[j * nx + i] > 0.0)) {
        current[i] = kNone;
        continue;
      }
      const std::size_t left = i > 0 ? current[i - 1] : kNone;
      const std::size_t up = previous[i];
      if (left == kNone && up == kNone) {
        current[i] = labels.add(1);
        continue;
      }
      current[i] = left != kNone ? left : up;
      labels.grow(current[i], 1);
      if (left != kNone && up != kNone) labels.unite(left, up);
    }
    if (wrap && current[nx - 1] != kNone && current[0] != kNone) labels.unite(current[nx - 1], current[0]);
    if (j == 0) first_row = current;
    std::swap(previous, current);
  }
  if (wrap && ny > 1) {
    for (std::size_t i = 0; i < nx; ++i) {
      if (previous[i] != kNone && first_row[i] != kNone) labels.unite(previous[i], first_row[i]);
    }
  }
  std::vector<std::int64_t> sizes;
  for (std::size_t label = 0; label < labels.count(); ++label) {
    if (labels.find(label) == label) sizes.push_back(labels.size_of_root(label));
  }
  std::sort(sizes.begin(), sizes.end(), std::greater<>());
  return sizes;
}

ContactStatistics contact_statistics(const Grid& grid, std::span<const double> pressure, std::span<const double> gap) {
  check_field_size("contact_statistics: the pressure", pressure.size(), grid);
  check_field_size("contact_statistics: the gap", gap.size(), grid);
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
