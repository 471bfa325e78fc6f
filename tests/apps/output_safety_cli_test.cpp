// The program never destroys a file it was not asked to write
// (docs/usage.md#output-files), tested through the real executable: outputs
// that would replace an input or each other are input errors with nothing
// written; a FIFO or device at an output path is refused and left alone; and
// a run killed by SIGTERM, SIGINT or SIGXFSZ while its output is being
// written leaves no `<name>.tmp-<pid>` file behind.
#include <fcntl.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/inotify.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
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
using testing::read_text;
using testing::run_program;

// A 16x16 text-matrix height map (a shallow bowl, m), given a .csv name.
void write_map_csv(const fs::path& path) {
  std::ofstream out(path);
  for (int j = 0; j < 16; ++j) {
    for (int i = 0; i < 16; ++i) {
      const double x = (i - 7.5) * 1e-6;
      const double y = (j - 7.5) * 1e-6;
      out << fmt::format("{}{:.6e}", i == 0 ? "" : ",", -(x * x + y * y) / (2 * 1e-4));
    }
    out << '\n';
  }
}

std::vector<std::string> solve_map(const std::string& map, const std::string& loads, const std::string& output) {
  return {
      "solve",           map,   "--dx",     "1e-6", "--dy",      "1e-6", "--boundary", "periodic", "--E-star", "1e11",
      "--mean-pressure", loads, "--output", output, "--threads", "1",    "--quiet"};
}

std::vector<std::string> names_in(const fs::path& directory) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

bool has_temporary(const fs::path& directory) {
  for (const std::string& name : names_in(directory)) {
    if (name.find(".tmp-") != std::string::npos) return true;
  }
  return false;
}

// The sweep's CSV is the output's name with .csv: here the input map.
TEST(OutputSafetyCliTest, SweepTableMayNotReplaceTheHeightMap) {
  const TempDir dir;
  write_map_csv(dir / "map.csv");
  const std::string before = read_text(dir / "map.csv");
  std::vector<std::string> arguments = solve_map("map.csv", "1e5,1e6", "map.h5");
  arguments.insert(arguments.begin() + 1, "--height-map");
  const auto run = run_program(arguments, dir.path());
  EXPECT_EQ(run.exit_code, kExitInputError) << run.err;
  EXPECT_NE(run.err.find("the sweep's CSV table map.csv"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("would overwrite the input --height-map map.csv"), std::string::npos) << run.err;
  EXPECT_EQ(read_text(dir / "map.csv"), before) << "the input was replaced";
  EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"map.csv"}) << "nothing is written";
}

// --output sw.csv: the result and its own table would be the same file.
TEST(OutputSafetyCliTest, SweepTableMayNotReplaceTheResult) {
  const TempDir dir;
  write_map_csv(dir / "map.csv");
  std::vector<std::string> arguments = solve_map("map.csv", "1e5,1e6", "sw.csv");
  arguments.insert(arguments.begin() + 1, "--height-map");
  const auto run = run_program(arguments, dir.path());
  EXPECT_EQ(run.exit_code, kExitInputError) << run.err;
  EXPECT_NE(run.err.find("--output sw.csv and the sweep's CSV table sw.csv"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("are the same file"), std::string::npos) << run.err;
  EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"map.csv"});
}

TEST(OutputSafetyCliTest, OutputMayNotReplaceTheHeightMapOrTheConfig) {
  const TempDir dir;
  write_map_csv(dir / "map.csv");
  const std::string map_before = read_text(dir / "map.csv");
  {
    // Under another spelling of the same path.
    fs::create_directory(dir / "sub");
    std::vector<std::string> arguments = solve_map("map.csv", "1e5", "sub/../map.csv");
    arguments.insert(arguments.begin() + 1, "--height-map");
    const auto run = run_program(arguments, dir.path());
    EXPECT_EQ(run.exit_code, kExitInputError) << run.err;
    EXPECT_NE(run.err.find("--output sub/../map.csv would overwrite the input --height-map map.csv"), std::string::npos)
        << run.err;
    EXPECT_EQ(read_text(dir / "map.csv"), map_before);
  }
  {
    std::ofstream(dir / "run.toml") << "E-star = 1e11\nmean-pressure = 1e5\n";
    const std::string config_before = read_text(dir / "run.toml");
    const auto run = run_program({"solve", "--config", "run.toml", "--height-map", "map.csv", "--dx", "1e-6", "--dy",
                                  "1e-6", "--output", "run.toml", "--quiet"},
                                 dir.path());
    EXPECT_EQ(run.exit_code, kExitInputError) << run.err;
    EXPECT_NE(run.err.find("--output run.toml would overwrite the input --config run.toml"), std::string::npos)
        << run.err;
    EXPECT_EQ(read_text(dir / "run.toml"), config_before);
  }
  EXPECT_EQ(names_in(dir.path()), (std::vector<std::string>{"map.csv", "run.toml", "sub"}));
}

