// The front ends' ranges of physical quantities (the program and Python
// call the same checks, make_problem): an adhesion law's given and derived
// stress and range (issue 32, defect 4: the derived quantity escaped the
// range of the option it replaces).
#include "halfspace/physical_ranges.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/problem.hpp"

namespace halfspace {
namespace {

// An adhesive problem whose law is md or exponential of work w and range
// (or, for md, stress).
ProblemOptions adhesive(const std::string& law, double work, std::optional<double> range,
                        std::optional<double> stress = std::nullopt) {
  ProblemOptions options;
  options.e_star = 1e9;
  options.approach = std::vector<double>{-1e-9};
  options.adhesion = law;
  options.work_of_adhesion = work;
  options.adhesion_range = range;
  options.adhesion_stress = stress;
  return options;
}

// The start of the sentence the check refuses `options` with.
void expect_refused(const ProblemOptions& options, const std::string& what) {
  try {
    make_problem(options);
    ADD_FAILURE() << "accepted: " << what;
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(what, 0), 0U) << error.what();
  }
}

TEST(PhysicalRangesTest, AdhesionLawsInsideTheRangesPass) {
  EXPECT_NO_THROW(make_problem(adhesive("md", 0.05, 1e-9)));
  EXPECT_NO_THROW(make_problem(adhesive("exponential", 0.05, 1e-9)));
  EXPECT_NO_THROW(make_problem(adhesive("md", 0.05, std::nullopt, 1e6)));
}

TEST(PhysicalRangesTest, AGivenRangeAndTheStressItGivesKeepTheirRanges) {
  expect_refused(adhesive("md", 0.05, 1e-13), "adhesion_range=1e-13 m is invalid: allowed range is [1e-12, 1000] m");
  expect_refused(adhesive("exponential", 0.05, 2e3),
                 "adhesion_range=2000 m is invalid: allowed range is [1e-12, 1000] m");
  // 1e300 / 1e-6: ended "converged" with a force of -inf.
  expect_refused(adhesive("md", 1e300, 1e-6),
                 "adhesion_range=1e-06 m is invalid with the work of adhesion 1e+300 J/m^2: the adhesive stress "
                 "work / range = 1e+306 Pa it gives must lie in [1e-09, 1e+13] Pa");
  expect_refused(adhesive("md", std::numeric_limits<double>::infinity(), 1e-6),
                 "work_of_adhesion=inf J/m^2 is invalid: must be positive and finite");
}

TEST(PhysicalRangesTest, AGivenStressAndTheRangeItGivesKeepTheirRanges) {
  expect_refused(adhesive("md", 0.05, std::nullopt, 1e300),
                 "adhesion_stress=1e+300 Pa is invalid: allowed range is [1e-09, 1e+13] Pa");
  // h0 = 0.05 / 1e13 = 5e-15 m, below the shortest length.
  expect_refused(adhesive("md", 0.05, std::nullopt, 1e13),
                 "adhesion_stress=1e+13 Pa is invalid with the work of adhesion 0.05 J/m^2: the range h0 = work / "
                 "stress = 5e-15 m it gives must lie in [1e-12, 1000] m");
  expect_refused(adhesive("md", 0.05, std::nullopt, 0.0), "adhesion_stress=0 Pa is invalid: allowed range is");
}

TEST(PhysicalRangesTest, ValuesOutsideARangeNameItsBounds) {
  EXPECT_EQ(require_in_range("x", 1.0, 0.0, 2.0, "m"), 1.0);
  try {
    require_in_range("--size 5", 5.0, 0.0, 2.0, "m");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "--size 5 is invalid: allowed range is [0, 2] m");
  }
}

}  // namespace
}  // namespace halfspace
