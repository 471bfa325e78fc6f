// The periodic tangential compliance per Fourier mode: for a traction mode
// t(q) (forward transform exp(-i q.x)) the relative tangential displacement is
//   u_a(q) = (1/|q|) (shear delta_ab - directional q_a q_b / q^2) t_b(q),
// shear = 1/G1 + 1/G2, directional = nu1/G1 + nu2/G2: the transform of
// Cerruti's point-load solution (FT(1/rho) = 2 pi/q, FT(x^2/rho^3) =
// 2 pi qy^2/q^3; docs/theory.md, "Friction"). Real and symmetric; xx and yy
// even in qx and qy, xy odd in each.
#pragma once

#include "halfspace/kernels/tangential_coefficients.hpp"

namespace halfspace::kernels {

// The symbol at (qx, qy) (rad/m); zero at q = 0, whose mode (a rigid
// tangential displacement) is set by the tangential load or approach.
TangentialCoefficients tangential_spectrum(double qx, double qy, double shear, double directional);

}  // namespace halfspace::kernels
