// Tests of `halfspace generate` through the real executable: the height-map
// file's layout and parameters, reading it back with `solve --height-map`,
// the same bits for a seed whatever the thread count, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
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
using testing::ProgramRun;
using testing::run_program;

// The rms slope is scaled onto the request; only rounding remains.
constexpr double kRmsTolerance = 1e-12;

std::vector<std::string> self_affine(const std::string& output, const std::string& seed = "7") {
  return {"generate",      "--kind",  "self-affine", "--grid",         "64x48", "--size",
          "6.4e-5x4.8e-5", "--hurst", "0.7",         "--cutoff-short", "4e-6",  "--rms-slope",
          "0.2",           "--seed",  seed,          "--output",       output,  "--quiet"};
}

TEST(GenerateCliTest, WritesSelfAffineHeightMapWithItsParameters) {
  const TempDir dir;
  const ProgramRun run = run_program(self_affine("surface.h5"), dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(run.err, "");

  const test::H5 file = test::open_file(dir / "surface.h5");
  EXPECT_EQ(test::dataset_shape(file.get(), "/height"), (std::vector<hsize_t>{48, 64}));
  EXPECT_DOUBLE_EQ(test::read_double_attribute(file.get(), "dx"), 1e-6);
  EXPECT_DOUBLE_EQ(test::read_double_attribute(file.get(), "dy"), 1e-6);
  EXPECT_EQ(test::read_int64_attribute(file.get(), "periodic"), 1);
  EXPECT_EQ(test::read_int64_attribute(file.get(), "seed"), 7);
  EXPECT_EQ(test::read_string_attribute(file.get(), "generator"), "self-affine");
  EXPECT_DOUBLE_EQ(test::read_double_attribute(file.get(), "hurst"), 0.7);
  EXPECT_DOUBLE_EQ(test::read_double_attribute(file.get(), "cutoff_short"), 4e-6);
  EXPECT_DOUBLE_EQ(test::read_double_attribute(file.get(), "cutoff_long"), 6.4e-5);
  EXPECT_NEAR(test::read_double_attribute(file.get(), "rms_slope"), 0.2, kRmsTolerance * 0.2);
  EXPECT_NE(test::read_string_attribute(file.get(), "command_line").find("--seed 7"), std::string::npos);

  // The heights themselves have zero mean and the rms height recorded.
  const std::vector<double> h = test::read_dataset<double>(file.get(), "/height", H5T_NATIVE_DOUBLE);
  double mean = 0.0;
  for (double v : h) mean += v;
  mean /= static_cast<double>(h.size());
  double square = 0.0;
  for (double v : h) square += (v - mean) * (v - mean);
  const double rms = std::sqrt(square / static_cast<double>(h.size()));
  EXPECT_NEAR(rms, test::read_double_attribute(file.get(), "rms_height"), 1e-12 * rms);
  EXPECT_LT(std::abs(mean), 1e-12 * rms);
}

TEST(GenerateCliTest, SolveReadsTheGeneratedFile) {
  const TempDir dir;
  ASSERT_EQ(run_program(self_affine("surface.h5"), dir.path()).exit_code, kExitOk);
  const ProgramRun run =
      run_program({"solve", "--height-map", "surface.h5", "--boundary", "periodic", "--E-star", "1e9",
                   "--mean-pressure", "2e6", "--output", "result.h5", "--threads", "1", "--quiet"},
                  dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  const test::H5 file = test::open_file(dir / "result.h5");
  // The solve measures the same rms slope (spectral, periodic) as requested.
  EXPECT_NEAR(test::read_double_attribute(file.get(), "surface_rms_slope"), 0.2, kRmsTolerance * 0.2);
  EXPECT_GT(test::read_int64_attribute(file.get(), "clusters"), 0);
}

TEST(GenerateCliTest, SameSeedGivesSameBitsForAnyThreadCount) {
  const TempDir dir;
  ASSERT_EQ(run_program(self_affine("one.h5"), dir.path(), {{"OMP_NUM_THREADS", "1"}}).exit_code, kExitOk);
  ASSERT_EQ(run_program(self_affine("two.h5"), dir.path(), {{"OMP_NUM_THREADS", "2"}}).exit_code, kExitOk);
  ASSERT_EQ(run_program(self_affine("other.h5", "8"), dir.path()).exit_code, kExitOk);
  const auto heights = [&](const std::string& name) {
    const test::H5 file = test::open_file(dir / name);
    return test::read_dataset<double>(file.get(), "/height", H5T_NATIVE_DOUBLE);
  };
  EXPECT_EQ(heights("one.h5"), heights("two.h5"));
  EXPECT_NE(heights("one.h5"), heights("other.h5"));
}

TEST(GenerateCliTest, WritesProfilesAndBuiltInSurfaces) {
  const TempDir dir;
  ASSERT_EQ(run_program({"generate", "--kind", "self-affine", "--grid", "1024", "--size", "1e-3", "--rms-height",
                         "1e-7", "--output", "profile.h5", "--quiet"},
                        dir.path())
                .exit_code,
            kExitOk);
  {
    const test::H5 file = test::open_file(dir / "profile.h5");
    EXPECT_EQ(test::dataset_shape(file.get(), "/height"), (std::vector<hsize_t>{1024}));
    EXPECT_EQ(test::read_double_attribute(file.get(), "dy"), 0.0);
    EXPECT_NEAR(test::read_double_attribute(file.get(), "rms_height"), 1e-7, kRmsTolerance * 1e-7);
  }
  const ProgramRun wavy = run_program({"generate", "--kind", "wavy", "--grid", "32x32", "--size", "1e-3",
                                       "--wavelength", "5e-4", "--amplitude", "1e-6", "--output", "wavy.h5"},
                                      dir.path());
  ASSERT_EQ(wavy.exit_code, kExitOk) << wavy.err;
  EXPECT_NE(wavy.out.find("periodic     yes"), std::string::npos) << wavy.out;
  const ProgramRun sphere = run_program({"generate", "--kind", "sphere", "--grid", "32x32", "--size", "1e-3",
                                         "--radius", "0.01", "--output", "sphere.h5", "--quiet"},
                                        dir.path());
  ASSERT_EQ(sphere.exit_code, kExitOk) << sphere.err;
  const test::H5 file = test::open_file(dir / "sphere.h5");
  EXPECT_EQ(test::read_int64_attribute(file.get(), "periodic"), 0);
  EXPECT_EQ(test::read_double_attribute(file.get(), "radius"), 0.01);
}

TEST(GenerateCliTest, ExampleHeightMapIsWhatItsCommandGenerates) {
  // examples/synthetic_sweep.toml documents the command that wrote its map.
  // Compared to rounding, not bits: another CPU may run other FFTW codelets.
  const TempDir dir;
  ASSERT_EQ(
      run_program({"generate", "--kind", "self-affine", "--grid", "128x128", "--size", "1.28e-4", "--hurst", "0.8",
                   "--cutoff-short", "4e-6", "--rms-slope", "0.1", "--seed", "1", "--output", "map.h5", "--quiet"},
                  dir.path())
          .exit_code,
      kExitOk);
  const test::H5 fresh = test::open_file(dir / "map.h5");
  const test::H5 shipped =
      test::open_file(fs::path(HALFSPACE_TEST_DATA_DIR) / ".." / ".." / "examples" / "self_affine_128.h5");
  const auto a = test::read_dataset<double>(fresh.get(), "/height", H5T_NATIVE_DOUBLE);
  const auto b = test::read_dataset<double>(shipped.get(), "/height", H5T_NATIVE_DOUBLE);
  ASSERT_EQ(a.size(), b.size());
  double largest = 0.0;
  double scale = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    largest = std::max(largest, std::abs(a[k] - b[k]));
    scale = std::max(scale, std::abs(b[k]));
  }
  EXPECT_LE(largest, 1e-12 * scale);
}

TEST(GenerateCliTest, RejectsBadInputWithOneLineAndNoFile) {
  struct Case {
    std::vector<std::string> arguments;
    std::string expected;
  };
  const std::vector<std::string> grid{"--grid", "64x64", "--size", "6.4e-5"};
  const auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> arguments{"generate"};
    arguments.insert(arguments.end(), grid.begin(), grid.end());
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    arguments.insert(arguments.end(), {"--output", "out.h5"});
    return arguments;
  };
  const std::vector<Case> cases{
      {with({}), "no surface kind given"},
      {with({"--kind", "blob"}),
       "--kind blob is invalid: the kind must be self-affine, sphere, cylinder, wavy or flat"},
      {with({"--kind", "self-affine"}), "--kind self-affine needs --rms-height (m) or --rms-slope"},
      {with({"--kind", "self-affine", "--rms-height", "1e-7", "--rms-slope", "0.1"}),
       "--rms-height and --rms-slope cannot be combined"},
      {with({"--kind", "self-affine", "--rms-height", "1e-7", "--radius", "1"}),
       "--radius does not apply to --kind self-affine"},
      {with({"--kind", "sphere", "--radius", "0.01", "--hurst", "0.5"}), "--hurst does not apply to --kind sphere"},
      {with({"--kind", "sphere"}), "--kind sphere needs --radius (m)"},
      {with({"--kind", "self-affine", "--rms-height", "abc"}), "--rms-height abc is invalid: expected a finite number"},
      {with({"--kind", "self-affine", "--rms-height", "1e-7", "--hurst", "1.2"}),
       "Hurst exponent 1.2 is invalid: allowed range is (0, 1]"},
      {with({"--kind", "self-affine", "--rms-height", "1e-7", "--cutoff-short", "1e-6"}),
       "short cutoff 1e-06 m is invalid: must be at least 2 max(dx, dy) = 2e-06 m"},
      {with({"--kind", "self-affine", "--rms-height", "1e-7", "--seed", "-3"}),
       "--seed -3 is invalid: the seed must be 0 or more"},
      {{"generate", "--kind", "flat", "--grid", "8", "--size", "1", "--output", "missing-dir/out.h5"},
       "directory 'missing-dir' does not exist"},
  };
  for (const Case& c : cases) {
    const TempDir dir;
    const ProgramRun run = run_program(c.arguments, dir.path());
    EXPECT_EQ(run.exit_code, kExitInputError) << c.expected;
    EXPECT_EQ(run.err.rfind("error: ", 0), 0U) << run.err;
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << "expected '" << c.expected << "' in: " << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_FALSE(fs::exists(dir / "out.h5"));
  }
}

