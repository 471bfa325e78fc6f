// The front ends' ranges of physical quantities (the program and Python
// call the same checks): an adhesion law's given and derived stress and
// range (issue 32, defect 4: the derived quantity escaped the range of the
// option it replaces).
#include "halfspace/physical_ranges.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "halfspace/error.hpp"

namespace halfspace {
namespace {

using solvers::AdhesionLaw;

// The option the check blames and the start of its sentence.
void expect_refused(const AdhesionLaw& law, bool given_as_stress, const std::string& option, const std::string& what) {
  try {
    check_adhesion_law_ranges(law, given_as_stress);
    ADD_FAILURE() << "accepted: " << what;
  } catch (const OptionError& error) {
    EXPECT_EQ(error.option(), option) << error.what();
    EXPECT_EQ(std::string(error.what()).rfind(what, 0), 0U) << error.what();
  }
}

TEST(PhysicalRangesTest, AdhesionLawsInsideTheRangesPass) {
  EXPECT_NO_THROW(check_adhesion_law_ranges(AdhesionLaw::maugis_dugdale(0.05, 1e-9), false));
  EXPECT_NO_THROW(check_adhesion_law_ranges(AdhesionLaw::exponential(0.05, 1e-9), false));
  EXPECT_NO_THROW(check_adhesion_law_ranges(AdhesionLaw::maugis_dugdale_from_stress(0.05, 1e6), true));
}

TEST(PhysicalRangesTest, AGivenRangeAndTheStressItGivesKeepTheirRanges) {
  expect_refused(AdhesionLaw::maugis_dugdale(0.05, 1e-13), false, "adhesion.range",
                 "adhesion.range = 1e-13 m is invalid: allowed range is [1e-12, 1000] m");
  expect_refused(AdhesionLaw::exponential(0.05, 2e3), false, "adhesion.range",
                 "adhesion.range = 2000 m is invalid: allowed range is [1e-12, 1000] m");
  // 1e300 / 1e-6: ended "converged" with a force of -inf.
  expect_refused(AdhesionLaw::maugis_dugdale(1e300, 1e-6), false, "adhesion.range",
                 "adhesion.range = 1e-06 m is invalid with the work of adhesion 1e+300 J/m^2: the adhesive stress "
                 "work / range = 1e+306 Pa it gives must lie in [1e-09, 1e+13] Pa");
  expect_refused(AdhesionLaw::maugis_dugdale(std::numeric_limits<double>::infinity(), 1e-6), false, "adhesion.work",
                 "adhesion.work = inf J/m^2 is invalid: must be positive and finite");
}

TEST(PhysicalRangesTest, AGivenStressAndTheRangeItGivesKeepTheirRanges) {
  expect_refused(AdhesionLaw::maugis_dugdale_from_stress(0.05, 1e300), true, "adhesion.stress",
                 "adhesion.stress = 1e+300 Pa is invalid: allowed range is [1e-09, 1e+13] Pa");
  // h0 = 0.05 / 1e13 = 5e-15 m, below the shortest length.
  expect_refused(AdhesionLaw::maugis_dugdale_from_stress(0.05, 1e13), true, "adhesion.stress",
                 "adhesion.stress = 1e+13 Pa is invalid with the work of adhesion 0.05 J/m^2: the range h0 = work / "
                 "stress = 5e-15 m it gives must lie in [1e-12, 1000] m");
  expect_refused(AdhesionLaw::maugis_dugdale_from_stress(0.05, 0.0), true, "adhesion.stress",
                 "adhesion.stress = 0 Pa is invalid: allowed range is");
}

}  // namespace
}  // namespace halfspace
