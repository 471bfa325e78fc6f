// scripts/halfspace_plot.py on real result files: maps and profiles of 1D
// and 2D results, a chosen output, and one-line errors for a file of the
// wrong kind. Skipped where Debian's python3 lacks matplotlib or h5py.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "io/hdf5_test_support.hpp"
#include "support/cli_checks.hpp"
#include "support/program_run.hpp"

namespace halfspace {
namespace {

namespace fs = std::filesystem;
using test::TempDir;
using testing::ProgramRun;
using testing::shell_quoted;

const fs::path kScript = fs::path(HALFSPACE_TEST_DATA_DIR) / ".." / ".." / "scripts" / "halfspace_plot.py";

bool plotting_available() {
  return std::system("/usr/bin/python3 -c 'import matplotlib, h5py, numpy' > /dev/null 2>&1") == 0;
}

// Runs the script with `arguments` from `dir`; returns the exit code.
int plot(const std::vector<std::string>& arguments, const TempDir& dir, std::string* err = nullptr) {
  std::string command = fmt::format("cd {} && {}", shell_quoted(dir.path().string()), shell_quoted(kScript.string()));
  for (const std::string& argument : arguments) command += fmt::format(" {}", shell_quoted(argument));
  command += " > /dev/null 2> stderr.txt";
  const int status = std::system(command.c_str());
  if (err != nullptr) *err = testing::read_text(dir / "stderr.txt");
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void solve(const std::vector<std::string>& arguments, const TempDir& dir) {
  std::vector<std::string> all{"solve", "--E-star", "1e11", "--quiet"};
  all.insert(all.end(), arguments.begin(), arguments.end());
  const ProgramRun run = testing::run_program(all, dir.path());
  ASSERT_EQ(run.exit_code, testing::kExitOk) << run.err;
}

TEST(PlotScriptTest, DrawsMapsAndProfilesOfResults) {
  if (!plotting_available()) GTEST_SKIP() << "/usr/bin/python3 with matplotlib, h5py and numpy is not installed";
  const TempDir dir;
  solve({"--geometry", "sphere", "--radius", "0.01", "--grid", "24x16", "--size", "3e-4x2e-4", "--force", "1",
         "--output", "sphere.h5"},
        dir);
  solve({"--geometry", "cylinder", "--radius", "0.01", "--grid", "64", "--size", "3e-4", "--force", "100", "--output",
         "line.h5"},
        dir);
  EXPECT_EQ(plot({"maps", "sphere.h5"}, dir), 0);
  EXPECT_TRUE(fs::exists(dir / "sphere_maps.png"));
  EXPECT_EQ(plot({"profile", "sphere.h5", "--row", "3"}, dir), 0);
  EXPECT_TRUE(fs::exists(dir / "sphere_profile_row3.png"));
  EXPECT_EQ(plot({"maps", "line.h5", "--out", (dir / "figures").string()}, dir), 0);
  EXPECT_TRUE(fs::exists(dir / "figures" / "line_maps.png"));
  EXPECT_EQ(plot({"profile", "line.h5", "--out", (dir / "mine.png").string()}, dir), 0);
  EXPECT_TRUE(fs::exists(dir / "mine.png"));
}

TEST(PlotScriptTest, ReportsAFileOfTheWrongKind) {
  if (!plotting_available()) GTEST_SKIP() << "/usr/bin/python3 with matplotlib, h5py and numpy is not installed";
  const TempDir dir;
  solve({"--geometry", "cylinder", "--radius", "0.01", "--grid", "32", "--size", "3e-4", "--force", "100", "--output",
         "line.h5"},
        dir);
  std::string err;
  EXPECT_EQ(plot({"sweep", "line.h5"}, dir, &err), 1);
  EXPECT_EQ(err, "error: line.h5: not a sweep file (no group /sweep)\n");
  EXPECT_EQ(plot({"maps", "missing.h5"}, dir, &err), 1);
  EXPECT_EQ(err, "error: missing.h5: no such file\n");
  EXPECT_EQ(plot({"profile", "line.h5", "--step", "2"}, dir, &err), 1);
  EXPECT_EQ(err, "error: --step 2: line.h5 is not a sweep file\n");
  EXPECT_EQ(plot({"paper", dir.path().string()}, dir, &err), 1);
  EXPECT_NE(err.find("no testN.h5 files"), std::string::npos) << err;
}

}  // namespace
}  // namespace halfspace
