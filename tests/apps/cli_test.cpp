// Tests of the `halfspace` program through the real executable: exit codes,
// one-line "error: ..." messages naming the offending value, no output file
// after an input error, and the result file after a (non-)converged solve.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "halfspace/version.hpp"
#include "io/hdf5_test_support.hpp"
#include "support/cli_checks.hpp"
#include "support/program_run.hpp"

namespace halfspace {
namespace {

namespace fs = std::filesystem;
using test::TempDir;
using testing::expect_input_error;
using testing::kExitInputError;
using testing::kExitNotConverged;
using testing::kExitOk;
using testing::run;

using testing::ProgramRun;

// Options of a small Hertz problem (32 x 32, converges in ~20 iterations).
std::vector<std::pair<std::string, std::string>> sphere_options(const fs::path& output) {
  return {{"--geometry", "sphere"}, {"--radius", "0.01"}, {"--grid", "32x32"},           {"--size", "4e-4"},
          {"--E-star", "1e11"},     {"--force", "1"},     {"--output", output.string()}, {"--threads", "1"}};
}

std::vector<std::string> solve_arguments(const testing::OptionPairs& options) {
  return testing::command_arguments("solve", options);
}

std::int64_t converged_attribute(const fs::path& file) {
  const test::H5 handle = test::open_file(file);
  return test::read_int64_attribute(handle.get(), "converged");
}

// A (ny, nx) height map (or a profile when ny == 0) of a sphere of radius
// 10 mm sampled at 12.5 um, with optional spacing attributes.
void write_height_map(const fs::path& path, std::size_t nx, std::size_t ny, bool with_spacing, double poison = 0.0) {
  const double spacing = 1.25e-5;
  const std::size_t rows = ny == 0 ? 1 : ny;
  std::vector<double> heights(nx * rows);
  for (std::size_t j = 0; j < rows; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const double x = (static_cast<double>(i) - 0.5 * static_cast<double>(nx - 1)) * spacing;
      const double y = ny == 0 ? 0.0 : (static_cast<double>(j) - 0.5 * static_cast<double>(ny - 1)) * spacing;
      heights[j * nx + i] = -(x * x + y * y) / (2.0 * 0.01);
    }
  }
  if (poison != 0.0) heights[heights.size() / 3] = poison;
  const test::H5 file = test::create_file(path);
  const std::vector<hsize_t> dims = ny == 0 ? std::vector<hsize_t>{nx} : std::vector<hsize_t>{ny, nx};
  test::add_double_dataset(file.get(), "height", dims, heights);
  if (with_spacing) {
    test::add_double_attribute(file.get(), "dx", spacing);
    if (ny != 0) test::add_double_attribute(file.get(), "dy", spacing);
  }
}

TEST(CliTest, VersionPrintsVersionAndGitHash) {
  const TempDir dir;
  const ProgramRun result = run({"--version"}, dir);
  EXPECT_EQ(result.exit_code, kExitOk);
  EXPECT_EQ(result.out, fmt::format("halfspace {} ({})\n", kVersion, kGitHash));
  EXPECT_EQ(result.err, "");
}

TEST(CliTest, HelpListsSolveCommand) {
  const TempDir dir;
  const ProgramRun result = run({"--help"}, dir);
  EXPECT_EQ(result.exit_code, kExitOk);
  EXPECT_NE(result.out.find("solve"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("Exit codes"), std::string::npos) << result.out;
}

TEST(CliTest, SolveHelpListsEveryOptionGroup) {
  const TempDir dir;
  const ProgramRun result = run({"solve", "--help"}, dir);
  EXPECT_EQ(result.exit_code, kExitOk);
  for (const char* flag : {"--config", "--height-map", "--dataset", "--geometry", "--grid", "--size", "--boundary",
                           "--E1", "--E-star", "--force", "--mean-pressure", "--approach", "--tol", "--max-iter",
                           "--threads", "--fft-planning", "--solver", "--output", "--quiet"}) {
    EXPECT_NE(result.out.find(flag), std::string::npos) << flag << " missing from:\n" << result.out;
  }
}

TEST(CliTest, UnknownFlagIsInputError) {
  const TempDir dir;
  expect_input_error(run({"solve", "--bogus", "3"}, dir), "--bogus", dir / "out.h5");
}

TEST(CliTest, UnknownCommandIsInputError) {
  const TempDir dir;
  expect_input_error(run({"frobnicate"}, dir), "frobnicate", dir / "out.h5");
}

TEST(CliTest, MissingCommandIsInputError) {
  const TempDir dir;
  expect_input_error(run({}, dir), "no command", dir / "out.h5");
}

TEST(CliTest, SphereSolveConvergesWritesFileAndPrintsSummary) {
  const TempDir dir;
  const fs::path output = dir / "sphere.h5";
  const ProgramRun result = run(solve_arguments(sphere_options(output)), dir);
  ASSERT_EQ(result.exit_code, kExitOk) << result.err;
  EXPECT_EQ(result.err, "");
  for (const char* field : {"32x32", "1e+11 Pa", "converged", "iterations", "residual", "total force", "1 N",
                            "mean pressure", "approach", "contact fraction", "max pressure", "solve time"}) {
    EXPECT_NE(result.out.find(field), std::string::npos) << field << " missing from:\n" << result.out;
  }
  EXPECT_NE(result.out.find(output.string()), std::string::npos) << result.out;
  ASSERT_TRUE(fs::exists(output));
  EXPECT_EQ(converged_attribute(output), 1);
  const test::H5 file = test::open_file(output);
  EXPECT_NE(test::read_string_attribute(file.get(), "command_line").find("solve --geometry sphere --radius 0.01"),
            std::string::npos);
  EXPECT_EQ(test::read_string_attribute(file.get(), "height_source"), "sphere (radius = 0.01 m)");
  EXPECT_EQ(test::read_string_attribute(file.get(), "load_mode"), "force");
  EXPECT_EQ(test::read_string_attribute(file.get(), "config"), "");
}

// The summary says when pk-multilevel's active-set phase ran: asked for
// with --active-set on, and not by default on a grid this small
// (automatic: from 4096^2 cells).
TEST(CliTest, SummaryReportsTheActiveSetPhaseWhenItRuns) {
  const TempDir dir;
  for (const char* mode : {"on", ""}) {
    auto options = sphere_options(dir / "phase.h5");
    std::erase_if(options, [](const auto& option) { return option.first == "--grid"; });
    options.emplace_back("--grid", "128x128");  // a contact radius of 13 cells, 2 coarse grids
    if (*mode != '\0') options.emplace_back("--active-set", mode);
    const ProgramRun result = run(solve_arguments(options), dir);
    ASSERT_EQ(result.exit_code, kExitOk) << result.err;
    const bool reported = result.out.find("active set") != std::string::npos;
    EXPECT_EQ(reported, *mode != '\0') << mode << ":\n" << result.out;
    if (reported) {
      EXPECT_NE(result.out.find("set updates"), std::string::npos) << result.out;
    }
  }
}

TEST(CliTest, QuietSolvePrintsNothing) {
  const TempDir dir;
  const fs::path output = dir / "quiet.h5";
  auto options = sphere_options(output);
  options.emplace_back("--quiet", "");
  const ProgramRun result = run(solve_arguments(options), dir);
  EXPECT_EQ(result.exit_code, kExitOk) << result.err;
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err, "");
  EXPECT_TRUE(fs::exists(output));
}

TEST(CliTest, NonConvergenceWritesResultAndExitsTwo) {
  const TempDir dir;
  const fs::path output = dir / "unconverged.h5";
  auto options = sphere_options(output);
  options.emplace_back("--max-iter", "2");
  options.emplace_back("--quiet", "");
  const ProgramRun result = run(solve_arguments(options), dir);
  EXPECT_EQ(result.exit_code, kExitNotConverged) << result.err;
  EXPECT_EQ(result.err.rfind("error: solver did not converge: ", 0), 0U) << result.err;
  EXPECT_NE(result.err.find("after 2 iterations"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("> tolerance"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("result written to " + output.string()), std::string::npos) << result.err;
  ASSERT_TRUE(fs::exists(output));
  EXPECT_EQ(converged_attribute(output), 0);
}

TEST(CliTest, LineContactReportsForcePerLength) {
  const TempDir dir;
  const fs::path output = dir / "line.h5";
  const ProgramRun result =
      run({"solve", "--geometry", "cylinder", "--radius", "0.01", "--grid", "256", "--size", "1e-4", "--E-star", "1e11",
           "--force", "1000", "--threads", "1", "--output", output.string()},
          dir);
  EXPECT_EQ(result.exit_code, kExitOk) << result.err;
  EXPECT_NE(result.out.find("1000 N/m"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("(1D)"), std::string::npos) << result.out;
  EXPECT_TRUE(fs::exists(output));
}

// One bad input: the options changed from the sphere problem, and a piece of
// the expected message (the flag and the value as typed, or the rule).
struct BadInput {
  std::string name;
  std::vector<std::string> remove;                           // flags dropped from the sphere problem
  std::vector<std::pair<std::string, std::string>> replace;  // flags added or replaced
  std::string expected;
};

std::ostream& operator<<(std::ostream& out, const BadInput& input) {
  return out << input.name;
}

class CliBadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInputTest, FailsWithOneLineErrorAndNoOutputFile) {
  const BadInput& input = GetParam();
  const TempDir dir;
  const fs::path output = dir / "out.h5";
  std::vector<std::pair<std::string, std::string>> options;
  for (const auto& option : sphere_options(output)) {
    const bool dropped = std::find(input.remove.begin(), input.remove.end(), option.first) != input.remove.end();
    const bool replaced = std::any_of(input.replace.begin(), input.replace.end(),
                                      [&](const auto& change) { return change.first == option.first; });
    if (!dropped && !replaced) options.push_back(option);
  }
  options.insert(options.end(), input.replace.begin(), input.replace.end());
  expect_input_error(run(solve_arguments(options), dir), input.expected, output);
}

const std::vector<std::pair<std::string, std::string>> kTwoBodies{
    {"--E1", "2e11"}, {"--nu1", "0.3"}, {"--E2", "7e10"}, {"--nu2", "0.33"}};

std::vector<std::pair<std::string, std::string>> two_bodies_with(const std::string& flag, const std::string& value) {
  auto options = kTwoBodies;
  for (auto& option : options) {
    if (option.first == flag) option.second = value;
  }
  return options;
}

INSTANTIATE_TEST_SUITE_P(
    Inputs, CliBadInputTest,
    ::testing::Values(
        BadInput{"GridOfOneCell", {}, {{"--grid", "1"}}, "--grid 1 is invalid: need at least 2 cells"},
        BadInput{"GridWithEmptyAxis", {}, {{"--grid", "0x5"}}, "--grid 0x5 is invalid"},
        BadInput{"GridNotANumber", {}, {{"--grid", "abc"}}, "--grid abc is invalid"},
        BadInput{"NegativeForce", {}, {{"--force", "-1"}}, "--force -1 is invalid: must be positive"},
        BadInput{"ZeroForce", {}, {{"--force", "0"}}, "--force 0 is invalid"},
        BadInput{"ForceWithUnit", {}, {{"--force", "10N"}}, "--force 10N is invalid: expected a finite number"},
        BadInput{"ZeroMeanPressure", {"--force"}, {{"--mean-pressure", "0"}}, "--mean-pressure 0 is invalid"},
        BadInput{"NegativeApproach", {"--force"}, {{"--approach", "-1e-6"}}, "--approach -1e-6 is invalid"},
        BadInput{"NoLoad", {"--force"}, {}, "no load given"},
        BadInput{"ForceAndApproach", {}, {{"--approach", "1e-6"}}, "--force and --approach cannot be combined"},
        BadInput{"NegativeYoungsModulus",
                 {"--E-star"},
                 two_bodies_with("--E1", "-5"),
                 "--E1 -5 is invalid: must be positive (Pa)"},
        BadInput{"PoissonRatioAboveHalf",
                 {"--E-star"},
                 two_bodies_with("--nu1", "0.7"),
                 "--nu1 0.7 is invalid: allowed range is (-1, 0.5]"},
        BadInput{"ZeroCompositeModulus", {}, {{"--E-star", "0"}}, "--E-star 0 is invalid: must be positive (Pa)"},
        BadInput{"CompositeModulusAndE1", {}, {{"--E1", "2e11"}}, "--E-star cannot be combined with --E1"},
        BadInput{"IncompleteMaterial", {"--E-star"}, {{"--E1", "2e11"}, {"--nu1", "0.3"}}, "missing --E2, --nu2"},
        BadInput{"NoMaterial", {"--E-star"}, {}, "no material given"},
        BadInput{"GeometryAndHeightMap",
                 {},
                 {{"--height-map", "surface.h5"}},
                 "--height-map and --geometry cannot be combined"},
        BadInput{"NoSurface", {"--geometry", "--radius", "--grid", "--size"}, {}, "no surface given"},
        BadInput{"SphereWithoutRadius", {"--radius"}, {}, "--geometry sphere needs --radius"},
        BadInput{"ZeroRadius", {}, {{"--radius", "0"}}, "--radius 0 is invalid"},
        BadInput{"UnknownGeometry", {}, {{"--geometry", "cube"}}, "'cube'"},
        BadInput{"WavelengthForSphere", {}, {{"--wavelength", "1e-3"}}, "--wavelength does not apply"},
        BadInput{"SizeWithHeightMap",
                 {"--geometry", "--radius", "--grid"},
                 {{"--height-map", "surface.h5"}},
                 "--size cannot be used with --height-map"},
        BadInput{"TwoLengthsForLine", {}, {{"--grid", "32"}, {"--size", "1e-3x2e-3"}}, "give one length"},
        BadInput{"UnknownBoundary", {}, {{"--boundary", "open"}}, "'open'"},
        BadInput{"ToleranceAboveOne", {}, {{"--tol", "2"}}, "--tol 2 is invalid"},
        BadInput{"ZeroThreads", {}, {{"--threads", "0"}}, "--threads 0 is invalid"},
        BadInput{"UnknownFftPlanning", {}, {{"--fft-planning", "slow"}}, "'slow'"},
        BadInput{"UnknownSolver", {}, {{"--solver", "magic"}}, "--solver magic is invalid"},
        BadInput{"UnknownPrecision",
                 {},
                 {{"--precision", "half"}},
                 "--precision half is invalid: the precision must be one of double, mixed"},
        BadInput{"MixedPrecisionForLemke",
                 {},
                 {{"--solver", "lemke"}, {"--precision", "mixed"}},
                 "--precision mixed does not apply to solver 'lemke'"},
        BadInput{"MixedPrecisionForAdhesion",
                 {},
                 {{"--adhesion", "md"},
                  {"--work-of-adhesion", "0.05"},
                  {"--adhesion-range", "1e-6"},
                  {"--precision", "mixed"}},
                 "--precision mixed does not apply to the adhesive solver"},
        BadInput{"IterationLimitForLcpQuad",
                 {},
                 {{"--solver", "lcpquad"}, {"--max-iter", "5"}},
                 "--max-iter 5 does not apply to solver 'lcpquad'"},
        BadInput{"UnknownActiveSet",
                 {},
                 {{"--active-set", "yes"}},
                 "--active-set yes is invalid: allowed values are on, off, automatic"},
        BadInput{"NegativeDeflationBlock", {}, {{"--deflation-block", "-1"}}, "--deflation-block -1 is invalid"},
        BadInput{"DeflationBlockNotDividing", {}, {{"--deflation-block", "12"}}, "it must divide nx and ny"},
        BadInput{"DeflationWithPlainPk",
                 {},
                 {{"--deflation-block", "8"}, {"--solver", "pk"}},
                 "deflation needs pk-fourier or pk-multilevel"},
        BadInput{"OutputInMissingDirectory",
                 {},
                 {{"--output", "/nonexistent-dir/out.h5"}},
                 "directory /nonexistent-dir does not exist"},
        BadInput{"OutputIsDirectory", {}, {{"--output", "."}}, "is a directory"},
        BadInput{"MissingOutput", {"--output"}, {}, "no output file given: pass --output"}),
    [](const ::testing::TestParamInfo<BadInput>& info) { return info.param.name; });

// Height map files -----------------------------------------------------------

TEST(CliTest, MissingHeightMapFileIsNamed) {
  const TempDir dir;
  const fs::path output = dir / "out.h5";
  const ProgramRun result = run(
      {"solve", "--height-map", "missing.h5", "--E-star", "1e11", "--force", "1", "--output", output.string()}, dir);
  expect_input_error(result, "missing.h5", output);
  EXPECT_NE(result.err.find("does not exist"), std::string::npos) << result.err;
}

TEST(CliTest, MissingDatasetIsNamed) {
  const TempDir dir;
  write_height_map(dir / "surface.h5", 32, 32, true);
  const fs::path output = dir / "out.h5";
  const ProgramRun result = run({"solve", "--height-map", "surface.h5", "--dataset", "/topography", "--E-star", "1e11",
                                 "--force", "1", "--output", output.string()},
                                dir);
  expect_input_error(result, "'/topography'", output);
}

TEST(CliTest, NonFiniteHeightIsReported) {
  const TempDir dir;
  write_height_map(dir / "surface.h5", 32, 32, true, std::numeric_limits<double>::quiet_NaN());
  const fs::path output = dir / "out.h5";
  const ProgramRun result = run(
      {"solve", "--height-map", "surface.h5", "--E-star", "1e11", "--force", "1", "--output", output.string()}, dir);
  expect_input_error(result, "not finite", output);
  EXPECT_NE(result.err.find("surface.h5"), std::string::npos) << result.err;
}

TEST(CliTest, HeightMapWithoutSpacingAsksForDxAndDy) {
  const TempDir dir;
  write_height_map(dir / "surface.h5", 32, 32, false);
  const fs::path output = dir / "out.h5";
  const ProgramRun result = run(
      {"solve", "--height-map", "surface.h5", "--E-star", "1e11", "--force", "1", "--output", output.string()}, dir);
  expect_input_error(result, "pass --dx and --dy", output);
  EXPECT_NE(result.err.find("surface.h5"), std::string::npos) << result.err;
}

TEST(CliTest, HeightMapSolvesWithSpacingFromFile) {
  const TempDir dir;
  write_height_map(dir / "surface.h5", 32, 24, true);
  const fs::path output = dir / "out.h5";
  const ProgramRun result = run({"solve", "--height-map", "surface.h5", "--E-star", "1e11", "--force", "1", "--threads",
                                 "1", "--output", output.string()},
                                dir);
  EXPECT_EQ(result.exit_code, kExitOk) << result.err;
  EXPECT_NE(result.out.find("32x24"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("surface.h5:/height"), std::string::npos) << result.out;
  EXPECT_TRUE(fs::exists(output));
}

TEST(CliTest, ProfileWithSpacingFlagSolvesIn1D) {
  const TempDir dir;
  write_height_map(dir / "profile.h5", 128, 0, false);
  const fs::path output = dir / "out.h5";
  const ProgramRun result = run({"solve", "--height-map", "profile.h5", "--dx", "1e-6", "--E-star", "1e11",
                                 "--mean-pressure", "1e6", "--threads", "1", "--output", output.string()},
                                dir);
  EXPECT_EQ(result.exit_code, kExitOk) << result.err;
  EXPECT_NE(result.out.find("(1D), dx = 1e-06 m"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("N/m"), std::string::npos) << result.out;
  EXPECT_TRUE(fs::exists(output));
}

// Config files ---------------------------------------------------------------

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

const char* const kSphereConfig = R"(# Hertz sphere, 32 x 32
geometry = "sphere"
radius = 0.01
grid = "32x32"
size = 4e-4
E-star = 1e11
force = 1
threads = 1
)";

TEST(CliTest, ConfigFileGivesTheSameOptionsAsFlags) {
  const TempDir dir;
  write_text(dir / "run.toml", kSphereConfig);
  const fs::path output = dir / "out.h5";
  const ProgramRun result = run({"solve", "--config", "run.toml", "--output", output.string()}, dir);
  EXPECT_EQ(result.exit_code, kExitOk) << result.err;
  EXPECT_NE(result.out.find("1 N"), std::string::npos) << result.out;
  ASSERT_TRUE(fs::exists(output));
  const test::H5 file = test::open_file(output);
  EXPECT_EQ(test::read_string_attribute(file.get(), "config"), kSphereConfig);
}

TEST(CliTest, CommandLineOverridesConfigFile) {
  const TempDir dir;
  write_text(dir / "run.toml", std::string(kSphereConfig) + "output = \"from-file.h5\"\n");
  const fs::path output = dir / "from-flags.h5";
  // --approach replaces the file's force (another load mode); --output its output.
  const ProgramRun result =
      run({"solve", "--config", "run.toml", "--approach", "1e-7", "--output", output.string()}, dir);
  EXPECT_EQ(result.exit_code, kExitOk) << result.err;
  EXPECT_NE(result.out.find("approach 1e-07 m"), std::string::npos) << result.out;
  EXPECT_TRUE(fs::exists(output));
  EXPECT_FALSE(fs::exists(dir / "from-file.h5"));
}

TEST(CliTest, GeometryOnCommandLineReplacesHeightMapOfConfigFile) {
  const TempDir dir;
  write_text(dir / "run.toml", "height-map = \"missing.h5\"\ndx = 1e-6\nE-star = 1e11\nforce = 1\nthreads = 1\n");
  const fs::path output = dir / "out.h5";
  const ProgramRun result = run({"solve", "--config", "run.toml", "--geometry", "sphere", "--radius", "0.01", "--grid",
                                 "32x32", "--size", "4e-4", "--output", output.string()},
                                dir);
  EXPECT_EQ(result.exit_code, kExitOk) << result.err;
  EXPECT_TRUE(fs::exists(output));
}

TEST(CliTest, GridOnCommandLineConflictsWithHeightMapOfConfigFile) {
  const TempDir dir;
  write_height_map(dir / "surface.h5", 32, 32, true);
  write_text(dir / "run.toml", "height-map = \"surface.h5\"\nE-star = 1e11\nforce = 1\n");
  const fs::path output = dir / "out.h5";
  expect_input_error(run({"solve", "--config", "run.toml", "--grid", "64x64", "--output", output.string()}, dir),
                     "--grid cannot be used with height-map (in run.toml)", output);
}

TEST(CliTest, ConfigPathsAreRelativeToTheConfigFile) {
  const TempDir dir;
  fs::create_directory(dir / "case");
  write_height_map(dir / "case" / "surface.h5", 32, 32, true);
  write_text(dir / "case" / "run.toml",
             "height-map = \"surface.h5\"\nE-star = 1e11\nforce = 1\nthreads = 1\noutput = \"result.h5\"\n");
  const ProgramRun result = run({"solve", "--config", "case/run.toml", "--quiet"}, dir);
  EXPECT_EQ(result.exit_code, kExitOk) << result.err;
  EXPECT_TRUE(fs::exists(dir / "case" / "result.h5"));
}

TEST(CliTest, InvalidValueInConfigNamesKeyAndFile) {
  const TempDir dir;
  write_text(dir / "run.toml", std::string(kSphereConfig) + "tol = 5.0\n");
  const fs::path output = dir / "out.h5";
  expect_input_error(run({"solve", "--config", "run.toml", "--output", output.string()}, dir),
                     "tol = 5 in run.toml is invalid", output);
}

TEST(CliTest, UnknownConfigKeyIsNamedWithSuggestion) {
  const TempDir dir;
  write_text(dir / "run.toml", "E_star = 1e11\n");
  const fs::path output = dir / "out.h5";
  expect_input_error(run({"solve", "--config", "run.toml", "--output", output.string()}, dir),
                     "unknown key 'E_star' in config file run.toml (did you mean 'E-star'?)", output);
}

TEST(CliTest, ConfigValueOfWrongTypeIsNamed) {
  const TempDir dir;
  write_text(dir / "run.toml", "radius = \"ten millimetres\"\n");
  const fs::path output = dir / "out.h5";
  expect_input_error(run({"solve", "--config", "run.toml", "--output", output.string()}, dir),
                     "key 'radius' in config file run.toml must be a number (got a string)", output);
}

TEST(CliTest, ConfigSyntaxErrorGivesLine) {
  const TempDir dir;
  write_text(dir / "run.toml", "geometry = \"sphere\"\nradius = \n");
  const fs::path output = dir / "out.h5";
  expect_input_error(run({"solve", "--config", "run.toml", "--output", output.string()}, dir),
                     "config file run.toml is not valid TOML", output);
}

TEST(CliTest, MissingConfigFileIsNamed) {
  const TempDir dir;
  const fs::path output = dir / "out.h5";
  expect_input_error(run({"solve", "--config", "nowhere.toml", "--output", output.string()}, dir),
                     "config file nowhere.toml does not exist", output);
}

}  // namespace
}  // namespace halfspace
