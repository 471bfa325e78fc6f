// The periodic normal-tangential coupling per Fourier mode (forward transform
// exp(-i q.x)): FT(x_a/rho^2) = -2 pi i q_a/q^2, so a pressure mode P(q) and
// a traction mode T_a(q) give
//   U_a(q) = i c_a P(q),   U_n(q) = -i c_a T_a(q),   c_a = -D q_a/(2 q^2),
// D = (1 - 2 nu1)/G1 - (1 - 2 nu2)/G2 (coupling_coefficients.hpp,
// docs/theory.md, "Friction"). c is odd in q; zero at q = 0.
#pragma once

#include "halfspace/kernels/coupling_coefficients.hpp"

namespace halfspace::kernels {

// c at (qx, qy) (rad/m) for the pair's coupling compliance D (1/Pa).
CouplingCoefficients coupling_spectrum(double qx, double qy, double coupling);

}  // namespace halfspace::kernels
