// Moving fields between a grid and the grid of twice its spacing, for the
// coarse-grid start of MultilevelSolver and the EHL film's grid sequencing:
// block averages down, piecewise constant or bilinear values up.
#pragma once

#include <optional>
#include <span>

#include "halfspace/grid.hpp"
#include "halfspace/linalg/communicator.hpp"

namespace halfspace::solvers {

// The grid of the same domain with half the cells per axis (2D: both axes),
// or nothing when an axis has an odd number of cells (the domain would
// change) or the coarse grid would have fewer than min_cells_per_axis cells
// along an axis.
std::optional<Grid> coarser_grid(const Grid& fine, std::size_t min_cells_per_axis);

// coarse(J, I) = mean of fine over the 2 (1D) or 2 x 2 (2D) cells it covers.
void restrict_by_average(const Grid& fine, std::span<const double> fine_values, std::span<double> coarse_values);

// fine(j, i) = coarse(j / 2, i / 2).
void prolong_constant(const Grid& fine, std::span<const double> coarse_values, std::span<double> fine_values);

// fine(j, i) interpolated bilinearly (linearly in 1D) from the coarse
// nodes, fine node (i, j) lying at coarse coordinates (i / 2 - 1/4, j / 2 -
// 1/4); wrapped around on periodic grids, held constant beyond the outer
// coarse nodes otherwise.
void prolong_bilinear(const Grid& fine, std::span<const double> coarse_values, std::span<double> fine_values);

// The same for the fine rows from `first_row` that `fine_rows` holds (a
// process's slab of a distributed field; the coarse field whole).
void prolong_bilinear_rows(const Grid& fine, std::span<const double> coarse_values, std::size_t first_row,
                           std::span<double> fine_rows);

// restrict_by_average of a 2D field of which each process of `comm` holds
// the rows from `first_row` that `fine_rows` holds: the coarse field whole
// on every process (a collective sum; on one process restrict_by_average
// itself).
void restrict_rows_by_average(const Grid& fine, std::span<const double> fine_rows, std::size_t first_row,
                              std::span<double> coarse_values, const linalg::Communicator& comm);

}  // namespace halfspace::solvers
