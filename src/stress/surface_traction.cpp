// Parities of the stress components under each traction. The pressure's
// field is even in x and y except xz (odd in x), yz (odd in y) and xy (odd in
// both); a shear along x is odd under x -> -x, so every component's parity in
// x flips (Johnson 1985, eq. 3.87: xx, yy, zz odd in x, xz even).
#include "halfspace/stress/surface_traction.hpp"

namespace halfspace::stress {

void make_traction_on_body1(std::span<double> shear) {
  for (double& value : shear) value = -value;
}

bool odd_in_x(Component component, Traction traction) {
  return odd_in_x(component) != (traction == Traction::shear_x);
}

bool odd_in_y(Component component, Traction traction) {
  return odd_in_y(component) != (traction == Traction::shear_y);
}

}  // namespace halfspace::stress
