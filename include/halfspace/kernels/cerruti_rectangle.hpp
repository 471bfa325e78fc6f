// Cerruti's tangential point-load solution (Johnson 1985, sec. 2.2) integrated
// over a rectangular cell: the free 2D tangential influence coefficients, in
// closed form (Kalker 1990) near the cell and by Gauss quadrature away from it.
#pragma once

#include "halfspace/kernels/tangential_coefficients.hpp"

namespace halfspace::kernels {

// Relative tangential displacement (m) at (x, y) (m, from the cell's centre)
// under a unit tangential traction (1 Pa) on |x'| <= half_width_x,
// |y'| <= half_width_y, for the pair's compliance factors
// shear = 1/G1 + 1/G2 and directional = nu1/G1 + nu2/G2 (1/Pa). The point
// force F at the origin gives, summed over both bodies (rho = |(x, y)|),
//   u_a = (1/(2 pi)) [(shear - directional) delta_ab / rho + directional x_a x_b / rho^3] F_b.
// Finite everywhere, including on the cell's edges and corners; xx and yy
// even in x and y, xy odd in each.
// With height h > 0 (m) the kernel is smoothed, rho^2 = x^2 + y^2 + h^2:
// its symbol is exp(-q h) (shear delta_ab / q - directional (1 + q h)
// q_a q_b / q^3), the point-load solution's times exp(-q h) up to the
// (1 + q h) of the directional part; a coated body's far field on free
// grids (docs/theory.md, "Tangential compliance of a coated half-space").
TangentialCoefficients cerruti_rectangle_displacement(double x, double y, double half_width_x, double half_width_y,
                                                      double shear, double directional, double height = 0.0);

}  // namespace halfspace::kernels
