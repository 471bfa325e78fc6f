// The tractions on the surface of the half-space whose stresses are computed:
// the pressure and, optionally, the shear tractions (q_x, q_y) beside it, and
// which stress components each of them makes odd in x or in y.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "halfspace/stress/fourier_stress.hpp"

namespace halfspace::stress {

// One traction field: the pressure p (Boussinesq) or a shear along x or y
// (Cerruti). At the surface sigma_zz = -p, sigma_xz = -q_x, sigma_yz = -q_y:
// q is the traction the other body exerts on this one along +x, +y (for a
// friction result, body 2's: solvers/tangential_result.hpp; body 1 carries
// -q and, in its own frame with z into it, the same formulas apply).
enum class Traction { pressure, shear_x, shear_y };

// Which of the two bodies the tractions act on, and so whose stress field
// they give. The pressure loads both alike; a friction result's shear q is
// the traction body 1 exerts on body 2, so body 2 takes q and body 1 -q
// (stressed_body.hpp chooses between them).
enum class StressedBody { body1, body2 };

// The fields, Pa, each grid.size() values in (ny, nx) row-major order; an
// empty shear span is a zero shear.
struct SurfaceTractions {
  std::span<const double> pressure;
  std::span<const double> shear_x;
  std::span<const double> shear_y;
  StressedBody body = StressedBody::body2;  // recorded with the stresses (the /stress group's `body`)

  bool has_shear() const { return !shear_x.empty() || !shear_y.empty(); }
};

// The tractions on `body` from a result's pressure and shear q (the
// traction on body 2): body 2's are the result's own; body 1's take -q,
// copied into `scratch` (in body 1's own frame, z into it, the same stress
// formulas apply). A coated result's coated body is body 1
// (ElasticPair::coated).
SurfaceTractions tractions_on(StressedBody body, const SurfaceTractions& result,
                              std::array<std::vector<double>, 2>& scratch);

// Whether the stress component `component` under traction `traction` is odd
// in x (in y): the pressure's parity (odd_in_x, odd_in_y) with x (y) flipped
// for a shear along x (y), which is itself odd under that reflection.
bool odd_in_x(Component component, Traction traction);
bool odd_in_y(Component component, Traction traction);

}  // namespace halfspace::stress
