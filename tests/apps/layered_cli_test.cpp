// `halfspace solve` on a coated half-space: --layer-thickness, --layer-E,
// --layer-nu, --substrate-E, --substrate-nu (all five, instead of the
// material options), recorded in the result's attributes, and their errors.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
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
using testing::expect_input_error;
using testing::kExitInputError;
using testing::kExitOk;
using testing::ProgramRun;

using Options = testing::OptionPairs;

ProgramRun run_solve(const Options& options, const TempDir& directory) {
  return testing::run(testing::command_arguments("solve", options), directory);
}

// A small sphere problem without a material.
Options sphere(const fs::path& output) {
  return {{"--geometry", "sphere"}, {"--radius", "0.01"},          {"--grid", "32x32"}, {"--size", "4e-4"},
          {"--force", "1"},         {"--output", output.string()}, {"--threads", "1"}};
}

Options coating(const std::string& thickness = "2e-5", const std::string& layer_e = "3e9",
                const std::string& layer_nu = "0.35") {
  return {{"--layer-thickness", thickness},
          {"--layer-E", layer_e},
          {"--layer-nu", layer_nu},
          {"--substrate-E", "2.1e11"},
          {"--substrate-nu", "0.29"}};
}

Options joined(Options a, const Options& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(LayeredCliTest, CoatedSolveRecordsTheCoatingAndTheLayersModulus) {
  const TempDir dir;
  const fs::path output = dir / "coated.h5";
  const ProgramRun result = run_solve(joined(sphere(output), coating()), dir);
  ASSERT_EQ(result.exit_code, kExitOk) << result.err;
  EXPECT_NE(result.out.find("coating"), std::string::npos) << result.out;
  const test::H5 file = test::open_file(output);
  EXPECT_EQ(test::read_double_attribute(file.get(), "layer_thickness"), 2e-5);
  EXPECT_EQ(test::read_double_attribute(file.get(), "layer_E"), 3e9);
  EXPECT_EQ(test::read_double_attribute(file.get(), "layer_nu"), 0.35);
  EXPECT_EQ(test::read_double_attribute(file.get(), "substrate_E"), 2.1e11);
  EXPECT_EQ(test::read_double_attribute(file.get(), "substrate_nu"), 0.29);
  EXPECT_DOUBLE_EQ(test::read_double_attribute(file.get(), "E_star"), 3e9 / (1 - 0.35 * 0.35));
  EXPECT_EQ(test::read_int64_attribute(file.get(), "converged"), 1);
}

// The same solve, two ways: rounding of the kernels (M = 1 + O(eps)) and of
// the solver's iterates.
constexpr double kSameSolveTolerance = 1e-8;

TEST(LayeredCliTest, CoatingOfTheSubstratesMaterialSolvesLikeTheHomogeneousHalfSpace) {
  const TempDir dir;
  const fs::path coated = dir / "coated.h5";
  const fs::path homogeneous = dir / "homogeneous.h5";
  const Options steel_on_steel = {{"--layer-thickness", "2e-5"},
                                  {"--layer-E", "2.1e11"},
                                  {"--layer-nu", "0.29"},
                                  {"--substrate-E", "2.1e11"},
                                  {"--substrate-nu", "0.29"}};
  ASSERT_EQ(run_solve(joined(sphere(coated), steel_on_steel), dir).exit_code, kExitOk);
  const double e_star = 2.1e11 / (1 - 0.29 * 0.29);
  ASSERT_EQ(run_solve(joined(sphere(homogeneous), {{"--E-star", fmt::format("{:.17g}", e_star)}}), dir).exit_code,
            kExitOk);
  const test::H5 a = test::open_file(coated);
  const test::H5 b = test::open_file(homogeneous);
  for (const char* name : {"max_pressure", "approach", "contact_fraction"}) {
    const double expected = test::read_double_attribute(b.get(), name);
    EXPECT_NEAR(test::read_double_attribute(a.get(), name), expected, kSameSolveTolerance * std::abs(expected)) << name;
  }
}

TEST(LayeredCliTest, CoatingOptionErrorsNameTheOptionValueAndRange) {
  const TempDir dir;
  const fs::path output = dir / "out.h5";
  Options missing = coating();
  missing.pop_back();
  expect_input_error(run_solve(joined(sphere(output), missing), dir),
                     "incomplete coated half-space: missing --substrate-nu", output);
  expect_input_error(run_solve(joined(joined(sphere(output), coating()), {{"--E-star", "1e11"}}), dir),
                     "cannot be combined with --E-star", output);
  expect_input_error(run_solve(joined(sphere(output), coating("1e4")), dir),
                     "--layer-thickness 1e4 is invalid: allowed range is [1e-12, 1000] m", output);
  expect_input_error(run_solve(joined(sphere(output), coating("2e-5", "10")), dir),
                     "--layer-E 10 is invalid: allowed range is [1000, 1e+15] Pa", output);
  expect_input_error(run_solve(joined(sphere(output), coating("2e-5", "3e9", "0.7")), dir),
                     "--layer-nu 0.7 is invalid: allowed range is (-1, 0.5]", output);
  expect_input_error(run_solve(joined(joined(sphere(output), coating()), {{"--solver", "lemke"}}), dir),
                     "--solver lemke is invalid for a coated half-space", output);
}

// A Hertz line contact (cylinder, R = 10 mm, 100 N/m) on a polymer coating
// (t = 20 um, about the contact's half-width) over steel, on a free 1D grid
// and on a periodic one of the same length (20 half-widths: its images move
// the pressure by about (b/L)^2): the same peak pressure and contact width,
// both between the Hertz values of the polymer's and the steel's half-plane.
TEST(LayeredCliTest, HertzLineOnACoatingFreeAndPeriodic) {
  const TempDir dir;
  const double radius = 0.01;
  const double force = 100.0;
  const auto solve_line = [&](const std::string& boundary) {
    const fs::path output = dir / (boundary + ".h5");
    const Options cylinder = {{"--geometry", "cylinder"}, {"--radius", "0.01"},    {"--grid", "512"},
                              {"--size", "4e-4"},         {"--force", "100"},      {"--output", output.string()},
                              {"--threads", "1"},         {"--boundary", boundary}};
    const ProgramRun run = run_solve(joined(cylinder, coating()), dir);
    EXPECT_EQ(run.exit_code, kExitOk) << run.err;
    const test::H5 file = test::open_file(output);
    return test::read_dataset<double>(file.get(), "/pressure", H5T_NATIVE_DOUBLE);
  };
  const std::vector<double> free = solve_line("free");
  const std::vector<double> periodic = solve_line("periodic");
  ASSERT_EQ(free.size(), periodic.size());
  const auto peak = [](const std::vector<double>& p) { return *std::max_element(p.begin(), p.end()); };
  const auto width = [](const std::vector<double>& p) {
    return std::count_if(p.begin(), p.end(), [](double v) { return v > 0.0; });
  };
  const auto hertz_peak = [&](double youngs, double nu) {  // p0 = sqrt(F E* / (pi R))
    return std::sqrt(force * youngs / (1.0 - nu * nu) / (std::numbers::pi * radius));
  };
  std::printf("Hertz line on a coating: peak %.4g (free), %.4g (periodic) Pa; %ld and %ld cells in contact\n",
              peak(free), peak(periodic), static_cast<long>(width(free)), static_cast<long>(width(periodic)));
  EXPECT_NEAR(peak(free), peak(periodic), 0.01 * peak(periodic));
  EXPECT_LE(std::abs(width(free) - width(periodic)), 2);
  EXPECT_GT(peak(free), 1.05 * hertz_peak(3e9, 0.35));
  EXPECT_LT(peak(free), hertz_peak(2.1e11, 0.29));
}

// The stress fields `names` of the stress command's file and of the solve's
// result file agree. The two processes may plan their transforms
// differently (measured plans), so to rounding, not bit for bit; and a
// field must not be zero (that would make the comparison vacuous).
void expect_same_stresses(const fs::path& from_command_file, const fs::path& from_solve_file,
                          std::initializer_list<const char*> names) {
  constexpr double kPlanRounding = 1e-12;  // relative to the field's largest value
  const test::H5 other = test::open_file(from_command_file);
  const test::H5 file = test::open_file(from_solve_file);
  for (const char* name : names) {
    const auto from_command = test::read_dataset<double>(other.get(), name, H5T_NATIVE_DOUBLE);
    const auto from_solve = test::read_dataset<double>(file.get(), name, H5T_NATIVE_DOUBLE);
    ASSERT_EQ(from_command.size(), from_solve.size()) << name;
    double largest = 0.0;
    double worst = 0.0;
    for (std::size_t i = 0; i < from_solve.size(); ++i) {
      largest = std::max(largest, std::abs(from_solve[i]));
      worst = std::max(worst, std::abs(from_command[i] - from_solve[i]));
    }
    EXPECT_GT(largest, 0.0) << name;
    EXPECT_LE(worst, kPlanRounding * largest) << name << ": largest difference " << worst << " of " << largest;
  }
}

// A hard coating on a periodic grid, stresses at depths on both sides of the
// interface: from `solve --stress-depths` and from `halfspace stress` on the
// result, which reads the coating back (the two must agree exactly).
TEST(LayeredCliTest, StressesBelowACoatingFromSolveAndFromTheStressCommand) {
  const TempDir dir;
  const fs::path output = dir / "coated.h5";
  Options options = joined(joined(sphere(output), coating("2e-5", "4e11", "0.22")), {{"--boundary", "periodic"}});
  options.push_back({"--stress-depths", "5e-6,2e-5,3e-5"});
  const ProgramRun solved = run_solve(options, dir);
  ASSERT_EQ(solved.exit_code, kExitOk) << solved.err;
  const test::H5 file = test::open_file(output);
  const auto in_layer = test::read_dataset<std::uint8_t>(file.get(), "/stress/in_layer", H5T_NATIVE_UINT8);
  EXPECT_EQ(in_layer, (std::vector<std::uint8_t>{1, 1, 0}));
  EXPECT_EQ(test::read_double_attribute(file.get(), "max_von_mises_z") > 0.0, true);
  EXPECT_EQ(test::dataset_shape(file.get(), "/stress/hydrostatic"), (std::vector<hsize_t>{3, 32, 32}));

  const fs::path stresses = dir / "stresses.h5";
  const ProgramRun command = testing::run_program(
      {"stress", output.string(), "--depths", "5e-6,2e-5,3e-5", "--output", stresses.string()}, dir.path());
  ASSERT_EQ(command.exit_code, kExitOk) << command.err;
  EXPECT_NE(command.out.find("coated: layer t = 2e-05 m"), std::string::npos) << command.out;
  expect_same_stresses(stresses, output, {"/stress/sigma_xx", "/stress/sigma_zz", "/stress/von_mises"});

  // A coated result brings its own Poisson's ratios; a free grid whose
  // shorter side is under 8 layer thicknesses (here L = 400 um, t = 60 um) is
  // refused before solving.
  const ProgramRun with_nu = testing::run_program(
      {"stress", output.string(), "--depths", "5e-6", "--nu", "0.3", "--output", (dir / "s.h5").string()}, dir.path());
  expect_input_error(with_nu, "--nu 0.3 is not used", dir / "s.h5");
  const fs::path free_output = dir / "free.h5";
  Options free = joined(sphere(free_output), coating("6e-5"));
  free.push_back({"--stress-depths", "5e-6"});
  expect_input_error(run_solve(free, dir),
                     "--stress-depths 5e-6: subsurface stresses in a coated half-space on a "
                     "free grid need a layer thickness t <= L/8",
                     free_output);
  free.push_back({"--stress-nu", "0.3"});
  expect_input_error(run_solve(free, dir), "is not used for a coated half-space", free_output);

  // The stress command on such a coated result of a free grid, and on a
  // result whose coating attributes are incomplete.
  ASSERT_EQ(run_solve(joined(sphere(free_output), coating("6e-5")), dir).exit_code, kExitOk);
  const auto stress_of = [&](const fs::path& result) {
    return testing::run_program({"stress", result.string(), "--depths", "5e-6", "--output", (dir / "s.h5").string()},
                                dir.path());
  };
  expect_input_error(stress_of(free_output), "coated half-space's result: subsurface stresses", dir / "s.h5");
  const fs::path partial = dir / "partial.h5";
  fs::copy_file(output, partial);
  {
    const hid_t file = H5Fopen(partial.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    ASSERT_GE(H5Adelete(file, "substrate_nu"), 0);
    H5Fclose(file);
  }
  expect_input_error(stress_of(partial), "some but not all of the coating's attributes", dir / "s.h5");
}

// A thin coating (t = 20 um, L = 400 um) on a free grid: solve --stress-depths
// and the stress command on its result give the same fields.
TEST(LayeredCliTest, StressesBelowACoatingOnAFreeGrid) {
  const TempDir dir;
  const fs::path output = dir / "coated.h5";
  Options options = joined(sphere(output), coating("2e-5", "4e11", "0.22"));
  options.push_back({"--stress-depths", "5e-6,2e-5,3e-5"});
  const ProgramRun solved = run_solve(options, dir);
  ASSERT_EQ(solved.exit_code, kExitOk) << solved.err;
  const test::H5 file = test::open_file(output);
  EXPECT_EQ(test::read_dataset<std::uint8_t>(file.get(), "/stress/in_layer", H5T_NATIVE_UINT8),
            (std::vector<std::uint8_t>{1, 1, 0}));
  const fs::path stresses = dir / "stresses.h5";
  const ProgramRun command = testing::run_program(
      {"stress", output.string(), "--depths", "5e-6,2e-5,3e-5", "--output", stresses.string()}, dir.path());
  ASSERT_EQ(command.exit_code, kExitOk) << command.err;
  expect_same_stresses(stresses, output,
                       {"/stress/sigma_xx", "/stress/sigma_zz", "/stress/sigma_xz", "/stress/von_mises"});
}

}  // namespace
}  // namespace halfspace
