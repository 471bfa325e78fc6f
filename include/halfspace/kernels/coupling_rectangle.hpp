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
// With height h > 0 (m) the kernel is smoothed to (D/(4 pi)) x_a/(rho (rho
// + h)), rho^2 = x^2 + y^2 + h^2, whose symbol is c_a exp(-q h): a coated
// body's far field on free grids (cerruti_rectangle.hpp).
CouplingCoefficients coupling_rectangle_displacement(double x, double y, double half_width_x, double half_width_y,
                                                     double coupling, double height = 0.0);

}  // namespace halfspace::kernels
