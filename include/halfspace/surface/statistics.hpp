// Statistics of a surface: rms height and rms slope (the statistics of a
// solved contact are in analysis/contact_statistics.hpp).
#pragma once

#include <span>

#include "halfspace/grid.hpp"

namespace halfspace::surface {

struct SurfaceStatistics {
  double rms_height = 0.0;  // m, sqrt(<(h - <h>)^2>)
  double rms_slope = 0.0;   // dimensionless, sqrt(<|grad h|^2>), see rms_slope()
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

}  // namespace halfspace::surface
