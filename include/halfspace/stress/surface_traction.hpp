// The tractions on the surface of the half-space whose stresses are computed:
// the pressure and, optionally, the shear tractions (q_x, q_y) beside it, and
// which stress components each of them makes odd in x or in y.
#pragma once

#include <span>

#include "halfspace/stress/fourier_stress.hpp"

namespace halfspace::stress {

// One traction field: the pressure p (Boussinesq) or a shear along x or y
// (Cerruti). At the surface sigma_zz = -p, sigma_xz = -q_x, sigma_yz = -q_y:
// q is the traction the other body exerts on this one along +x, +y (for a
// friction result, body 2's: solvers/tangential_result.hpp; body 1 carries
// -q and, in its own frame with z into it, the same formulas apply).
enum class Traction { pressure, shear_x, shear_y };

// The fields, Pa, each grid.size() values in (ny, nx) row-major order; an
// empty shear span is a zero shear.
struct SurfaceTractions {
  std::span<const double> pressure;
  std::span<const double> shear_x;
  std::span<const double> shear_y;

  bool has_shear() const { return !shear_x.empty() || !shear_y.empty(); }
};

// Turns a friction result's shear q (one component, in place) into the
// traction on body 1, -q: what the stresses of body 1 take (in its own
// frame, z into it), among them those of a coated result, whose coated body
// is body 1 (ElasticPair::coated).
void make_traction_on_body1(std::span<double> shear);

// Whether the stress component `component` under traction `traction` is odd
// in x (in y): the pressure's parity (odd_in_x, odd_in_y) with x (y) flipped
// for a shear along x (y), which is itself odd under that reflection.
bool odd_in_x(Component component, Traction traction);
bool odd_in_y(Component component, Traction traction);

}  // namespace halfspace::stress
