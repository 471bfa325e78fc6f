// The film thickness between a rigid rough surface and a rigid flat: the
// surface's heights hanging below the flat at a given separation.
#pragma once

#include <Eigen/Core>

#include "halfspace/grid.hpp"

namespace halfspace::lubrication {

// h = separation + (max z - z) for the surface heights z (m, (ny, nx)
// row-major on `grid`): the separation is the minimum film thickness, taken
// at the surface's highest point. Throws InputError unless the separation is
// positive and finite and the heights are finite and as many as the grid's
// cells.
Eigen::ArrayXd film_thickness(const Grid& grid, const Eigen::ArrayXd& heights, double separation);
// The same for some of the surface's heights (a process's rows), whose
// highest point over the whole surface is `highest`.
Eigen::ArrayXd film_thickness(const Eigen::ArrayXd& heights, double highest, double separation);

}  // namespace halfspace::lubrication
