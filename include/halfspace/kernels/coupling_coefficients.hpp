// The normal-tangential coupling of two elastically dissimilar bodies
// (Dundurs' beta != 0; elastic_pair.hpp) at one offset or one wave vector.
// With D = (1 - 2 nu1)/G1 - (1 - 2 nu2)/G2 (ElasticPair::coupling_compliance)
// a point pressure force P at the origin moves body 2's surface against body
// 1's tangentially by, and a point tangential force F_a moves the surfaces
// normally (towards each other's interior, the sense of K p) by
//   u_a = (D/(4 pi)) x_a/rho^2 P,        u_n = -(D/(4 pi)) x_a/rho^2 F_a,
// Boussinesq's and Cerruti's surface displacements (Johnson 1985, eqs.
// 3.21a, 3.86c) summed over the bodies with the signs of docs/theory.md,
// "Friction". The two are each other's transposes (the kernel is odd): the
// 3x3 compliance of (p, q) stays symmetric (Betti's reciprocity).
// `CouplingCoefficients` holds the tangential displacement (x, y) of a unit
// pressure; the normal displacement of a unit traction component a is its
// negative. One file per family: coupling_rectangle (free 2D),
// coupling_strip (free 1D), coupling_fourier (periodic).
#pragma once

namespace halfspace::kernels {

struct CouplingCoefficients {
  double x = 0.0;
  double y = 0.0;
};

}  // namespace halfspace::kernels
