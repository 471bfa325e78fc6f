// Gross sliding: Coulomb's law at its limit in every contact cell, the
// traction along the relative sliding velocity (Johnson 1985, sec. 7.2).
#include "halfspace/stress/sliding_traction.hpp"

#include <fmt/format.h>

#include <cmath>

#include "halfspace/error.hpp"

namespace halfspace::stress {

SlidingShear gross_sliding_shear(std::span<const double> pressure, double friction_coefficient, double direction_x,
                                 double direction_y) {
  if (!(std::isfinite(friction_coefficient) && friction_coefficient >= 0.0)) {
    throw InputError(
        fmt::format("friction coefficient mu = {} is invalid: it must be finite and >= 0", friction_coefficient));
  }
  const double length = std::hypot(direction_x, direction_y);
  if (!(std::isfinite(length) && length > 0.0)) {
    throw InputError(
        fmt::format("sliding direction ({}, {}) is invalid: it must be finite and not zero", direction_x, direction_y));
  }
  SlidingShear shear{std::vector<double>(pressure.size()), std::vector<double>(pressure.size())};
  const double cx = friction_coefficient * direction_x / length;
  const double cy = friction_coefficient * direction_y / length;
  for (std::size_t k = 0; k < pressure.size(); ++k) {
    if (!(std::isfinite(pressure[k]) && pressure[k] >= 0.0)) {
      throw InputError(fmt::format(
          "gross sliding: pressure value {} Pa at index {} is invalid: it must be finite and >= 0", pressure[k], k));
    }
    shear.x[k] = cx * pressure[k];
    shear.y[k] = cy * pressure[k];
  }
  return shear;
}

}  // namespace halfspace::stress
