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
    throw InputError(
        fmt::format("{} = {} is invalid: must be positive and finite", to_string(mode), format_number(value)));
  }
}

void check_periodic_approach(double approach, double mean_initial_gap) {
  if (approach < mean_initial_gap) return;
  throw OptionError("approach", format_number(approach) + " m",
                    fmt::format("is invalid for a periodic surface: it must be below the mean initial gap {} m (full "
                                "contact needs infinite pressure there)",
                                format_number(mean_initial_gap)));
}

}  // namespace halfspace::solvers
