// The two cohesive laws and their checks.
#include "halfspace/solvers/adhesion_law.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "halfspace/error.hpp"

namespace halfspace::solvers {

std::string_view to_string(AdhesionLawType type) {
  switch (type) {
    case AdhesionLawType::maugis_dugdale:
      return "md";
    case AdhesionLawType::exponential:
      return "exponential";
  }
  return "unknown";
}

AdhesionLawType parse_adhesion_law_type(std::string_view name) {
  if (name == "md" || name == "maugis-dugdale") return AdhesionLawType::maugis_dugdale;
  if (name == "exponential") return AdhesionLawType::exponential;
  throw InputError(fmt::format("adhesion = {} is invalid: allowed laws are md, exponential", name));
}

// traction and energy are inline in the header: the solvers call them for
// every cell in every pass.

double AdhesionLaw::traction_slope(double gap) const {
  if (type == AdhesionLawType::maugis_dugdale) return 0.0;
  return stress() / range * std::exp(-gap / range);
}

double AdhesionLaw::cohesive_zone_length(double e_star) const {
  // pi E* w / (4 sigma0^2) with sigma0 = w / range, written so that no
  // square overflows.
  return std::numbers::pi * e_star * (range / 4.0) * (range / work);
}

bool AdhesionLaw::interacts(double gap) const {
  if (type == AdhesionLawType::maugis_dugdale) return gap < range;
  return gap < range * std::log(1.0 / kInteractionFraction);
}

void AdhesionLaw::validate() const {
  if (!(std::isfinite(work) && work > 0.0)) {
    throw InputError(
        fmt::format("work-of-adhesion = {} is invalid: must be positive and finite (J/m^2)", format_number(work)));
  }
  if (!(std::isfinite(range) && range > 0.0)) {
    throw InputError(
        fmt::format("adhesion-range = {} is invalid: must be positive and finite (m)", format_number(range)));
  }
  const double sigma = stress();
  if (!(std::isfinite(sigma) && std::isnormal(sigma))) {
    throw InputError(fmt::format(
        "adhesion stress = work-of-adhesion / adhesion-range = {} / {} = {} Pa is invalid: must be finite and normal",
        format_number(work), format_number(range), format_number(sigma)));
  }
}

}  // namespace halfspace::solvers
