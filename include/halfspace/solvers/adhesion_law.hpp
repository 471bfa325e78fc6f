// Cohesive (adhesive) interface laws: the attractive traction and the
// interaction energy per unit area as functions of the gap, acting beside
// the hard wall gap >= 0 of the repulsive contact.
#pragma once

#include <cmath>
#include <string_view>

namespace halfspace::solvers {

enum class AdhesionLawType {
  // Maugis-Dugdale: a constant attractive stress sigma0 where 0 <= gap < h0,
  // none beyond; work of adhesion w = sigma0 h0 (Maugis 1992, J. Colloid
  // Interface Sci. 150, 243).
  maugis_dugdale,
  // A smooth exponential attraction of range rho: energy -w exp(-gap/rho),
  // traction -(w/rho) exp(-gap/rho) (the Contact Mechanics Challenge's kind,
  // Mueser et al. 2017, Tribol. Lett. 65, 118).
  exponential,
};

// "md", "exponential".
std::string_view to_string(AdhesionLawType type);
// The inverse of to_string ("maugis-dugdale" is accepted for "md"); throws
// InputError naming the option "adhesion", the value and the allowed names.
AdhesionLawType parse_adhesion_law_type(std::string_view name);

struct AdhesionLaw {
  AdhesionLawType type = AdhesionLawType::maugis_dugdale;
  double work = 0.0;   // work of adhesion w (J/m^2): the energy per area to separate from contact
  double range = 0.0;  // m: h0 (maugis_dugdale, where the stress stops) or rho (exponential, decay length)

  static AdhesionLaw maugis_dugdale(double work_of_adhesion, double h0) {
    return {AdhesionLawType::maugis_dugdale, work_of_adhesion, h0};
  }
  // Maugis-Dugdale given its stress sigma0 (Pa): h0 = w / sigma0.
  static AdhesionLaw maugis_dugdale_from_stress(double work_of_adhesion, double sigma0) {
    return {AdhesionLawType::maugis_dugdale, work_of_adhesion, work_of_adhesion / sigma0};
  }
  static AdhesionLaw exponential(double work_of_adhesion, double rho) {
    return {AdhesionLawType::exponential, work_of_adhesion, rho};
  }

  // The largest attractive stress (Pa), w / range for both laws: sigma0 of
  // Maugis-Dugdale, the traction at contact of the exponential law.
  double stress() const { return work / range; }
  // Signed pressure (Pa) the law exerts at `gap` (m, >= 0): <= 0 (attractive).
  double traction(double gap) const {
    if (type == AdhesionLawType::maugis_dugdale) return gap < range ? -stress() : 0.0;
    return -stress() * std::exp(-gap / range);
  }
  // Interaction energy per area (J/m^2) at `gap`: -w at contact, rising to 0;
  // traction = -d energy / d gap.
  double energy(double gap) const {
    if (type == AdhesionLawType::maugis_dugdale) return gap < range ? -work + stress() * gap : 0.0;
    return -work * std::exp(-gap / range);
  }
  // d traction / d gap (Pa/m): 0 for Maugis-Dugdale away from h0.
  double traction_slope(double gap) const;
  // Whether a cell at `gap` interacts: 0 <= gap < h0 for Maugis-Dugdale;
  // for the exponential law, while the attraction exceeds
  // kInteractionFraction of its value at contact (gap < rho ln(1/0.01)).
  bool interacts(double gap) const;
  static constexpr double kInteractionFraction = 0.01;

  // The length (m) of the cohesive zone at a contact edge on a body of
  // contact modulus e_star (Pa): the Dugdale zone of the edge crack in the
  // small-zone (JKR) limit, s = pi K^2 / (8 sigma0^2) with K^2 = 2 E* w
  // (Maugis 1992; Johnson 1985, Contact Mechanics), pi E* w / (4 sigma0^2),
  // sigma0 the largest attractive stress. A grid resolves the law's
  // traction at a contact edge only if its cells are not much longer.
  double cohesive_zone_length(double e_star) const;

  // Throws InputError naming the option ("work-of-adhesion",
  // "adhesion-range") and value unless w and range are positive and finite,
  // and the stress w / range is finite and normal.
  void validate() const;
};

}  // namespace halfspace::solvers

namespace halfspace {
using solvers::AdhesionLaw;
using solvers::AdhesionLawType;
}  // namespace halfspace
