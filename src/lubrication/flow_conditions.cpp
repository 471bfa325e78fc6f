// The rules of a film's flow conditions, checked once for every front end.
#include "halfspace/lubrication/flow_conditions.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <utility>

#include "halfspace/error.hpp"

namespace halfspace::lubrication {

std::string_view to_string(AxisBoundary boundary) {
  return boundary == AxisBoundary::periodic ? "periodic" : "fixed pressure";
}

namespace {

// The library's names of the options (OptionError::option()), which the
// front ends restate with their own spelling.
void require_finite(double value, std::string_view name) {
  if (!std::isfinite(value))
    throw OptionError(std::string(name), format_number(value) + " m/s", "is invalid: it must be finite");
}

void require_pressure(double value, std::string_view name) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    throw OptionError(std::string(name), format_number(value) + " Pa",
                      "is invalid: allowed range is 0 (the cavitation pressure) to any finite pressure");
  }
}

}  // namespace

void FlowConditions::validate(const Grid& grid) const {
  if (!(std::isfinite(viscosity) && viscosity > 0.0)) {
    throw OptionError("viscosity", format_number(viscosity) + " Pa s", "is invalid: it must be positive and finite");
  }
  require_finite(entrainment_velocity[0], "entrainment_velocity.x");
  require_finite(entrainment_velocity[1], "entrainment_velocity.y");
  require_finite(sliding_velocity[0], "sliding_velocity.x");
  require_finite(sliding_velocity[1], "sliding_velocity.y");
  for (const auto& [name, velocity] : {std::pair{"entrainment_velocity.y", entrainment_velocity[1]},
                                       std::pair{"sliding_velocity.y", sliding_velocity[1]}}) {
    if (grid.dimension() == 1 && velocity != 0.0) {
      throw OptionError(name, format_number(velocity) + " m/s", "is invalid on a 1D grid: give the x component only");
    }
  }
  require_pressure(boundary.x_low_pressure, "boundary.x_low_pressure");
  require_pressure(boundary.x_high_pressure, "boundary.x_high_pressure");
  require_pressure(boundary.y_low_pressure, "boundary.y_low_pressure");
  require_pressure(boundary.y_high_pressure, "boundary.y_high_pressure");
  if (!(boundary.supply_fluid_fraction >= 0.0 && boundary.supply_fluid_fraction <= 1.0)) {
    throw OptionError("boundary.supply_fluid_fraction", format_number(boundary.supply_fluid_fraction),
                      "is invalid: allowed range is 0 to 1");
  }
  const bool x_fixed = boundary.x == AxisBoundary::fixed_pressure;
  const bool y_fixed = grid.dimension() == 2 && boundary.y == AxisBoundary::fixed_pressure;
  if (!x_fixed && !y_fixed) {
    throw InputError(
        "film boundary is periodic along every axis: fix the pressures along one axis (a film periodic in every "
        "direction has no pressure level and no supply)");
  }
  if (x_fixed && grid.nx() < 3) {
    throw InputError(fmt::format("grid nx = {} is too small for fixed pressures along x: at least 3 nodes", grid.nx()));
  }
  if (y_fixed && grid.ny() < 3) {
    throw InputError(fmt::format("grid ny = {} is too small for fixed pressures along y: at least 3 nodes", grid.ny()));
  }
}

}  // namespace halfspace::lubrication
