// Small helpers to lay out test surfaces on a grid: cell-centre coordinates
// measured from the grid centre, and filling a field from a function.
#pragma once

#include <Eigen/Core>

#include "halfspace/grid.hpp"

namespace halfspace::testing {

// x of column i measured from the grid centre (nx - 1) dx / 2.
inline double centred_x(const Grid& grid, std::size_t i) {
  return (static_cast<double>(i) - 0.5 * static_cast<double>(grid.nx() - 1)) * grid.dx();
}
inline double centred_y(const Grid& grid, std::size_t j) {
  return grid.dimension() == 1 ? 0.0 : (static_cast<double>(j) - 0.5 * static_cast<double>(grid.ny() - 1)) * grid.dy();
}

// f(x, y) at every cell, (ny, nx) row-major, coordinates from the centre.
template <class Function>
Eigen::ArrayXd field_from(const Grid& grid, Function&& f) {
  Eigen::ArrayXd field(static_cast<Eigen::Index>(grid.size()));
  for (std::size_t j = 0; j < grid.ny(); ++j) {
    for (std::size_t i = 0; i < grid.nx(); ++i) {
      field[static_cast<Eigen::Index>(j * grid.nx() + i)] = f(centred_x(grid, i), centred_y(grid, j));
    }
  }
  return field;
}

}  // namespace halfspace::testing
