// The tangential surface compliance of the two bodies (elastic_pair.hpp) at one
// offset or one wave vector: the symmetric 2x2 block
//   u_x = xx t_x + xy t_y,   u_y = xy t_x + yy t_y
// of the relative tangential displacement u (m) of the surfaces under the
// tangential traction t (Pa) that body 1 exerts on body 2 (docs/theory.md,
// "Friction"). One file per family: cerruti_rectangle (free 2D),
// tangential_strip (free 1D), tangential_fourier (periodic).
#pragma once

namespace halfspace::kernels {

struct TangentialCoefficients {
  double xx = 0.0;
  double yy = 0.0;
  double xy = 0.0;
};

}  // namespace halfspace::kernels