// Measured FFT plans save wisdom: never over the height map being read.
TEST(OutputSafetyCliTest, WisdomFileMayNotReplaceAnInput) {
  const TempDir dir;
  write_map_csv(dir / "map.csv");
  const std::string before = read_text(dir / "map.csv");
  std::vector<std::string> arguments = solve_map("map.csv", "1e5", "out.h5");
  arguments.insert(arguments.begin() + 1, "--height-map");
  const auto run = run_program(arguments, dir.path(), {{"HALFSPACE_FFTW_WISDOM", (dir / "map.csv").string()}});
  EXPECT_EQ(run.exit_code, kExitInputError) << run.err;
  EXPECT_NE(run.err.find("the FFTW wisdom file"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("would overwrite the input --height-map map.csv"), std::string::npos) << run.err;
  EXPECT_EQ(read_text(dir / "map.csv"), before);
  EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"map.csv"});
}

// A FIFO (or a device node, as root) at the output path is refused before
// solving and is still there afterwards: the rename would have replaced it.
TEST(OutputSafetyCliTest, RefusesAFifoOrDeviceAsOutputAndLeavesIt) {
  const TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "pipe.h5").c_str(), 0600), 0);
  std::vector<std::string> kinds{"pipe.h5"};
  if (::mknod((dir / "device.h5").c_str(), S_IFCHR | 0600, makedev(1, 3)) == 0) kinds.push_back("device.h5");
  for (const std::string& name : kinds) {
    SCOPED_TRACE(name);
    const auto solve = run_program({"solve", "--geometry", "sphere", "--radius", "1e-2", "--grid", "16x16", "--size",
                                    "1e-4", "--E-star", "1e11", "--force", "1", "--output", name, "--quiet"},
                                   dir.path());
    EXPECT_EQ(solve.exit_code, kExitInputError) << solve.err;
    EXPECT_NE(solve.err.find(fmt::format("--output {} is invalid: cannot write output '{}': it is a", name, name)),
              std::string::npos)
        << solve.err;
    const auto generate = run_program(
        {"generate", "--kind", "flat", "--grid", "8x8", "--size", "1e-4", "--output", name, "--quiet"}, dir.path());
    EXPECT_EQ(generate.exit_code, kExitInputError) << generate.err;
    EXPECT_NE(generate.err.find(fmt::format("cannot write output '{}': it is a", name)), std::string::npos)
        << generate.err;
  }
  EXPECT_EQ(fs::symlink_status(dir / "pipe.h5").type(), fs::file_type::fifo);
  if (kinds.size() == 2) {
    EXPECT_EQ(fs::symlink_status(dir / "device.h5").type(), fs::file_type::character);
  }
  EXPECT_FALSE(has_temporary(dir.path()));
}

// The wisdom file follows the same rules: a FIFO there is neither read (it
// is not a regular file) nor replaced when the new plans are saved; the
// solve itself goes on, since wisdom only saves planning time.
TEST(OutputSafetyCliTest, WisdomIsNotSavedOverAFifo) {
  const TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "wisdom").c_str(), 0600), 0);
  const auto run = run_program({"solve", "--geometry", "sphere", "--radius", "1e-2", "--grid", "24x20", "--size",
                                "1e-4", "--E-star", "1e11", "--force", "1", "--output", "out.h5", "--quiet"},
                               dir.path(), {{"HALFSPACE_FFTW_WISDOM", (dir / "wisdom").string()}});
  EXPECT_EQ(run.exit_code, testing::kExitOk) << run.err;
  EXPECT_EQ(fs::symlink_status(dir / "wisdom").type(), fs::file_type::fifo);
  EXPECT_EQ(names_in(dir.path()), (std::vector<std::string>{"out.h5", "out.xdmf", "wisdom"}));
}

