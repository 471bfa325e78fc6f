// Plane-strain (1D) influence coefficient: surface displacement of a half-plane
// under uniform pressure on a strip, the exact integral of the logarithmic
// line-load kernel over one cell.
#pragma once

namespace halfspace::kernels {

// Displacement (m) at distance d (m) from the centre of a strip of width
// `width` (m) under unit pressure (1 Pa), composite modulus e_star (Pa):
//   K(d) = -(2 / (pi E*)) [F(d + w/2) - F(d - w/2)],  F(t) = t ln|t| - t.
// The logarithm takes lengths in metres: the datum (zero displacement) is at
// 1 m, which shifts the approach but never the pressure.
double plane_strain_strip_displacement(double d, double width, double e_star);

}  // namespace halfspace::kernels
