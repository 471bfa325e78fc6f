// The normal-tangential coupling kernel (D/(4 pi)) x_a/rho^2
// (coupling_coefficients.hpp) integrated over a rectangular cell: the free 2D
// coupling influence coefficients, in closed form near the cell and by Gauss
// quadrature away from it (as cerruti_rectangle.hpp).
#pragma once

#include "halfspace/kernels/coupling_coefficients.hpp"

namespace halfspace::kernels {

// Tangential displacement (m) at (x, y) (m, from the cell's centre) under a
// unit pressure (1 Pa) on |x'| <= half_width_x, |y'| <= half_width_y; the
// normal displacement under a unit traction along a is its component a,
// negated. coupling = D (1/Pa). Finite everywhere; x odd in x and even in y,
// y odd in y and even in x, bit for bit.
CouplingCoefficients coupling_rectangle_displacement(double x, double y, double half_width_x, double half_width_y,
                                                     double coupling);

}  // namespace halfspace::kernels
