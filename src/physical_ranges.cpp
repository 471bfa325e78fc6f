// Range checks of physical quantities.
#include "halfspace/physical_ranges.hpp"

#include <fmt/format.h>

#include "halfspace/error.hpp"

namespace halfspace {

double require_in_range(const std::string& what, double value, double low, double high, std::string_view unit) {
  if (!(value >= low && value <= high)) {
    throw InputError(fmt::format("{} is invalid: allowed range is [{:g}, {:g}] {}", what, low, high, unit));
  }
  return value;
}

}  // namespace halfspace
