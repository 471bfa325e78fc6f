// `halfspace solve --adhesion ...` through the real executable: a single
// adhesive solve and a loading-unloading sweep with their attributes, the
// TOML keys, and the refusals of inconsistent adhesion options.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "io/hdf5_test_support.hpp"
#include "support/cli_checks.hpp"
#include "support/program_run.hpp"

namespace halfspace {
namespace {

namespace fs = std::filesystem;
using test::TempDir;
using testing::kExitInputError;
using testing::kExitOk;
using testing::run;

// A soft sphere (R = 10 mm, E* = 1 MPa, w = 0.05 J/m^2) on a 32 x 32 free
// grid of 1 mm: ell = (pi w R^2 / K)^(1/3) = 0.23 mm, the approach unit
// ell^2 / R = 5.3 um; sigma0 = 15 kPa makes the Tabor parameter about 1.
std::vector<std::string> sphere_arguments(const fs::path& output, const std::string& approach) {
  return {"solve",     "--geometry",
          "sphere",    "--radius",
          "0.01",      "--grid",
          "32x32",     "--size",
          "1e-3",      "--E-star",
          "1e6",       "--adhesion",
          "md",        "--work-of-adhesion",
          "0.05",      "--adhesion-stress",
          "1.5e4",     "--approach=" + approach,
          "--threads", "1",
          "--output",  output.string()};
}

using testing::ProgramRun;

TEST(AdhesionCliTest, SingleSolveWritesSignedPressureAndAdhesionAttributes) {
  const TempDir dir;
  const fs::path output = dir / "adhesive.h5";
  const ProgramRun result = run(sphere_arguments(output, "0"), dir);
  ASSERT_EQ(result.exit_code, kExitOk) << result.err;
  EXPECT_NE(result.out.find("adhesive-pcg"), std::string::npos) << result.out;  // the default minimiser
  EXPECT_NE(result.out.find("adhesive force"), std::string::npos) << result.out;
  const test::H5 file = test::open_file(output);
  EXPECT_EQ(test::read_string_attribute(file.get(), "adhesion_law"), "md");
  EXPECT_DOUBLE_EQ(test::read_double_attribute(file.get(), "work_of_adhesion"), 0.05);
  EXPECT_DOUBLE_EQ(test::read_double_attribute(file.get(), "adhesion_stress"), 1.5e4);
  EXPECT_NEAR(test::read_double_attribute(file.get(), "adhesion_range"), 0.05 / 1.5e4, 1e-20);
  const double adhesive = test::read_double_attribute(file.get(), "adhesive_force");
  EXPECT_LT(adhesive, 0.0);
  EXPECT_GT(test::read_double_attribute(file.get(), "interaction_fraction"),
            test::read_double_attribute(file.get(), "repulsive_contact_fraction"));
  const std::vector<double> pressure = test::read_dataset<double>(file.get(), "pressure", H5T_NATIVE_DOUBLE);
  // Inside the Dugdale zone the pressure is exactly -sigma0.
  EXPECT_DOUBLE_EQ(*std::min_element(pressure.begin(), pressure.end()), -1.5e4);
  EXPECT_GT(*std::max_element(pressure.begin(), pressure.end()), 0.0);
}

TEST(AdhesionCliTest, LoadingUnloadingSweepReportsPullOff) {
  const TempDir dir;
  const fs::path output = dir / "sweep.h5";
  // Up and back down: the unloading branch stays in contact where loading had none (hysteresis).
  const ProgramRun result = run(sphere_arguments(output, "-4e-6,0,5e-6,0,-2e-6,-4e-6"), dir);
  ASSERT_EQ(result.exit_code, kExitOk) << result.err;
  EXPECT_NE(result.out.find("pull-off force"), std::string::npos) << result.out;
  const test::H5 file = test::open_file(output);
  const std::vector<double> force = test::read_dataset<double>(file.get(), "sweep/total_force", H5T_NATIVE_DOUBLE);
  ASSERT_EQ(force.size(), 6U);
  const double scale = std::numbers::pi * 0.05 * 0.01;  // pi w R
  // At -4 um on loading the sphere is beyond h0 = 3.3 um: no force at all;
  // at -4 um on unloading it is still stuck (hysteresis).
  EXPECT_EQ(force[0], 0.0);
  EXPECT_LT(force[5], -0.5 * scale);
  const double pull_off = test::read_double_attribute(file.get(), "pull_off_force");
  EXPECT_DOUBLE_EQ(pull_off, *std::min_element(force.begin() + 3, force.end()));
  // Of the order of the JKR and DMT values, -3/2 and -2 pi w R, on this
  // coarse grid (7 cells per ell) and coarse list of approaches.
  EXPECT_LT(pull_off, -1.0 * scale);
  EXPECT_GT(pull_off, -2.5 * scale);
}

TEST(AdhesionCliTest, ConfigFileKeysMatchTheFlags) {
  const TempDir dir;
  const fs::path config = dir / "run.toml";
  std::ofstream(config) << "geometry = \"sphere\"\nradius = 0.01\ngrid = \"32x32\"\nsize = 1e-3\nE-star = 1e6\n"
                           "adhesion = \"exponential\"\nwork-of-adhesion = 0.05\nadhesion-range = 2e-6\n"
                           "approach = 0.0\nthreads = 1\noutput = \"out.h5\"\n";
  const ProgramRun result = run({"solve", "--config", config.string()}, dir);
  ASSERT_EQ(result.exit_code, kExitOk) << result.err;
  const test::H5 file = test::open_file(dir / "out.h5");
  EXPECT_EQ(test::read_string_attribute(file.get(), "adhesion_law"), "exponential");
  EXPECT_DOUBLE_EQ(test::read_double_attribute(file.get(), "adhesion_range"), 2e-6);
}

void expect_refused(const std::vector<std::string>& extra, const std::string& expected, bool adhesive = true,
                    const std::string& approach = "-1e-6") {
  const TempDir dir;
  const fs::path output = dir / "out.h5";
  std::vector<std::string> arguments{"solve",    "--geometry",   "sphere", "--radius", "0.01", "--grid",
                                     "16x16",    "--size",       "1e-3",   "--E-star", "1e6",  "--approach=" + approach,
                                     "--output", output.string()};
  if (adhesive) arguments.insert(arguments.end(), {"--adhesion", "md", "--work-of-adhesion", "0.05"});
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  testing::expect_input_error(run(arguments, dir), expected, output);
}

TEST(AdhesionCliTest, RefusesInconsistentAdhesionOptions) {
  expect_refused({}, "needs --adhesion-range H0 (m) or --adhesion-stress SIGMA0 (Pa)");
  expect_refused({"--adhesion-range", "1e-6", "--adhesion-stress", "1e4"}, "cannot be combined");
  expect_refused({"--adhesion-range", "-1e-6"}, "--adhesion-range -1e-6 is invalid");
  expect_refused({"--adhesion-stress", "0"}, "--adhesion-stress 0 is invalid");
  expect_refused({"--adhesion-range", "1e-6", "--solver", "pk"}, "adhesion has its own solver");
  expect_refused({"--adhesion-range", "1e-6", "--adhesion-precondition", "yes"},
                 "--adhesion-precondition yes is invalid: allowed values are on and off");
  expect_refused({"--adhesion", "jkr", "--work-of-adhesion", "0.05", "--adhesion-range", "1e-6"},
                 "allowed laws are md, exponential", false);
  // Without --adhesion: the law's options alone, and a negative approach, are refused.
  expect_refused({"--work-of-adhesion", "0.05"}, "--work-of-adhesion needs --adhesion md|exponential", false, "1e-6");
  expect_refused({}, "--approach -1e-6 is invalid", false);
}

// Issue 32, defects 3 and 4: a derived stress or range keeps the range of
// the option it replaces (no -inf force, no h0 of 5e-302 m), and a law whose
// cohesive zone the grid cannot resolve is refused with the numbers.
TEST(AdhesionCliTest, RefusesAdhesionParametersOutOfRange) {
  // The rules are the library's (make_problem, which Python calls too),
  // written with the flags.
  expect_refused({"--adhesion", "md", "--work-of-adhesion", "1e300", "--adhesion-range", "1e-6"},
                 "--adhesion-range 1e-6 is invalid with the work of adhesion 1e+300 J/m^2: the adhesive stress work / "
                 "range = 1e+306 Pa it gives must lie in [1e-09, 1e+13] Pa",
                 false);
  expect_refused({"--adhesion-stress", "1e300"},
                 "--adhesion-stress 1e300 is invalid: allowed range is [1e-09, 1e+13] Pa");
  expect_refused({"--adhesion-stress", "1e13"},
                 "--adhesion-stress 1e13 is invalid with the work of adhesion 0.05 J/m^2: the range h0 = work / stress "
                 "= 5e-15 m it gives must lie in [1e-12, 1000] m");
  expect_refused({"--adhesion", "md", "--work-of-adhesion", "-1", "--adhesion-range", "1e-6"},
                 "--work-of-adhesion -1 is invalid: must be positive and finite", false);
  // 16 cells on 1 mm: cells of 62.5 um against a zone of pi E* w / (4 sigma0^2) = 1.6e-17 m.
  expect_refused({"--adhesion-range", "1e-12"},
                 "its cohesive zone at a contact edge, pi E* w / (4 sigma0^2) = 1.57e-17 m");
}

TEST(AdhesionCliTest, RefusesStressForTheExponentialLaw) {
  const TempDir dir;
  std::vector<std::string> arguments = sphere_arguments(dir / "out.h5", "0");
  std::replace(arguments.begin(), arguments.end(), std::string("md"), std::string("exponential"));
  const ProgramRun result = run(arguments, dir);
  EXPECT_EQ(result.exit_code, kExitInputError);
  EXPECT_NE(result.err.find("applies only to --adhesion md"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace halfspace
