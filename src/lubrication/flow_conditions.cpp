// The rules of a film's flow conditions, checked once for every front end.
#include "halfspace/lubrication/flow_conditions.hpp"

#include <fmt/format.h>

#include <cmath>

#include "halfspace/error.hpp"

namespace halfspace::lubrication {

std::string_view to_string(AxisBoundary boundary) {
  return boundary == AxisBoundary::periodic ? "periodic" : "fixed pressure";
}

namespace {

void require_finite(double value, std::string_view name) {
  if (!std::isfinite(value)) throw InputError(fmt::format("{} = {} is invalid: it must be finite", name, value));
}

void require_pressure(double value, std::string_view name) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    throw InputError(fmt::format(
        "{} = {} Pa is invalid: allowed range is 0 (the cavitation pressure) to any finite pressure", name, value));
  }
}

}  // namespace

void FlowConditions::validate(const Grid& grid) const {
  if (!(std::isfinite(viscosity) && viscosity > 0.0)) {
    throw InputError(fmt::format("viscosity = {} Pa s is invalid: it must be positive and finite", viscosity));
  }
  require_finite(entrainment_velocity[0], "entrainment velocity x");
  require_finite(entrainment_velocity[1], "entrainment velocity y");
  require_finite(sliding_velocity[0], "sliding velocity x");
  require_finite(sliding_velocity[1], "sliding velocity y");
  if (grid.dimension() == 1 && (entrainment_velocity[1] != 0.0 || sliding_velocity[1] != 0.0)) {
    throw InputError(
        fmt::format("entrainment velocity y = {} m/s and sliding velocity y = {} m/s are invalid on a 1D grid: give x "
                    "components only",
                    entrainment_velocity[1], sliding_velocity[1]));
  }
  require_pressure(boundary.x_low_pressure, "pressure at x low");
  require_pressure(boundary.x_high_pressure, "pressure at x high");
  require_pressure(boundary.y_low_pressure, "pressure at y low");
  require_pressure(boundary.y_high_pressure, "pressure at y high");
  if (!(boundary.supply_fluid_fraction >= 0.0 && boundary.supply_fluid_fraction <= 1.0)) {
    throw InputError(
        fmt::format("supply fluid fraction = {} is invalid: allowed range is 0 to 1", boundary.supply_fluid_fraction));
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
