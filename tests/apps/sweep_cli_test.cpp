// Tests of load sweeps, statistics, progress and --plot through the real
// executable: the sweep file's groups and summary table, the CSV beside it,
// lists and ranges on the command line and in config files, the statistics
// of single solves, the progress line on terminals only, and the figures.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
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
using testing::kExitNotConverged;
using testing::kExitOk;
using testing::kExitPlotFailed;
using testing::ProgramRun;
using testing::run_program;

// A periodic 2D wave: two contact spots per period, converges in ~20
// iterations per step.
std::vector<std::string> wavy(const std::string& load_flag, const std::string& loads, const std::string& output) {
  return {"solve",  "--geometry", "wavy",   "--wavelength", "1e-3",       "--amplitude", "1e-6",
          "--grid", "32x32",      "--size", "1e-3",         "--boundary", "periodic",    "--E-star",
          "1e11",   load_flag,    loads,    "--output",     output,       "--threads",   "1"};
}

std::vector<std::string> with(std::vector<std::string> arguments, const std::vector<std::string>& extra) {
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  return arguments;
}

std::vector<std::vector<double>> read_csv(const fs::path& path, std::vector<std::string>& header) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::stringstream names(line);
  for (std::string name; std::getline(names, name, ',');) header.push_back(name);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    std::vector<double> row;
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::strtod(cell.c_str(), nullptr));
    rows.push_back(row);
  }
  return rows;
}

bool python_with_matplotlib() {
  return std::system("/usr/bin/python3 -c 'import matplotlib, h5py, numpy' > /dev/null 2>&1") == 0;
}

