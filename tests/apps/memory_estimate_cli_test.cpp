// The memory estimate against what real runs of the program use: for solves
// of every solver family, both boundaries, 1D and 2D, and a sweep, the peak
// resident set size of the child process (wait4's ru_maxrss) must stay below
// the estimate, and the estimate must not exceed three times that peak (an
// estimate that refuses runs the machine could do is no use either).
#include <fcntl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "halfspace/memory_estimate.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "io/hdf5_test_support.hpp"
#include "support/cli_checks.hpp"
#include "support/program_run.hpp"

namespace halfspace {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

struct Measured {
  int exit_code = -1;
  double peak_bytes = 0.0;  // maximum resident set size
};

// Runs the program with `arguments` in `directory` (stdout discarded, stderr
// to stderr.txt there), and reads its peak memory from the kernel's
// accounting of that one child.
Measured run_measured(const std::vector<std::string>& arguments, const fs::path& directory) {
  std::vector<std::string> words{HALFSPACE_EXECUTABLE};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const std::string where = directory.string();
  const std::string err = (directory / "stderr.txt").string();
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child == 0) {
    // Only async-signal-safe calls between fork and exec.
    const int null = ::open("/dev/null", O_WRONLY);
    const int errors = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (::chdir(where.c_str()) != 0 || null < 0 || errors < 0) ::_exit(127);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(errors, STDERR_FILENO);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  Measured measured;
  int status = 0;
  struct rusage usage {};
  if (child < 0 || ::wait4(child, &status, 0, &usage) != child) return measured;
  measured.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  measured.peak_bytes = static_cast<double>(usage.ru_maxrss) * 1024.0;  // KiB on Linux
  return measured;
}

struct Case {
  std::string name;
  std::vector<std::string> arguments;  // after "solve", without --output
  Grid grid;                           // the grid those options make
  solvers::SolverOptions settings;     // the settings they choose
  std::size_t steps = 1;
};

solvers::SolverOptions solver(const std::string& name, std::optional<std::size_t> deflation_block = std::nullopt) {
  solvers::SolverOptions settings;
  settings.type = solvers::parse_solver_type(name);
  if (deflation_block) {
    settings.deflation.mode =
        *deflation_block > 0 ? solvers::DeflationOptions::Mode::on : solvers::DeflationOptions::Mode::off;
    if (*deflation_block > 0) settings.deflation.block = *deflation_block;
  }
  return settings;
}

// The same with --precision mixed.
solvers::SolverOptions mixed(solvers::SolverOptions settings) {
  settings.precision = solvers::Precision::mixed;
  return settings;
}

// Maugis-Dugdale, w = 0.05 J/m^2, h0 = 10 nm, as the adhesive cases ask.
solvers::SolverOptions adhesive(bool precondition) {
  solvers::SolverOptions settings;
  settings.adhesion = solvers::SolverOptions::Adhesion{AdhesionLaw::maugis_dugdale(0.05, 1e-8), 1e-6, precondition};
  return settings;
}

TEST(MemoryEstimateCliTest, EstimateBoundsTheMeasuredPeakWithinAFactorOfThree) {
  const std::vector<Case> cases{
      {"periodic 2D wavy, pk-multilevel",
       {"--geometry", "wavy", "--wavelength", "2.5e-4", "--amplitude", "1e-6", "--grid", "512x512", "--size", "1e-3",
        "--boundary", "periodic", "--mean-pressure", "1e7"},
       Grid::plane(512, 512, 1e-3 / 512, 1e-3 / 512, Boundary::periodic),
       solver("pk-multilevel")},
      {"free 2D sphere, pk-multilevel",
       {"--geometry", "sphere", "--radius", "0.01", "--grid", "512x512", "--size", "5e-4", "--force", "10"},
       Grid::plane(512, 512, 5e-4 / 512, 5e-4 / 512, Boundary::free),
       solver("pk-multilevel")},
      {"periodic 2D wavy, pk-fourier with block deflation",
       {"--geometry", "wavy", "--wavelength", "2.5e-4", "--amplitude", "1e-6", "--grid", "512x512", "--size", "1e-3",
        "--boundary", "periodic", "--mean-pressure", "1e7", "--solver", "pk-fourier", "--deflation-block", "32"},
       Grid::plane(512, 512, 1e-3 / 512, 1e-3 / 512, Boundary::periodic),
       solver("pk-fourier", 32)},
      {"periodic 2D wavy, pk-multilevel with block deflation, mixed precision",
       {"--geometry", "wavy", "--wavelength", "2.5e-4", "--amplitude", "1e-6", "--grid", "512x512", "--size", "1e-3",
        "--boundary", "periodic", "--mean-pressure", "1e7", "--deflation-block", "32", "--precision", "mixed"},
       Grid::plane(512, 512, 1e-3 / 512, 1e-3 / 512, Boundary::periodic),
       mixed(solver("pk-multilevel", 32))},
      {"periodic 2D wavy, pk-multilevel with the active-set phase, mixed precision",
       {"--geometry", "wavy", "--wavelength", "2.5e-4", "--amplitude", "1e-6", "--grid", "512x512", "--size", "1e-3",
        "--boundary", "periodic", "--mean-pressure", "1e7", "--active-set", "on", "--precision", "mixed"},
       Grid::plane(512, 512, 1e-3 / 512, 1e-3 / 512, Boundary::periodic),
       mixed(solver("pk-multilevel"))},
      {"free 1D cylinder, pk",
       {"--geometry", "cylinder", "--radius", "0.01", "--grid", "262144", "--size", "1e-3", "--force", "1e4",
        "--solver", "pk"},
       Grid::line(262144, 1e-3 / 262144, Boundary::free),
       solver("pk")},
      {"periodic 1D wavy, pk-multilevel",
       {"--geometry", "wavy", "--wavelength", "2.5e-4", "--amplitude", "1e-6", "--grid", "262144", "--size", "1e-3",
        "--boundary", "periodic", "--mean-pressure", "1e7"},
       Grid::line(262144, 1e-3 / 262144, Boundary::periodic),
       solver("pk-multilevel")},
      {"free 2D sphere, sweep of 4 loads",
       {"--geometry", "sphere", "--radius", "0.01", "--grid", "256x256", "--size", "5e-4", "--force", "1,3,10,30"},
       Grid::plane(256, 256, 5e-4 / 256, 5e-4 / 256, Boundary::free),
       solver("pk-multilevel"),
       4},
      {"free 2D sphere, adhesive (SPG)",
       {"--geometry", "sphere", "--radius", "0.01", "--grid", "256x256", "--size", "5e-4", "--approach", "1e-7",
        "--adhesion", "md", "--work-of-adhesion", "0.05", "--adhesion-range", "1e-8"},
       Grid::plane(256, 256, 5e-4 / 256, 5e-4 / 256, Boundary::free),
       adhesive(false)},
      {"periodic 2D wavy, adhesive (conjugate gradients)",
       {"--geometry",
        "wavy",
        "--wavelength",
        "2.5e-4",
        "--amplitude",
        "1e-6",
        "--grid",
        "512x512",
        "--size",
        "1e-3",
        "--boundary",
        "periodic",
        "--approach",
        "5e-7",
        "--adhesion",
        "md",
        "--work-of-adhesion",
        "0.05",
        "--adhesion-range",
        "1e-8",
        "--adhesion-precondition",
        "on"},
       Grid::plane(512, 512, 1e-3 / 512, 1e-3 / 512, Boundary::periodic),
       adhesive(true)},
      {"free 1D cylinder, lemke (dense)",
       {"--geometry", "cylinder", "--radius", "0.01", "--grid", "1024", "--size", "1e-4", "--force", "1e3", "--solver",
        "lemke"},
       Grid::line(1024, 1e-4 / 1024, Boundary::free),
       solver("lemke")},
  };
  const TempDir dir;
  for (const Case& c : cases) {
    std::vector<std::string> arguments{"solve"};
    arguments.insert(arguments.end(), c.arguments.begin(), c.arguments.end());
    arguments.insert(arguments.end(), {"--E-star", "1e11", "--output", "out.h5", "--quiet"});
    const Measured measured = run_measured(arguments, dir.path());
    ASSERT_EQ(measured.exit_code, testing::kExitOk) << c.name << ": " << testing::read_text(dir / "stderr.txt");
    // As the program counts it: a single load-controlled Polonsky-Keer solve
    // keeps its initial gap in the heights' place.
    const bool load_controlled = std::find(c.arguments.begin(), c.arguments.end(), "--approach") == c.arguments.end();
    const bool gap_in_heights =
        c.steps == 1 &&
        solvers::initial_gap_in_heights(
            load_controlled ? solvers::Loading::mean_pressure(1.0) : solvers::Loading::approach(1.0), c.settings);
    const double estimate = solve_memory_estimate(c.grid, c.settings, c.steps, gap_in_heights);
    std::printf("  %-50s peak %8.1f MiB, estimate %8.1f MiB (%.2fx)\n", c.name.c_str(), measured.peak_bytes / 1048576.0,
                estimate / 1048576.0, estimate / measured.peak_bytes);
    EXPECT_LT(measured.peak_bytes, estimate) << c.name;
    EXPECT_LT(estimate, 3.0 * measured.peak_bytes) << c.name;
  }
}

// `halfspace stress` computes and writes one depth at a time: its peak is the
// transforms and one depth's fields, far below the volume it writes (the
// whole volume, then HDF5's in-memory image of the file and its copy, three
// times the volume, before).
TEST(MemoryEstimateCliTest, StressCommandHoldsOneDepthNotTheVolume) {
  const TempDir dir;
  constexpr std::size_t kCells = 128 * 128;
  constexpr std::size_t kDepths = 96;
  const Measured solve =
      run_measured({"solve",  "--geometry", "sphere",     "--radius", "0.01",      "--grid", "128x128",
                    "--size", "4e-4",       "--boundary", "periodic", "--E-star",  "1e11",   "--force",
                    "1",      "--threads",  "1",          "--output", "result.h5", "--quiet"},
                   dir.path());
  ASSERT_EQ(solve.exit_code, testing::kExitOk) << testing::read_text(dir / "stderr.txt");
  const Measured stress = run_measured({"stress", "result.h5", "--depth-range", "1e-6:1e-4:96", "--nu", "0.3",
                                        "--threads", "1", "--output", "stress.h5", "--quiet"},
                                       dir.path());
  ASSERT_EQ(stress.exit_code, testing::kExitOk) << testing::read_text(dir / "stderr.txt");
  const double volume = 9.0 * 8.0 * static_cast<double>(kCells * kDepths);  // 113 MB
  const Grid grid = Grid::plane(128, 128, 4e-4 / 128, 4e-4 / 128, Boundary::periodic);
  // What the command checks before it starts (stress_command.cpp).
  const double estimate = stress_command_memory_estimate(grid, false, false);
  std::printf("  stress, 128^2 x 96 depths: peak %.1f MiB, estimate %.1f MiB, volume %.1f MiB, solve's peak %.1f MiB\n",
              stress.peak_bytes / 1048576.0, estimate / 1048576.0, volume / 1048576.0, solve.peak_bytes / 1048576.0);
  EXPECT_GT(fs::file_size(dir / "stress.h5"), volume);
  EXPECT_LT(stress.peak_bytes, estimate);
  // Beyond the program itself (the small solve's peak): HDF5's caches and
  // one depth's fields, not a fraction of the volume.
  EXPECT_LT(stress.peak_bytes - solve.peak_bytes, volume / 8.0);
}

}  // namespace
}  // namespace halfspace
