// Clusters across slabs: each process labels its slab's contact cells with a
// union-find (rows joined within the slab, columns across the x edge of a
// periodic grid), then sends the first process its clusters (a label and a
// size each) and the labels of its first and last row. The first process
// joins the labels that face each other across every slab boundary (and
// across the y edge of a periodic grid) in a second union-find over the
// clusters alone, which is small next to the grid, and hands the sizes out.
#include "halfspace/mpi/slab_contact_statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <vector>

#include "halfspace/analysis/disjoint_sets.hpp"
#include "halfspace/error.hpp"

namespace halfspace::mpi {
namespace {

constexpr std::int64_t kNoContact = -1;

// What a process tells the first about its slab: first row, rows, the
// number of clusters, then (label, cells) per cluster, the labels of its
// first row and of its last row (kNoContact where there is no contact).
// Labels are global cell indices, so they differ between processes.
std::vector<std::int64_t> describe_slab(const Grid& grid, const SlabLayout& layout, std::span<const double> pressure) {
  const std::size_t nx = grid.nx();
  const std::size_t rows = layout.rows;
  const bool wrap = grid.periodic();
  analysis::DisjointSets sets(pressure.size());
  const auto touching = [&](std::size_t k) { return pressure[k] > 0.0; };
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t k = r * nx + i;
      if (!touching(k)) continue;
      const std::size_t right = i + 1 < nx ? k + 1 : r * nx;
      if ((i + 1 < nx || wrap) && touching(right)) sets.unite(k, right);
      if (r + 1 < rows && touching(k + nx)) sets.unite(k, k + nx);
    }
  }
  const auto offset = static_cast<std::int64_t>(layout.first_row * nx);
  std::vector<std::int64_t> message{static_cast<std::int64_t>(layout.first_row), static_cast<std::int64_t>(rows), 0};
  for (std::size_t k = 0; k < pressure.size(); ++k) {
    if (touching(k) && sets.find(k) == k) {
      message.push_back(offset + static_cast<std::int64_t>(k));
      message.push_back(sets.size_of_root(k));
      ++message[2];
    }
  }
  for (const std::size_t r : {std::size_t{0}, rows - 1}) {
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t k = r * nx + i;
      message.push_back(rows > 0 && touching(k) ? offset + static_cast<std::int64_t>(sets.find(k)) : kNoContact);
    }
  }
  return message;
}

// The first process: every slab's clusters joined across the boundaries.
std::vector<std::int64_t> merge_slabs(const Grid& grid, const std::vector<std::int64_t>& messages,
                                      const std::vector<int>& lengths) {
  const std::size_t nx = grid.nx();
  struct Slab {
    std::size_t rows = 0;
    const std::int64_t* first_labels = nullptr;
    const std::int64_t* last_labels = nullptr;
  };
  std::vector<Slab> slabs;  // in rank order, which is row order
  std::vector<std::int64_t> labels, sizes;
  std::size_t at = 0;
  for (const int length : lengths) {
    const std::int64_t* m = messages.data() + at;
    at += static_cast<std::size_t>(length);
    const auto rows = static_cast<std::size_t>(m[1]);
    const auto clusters = static_cast<std::size_t>(m[2]);
    for (std::size_t c = 0; c < clusters; ++c) {
      labels.push_back(m[3 + 2 * c]);
      sizes.push_back(m[4 + 2 * c]);
    }
    if (rows > 0) slabs.push_back({rows, m + 3 + 2 * clusters, m + 3 + 2 * clusters + nx});
  }
  // Labels arrive in increasing order (slabs in row order, roots in cell
  // order), so a label's cluster is found by binary search.
  const auto index_of = [&](std::int64_t label) {
    return static_cast<std::size_t>(std::lower_bound(labels.begin(), labels.end(), label) - labels.begin());
  };
  analysis::DisjointSets sets(labels.size());
  const auto join_rows = [&](const std::int64_t* upper_last, const std::int64_t* lower_first) {
    for (std::size_t i = 0; i < nx; ++i) {
      if (upper_last[i] != kNoContact && lower_first[i] != kNoContact) {
        sets.unite(index_of(upper_last[i]), index_of(lower_first[i]));
      }
    }
  };
  for (std::size_t s = 1; s < slabs.size(); ++s) join_rows(slabs[s - 1].last_labels, slabs[s].first_labels);
  if (grid.periodic() && !slabs.empty()) join_rows(slabs.back().last_labels, slabs.front().first_labels);
  std::vector<std::int64_t> joined(labels.size(), 0);
  for (std::size_t c = 0; c < labels.size(); ++c) joined[sets.find(c)] += sizes[c];
  std::vector<std::int64_t> result;
  for (std::size_t c = 0; c < labels.size(); ++c) {
    if (sets.find(c) == c) result.push_back(joined[c]);
  }
  std::sort(result.begin(), result.end(), std::greater<>());
  return result;
}

std::vector<std::int64_t> slab_cluster_sizes(const Grid& grid, const SlabLayout& layout,
                                             std::span<const double> pressure, const MpiCommunicator& comm) {
  const std::vector<std::int64_t> message = describe_slab(grid, layout, pressure);
  const int length = static_cast<int>(message.size());
  // Checked on every process alike: MPI_Gatherv counts in int.
  std::int64_t total = length;
  check(MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_INT64_T, MPI_SUM, comm.get()), "MPI_Allreduce");
  if (total > std::numeric_limits<int>::max()) {
    throw InputError(
        fmt::format("the {} grid's contact clusters are too many to join on one process", grid.shape_string()));
  }
  const bool root = comm.rank() == 0;
  std::vector<int> lengths(root ? static_cast<std::size_t>(comm.size()) : 0);
  check(MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, comm.get()), "MPI_Gather");
  std::vector<int> offsets(lengths.size(), 0);
  for (std::size_t p = 1; p < lengths.size(); ++p) offsets[p] = offsets[p - 1] + lengths[p - 1];
  std::vector<std::int64_t> messages(root ? static_cast<std::size_t>(total) : 0);
  check(MPI_Gatherv(message.data(), length, MPI_INT64_T, messages.data(), lengths.data(), offsets.data(), MPI_INT64_T,
                    0, comm.get()),
        "MPI_Gatherv");
  std::vector<std::int64_t> sizes;
  if (root) sizes = merge_slabs(grid, messages, lengths);
  std::uint64_t count = sizes.size();
  check(MPI_Bcast(&count, 1, MPI_UINT64_T, 0, comm.get()), "MPI_Bcast");
  sizes.resize(count);
  check(MPI_Bcast(sizes.data(), static_cast<int>(count), MPI_INT64_T, 0, comm.get()), "MPI_Bcast");
  return sizes;
}

}  // namespace

analysis::ContactStatistics slab_contact_statistics(const Grid& grid, const SlabLayout& layout,
                                                    std::span<const double> pressure, std::span<const double> gap,
                                                    const MpiCommunicator& comm) {
  if (grid.dimension() != 2 || pressure.size() != layout.local_size() || gap.size() != layout.local_size()) {
    throw InputError(fmt::format("slab_contact_statistics: {} pressures and {} gaps for {} rows of the {} grid",
                                 pressure.size(), gap.size(), layout.rows, grid.shape_string()));
  }
  return analysis::contact_statistics(grid, pressure, gap, comm, slab_cluster_sizes(grid, layout, pressure, comm));
}

}  // namespace halfspace::mpi
