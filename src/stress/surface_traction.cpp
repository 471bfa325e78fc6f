// Parities of the stress components under each traction. The pressure's
// field is even in x and y except xz (odd in x), yz (odd in y) and xy (odd in
// both); a shear along x is odd under x -> -x, so every component's parity in
// x flips (Johnson 1985, eq. 3.87: xx, yy, zz odd in x, xz even).
#include "halfspace/stress/surface_traction.hpp"

namespace halfspace::stress {

SurfaceTractions tractions_on(StressedBody body, const SurfaceTractions& result,
                              std::array<std::vector<double>, 2>& scratch) {
  SurfaceTractions on = result;
  on.body = body;
  if (body == StressedBody::body2) return on;
  const std::array<std::span<const double>, 2> shear{result.shear_x, result.shear_y};
  for (std::size_t c = 0; c < 2; ++c) {
    scratch[c].resize(shear[c].size());
    for (std::size_t i = 0; i < shear[c].size(); ++i) scratch[c][i] = -shear[c][i];
  }
  on.shear_x = scratch[0];
  on.shear_y = scratch[1];
  return on;
}

bool odd_in_x(Component component, Traction traction) {
  return odd_in_x(component) != (traction == Traction::shear_x);
}

bool odd_in_y(Component component, Traction traction) {
  return odd_in_y(component) != (traction == Traction::shear_y);
}

}  // namespace halfspace::stress
