// Statistics of a solved contact: contact fraction, gap moments, free volume
// and contact clusters.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/linalg/communicator.hpp"

namespace halfspace::analysis {

struct ContactStatistics {
  double contact_fraction = 0.0;  // cells with p > 0 over all cells
  double mean_gap = 0.0;          // m, <g> over all cells (contact cells count as 0)
  double rms_gap = 0.0;           // m, sqrt(<g^2>) over all cells
  double free_volume = 0.0;       // m^3 (m^2 per unit length in 1D): sum of g * cell area
  // Cells of each contact cluster, largest first; clusters() of them.
  std::vector<std::int64_t> cluster_sizes;

  std::int64_t clusters() const { return static_cast<std::int64_t>(cluster_sizes.size()); }
};

// Sizes (cells) of the connected components of the contact set
// {i : pressure_i > 0}, largest first. Cells are connected through shared
// edges (4-connectivity in 2D, neighbours i +- 1 in 1D), across the domain's
// edges too when the grid is periodic. Throws InputError on a size mismatch.
std::vector<std::int64_t> contact_cluster_sizes(const Grid& grid, std::span<const double> pressure);

// Contact fraction, gap moments, free volume and clusters of a solved contact
// from its pressure (Pa) and gap (m) fields. The gap is clipped at 0 (a
// converged solve leaves rounding-level negative gaps in contact). Throws
// InputError if the fields do not match the grid.
ContactStatistics contact_statistics(const Grid& grid, std::span<const double> pressure, std::span<const double> gap);

// The same from this process's part of the fields (its cells of a grid
// spread over the processes of `comm`, the sums reduced over them) and the
// `cluster_sizes` found by the caller.
ContactStatistics contact_statistics(const Grid& grid, std::span<const double> pressure, std::span<const double> gap,
                                     const linalg::Communicator& comm, std::vector<std::int64_t> cluster_sizes);

}  // namespace halfspace::analysis
