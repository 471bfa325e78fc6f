// Range checks of physical quantities, and of the adhesion law's derived ones.
#include "halfspace/physical_ranges.hpp"

#include <fmt/format.h>

#include <cmath>

#include "halfspace/error.hpp"

namespace halfspace {
namespace {

std::string allowed(double low, double high, std::string_view unit) {
  return fmt::format("allowed range is [{:g}, {:g}] {}", low, high, unit);
}

bool inside(double value, double low, double high) {
  return value >= low && value <= high;
}

}  // namespace

double require_in_range(const std::string& what, double value, double low, double high, std::string_view unit) {
  if (!inside(value, low, high)) throw InputError(fmt::format("{} is invalid: {}", what, allowed(low, high, unit)));
  return value;
}

void check_adhesion_law_ranges(const solvers::AdhesionLaw& law, bool given_as_stress) {
  if (!(std::isfinite(law.work) && law.work > 0.0)) {
    throw OptionError("adhesion.work", format_number(law.work) + " J/m^2", "is invalid: must be positive and finite");
  }
  const std::string work = fmt::format("the work of adhesion {} J/m^2", format_number(law.work));
  if (given_as_stress) {
    // sigma0 given; the range h0 = w / sigma0 derived.
    const double sigma0 = law.work / law.range;
    const std::string value = format_number(sigma0) + " Pa";
    if (!inside(sigma0, kMinMeanPressure, kMaxMeanPressure)) {
      throw OptionError("adhesion.stress", value, "is invalid: " + allowed(kMinMeanPressure, kMaxMeanPressure, "Pa"));
    }
    if (!inside(law.range, kMinLength, kMaxLength)) {
      throw OptionError("adhesion.stress", value,
                        fmt::format("is invalid with {}: the range h0 = work / stress = {} m it gives must lie in "
                                    "[{:g}, {:g}] m, the range of lengths",
                                    work, format_number(law.range), kMinLength, kMaxLength));
    }
  } else {
    const std::string value = format_number(law.range) + " m";
    if (!inside(law.range, kMinLength, kMaxLength)) {
      throw OptionError("adhesion.range", value, "is invalid: " + allowed(kMinLength, kMaxLength, "m"));
    }
    const double stress = law.stress();
    if (!inside(stress, kMinMeanPressure, kMaxMeanPressure)) {
      throw OptionError("adhesion.range", value,
                        fmt::format("is invalid with {}: the adhesive stress work / range = {} Pa it gives must lie "
                                    "in [{:g}, {:g}] Pa, the range of stresses",
                                    work, format_number(stress), kMinMeanPressure, kMaxMeanPressure));
    }
  }
  law.validate();
}

}  // namespace halfspace
