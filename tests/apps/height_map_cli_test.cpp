// Tests of the height-map formats and preparation options of `halfspace
// solve` through the real executable: every format, --window, --invalid,
// --detrend, --resample, --pad, their record in the result file, and their input errors.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "io/hdf5_test_support.hpp"
#include "io/reader_test_support.hpp"
#include "support/cli_checks.hpp"
#include "support/program_run.hpp"

namespace halfspace {
namespace {

namespace fs = std::filesystem;
using test::kFormatDataDir;
using test::TempDir;
using testing::expect_input_error;
using testing::kExitInputError;
using testing::kExitOk;
using testing::run;

// Padding adds non-contacting cells only: the pressure on the map agrees to
// the solver's tolerance (1e-10 relative residual), a little amplified.
constexpr double kPaddingPressureTolerance = 1e-6;

using testing::ProgramRun;

// solve with a soft material and a small force: a few contact spots on the
// di-5 AFM crop, converged in a few dozen iterations.
std::vector<std::string> solve(const fs::path& map, const fs::path& output, std::vector<std::string> extra) {
  std::vector<std::string> arguments{"solve", "--height-map", map.string(),    "--E-star", "1e9", "--threads",
                                     "1",     "--output",     output.string(), "--quiet"};
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  return arguments;
}

std::string string_attribute(const fs::path& file, const std::string& name) {
  const test::H5 handle = test::open_file(file);
  return test::read_string_attribute(handle.get(), name);
}

std::vector<double> dataset(const fs::path& file, const std::string& name) {
  const test::H5 handle = test::open_file(file);
  return test::read_dataset<double>(handle.get(), name, H5T_NATIVE_DOUBLE);
}

TEST(HeightMapCliTest, SolvesEveryFormatOfTheDi5Crop) {
  const TempDir dir;
  for (const char* name : {"di-5-crop-48x64.h5", "di-5-crop-f-be-f8.npy", "di-5-crop-space.txt", "di-5-crop-comma.csv",
                           "di-5-crop-m.gsf"}) {
    SCOPED_TRACE(name);
    const fs::path output = dir / "out.h5";
    const ProgramRun result =
        run(solve(kFormatDataDir / name, output,
                  {"--dx", "1.953125e-9", "--dy", "1.953125e-9", "--detrend", "plane", "--force", "1e-9"}),
            dir);
    ASSERT_EQ(result.exit_code, kExitOk) << result.err;
    EXPECT_NE(string_attribute(output, "height_source").find(name), std::string::npos);
    EXPECT_EQ(string_attribute(output, "preparation").rfind("detrend plane: subtracted the least-squares plane", 0), 0u)
        << string_attribute(output, "preparation");
    const std::vector<double> height = dataset(output, "height");
    ASSERT_EQ(height.size(), 48u * 64u);
    double mean = 0.0;
    for (double h : height) mean += h / static_cast<double>(height.size());
    EXPECT_LE(std::abs(mean), 1e-20);  // detrended: the mean is rounding of 6e-10 heights
    fs::remove(output);
  }
}

TEST(HeightMapCliTest, X3pWithInvalidPointsIsRefusedUnlessFilledOrCropped) {
  const TempDir dir;
  const fs::path map = kFormatDataDir / "kautschuk-crop-40x56.x3p";
  const fs::path output = dir / "out.h5";
  expect_input_error(run(solve(map, output, {"--force", "1e-3"}), dir),
                     {"kautschuk-crop-40x56.x3p", "85 of 2240 heights are invalid", "not finite", "(j, i) = (0, 0)",
                      "--invalid fill or --invalid crop"},
                     output);

  ProgramRun filled = run(solve(map, output, {"--invalid", "fill", "--detrend", "plane", "--force", "1e-3"}), dir);
  ASSERT_EQ(filled.exit_code, kExitOk) << filled.err;
  const std::string record = string_attribute(output, "preparation");
  test::expect_contains(record, {"detrend plane", "\ninvalid points: filled 29 of 2184 points",
                                 "keeping columns 0 to 55 and rows 1 to 39 of the 56x40 map"});
  EXPECT_EQ(dataset(output, "height").size(), 56u * 39u);
  fs::remove(output);

  ProgramRun cropped = run(solve(map, output, {"--invalid", "crop", "--force", "1e-3"}), dir);
  ASSERT_EQ(cropped.exit_code, kExitOk) << cropped.err;
  EXPECT_NE(string_attribute(output, "preparation").find("cropped to the largest rectangle of valid points"),
            std::string::npos);
}

// A height map in the shared layout whose /valid flags one point as filled
// in: the file's own fill is not trusted by default either.
TEST(HeightMapCliTest, PointsFlaggedInTheValidMaskAreRefusedUnlessFilled) {
  const TempDir dir;
  const fs::path map = dir / "flagged.h5";
  {
    const test::H5 source = test::open_file(kFormatDataDir / "di-5-crop-48x64.h5");
    const std::vector<double> height = test::read_dataset<double>(source.get(), "height", H5T_NATIVE_DOUBLE);
    std::vector<std::uint8_t> valid(height.size(), 1);
    valid[5 * 64 + 7] = 0;
    const test::H5 file = test::create_file(map);
    test::add_double_dataset(file.get(), "/height", {48, 64}, height);
    test::add_dataset(file.get(), "/valid", {48, 64}, H5T_STD_U8LE, H5T_NATIVE_UINT8, valid.data());
    test::add_double_attribute(file.get(), "dx", 1.953125e-9);
    test::add_double_attribute(file.get(), "dy", 1.953125e-9);
  }
  const fs::path output = dir / "out.h5";
  expect_input_error(run(solve(map, output, {"--force", "1e-9"}), dir),
                     {"flagged.h5", "1 of 3072 heights are invalid", "marked invalid by the file", "(j, i) = (5, 7)"},
                     output);
  const ProgramRun filled = run(solve(map, output, {"--invalid", "fill", "--force", "1e-9"}), dir);
  ASSERT_EQ(filled.exit_code, kExitOk) << filled.err;
  EXPECT_NE(string_attribute(output, "preparation").find("filled 1 of 3072 points"), std::string::npos)
      << string_attribute(output, "preparation");
}

TEST(HeightMapCliTest, DektakProfileWindowSolvesIn1D) {
  const TempDir dir;
  const fs::path output = dir / "out.h5";
  const std::vector<std::string> arguments{"solve",     "--height-map", (kFormatDataDir / "dektak-1.csv").string(),
                                           "--window",  "1000,512",     "--detrend",
                                           "curvature", "--E-star",     "1e9",
                                           "--force",   "10",           "--threads",
                                           "1",         "--output",     output.string()};
  const ProgramRun result = run(arguments, dir);
  ASSERT_EQ(result.exit_code, kExitOk) << result.err;
  test::expect_contains(result.out, {"512 cells (1D), dx = 1.5625e-07 m", "preparation", "window: points 1000 to 1511",
                                     "Dektak CSV profile"});
  EXPECT_EQ(string_attribute(output, "preparation").rfind("window: points 1000 to 1511 of 9600", 0), 0u);
}

TEST(HeightMapCliTest, PaddingKeepsThePressureOnTheMap) {
  const TempDir dir;
  const fs::path map = kFormatDataDir / "di-5-crop-c-le-f8.npy";
  const std::vector<std::string> common{"--dx",  "1.953125e-9", "--dy", "1.953125e-9", "--detrend",
                                        "plane", "--force",     "2e-9", "--tol",       "1e-12"};
  std::vector<std::string> padded_options = common;
  padded_options.insert(padded_options.end(), {"--pad", "2"});
  ASSERT_EQ(run(solve(map, dir / "plain.h5", common), dir).exit_code, kExitOk);
  const ProgramRun padded = run(solve(map, dir / "padded.h5", padded_options), dir);
  ASSERT_EQ(padded.exit_code, kExitOk) << padded.err;
  test::expect_contains(string_attribute(dir / "padded.h5", "preparation"), {"pad 2x", "64x48 -> 128x96"});

  const std::vector<double> plain = dataset(dir / "plain.h5", "pressure");
  const std::vector<double> wide = dataset(dir / "padded.h5", "pressure");
  ASSERT_EQ(wide.size(), 128u * 96u);
  const double peak = *std::max_element(plain.begin(), plain.end());
  double worst = 0.0;
  double margin = 0.0;
  for (std::size_t j = 0; j < 96; ++j) {
    for (std::size_t i = 0; i < 128; ++i) {
      const bool inside = j >= 24 && j < 72 && i >= 32 && i < 96;
      const double p = wide[j * 128 + i];
      if (inside) {
        worst = std::max(worst, std::abs(p - plain[(j - 24) * 64 + (i - 32)]));
      } else {
        margin = std::max(margin, p);
      }
    }
  }
  EXPECT_EQ(margin, 0.0) << "the margin touched";
  EXPECT_LE(worst, kPaddingPressureTolerance * peak) << "largest pressure difference on the map";
}

// --resample changes the cells, not the lengths: the refined map's spacing
// is half the file's, the coarsened map's twice, and both carry the force.
TEST(HeightMapCliTest, ResampleChangesTheCellsNotTheLengths) {
  const TempDir dir;
  const fs::path map = kFormatDataDir / "di-5-crop-c-le-f8.npy";
  const fs::path output = dir / "out.h5";
  for (const auto& [cells, nx, ny, method] :
       {std::tuple<const char*, std::size_t, std::size_t, const char*>{"128x96", 128, 96, "x: linear interpolation"},
        {"32x24", 32, 24, "x: cell means"}}) {
    SCOPED_TRACE(cells);
    const ProgramRun result = run(solve(map, output,
                                        {"--dx", "1.953125e-9", "--dy", "1.953125e-9", "--detrend", "plane",
                                         "--resample", cells, "--force", "2e-9"}),
                                  dir);
    ASSERT_EQ(result.exit_code, kExitOk) << result.err;
    test::expect_contains(string_attribute(output, "preparation"),
                          {"detrend plane", fmt::format("resample: the 64x48 map to {}", cells), method});
    EXPECT_EQ(dataset(output, "height").size(), nx * ny);
    const test::H5 file = test::open_file(output);
    EXPECT_DOUBLE_EQ(test::read_double_attribute(file.get(), "dx") * static_cast<double>(nx), 64 * 1.953125e-9);
    EXPECT_DOUBLE_EQ(test::read_double_attribute(file.get(), "dy") * static_cast<double>(ny), 48 * 1.953125e-9);
    const std::vector<double> pressure = dataset(output, "pressure");
    double force = 0.0;
    for (const double p : pressure)
      force += p * 64 * 1.953125e-9 / static_cast<double>(nx) * 48 * 1.953125e-9 / static_cast<double>(ny);
    EXPECT_NEAR(force, 2e-9, 1e-9 * 2e-9);
    fs::remove(output);
  }
}

TEST(HeightMapCliTest, PreparationOptionsAreCheckedBeforeReading) {
  const TempDir dir;
  const fs::path output = dir / "out.h5";
  const fs::path npy = kFormatDataDir / "di-5-crop-c-le-f8.npy";
  const std::vector<std::string> spacing{"--dx", "1e-9", "--dy", "1e-9"};
  const auto with = [&](std::vector<std::string> extra) {
    extra.insert(extra.end(), spacing.begin(), spacing.end());
    return solve(npy, output, extra);
  };
  expect_input_error(run(with({"--force", "1", "--format", "sur"}), dir), {"--format", "'sur' is unknown"}, output);
  expect_input_error(run(with({"--force", "1", "--detrend", "cubic"}), dir), {"--detrend", "'cubic'"}, output);
  expect_input_error(run(with({"--force", "1", "--invalid", "ignore"}), dir), {"--invalid", "'ignore'"}, output);
  expect_input_error(run(with({"--force", "1", "--window", "0,0,100,10"}), dir),
                     {"window i0 = 0, j0 = 0, nx = 100, ny = 10", "ends at column 99", "64x48 map"}, output);
  expect_input_error(run(with({"--force", "1", "--unit", "furlong"}), dir), {"--unit", "'furlong'"}, output);
  expect_input_error(run(with({"--force", "1", "--dataset", "/height"}), dir), {"dataset", "only to HDF5"}, output);
  expect_input_error(run(with({"--force", "1", "--pad", "2", "--boundary", "periodic"}), dir), {"--pad 2", "periodic"},
                     output);
  expect_input_error(run(with({"--mean-pressure", "1e5", "--pad", "2"}), dir), {"--pad 2", "--mean-pressure"}, output);
  expect_input_error(run(with({"--force", "1", "--pad", "40"}), dir), {"--pad 40 is invalid", "[1, 16]"}, output);
  expect_input_error(run(with({"--force", "1", "--resample", "64by48"}), dir), {"--resample", "expected NXxNY"},
                     output);
  expect_input_error(run(with({"--force", "1", "--resample", "1025x48"}), dir),
                     {"resample 1025x48", "refine the 64x48 map", "more than 16 times (at most 1024 cells)"}, output);
  expect_input_error(run({"solve", "--geometry", "flat", "--grid", "8x8", "--size", "1e-3", "--E-star", "1e9",
                          "--force", "1", "--detrend", "plane", "--output", output.string()},
                         dir),
                     {"--detrend", "applies only to --height-map"}, output);
  expect_input_error(run({"solve", "--geometry", "flat", "--grid", "8x8", "--size", "1e-3", "--E-star", "1e9",
                          "--force", "1", "--resample", "16x16", "--output", output.string()},
                         dir),
                     {"--resample", "applies only to --height-map"}, output);
}

TEST(HeightMapCliTest, MislabelledFilesAreNamed) {
  const TempDir dir;
  const fs::path output = dir / "out.h5";
  const fs::path fake = dir / "surface.dat";
  fs::copy_file(kFormatDataDir / "di-5-crop-m.gsf", fake);
  expect_input_error(run(solve(fake, output, {"--force", "1"}), dir),
                     {"surface.dat", "not text", "Gwyddion", "set the format to gsf"}, output);
  // The suggested format works.
  const ProgramRun fixed = run(solve(fake, output, {"--force", "1e-9", "--format", "gsf"}), dir);
  EXPECT_EQ(fixed.exit_code, kExitOk) << fixed.err;
  expect_input_error(run(solve(dir / "scan.sur", dir / "out2.h5", {"--force", "1"}), dir), {"'.sur'", "set the format"},
                     dir / "out2.h5");
}

TEST(HeightMapCliTest, ConfigFileTakesPreparationKeys) {
  const TempDir dir;
  fs::copy_file(kFormatDataDir / "kautschuk-crop-40x56.x3p", dir / "scan.x3p");
  test::write_bytes(dir / "run.toml",
                    "height-map = \"scan.x3p\"\ninvalid = \"crop\"\ndetrend = \"mean\"\nE-star = 1e9\nforce = 1e-3\n"
                    "threads = 1\nquiet = true\n");
  const fs::path output = dir / "out.h5";
  const ProgramRun result = run({"solve", "--config", "run.toml", "--output", output.string()}, dir);
  ASSERT_EQ(result.exit_code, kExitOk) << result.err;
  test::expect_contains(string_attribute(output, "preparation"), {"cropped", "detrend mean"});
}

}  // namespace
}  // namespace halfspace
