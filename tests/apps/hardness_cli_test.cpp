// The hardness cap through the real executable: --hardness (and the config
// key) writes /plastic, /plastic_displacement and the hardness attributes,
// the summary names the plastic fraction, sweeps carry plastic_fraction in
// their table and CSV, and bad values are refused with messages that name
// the option, the value and the rule.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
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

// A sphere on a free 2D grid whose elastic peak (about 3.6 GPa) lies above
// the hardness of 2 GPa used below.
std::vector<std::string> sphere(const std::string& output, const std::vector<std::string>& extra) {
  std::vector<std::string> arguments{"solve",  "--geometry", "sphere",   "--radius", "1e-4",    "--grid", "32x32",
                                     "--size", "32e-6",      "--E-star", "1e11",     "--force", "0.1",    "--output",
                                     output,   "--threads",  "1",        "--tol",    "1e-11"};
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  return arguments;
}

TEST(HardnessCliTest, WritesThePlasticFieldsAndAttributes) {
  const TempDir dir;
  const ProgramRun run = run_program(sphere("capped.h5", {"--hardness", "2e9"}), dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  EXPECT_NE(run.out.find("plastic fraction"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("at the hardness 2e+09 Pa"), std::string::npos) << run.out;

  const test::H5 file = test::open_file(dir / "capped.h5");
  EXPECT_EQ(test::read_double_attribute(file.get(), "hardness"), 2e9);
  EXPECT_EQ(test::read_double_attribute(file.get(), "max_pressure"), 2e9);
  const double plastic_fraction = test::read_double_attribute(file.get(), "plastic_fraction");
  EXPECT_GT(plastic_fraction, 0.0);
  EXPECT_LT(plastic_fraction, test::read_double_attribute(file.get(), "contact_fraction"));

  const auto pressure = test::read_dataset<double>(file.get(), "/pressure", H5T_NATIVE_DOUBLE);
  const auto gap = test::read_dataset<double>(file.get(), "/gap", H5T_NATIVE_DOUBLE);
  const auto plastic = test::read_dataset<std::uint8_t>(file.get(), "/plastic", H5T_NATIVE_UINT8);
  const auto plastic_displacement = test::read_dataset<double>(file.get(), "/plastic_displacement", H5T_NATIVE_DOUBLE);
  ASSERT_EQ(plastic.size(), pressure.size());
  double plastic_cells = 0.0;
  for (std::size_t i = 0; i < pressure.size(); ++i) {
    EXPECT_EQ(plastic[i] == 1, pressure[i] == 2e9) << "cell " << i;
    EXPECT_EQ(plastic_displacement[i], plastic[i] == 1 ? std::max(-gap[i], 0.0) : 0.0) << "cell " << i;
    plastic_cells += plastic[i];
  }
  EXPECT_DOUBLE_EQ(plastic_fraction, plastic_cells / static_cast<double>(pressure.size()));
}

TEST(HardnessCliTest, ElasticResultsHaveNoPlasticFields) {
  const TempDir dir;
  const ProgramRun run = run_program(sphere("elastic.h5", {}), dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  EXPECT_EQ(run.out.find("plastic fraction"), std::string::npos) << run.out;
  const test::H5 file = test::open_file(dir / "elastic.h5");
  EXPECT_EQ(test::read_double_attribute(file.get(), "hardness"), 0.0);
  EXPECT_EQ(test::read_double_attribute(file.get(), "plastic_fraction"), 0.0);
  EXPECT_LT(H5Lexists(file.get(), "/plastic", H5P_DEFAULT), 1);
}

TEST(HardnessCliTest, ConfigKeyAndSweepColumns) {
  const TempDir dir;
  {
    std::ofstream config(dir / "capped.toml");
    config << "hardness = 2e9\n";
  }
  const ProgramRun run = run_program(
      {"solve", "--geometry", "sphere", "--radius", "1e-4", "--grid", "32x32", "--size", "32e-6", "--E-star", "1e11",
       "--force", "0.02,0.05,0.1", "--config", "capped.toml", "--output", "sweep.h5", "--threads", "1"},
      dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  const std::string csv = testing::read_text(dir / "sweep.csv");
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_NE(header.find(",plastic_fraction,"), std::string::npos) << header;
  const test::H5 file = test::open_file(dir / "sweep.h5");
  const auto plastic = test::read_dataset<double>(file.get(), "/sweep/plastic_fraction", H5T_NATIVE_DOUBLE);
  ASSERT_EQ(plastic.size(), 3u);
  EXPECT_LE(plastic[0], plastic[1]);
  EXPECT_LT(plastic[1], plastic[2]);
  EXPECT_GT(plastic[2], 0.0);
  EXPECT_EQ(test::dataset_shape(file.get(), "/steps/002/plastic"), (std::vector<hsize_t>{32, 32}));
}

TEST(HardnessCliTest, RefusesBadValuesWithTheOptionAndTheRule) {
  const TempDir dir;
  struct Case {
    std::vector<std::string> extra;
    std::string message;
  };
  const std::vector<Case> cases{
      {{"--hardness", "10"}, "--hardness 10 Pa is invalid: allowed range is 1000 to 1e+13 Pa"},
      {{"--hardness", "2e9", "--solver", "lemke"}, "does not apply to solver 'lemke'"},
      // 32 um x 32 um at 2e7 Pa carries 2.048e-05 N, less than the 0.1 N asked for.
      {{"--hardness", "2e7"}, "--force 0.1: the load is infeasible with hardness = 2e+07 Pa"},
  };
  for (const Case& c : cases) {
    const ProgramRun run = run_program(sphere("bad.h5", c.extra), dir.path());
    EXPECT_EQ(run.exit_code, kExitInputError) << c.message;
    EXPECT_NE(run.err.find(c.message), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(dir / "bad.h5")) << c.message;
  }
}

// A sweep names the value the hardness cannot carry and prints six digits,
// not the round trip of H times the area (issue 32: "1.3107199999999999 N").
TEST(HardnessCliTest, InfeasibleSweepNamesTheValueWithSixDigits) {
  const TempDir dir;
  std::vector<std::string> arguments = sphere("bad.h5", {"--hardness", "1.28e8"});
  const auto force = std::find(arguments.begin(), arguments.end(), "--force");
  ASSERT_NE(force, arguments.end());
  *(force + 1) = "0.01,0.2,0.1";  // 32 um x 32 um at 1.28e8 Pa carries 0.131072 N
  const ProgramRun run = run_program(arguments, dir.path());
  EXPECT_EQ(run.exit_code, kExitInputError);
  EXPECT_NE(run.err.find("--force 0.01,0.2,0.1 (value 2: 0.2): the load is infeasible with hardness = 1.28e+08 Pa: "
                         "the force 0.2 N exceeds the hardness times the domain area 1.024e-09 m^2 = 0.131072 N"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(dir / "bad.h5"));
}

}  // namespace
}  // namespace halfspace
