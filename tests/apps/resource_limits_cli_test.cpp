// Hostile requests to the `halfspace` program: grids whose cell counts
// overflow or do not fit in memory, absurd thread counts, values far outside
// physical ranges, a plotting tool that never exits. Each must end in a
// clean refusal (exit 1, one line naming the option, the value and what is
// allowed) or a bounded wait, never a crash, a hang or a NaN breakdown.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
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
using testing::kExitPlotFailed;
using testing::ProgramRun;

using Environment = std::vector<std::pair<std::string, std::string>>;

// The value of a flag in sphere()'s changes: given without a value.
const std::string kFlag = "(flag)";

// A sphere solve with `changes` replacing or adding options (an empty value
// drops the option, kFlag gives it without a value).
std::vector<std::string> sphere(const std::vector<std::pair<std::string, std::string>>& changes) {
  std::vector<std::pair<std::string, std::string>> options{
      {"--geometry", "sphere"}, {"--radius", "0.01"}, {"--grid", "32x32"},  {"--size", "5e-4"},
      {"--E-star", "1e11"},     {"--force", "10"},    {"--output", "o.h5"}, {"--threads", "1"}};
  for (const auto& [flag, value] : changes) {
    const auto found = std::find_if(options.begin(), options.end(), [&](const auto& o) { return o.first == flag; });
    if (found != options.end()) {
      found->second = value;
    } else {
      options.emplace_back(flag, value);
    }
  }
  std::vector<std::string> arguments{"solve"};
  for (const auto& [flag, value] : options) {
    if (value.empty()) continue;
    arguments.push_back(flag);
    if (value != kFlag) arguments.push_back(value);
  }
  return arguments;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Crashed with SIGSEGV on 206cf1f: 2^32 x 2^32 cells is 2^64, which wrapped
// round to 0 cells.
TEST(ResourceLimitsCliTest, GridWhoseCellCountOverflowsIsRefused) {
  const TempDir dir;
  const std::string grid = "4294967296x4294967296";
  testing::expect_input_error(testing::run_program(sphere({{"--grid", grid}}), dir.path()),
                              {"--grid " + grid + " is invalid", "cells is more than the"}, dir / "o.h5");
  testing::expect_input_error(
      testing::run_program({"generate", "--kind", "flat", "--grid", grid, "--size", "5e-4", "--output", "g.h5"},
                           dir.path()),
      {"--grid " + grid + " is invalid", "cells is more than the"}, dir / "g.h5");
  // One axis alone beyond the limit.
  testing::expect_input_error(testing::run_program(sphere({{"--grid", "18446744073709551615"}}), dir.path()),
                              {"--grid 18446744073709551615 is invalid"}, dir / "o.h5");
}

// Ended in "error: std::bad_alloc" (2D) or sat in FFT planning at 8 GB (1D)
// on 206cf1f.
TEST(ResourceLimitsCliTest, GridBeyondTheMachinesMemoryIsRefusedBeforeAllocating) {
  const TempDir dir;
  const auto start = std::chrono::steady_clock::now();
  testing::expect_input_error(
      testing::run_program(sphere({{"--grid", "1000000x1000000"}}), dir.path()),
      {"--grid 1000000x1000000: the solve (pk-multilevel, free boundary, 1000000000000 cells) needs about",
       "TiB of memory at its peak, but", "is available (", "--max-memory"},
      dir / "o.h5");
  testing::expect_input_error(testing::run_program(sphere({{"--grid", "1000000000"}, {"--size", "1"}}), dir.path()),
                              {"--grid 1000000000: the solve", "GiB of memory at its peak, but"}, dir / "o.h5");
  // The self-affine generator spent minutes counting Fourier modes first.
  testing::expect_input_error(testing::run_program({"generate", "--kind", "self-affine", "--grid", "1000000x1000000",
                                                    "--size", "1e-3", "--rms-height", "1e-7", "--output", "g.h5"},
                                                   dir.path()),
                              {"--grid 1000000x1000000: generating 1000000000000 cells needs about", "TiB"},
                              dir / "g.h5");
  EXPECT_LT(seconds_since(start), 30.0);
}

TEST(ResourceLimitsCliTest, MaxMemoryLowersTheLimit) {
  const TempDir dir;
  // 512x512 free: about 60 MiB, more than 16M allows.
  testing::expect_input_error(
      testing::run_program(sphere({{"--grid", "512x512"}, {"--max-memory", "16M"}}), dir.path()),
      {"--grid 512x512: the solve (pk-multilevel, free boundary, 262144 cells) needs about",
       "more than the 16 MiB that --max-memory 16M allows"},
      dir / "o.h5");
  // The same key in a config file, as bytes.
  std::ofstream(dir / "run.toml") << "max-memory = 16777216\n";
  testing::expect_input_error(
      testing::run_program(sphere({{"--grid", "512x512"}, {"--config", "run.toml"}}), dir.path()),
      {"that max-memory = 16777216 in run.toml allows"}, dir / "o.h5");
  testing::expect_input_error(testing::run_program({"generate", "--kind", "flat", "--grid", "1024x1024", "--size",
                                                    "1e-3", "--max-memory", "8M", "--output", "g.h5"},
                                                   dir.path()),
                              {"more than the 8 MiB that --max-memory 8M allows"}, dir / "g.h5");
  for (const std::string size : {"abc", "0", "-5G", "12X", "1e400"}) {
    testing::expect_input_error(testing::run_program(sphere({{"--max-memory", size}}), dir.path()),
                                {"--max-memory " + size + " is invalid"}, dir / "o.h5");
  }
  // Enough: solved.
  const ProgramRun run = testing::run_program(sphere({{"--max-memory", "2G"}, {"--quiet", kFlag}}), dir.path());
  EXPECT_EQ(run.exit_code, kExitOk) << run.err;
}

// With the limit raised past anything the machine has, the allocation
// itself fails: the message says what was being done, not "std::bad_alloc".
TEST(ResourceLimitsCliTest, OutOfMemoryNamesWhatWasBeingDone) {
  const TempDir dir;
  const ProgramRun run =
      testing::run_program(sphere({{"--grid", "100000000x100000000"}, {"--max-memory", "1e9T"}}), dir.path());
  testing::expect_input_error(
      run,
      {"error: out of memory while making the --geometry sphere surface on the 100000000x100000000 grid",
       "available now"},
      dir / "o.h5");
  EXPECT_EQ(run.err.find("std::bad_alloc"), std::string::npos) << run.err;
}

// --threads 10000 started 10,001 threads; 99999999999 was refused as "need
// at least 1 thread".
TEST(ResourceLimitsCliTest, ThreadCountsBeyondTheCapAreRefusedWithTheRange) {
  const TempDir dir;
  for (const std::string threads : {"10000", "99999999999", "0", "-1"}) {
    testing::expect_input_error(testing::run_program(sphere({{"--threads", threads}}), dir.path()),
                                {"--threads " + threads + " is invalid: allowed range is 1 to", "hardware threads"},
                                dir / "o.h5");
  }
}

TEST(ResourceLimitsCliTest, DefaultThreadsFollowOmpNumThreads) {
  const TempDir dir;
  const ProgramRun run = testing::run_program(sphere({{"--threads", ""}}), dir.path(), {{"OMP_NUM_THREADS", "1"}});
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  EXPECT_NE(run.out.find(", 1 thread,"), std::string::npos) << run.out;
}

// Values far outside physical ranges used to pass validation and end in a
// NaN breakdown (exit 2) or, for --size 1e300, in a message naming no option.
TEST(ResourceLimitsCliTest, ExtremeButFiniteValuesAreRefusedWithTheirRange) {
  const TempDir dir;
  const std::vector<std::pair<std::vector<std::pair<std::string, std::string>>, std::vector<std::string>>> cases{
      {{{"--size", "1e300"}}, {"--size 1e300 is invalid: each length of the domain must be in [1e-12, 1000] m"}},
      {{{"--size", "1e-300"}}, {"--size 1e-300 is invalid: each length of the domain must be in [1e-12, 1000] m"}},
      {{{"--size", "1e-9"}, {"--grid", "10000"}},
       {"the spacing dx = 1e-13 m of --size 1e-9 over --grid 10000 is invalid: allowed range is [1e-12, 1000] m"}},
      {{{"--E-star", "1e-300"}}, {"--E-star 1e-300 is invalid: allowed range is [1000, 1e+15] Pa"}},
      {{{"--E-star", "4.9e-324"}}, {"--E-star 4.9e-324 is invalid"}},
      {{{"--E-star", "1e300"}}, {"--E-star 1e300 is invalid: allowed range is [1000, 1e+15] Pa"}},
      {{{"--E-star", ""}, {"--E1", "1e-300"}, {"--nu1", "0.3"}, {"--E2", "2e11"}, {"--nu2", "0.3"}},
       {"--E1 1e-300 is invalid: allowed range is [1000, 1e+15] Pa"}},
      {{{"--E-star", ""}, {"--E1", "2e14"}, {"--nu1", "-0.99999999"}, {"--E2", "2e14"}, {"--nu2", "-0.99999999"}},
       {"the composite modulus E* = ", "of --E1 2e14, --nu1 -0.99999999", "allowed range is [1000, 1e+15] Pa"}},
      {{{"--radius", "1e300"}}, {"--radius 1e300 is invalid: allowed range is [1e-12, 1000] m"}},
      {{{"--force", "1e-310"}},
       {"--force 1e-310 on the 32x32 grid of area 2.5e-07 m^2: the mean pressure force / area = ",
        "allowed range is [1e-09, 1e+13] Pa"}},
      {{{"--force", "1e300"}}, {"--force 1e300 on the 32x32 grid", "allowed range is [1e-09, 1e+13] Pa"}},
      {{{"--force", ""}, {"--mean-pressure", "1e-300"}},
       {"--mean-pressure 1e-300 is invalid: allowed range is [1e-09, 1e+13] Pa"}},
      {{{"--force", "1,1e300"}}, {"--force 1,1e300 (value 2: 1e+300) on the 32x32 grid"}},
      {{{"--force", ""}, {"--approach", "1e-300"}}, {"--approach 1e-300 is invalid: allowed range is [1e-12, 1000] m"}},
  };
  for (const auto& [changes, expected] : cases) {
    testing::expect_input_error(testing::run_program(sphere(changes), dir.path()), expected, dir / "o.h5");
  }
  testing::expect_input_error(testing::run_program({"generate", "--kind", "sphere", "--radius", "1e300", "--grid", "8",
                                                    "--size", "1e-3", "--output", "g.h5"},
                                                   dir.path()),
                              {"--radius 1e300 is invalid: allowed range is [1e-12, 1000] m"}, dir / "g.h5");
  testing::expect_input_error(
      testing::run_program({"generate", "--kind", "flat", "--grid", "8", "--size", "1e300", "--output", "g.h5"},
                           dir.path()),
      {"--size 1e300 is invalid"}, dir / "g.h5");
}

// A flat 16x16 height map, map.h5 in `dir`, for the solves below to read.
void generate_flat_map(const TempDir& dir) {
  ASSERT_EQ(testing::run_program(
                {"generate", "--kind", "flat", "--grid", "16x16", "--size", "1e-3", "--output", "map.h5", "--quiet"},
                dir.path())
                .exit_code,
            kExitOk);
}

// A height map whose spacing attribute is absurd is refused naming the file.
TEST(ResourceLimitsCliTest, HeightMapSpacingOutsideTheRangeIsRefused) {
  const TempDir dir;
  ASSERT_NO_FATAL_FAILURE(generate_flat_map(dir));
  const std::vector<std::string> base{"solve", "--height-map", "map.h5", "--E-star", "1e11", "--force",
                                      "1",     "--output",     "o.h5"};
  std::vector<std::string> tiny = base;
  tiny.insert(tiny.end(), {"--dx", "1e-20"});
  testing::expect_input_error(testing::run_program(tiny, dir.path()),
                              {"--dx 1e-20 is invalid: allowed range is [1e-12, 1000] m"}, dir / "o.h5");
}

// "window i0 = 18446744073709551615, ... ends at column 0": the end column
// wrapped round.
TEST(ResourceLimitsCliTest, WindowPastTheLastColumnSaysWhere) {
  const TempDir dir;
  ASSERT_NO_FATAL_FAILURE(generate_flat_map(dir));
  const auto solve_window = [&](const std::string& window) {
    return testing::run_program(
        {"solve", "--height-map", "map.h5", "--E-star", "1e11", "--force", "1", "--window", window, "--output", "o.h5"},
        dir.path());
  };
  testing::expect_input_error(solve_window("18446744073709551615,0,2,2"),
                              {"it starts at column 18446744073709551615 but the 16x16 map", "has columns 0 to 15"},
                              dir / "o.h5");
  testing::expect_input_error(solve_window("5,0,18446744073709551615,2"), {"it has 18446744073709551615 columns but"},
                              dir / "o.h5");
  testing::expect_input_error(solve_window("0,4,2,13"), {"it ends at row 16 but"}, dir / "o.h5");
}

// A plotting tool that never exits is stopped after HALFSPACE_PLOT_TIMEOUT
// seconds (120 by default); the result stays written and the exit code says
// the figures failed.
TEST(ResourceLimitsCliTest, PlottingToolThatNeverExitsIsStopped) {
  const TempDir dir;
  const fs::path python = dir / "fake-python";
  // Passes the import check, then hangs (exec: no child survives the kill).
  std::ofstream(python) << "#!/bin/sh\nif [ \"$1\" = -c ]; then exit 0; fi\nexec sleep 60\n";
  fs::permissions(python, fs::perms::owner_all);
  const Environment environment{{"HALFSPACE_PYTHON", python.string()}, {"HALFSPACE_PLOT_TIMEOUT", "1"}};
  const auto start = std::chrono::steady_clock::now();
  const ProgramRun run = testing::run_program(sphere({{"--plot", kFlag}, {"--quiet", kFlag}}), dir.path(), environment);
  EXPECT_LT(seconds_since(start), 30.0);
  EXPECT_EQ(run.exit_code, kExitPlotFailed) << run.err;
  EXPECT_NE(run.err.find("did not finish within 1 s and was stopped (set HALFSPACE_PLOT_TIMEOUT"), std::string::npos)
      << run.err;
  EXPECT_TRUE(fs::exists(dir / "o.h5"));

  const ProgramRun bad =
      testing::run_program(sphere({{"--plot", kFlag}}), dir.path(), {{"HALFSPACE_PLOT_TIMEOUT", "soon"}});
  testing::expect_input_error(bad, {"--plot: HALFSPACE_PLOT_TIMEOUT=soon is invalid"}, dir / "unwritten.h5");
}

// Removes an environment variable for its lifetime (the programs a test
// starts inherit the test's environment), then restores it.
class WithoutVariable {
 public:
  explicit WithoutVariable(std::string name) : name_(std::move(name)) {
    if (const char* value = std::getenv(name_.c_str())) saved_ = value;
    ::unsetenv(name_.c_str());
  }
  WithoutVariable(const WithoutVariable&) = delete;
  WithoutVariable& operator=(const WithoutVariable&) = delete;
  ~WithoutVariable() {
    if (saved_) ::setenv(name_.c_str(), saved_->c_str(), 1);
  }

 private:
  std::string name_;
  std::optional<std::string> saved_;
};

// The OpenMP threads wait passively unless the user chose otherwise; the
// plotting tool inherits the environment the program ran with, so a fake
// one reports it.
TEST(ResourceLimitsCliTest, OpenMpWaitsPassivelyUnlessTheUserChose) {
  const TempDir dir;
  const fs::path python = dir / "fake-python";
  std::ofstream(python) << "#!/bin/sh\nif [ \"$1\" = -c ]; then exit 0; fi\necho \"$OMP_WAIT_POLICY\" > policy.txt\n";
  fs::permissions(python, fs::perms::owner_all);
  const WithoutVariable policy_unset("OMP_WAIT_POLICY");
  const WithoutVariable spin_unset("GOMP_SPINCOUNT");
  const auto policy_with = [&](Environment environment) {
    environment.emplace_back("HALFSPACE_PYTHON", python.string());
    fs::remove(dir / "policy.txt");
    const ProgramRun run =
        testing::run_program(sphere({{"--plot", kFlag}, {"--quiet", kFlag}}), dir.path(), environment);
    EXPECT_EQ(run.exit_code, kExitOk) << run.err;
    std::ifstream in(dir / "policy.txt");
    std::string policy;
    std::getline(in, policy);
    return policy;
  };
  EXPECT_EQ(policy_with({}), "passive");
  EXPECT_EQ(policy_with({{"OMP_WAIT_POLICY", ""}}), "passive");  // empty: as if unset
  EXPECT_EQ(policy_with({{"OMP_WAIT_POLICY", "active"}}), "active");
  EXPECT_EQ(policy_with({{"GOMP_SPINCOUNT", "1000"}}), "");  // the user tuned the spinning: left alone
}

}  // namespace
}  // namespace halfspace
