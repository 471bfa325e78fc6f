// The cohesive laws: values, traction = -d energy / d gap, and their checks.
#include "halfspace/solvers/adhesion_law.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "halfspace/error.hpp"

namespace halfspace {
namespace {

// Central differences of the smooth exponential energy at step 1e-6 rho:
// truncation ~1e-12 relative, rounding ~1e-10 relative.
constexpr double kDerivativeTolerance = 1e-7;

TEST(AdhesionLawTest, MaugisDugdaleHasConstantStressWithinRange) {
  const AdhesionLaw law = AdhesionLaw::maugis_dugdale(0.05, 2e-9);
  EXPECT_DOUBLE_EQ(law.stress(), 0.05 / 2e-9);
  EXPECT_DOUBLE_EQ(law.traction(0.0), -law.stress());
  EXPECT_DOUBLE_EQ(law.traction(1.999e-9), -law.stress());
  EXPECT_EQ(law.traction(2e-9), 0.0);
  EXPECT_DOUBLE_EQ(law.energy(0.0), -0.05);
  EXPECT_NEAR(law.energy(1e-9), -0.025, 1e-15);
  EXPECT_EQ(law.energy(3e-9), 0.0);
  EXPECT_TRUE(law.interacts(1e-9));
  EXPECT_FALSE(law.interacts(2e-9));
  const AdhesionLaw same = AdhesionLaw::maugis_dugdale_from_stress(0.05, 0.05 / 2e-9);
  EXPECT_DOUBLE_EQ(same.range, 2e-9);
}

// The Dugdale zone pi E* w / (4 sigma0^2): issue 32's h0 = 1e-12 m (sigma0 =
// 5e10 Pa) on E* = 1 MPa gives 1.57e-17 m; a stress whose square overflows
// still gives a finite length.
TEST(AdhesionLawTest, CohesiveZoneLengthIsTheDugdaleZone) {
  const double sigma0 = 0.05 / 1e-12;
  EXPECT_NEAR(AdhesionLaw::maugis_dugdale(0.05, 1e-12).cohesive_zone_length(1e6),
              std::numbers::pi * 1e6 * 0.05 / (4.0 * sigma0 * sigma0), 1e-14 * 1.57e-17);
  const double huge = AdhesionLaw::maugis_dugdale(1e300, 1e-6).cohesive_zone_length(1e6);
  EXPECT_TRUE(std::isfinite(huge));
  EXPECT_LT(huge, 1e-290);
}

TEST(AdhesionLawTest, ExponentialTractionIsMinusEnergySlope) {
  const AdhesionLaw law = AdhesionLaw::exponential(0.1, 1e-9);
  EXPECT_DOUBLE_EQ(law.energy(0.0), -0.1);
  EXPECT_DOUBLE_EQ(law.traction(0.0), -0.1 / 1e-9);
  for (const double gap : {0.0, 0.3e-9, 1e-9, 4e-9}) {
    const double h = 1e-6 * law.range;
    const double slope = (law.energy(gap + h) - law.energy(std::max(gap - h, 0.0))) / (gap > 0.0 ? 2 * h : h);
    EXPECT_NEAR(law.traction(gap), -slope,
                kDerivativeTolerance * law.stress() + (gap > 0.0 ? 0.0 : 1e-6 * law.stress()))
        << "gap " << gap;
    const double t = 1e-6 * law.range;
    EXPECT_NEAR(law.traction_slope(gap + t), (law.traction(gap + 2 * t) - law.traction(gap)) / (2 * t),
                1e-5 * law.stress() / law.range);
  }
  // Interacting while the attraction exceeds 1 % of its value at contact.
  EXPECT_TRUE(law.interacts(4.5e-9));
  EXPECT_FALSE(law.interacts(4.7e-9));
}

TEST(AdhesionLawTest, RefusesNonPositiveOrNonFiniteParameters) {
  const auto message = [](const AdhesionLaw& law) {
    try {
      law.validate();
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  EXPECT_NE(message(AdhesionLaw::exponential(-1.0, 1e-9)).find("work-of-adhesion = -1"), std::string::npos);
  EXPECT_NE(message(AdhesionLaw::exponential(0.1, 0.0)).find("adhesion-range = 0"), std::string::npos);
  EXPECT_NE(message(AdhesionLaw::maugis_dugdale(0.1, NAN)).find("adhesion-range"), std::string::npos);
  EXPECT_NE(message(AdhesionLaw::maugis_dugdale(1e300, 1e-300)).find("adhesion stress"), std::string::npos);
  EXPECT_EQ(message(AdhesionLaw::maugis_dugdale(0.1, 1e-9)), "");
  EXPECT_THROW(solvers::parse_adhesion_law_type("jkr"), InputError);
  EXPECT_EQ(solvers::parse_adhesion_law_type("md"), AdhesionLawType::maugis_dugdale);
  EXPECT_EQ(solvers::parse_adhesion_law_type("exponential"), AdhesionLawType::exponential);
}

}  // namespace
}  // namespace halfspace
