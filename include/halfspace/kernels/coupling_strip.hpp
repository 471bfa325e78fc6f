// Plane-strain (1D) normal-tangential coupling: Flamant's line loads give the
// surface displacements u_x = (D/4) sgn(x) P (of a normal line load) and
// u_n = -(D/4) sgn(x) Q (of a tangential one), D = (1 - 2 nu1)/G1 -
// (1 - 2 nu2)/G2 (Johnson 1985, eqs. 2.19, 2.22; the 2D point kernel
// x/rho^2 integrated along y, pi sgn(x)). Over a strip of width w:
// (D/4) (|d + w/2| - |d - w/2|). No datum: the kernel is odd.
#pragma once

#include "halfspace/kernels/coupling_coefficients.hpp"

namespace halfspace::kernels {

// At distance d (m) from the centre of a strip of `width` (m), unit pressure
// (1 Pa): the tangential displacement x (y is zero).
CouplingCoefficients coupling_strip_displacement(double d, double width, double coupling);

}  // namespace halfspace::kernels
