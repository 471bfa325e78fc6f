// Plane-strain (1D) tangential influence coefficients: the surface
// displacement of a half-plane under a uniform tangential traction on a strip.
// In-plane (x): the tangential line load gives -(1/pi) ((1 - nu1)/G1 +
// (1 - nu2)/G2) ln|x| (Johnson 1985, sec. 2.2), the normal strip's kernel with
// the same E* (its compliance is 2/E*). Out of plane (y, antiplane shear):
// -(1/pi) (1/G1 + 1/G2) ln|x|. No xy part.
#pragma once

#include "halfspace/kernels/tangential_coefficients.hpp"

namespace halfspace::kernels {

// At distance d (m) from the centre of a strip of `width` (m), unit traction
// (1 Pa); e_star (Pa) and shear = 1/G1 + 1/G2 (1/Pa) of the pair. Lengths in
// metres inside the logarithm: the datum is at 1 m, as for the normal strip.
TangentialCoefficients tangential_strip_displacement(double d, double width, double e_star, double shear);

}  // namespace halfspace::kernels