TEST(SweepCliTest, RangeWritesOneGroupPerStepTheTableAndTheCsv) {
  const TempDir dir;
  const ProgramRun run = run_program(wavy("--mean-pressure", "1e6:3e7:4", "sweep.h5"), dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  EXPECT_EQ(run.err, "") << "no progress line when stderr is not a terminal";
  EXPECT_NE(run.out.find("mean pressure sweep, 4 steps from 1e+06 to 3e+07 Pa"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("sweep.csv (summary table)"), std::string::npos) << run.out;

  const test::H5 file = test::open_file(dir / "sweep.h5");
  EXPECT_EQ(test::read_int64_attribute(file.get(), "sweep_steps"), 4);
  EXPECT_EQ(test::read_string_attribute(file.get(), "load_mode"), "mean_pressure");
  EXPECT_EQ(test::dataset_shape(file.get(), "/height"), (std::vector<hsize_t>{32, 32}));
  for (const char* step : {"/steps/000", "/steps/001", "/steps/002", "/steps/003"}) {
    for (const char* field : {"pressure", "gap", "displacement", "contact"}) {
      EXPECT_EQ(test::dataset_shape(file.get(), std::string(step) + "/" + field), (std::vector<hsize_t>{32, 32}))
          << step << "/" << field;
    }
    EXPECT_EQ(test::dataset_type(file.get(), std::string(step) + "/contact").size, 1u);
    const auto sizes =
        test::read_dataset<std::int64_t>(file.get(), std::string(step) + "/cluster_sizes", H5T_NATIVE_INT64);
    EXPECT_EQ(sizes.size(), 2u) << "two contact spots per period, " << step;
  }
  // The range is log-spaced with exact ends.
  const auto load = test::read_dataset<double>(file.get(), "/sweep/load", H5T_NATIVE_DOUBLE);
  ASSERT_EQ(load.size(), 4u);
  EXPECT_EQ(load.front(), 1e6);
  EXPECT_EQ(load.back(), 3e7);
  EXPECT_NEAR(load[1] / load[0], std::cbrt(30.0), 1e-12);
  const auto fraction = test::read_dataset<double>(file.get(), "/sweep/contact_fraction", H5T_NATIVE_DOUBLE);
  EXPECT_TRUE(std::is_sorted(fraction.begin(), fraction.end())) << "contact grows with the load";
  // The root describes the last step.
  EXPECT_EQ(test::read_double_attribute(file.get(), "contact_fraction"), fraction.back());
  const test::H5 last(H5Gopen2(file.get(), "/steps/003", H5P_DEFAULT), H5Gclose, "open /steps/003");
  EXPECT_EQ(test::read_int64_attribute(last.get(), "warm_started"), 1);
  EXPECT_EQ(test::read_double_attribute(last.get(), "load"), 3e7);

  std::vector<std::string> header;
  const auto rows = read_csv(dir / "sweep.csv", header);
  EXPECT_EQ(header, (std::vector<std::string>{"load", "mean_pressure", "total_force", "approach", "contact_fraction",
                                              "plastic_fraction", "mean_gap", "rms_gap", "free_volume", "max_pressure",
                                              "clusters", "iterations", "residual", "seconds", "converged"}));
  ASSERT_EQ(rows.size(), 4u);
  for (std::size_t k = 0; k < header.size(); ++k) {
    const auto column = test::read_dataset<double>(file.get(), "/sweep/" + header[k], H5T_NATIVE_DOUBLE);
    ASSERT_EQ(column.size(), 4u) << header[k];
    for (std::size_t s = 0; s < 4; ++s) EXPECT_EQ(rows[s][k], column[s]) << header[k] << " step " << s;
  }
}

TEST(SweepCliTest, ListsAndConfigArraysMakeSweeps) {
  const TempDir dir;
  const ProgramRun list = run_program(wavy("--approach", "2e-7,1e-7,3e-7", "list.h5"), dir.path());
  ASSERT_EQ(list.exit_code, kExitOk) << list.err;
  {
    const test::H5 file = test::open_file(dir / "list.h5");
    EXPECT_EQ(test::read_string_attribute(file.get(), "load_mode"), "approach");
    EXPECT_EQ(test::read_dataset<double>(file.get(), "/sweep/load", H5T_NATIVE_DOUBLE),
              (std::vector<double>{2e-7, 1e-7, 3e-7}))
        << "kept in the given order";
  }
  std::ofstream(dir / "run.toml") << "geometry = \"wavy\"\nwavelength = 1e-3\namplitude = 1e-6\ngrid = \"32x32\"\n"
                                     "size = 1e-3\nboundary = \"periodic\"\nE-star = 1e11\nforce = [1e-3, 2e-3]\n"
                                     "threads = 1\nquiet = true\n";
  const ProgramRun config = run_program({"solve", "--config", "run.toml", "--output", "config.h5"}, dir.path());
  ASSERT_EQ(config.exit_code, kExitOk) << config.err;
  EXPECT_EQ(config.out, "");
  {
    const test::H5 file = test::open_file(dir / "config.h5");
    EXPECT_EQ(test::read_int64_attribute(file.get(), "sweep_steps"), 2);
  }
  // A range string in the file; the command line's --mean-pressure would
  // replace it, and a single value there gives a single solve.
  std::ofstream(dir / "range.toml") << "geometry = \"wavy\"\nwavelength = 1e-3\namplitude = 1e-6\ngrid = \"32x32\"\n"
                                       "size = 1e-3\nboundary = \"periodic\"\nE-star = 1e11\n"
                                       "mean-pressure = \"1e6:1e7:3\"\nthreads = 1\nquiet = true\n";
  ASSERT_EQ(run_program({"solve", "--config", "range.toml", "--output", "range.h5"}, dir.path()).exit_code, kExitOk);
  const test::H5 file = test::open_file(dir / "range.h5");
  EXPECT_EQ(test::read_int64_attribute(file.get(), "sweep_steps"), 3);
}

TEST(SweepCliTest, SingleSolveKeepsItsLayoutPlusStatistics) {
  const TempDir dir;
  const ProgramRun run = run_program(wavy("--mean-pressure", "1e7", "single.h5"), dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  EXPECT_FALSE(fs::exists(dir / "single.csv"));
  const test::H5 file = test::open_file(dir / "single.h5");
  EXPECT_EQ(H5Lexists(file.get(), "steps", H5P_DEFAULT), 0);
  EXPECT_EQ(H5Aexists(file.get(), "sweep_steps"), 0);
  EXPECT_EQ(test::dataset_shape(file.get(), "/pressure"), (std::vector<hsize_t>{32, 32}));
  EXPECT_EQ(test::read_int64_attribute(file.get(), "clusters"), 2);
  // The wave -A (1 - cos kx cos ky) has rms height A/2 and rms slope A k / sqrt(2).
  const double k = 2 * 3.141592653589793 / 1e-3;
  EXPECT_NEAR(test::read_double_attribute(file.get(), "surface_rms_height"), 0.5e-6, 1e-12 * 0.5e-6);
  EXPECT_NEAR(test::read_double_attribute(file.get(), "surface_rms_slope"), 1e-6 * k / std::sqrt(2.0), 1e-12);
  const double mean_gap = test::read_double_attribute(file.get(), "mean_gap");
  const double rms_gap = test::read_double_attribute(file.get(), "rms_gap");
  EXPECT_GT(mean_gap, 0.0);
  EXPECT_GE(rms_gap, mean_gap);
  EXPECT_NEAR(test::read_double_attribute(file.get(), "free_volume"), mean_gap * 1e-6, 1e-12 * mean_gap * 1e-6);
}

TEST(SweepCliTest, RejectsBadLoadListsBeforeSolving) {
  struct Case {
    std::string flag;
    std::string value;
    std::string expected;
  };
  const std::vector<Case> cases{
      {"--force", "1,-2", "--force 1,-2 is invalid: every value must be positive (N in 2D, N/m in 1D); value 2 is -2"},
      {"--force", "1,,2", "--force 1,,2 is invalid: '' is not a finite number"},
      {"--force", "1e5:1e7:1", "--force 1e5:1e7:1 is invalid: the range needs a COUNT from 2 to 10000 (got 1)"},
      {"--force", "1e5:1e7:x", "--force 1e5:1e7:x is invalid: expected a whole number"},
      {"--force", "0:1:3", "--force 0:1:3 is invalid: a range is log-spaced, so START and STOP must be positive"},
      {"--force", "1:2", "--force 1:2 is invalid: a range is START:STOP:COUNT"},
      {"--force", "1,2:3:4", "give a list A,B,C or a range START:STOP:COUNT, not both"},
      {"--force", "-1", "--force -1 is invalid: must be positive"},
      // The flag as given, which value, six digits (issue 32).
      {"--approach", "1e-7,2e-6",
       "--approach 1e-7,2e-6 (value 2: 2e-06 m) is invalid for a periodic surface: it must be below the mean "
       "initial gap 9.90393e-07 m"},
      {"--approach", "2e-6",
       "--approach 2e-6 is invalid for a periodic surface: it must be below the mean initial gap "
       "9.90393e-07 m (full contact needs infinite pressure there)"},
  };
  for (const Case& c : cases) {
    const TempDir dir;
    const ProgramRun run = run_program(wavy(c.flag, c.value, "out.h5"), dir.path());
    EXPECT_EQ(run.exit_code, kExitInputError) << c.value;
    EXPECT_EQ(run.err.rfind("error: ", 0), 0U) << run.err;
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << "expected '" << c.expected << "' in: " << run.err;
    EXPECT_FALSE(fs::exists(dir / "out.h5")) << c.value;
    EXPECT_FALSE(fs::exists(dir / "out.csv")) << c.value;
  }
  const TempDir dir;
  std::ofstream(dir / "bad.toml") << "force = [\"1\", 2]\n";
  const ProgramRun run =
      run_program(with(wavy("--mean-pressure", "1e6", "out.h5"), {"--config", "bad.toml"}), dir.path());
  // The command line's --mean-pressure drops the file's force: no error.
  EXPECT_EQ(run.exit_code, kExitOk) << run.err;
  const ProgramRun typed = run_program({"solve", "--config", "bad.toml", "--output", "typed.h5"}, dir.path());
  EXPECT_EQ(typed.exit_code, kExitInputError);
  EXPECT_NE(typed.err.find("key 'force' in config file bad.toml must be a number, an array of numbers"),
            std::string::npos)
      << typed.err;
}

TEST(SweepCliTest, NonConvergedStepsAreWrittenAndReported) {
  const TempDir dir;
  const ProgramRun run =
      run_program(with(wavy("--mean-pressure", "1e6,1e7", "slow.h5"), {"--max-iter", "1", "--quiet"}), dir.path());
  EXPECT_EQ(run.exit_code, kExitNotConverged) << run.err;
  EXPECT_NE(run.err.find("error: solver did not converge at 2 of 2 steps (0, 1)"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("results written to slow.h5"), std::string::npos) << run.err;
  const test::H5 file = test::open_file(dir / "slow.h5");
  EXPECT_EQ(test::read_dataset<double>(file.get(), "/sweep/converged", H5T_NATIVE_DOUBLE),
            (std::vector<double>{0.0, 0.0}));
  EXPECT_TRUE(fs::exists(dir / "slow.csv"));
}

// The progress line needs a terminal: `script` runs the program on a pseudo
// terminal, and HALFSPACE_PROGRESS_INTERVAL=0 draws at every iteration.
TEST(SweepCliTest, ProgressLineOnTerminalsOnly) {
  if (std::system("command -v script > /dev/null 2>&1") != 0) GTEST_SKIP() << "script (util-linux) is not installed";
  const TempDir dir;
  const auto on_terminal = [&](const std::string& extra) {
    const std::string program = fmt::format(
        "{} solve --geometry wavy --wavelength 1e-3 --amplitude 1e-6 --grid 32x32 --size 1e-3 --boundary periodic "
        "--E-star 1e11 --mean-pressure 1e6,2e6 --threads 1 --output tty.h5{}",
        testing::shell_quoted(HALFSPACE_EXECUTABLE), extra);
    const std::string command =
        fmt::format("cd {} && HALFSPACE_PROGRESS_INTERVAL=0 script -qec {} /dev/null > terminal.txt 2>&1",
                    testing::shell_quoted(dir.path().string()), testing::shell_quoted(program));
    EXPECT_EQ(std::system(command.c_str()), 0);
    return testing::read_text(dir / "terminal.txt");
  };
  const std::string shown = on_terminal("");
  EXPECT_NE(shown.find("\rstep 1/2 (mean pressure 1e+06 Pa)  iteration 0  residual"), std::string::npos) << shown;
  EXPECT_NE(shown.find("remaining"), std::string::npos);
  EXPECT_NE(shown.find("\r\x1b[K"), std::string::npos) << "the line is cleared before the summary";
  const std::string quiet = on_terminal(" --quiet");
  EXPECT_EQ(quiet.find("iteration"), std::string::npos) << quiet;
}

TEST(SweepCliTest, PlotReportsMissingToolsBeforeSolving) {
  const TempDir dir;
  const ProgramRun python = run_program(with(wavy("--mean-pressure", "1e6", "out.h5"), {"--plot"}), dir.path(),
                                        {{"HALFSPACE_PYTHON", "/nonexistent/python3"}});
  EXPECT_EQ(python.exit_code, kExitInputError);
  EXPECT_NE(python.err.find("error: --plot: the plotting tool's interpreter /nonexistent/python3 cannot be run"),
            std::string::npos)
      << python.err;
  EXPECT_NE(python.err.find("install python3-matplotlib"), std::string::npos) << python.err;
  EXPECT_FALSE(fs::exists(dir / "out.h5"));

  const ProgramRun tool = run_program(with(wavy("--mean-pressure", "1e6", "out.h5"), {"--plot"}), dir.path(),
                                      {{"HALFSPACE_PLOT_TOOL", "/nonexistent/plot.py"}});
  EXPECT_EQ(tool.exit_code, kExitInputError);
  EXPECT_NE(tool.err.find("/nonexistent/plot.py (from HALFSPACE_PLOT_TOOL) is not a file"), std::string::npos)
      << tool.err;

  // A python without the packages: /bin/false stands in (it runs, but fails).
  const ProgramRun packages = run_program(with(wavy("--mean-pressure", "1e6", "out.h5"), {"--plot"}), dir.path(),
                                          {{"HALFSPACE_PYTHON", "/bin/false"}});
  EXPECT_EQ(packages.exit_code, kExitInputError);
  EXPECT_NE(packages.err.find("/bin/false cannot import matplotlib, h5py and numpy"), std::string::npos)
      << packages.err;
  EXPECT_FALSE(fs::exists(dir / "out.h5"));
}

// Whether process `pid` is gone (or only a zombie left for its parent).
bool process_ended(long pid) {
  std::ifstream stat(fmt::format("/proc/{}/stat", pid));
  std::string line;
  if (!std::getline(stat, line)) return true;
  const std::size_t close = line.rfind(')');
  return close != std::string::npos && close + 2 < line.size() && line[close + 2] == 'Z';
}

// The time limit ends the plotting tool's whole process group: a tool that
// forks a child which outlives it (here a shell that starts a background
// sleep, then sleeps itself) leaves nothing running (the child's sleep went
// on after the tool was stopped).
TEST(SweepCliTest, PlotTimeLimitEndsTheToolAndItsChildren) {
  const TempDir dir;
  {
    std::ofstream interpreter(dir / "fake-python");
    interpreter << "#!/bin/sh\n"
                   "# The import check passes; the tool forks a sleeper, records its pid and sleeps.\n"
                   "if [ \"$1\" = \"-c\" ]; then exit 0; fi\n"
                   "sleep 300 &\n"
                   "echo $! > grandchild.pid\n"
                   "sleep 300\n";
  }
  fs::permissions(dir / "fake-python", fs::perms::owner_all);
  { std::ofstream(dir / "tool.py") << "# run by fake-python\n"; }
  const ProgramRun run =
      run_program(with(wavy("--mean-pressure", "1e7", "single.h5"), {"--plot", "--quiet"}), dir.path(),
                  {{"HALFSPACE_PYTHON", (dir / "fake-python").string()},
                   {"HALFSPACE_PLOT_TOOL", (dir / "tool.py").string()},
                   {"HALFSPACE_PLOT_TIMEOUT", "1"}});
  EXPECT_EQ(run.exit_code, kExitPlotFailed) << run.err;
  EXPECT_NE(run.err.find("did not finish within 1 s and was stopped"), std::string::npos) << run.err;
  EXPECT_TRUE(fs::exists(dir / "single.h5"));
  std::ifstream recorded(dir / "grandchild.pid");
  long grandchild = 0;
  ASSERT_TRUE(recorded >> grandchild) << "the tool did not start its child";
  // The group was sent SIGKILL before the program returned; allow the
  // orphan's new parent a moment to reap it.
  bool ended = false;
  for (int k = 0; k < 100 && !ended; ++k) {
    ended = process_ended(grandchild);
    if (!ended) std::system("sleep 0.05");
  }
  EXPECT_TRUE(ended) << "the tool's child " << grandchild << " is still running";
  if (!ended) std::system(fmt::format("kill -9 {}", grandchild).c_str());
}

TEST(SweepCliTest, PlotDrawsFiguresNextToTheResult) {
  if (!python_with_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 with matplotlib, h5py and numpy is not installed";
  const TempDir dir;
  const ProgramRun single = run_program(with(wavy("--mean-pressure", "1e7", "single.h5"), {"--plot", "--quiet"}),
                                        dir.path(), {{"HALFSPACE_PYTHON", "/usr/bin/python3"}});
  ASSERT_EQ(single.exit_code, kExitOk) << single.err;
  EXPECT_TRUE(fs::exists(dir / "single_maps.png"));
  const ProgramRun sweep = run_program(with(wavy("--mean-pressure", "1e6:1e7:3", "sweep.h5"), {"--plot", "--quiet"}),
                                       dir.path(), {{"HALFSPACE_PYTHON", "/usr/bin/python3"}});
  ASSERT_EQ(sweep.exit_code, kExitOk) << sweep.err;
  EXPECT_EQ(sweep.out, "") << "--quiet silences the tool too";
  EXPECT_TRUE(fs::exists(dir / "sweep_maps.png")) << "the last step's maps";
  EXPECT_TRUE(fs::exists(dir / "sweep_sweep.png")) << "the sweep's curves";

  // A tool that fails after the solve: the result stays, exit code 3.
  std::ofstream(dir / "failing.py") << "import sys\nsys.exit(4)\n";
  const ProgramRun failing =
      run_program(with(wavy("--mean-pressure", "1e7", "kept.h5"), {"--plot", "--quiet"}), dir.path(),
                  {{"HALFSPACE_PYTHON", "/usr/bin/python3"}, {"HALFSPACE_PLOT_TOOL", "failing.py"}});
  EXPECT_EQ(failing.exit_code, kExitPlotFailed);
  EXPECT_NE(failing.err.find("error: --plot: '/usr/bin/python3 failing.py maps kept.h5' failed (exit status 4); "
                             "the result is written to kept.h5"),
            std::string::npos)
      << failing.err;
  EXPECT_TRUE(fs::exists(dir / "kept.h5"));
}

}  // namespace
}  // namespace halfspace