// A child running the program from `directory`, its output discarded;
// `prepare` runs in the child before exec (async-signal-safe calls only).
pid_t start_program(const std::vector<std::string>& arguments, const fs::path& directory, void (*prepare)() = nullptr) {
  std::vector<std::string> argv_text{HALFSPACE_EXECUTABLE};
  argv_text.insert(argv_text.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& text : argv_text) argv.push_back(text.data());
  argv.push_back(nullptr);
  const std::string where = directory.string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    if (::chdir(where.c_str()) != 0) ::_exit(127);
    // As in an interactive shell, whatever this test process inherited.
    ::signal(SIGINT, SIG_DFL);
    ::signal(SIGTERM, SIG_DFL);
    if (prepare != nullptr) prepare();
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

// A random surface: its heights barely compress, so writing the file takes
// long enough to be caught.
std::vector<std::string> generate_large(const std::string& output) {
  return {"generate",    "--kind", "self-affine", "--grid", "1024x1024", "--size", "1e-3",
          "--rms-slope", "0.1",    "--seed",      "3",      "--output",  output,   "--quiet"};
}

// Stops the child the moment a temporary file appears in `directory`
// (inotify), so that the signal lands while it exists. Returns whether it
// was caught in time.
bool stop_when_temporary_appears(pid_t child, const fs::path& directory) {
  const int watch = ::inotify_init1(IN_CLOEXEC | IN_NONBLOCK);
  if (watch < 0) return false;
  ::inotify_add_watch(watch, directory.c_str(), IN_CREATE);
  bool caught = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(3);
  while (!caught && std::chrono::steady_clock::now() < deadline) {
    pollfd ready{watch, POLLIN, 0};
    if (::poll(&ready, 1, 200) <= 0) {
      int status = 0;
      if (::waitpid(child, &status, WNOHANG) == child) break;  // ended without a temporary (or before the watch)
      continue;
    }
    alignas(inotify_event) std::array<char, 4096> buffer{};
    const ssize_t length = ::read(watch, buffer.data(), buffer.size());
    for (ssize_t offset = 0; offset < length;) {
      const auto* event = reinterpret_cast<const inotify_event*>(buffer.data() + offset);
      if (event->len > 0 && std::string(event->name).find(".tmp-") != std::string::npos) {
        ::kill(child, SIGSTOP);
        caught = true;
      }
      offset += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
    }
  }
  ::close(watch);
  return caught && has_temporary(directory);
}

TEST(OutputSafetyCliTest, TerminationWhileWritingLeavesNoTemporary) {
  for (const int signal : {SIGTERM, SIGINT}) {
    SCOPED_TRACE(strsignal(signal));
    bool tested = false;
    // The child is niced so that this process, woken by inotify, stops it
    // before its write ends; a lost race is retried, never counted as a pass.
    for (int attempt = 0; attempt < 3 && !tested; ++attempt) {
      const TempDir dir;
      const pid_t child = start_program(generate_large("surface.h5"), dir.path(), [] {
        if (::nice(19) == -1) ::_exit(126);
      });
      ASSERT_GT(child, 0);
      if (!stop_when_temporary_appears(child, dir.path())) {
        ::kill(child, SIGKILL);
        ::waitpid(child, nullptr, 0);
        continue;
      }
      ::kill(child, signal);
      ::kill(child, SIGCONT);
      int status = 0;
      ASSERT_EQ(::waitpid(child, &status, 0), child);
      EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << "status " << status;
      EXPECT_FALSE(has_temporary(dir.path())) << fmt::format("{}", fmt::join(names_in(dir.path()), " "));
      EXPECT_FALSE(fs::exists(dir / "surface.h5"));
      tested = true;
    }
    EXPECT_TRUE(tested) << "the temporary file was never caught while it existed";
  }
}

// A file-size limit ends the write with SIGXFSZ (default action: terminate),
// deterministically in the middle of the temporary.
TEST(OutputSafetyCliTest, FileSizeLimitWhileWritingLeavesNoTemporary) {
  const TempDir dir;
  const pid_t child = start_program({"generate", "--kind", "self-affine", "--grid", "256x256", "--size", "1e-3",
                                     "--rms-slope", "0.1", "--output", "surface.h5", "--quiet"},
                                    dir.path(), [] {
                                      const rlimit limit{65536, 65536};  // far below the ~480 KB file
                                      ::setrlimit(RLIMIT_FSIZE, &limit);
                                    });
  ASSERT_GT(child, 0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGXFSZ) << "status " << status;
  EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{}) << "no temporary, no output";
}

}  // namespace
}  // namespace halfspace