// A config file gives the same options as flags (the same option table), a
// flag overrides its key, and an unknown key is refused naming the command.
TEST(GenerateCliTest, ConfigFileGivesTheOptionsAndFlagsOverrideIt) {
  const TempDir dir;
  ASSERT_EQ(run_program(self_affine("flags.h5", "7"), dir.path()).exit_code, kExitOk);
  {
    std::ofstream config(dir / "surface.toml");
    config << "kind = \"self-affine\"\ngrid = \"64x48\"\nsize = \"6.4e-5x4.8e-5\"\nhurst = 0.7\n"
              "cutoff-short = 4e-6\nrms-slope = 0.2\nseed = 3\noutput = \"config.h5\"\n";
  }
  const ProgramRun run = run_program({"generate", "--config", "surface.toml", "--seed", "7", "--quiet"}, dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  const test::H5 flags = test::open_file(dir / "flags.h5");
  const test::H5 config = test::open_file(dir / "config.h5");
  EXPECT_EQ(test::read_int64_attribute(config.get(), "seed"), 7);
  // Same options, same generator: the same bits.
  EXPECT_EQ(test::read_dataset<double>(config.get(), "/height", H5T_NATIVE_DOUBLE),
            test::read_dataset<double>(flags.get(), "/height", H5T_NATIVE_DOUBLE));

  {
    std::ofstream config(dir / "bad.toml");
    config << "kind = \"flat\"\nradius_ = 1\n";
  }
  testing::expect_input_error(run_program({"generate", "--config", "bad.toml"}, dir.path()),
                              {"unknown key 'radius_'", "bad.toml", "'halfspace generate'"});
}

}  // namespace
}  // namespace halfspace
