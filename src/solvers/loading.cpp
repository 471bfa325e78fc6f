// Names and validation of the loading modes.
#include "halfspace/solvers/loading.hpp"

#include <fmt/format.h>

#include <cmath>

#include "halfspace/error.hpp"

namespace halfspace::solvers {

std::string_view to_string(ControlMode mode) {
  switch (mode) {
    case ControlMode::force:
      return "force";
    case ControlMode::mean_pressure:
      return "mean_pressure";
    case ControlMode::approach:
      return "approach";
  }
  return "unknown";
}

void Loading::validate() const {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InputError(fmt::format("{} = {} is invalid: must be positive and finite", to_string(mode), value));
  }
}

}  // namespace halfspace::solvers
