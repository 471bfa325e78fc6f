// Statistics of a surface (rms height, rms slope) and of a solved contact
// (contact fraction, gap moments, free volume, contact clusters).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "halfspace/grid.hpp"

namespace halfspace::surface {

struct SurfaceStatistics {
  double rms_height = 0.0;  // m, sqrt(<(h - <h>)^2>)
  double rms_slope = 0.0;   // dimensionless, sqrt(<|grad h|^2>), see rms_slope()
};

struct ContactStatistics {
  double contact_fraction = 0.0;  // cells with p > 0 over all cells
  double mean_gap = 0.0;          // m, <g> over all cells (contact cells count as 0)
  double rms_gap = 0.0;           // m, sqrt(<g^2>) over all cells
  double free_volume = 0.0;       // m^3 (m^2 per unit length in 1D): sum of g * cell area
  // Cells of each contact cluster, largest first; clusters() of them.
  std::vector<std::int64_t> cluster_sizes;

  std::int64_t clusters() const { return static_cast<std::int64_t>(cluster_sizes.size()); }
};

// Root mean square of the heights about their mean (Sq), m. `heights` must
// not be empty.
double rms_height(std::span<const double> heights);

// Root mean square of the gradient magnitude, sqrt(<|grad h|^2>), <.> the mean
// over the cells (in 1D, the rms of dh/dx). The gradient depends on the
// boundary:
//  * periodic: the exact gradient of the real trigonometric interpolant of
//    the heights, sampled at the cells, i.e. the spectral derivative i q H(q)
//    with the Nyquist mode of an even axis dropped for the derivative along
//    that axis (its interpolant cos(pi x / dx) has zero slope at every cell).
//    By Parseval, rms_slope^2 = (1/N^2) sum_q |q|^2 |H(q)|^2 over the modes
//    kept, with H the unnormalised DFT and N the number of cells.
//  * free: second-order central differences inside and first-order one-sided
//    differences on the edges (numpy.gradient's rule); a spectral derivative
//    would see the jump between opposite edges.
// Uses the threads in force for the FFT. Throws InputError if the number of
// heights differs from grid.size().
double rms_slope(const Grid& grid, std::span<const double> heights);

SurfaceStatistics surface_statistics(const Grid& grid, std::span<const double> heights);

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

}  // namespace halfspace::surface
