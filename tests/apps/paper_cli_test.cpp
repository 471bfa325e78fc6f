// `halfspace paper` and the dense solvers of `halfspace solve`, through the
// real executable: files written, exit codes, one-line errors.
#include <gtest/gtest.h>

#include <cstdlib>
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
using testing::run;

using testing::ProgramRun;

TEST(PaperCliTest, WritesTheDataFilesAndTheSummary) {
  const TempDir dir;
  const fs::path out = dir / "paper";
  const ProgramRun result = run({"paper", "--test", "4", "--output-dir", out.string(), "--no-figures"}, dir);
  EXPECT_EQ(result.exit_code, testing::kExitOk) << result.err;
  EXPECT_NE(result.out.find("test 4: N =   7"), std::string::npos) << result.out;
  for (const char* name : {"test4.csv", "test4.h5", "summary.md"}) EXPECT_TRUE(fs::exists(out / name)) << name;
  EXPECT_FALSE(fs::exists(out / "test1.csv"));
}

TEST(PaperCliTest, DrawsTheFiguresWithThePlottingTool) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib, h5py, numpy' > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "Debian's python3 with matplotlib and h5py is not installed";
  }
  const TempDir dir;
  const ProgramRun result =
      run({"paper", "--test", "4", "--output-dir", dir.path().string(), "--point-load-kernel", "--quiet"}, dir);
  EXPECT_EQ(result.exit_code, testing::kExitOk) << result.err;
  for (const char* name : {"test4.png", "test4_zoom.png", "test4_variants.png"}) {
    EXPECT_TRUE(fs::exists(dir / name)) << name;
  }
}

TEST(PaperCliTest, RejectsBadOptions) {
  const TempDir dir;
  testing::expect_input_error(run({"paper", "--test", "5", "--output-dir", dir.path().string()}, dir), "--test");
  testing::expect_input_error(run({"paper", "--test", "1"}, dir), "--output-dir is required");
  testing::expect_input_error(run({"paper", "--load", "-3", "--output-dir", dir.path().string(), "--no-figures"}, dir),
                              "load = -3 N/m is invalid");
}

// The options from a config file, its relative output directory taken
// relative to the file.
TEST(PaperCliTest, ConfigFileGivesTheOptions) {
  const TempDir dir;
  fs::create_directories(dir / "runs");
  {
    std::ofstream config(dir / "runs" / "paper.toml");
    config << "test = 4\noutput-dir = \"out\"\nno-figures = true\nquiet = true\n";
  }
  const ProgramRun result = run({"paper", "--config", (dir / "runs" / "paper.toml").string()}, dir);
  EXPECT_EQ(result.exit_code, testing::kExitOk) << result.err;
  EXPECT_EQ(result.out, "");
  EXPECT_TRUE(fs::exists(dir / "runs" / "out" / "test4.csv"));
  EXPECT_FALSE(fs::exists(dir / "runs" / "out" / "test1.csv"));
}

TEST(PaperCliTest, SolveRunsTheDenseSolversByName) {
  const TempDir dir;
  for (const char* name : {"lemke", "lcpquad"}) {
    const fs::path output = dir / (std::string(name) + ".h5");
    const ProgramRun result =
        run({"solve", "--geometry", "cylinder", "--radius", "0.01", "--grid", "129", "--size", "8e-4", "--E-star",
             "1e11", "--force", "1e5", "--solver", name, "--output", output.string(), "--quiet"},
            dir);
    EXPECT_EQ(result.exit_code, testing::kExitOk) << name << ": " << result.err;
    const test::H5 file = test::open_file(output);
    EXPECT_EQ(test::read_string_attribute(file.get(), "solver"), name);
    EXPECT_EQ(test::read_int64_attribute(file.get(), "converged"), 1) << name;
  }
}

TEST(PaperCliTest, SolveRefusesADenseSolverOnALargeGrid) {
  const TempDir dir;
  const fs::path output = dir / "big.h5";
  const ProgramRun result =
      run({"solve", "--geometry", "sphere", "--radius", "0.01", "--grid", "128x128", "--size", "1e-3", "--E-star",
           "1e11", "--force", "1", "--solver", "lemke", "--max-memory", "64G", "--output", output.string()},
          dir);
  // --max-memory: the grid's refusal, not the machine's free memory, must decide.
  testing::expect_input_error(result, "grid 128x128 has 16384 cells");
  EXPECT_NE(result.err.find("solver pk-multilevel"), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(output));
}

}  // namespace
}  // namespace halfspace
