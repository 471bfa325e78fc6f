// The plotting tool runs as a child process (posix_spawn, no shell), so file
// names need no quoting and the program keeps its own exit code.
#include "plot_tool.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include "halfspace/error.hpp"
#include "value_parsing.hpp"

extern char** environ;

namespace halfspace::app {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kPackages = "matplotlib, h5py and numpy";

std::string install_hint(const PlotRequest& request) {
  return fmt::format(
      "install python3-matplotlib, python3-h5py and python3-numpy (scripts/install-deps.sh), set HALFSPACE_PYTHON to "
      "a python3 that has them, or {}",
      request.skip_hint);
}

fs::path locate_script(const PlotRequest& request) {
  if (!request.script.empty()) {
    if (!fs::is_regular_file(request.script)) {
      throw InputError(fmt::format("{}: the plotting tool {} is not a file", request.by, request.script.string()));
    }
    return request.script;
  }
  if (const char* given = std::getenv("HALFSPACE_PLOT_TOOL"); given != nullptr && *given != '\0') {
    if (!fs::is_regular_file(given)) {
      throw InputError(
          fmt::format("{}: the plotting tool {} (from HALFSPACE_PLOT_TOOL) is not a file", request.by, given));
    }
    return given;
  }
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    const fs::path installed = program.parent_path().parent_path() / "share" / "halfspace" / "halfspace_plot.py";
    if (fs::is_regular_file(installed)) return installed;
  }
#ifdef HALFSPACE_PLOT_SCRIPT
  if (fs::is_regular_file(HALFSPACE_PLOT_SCRIPT)) return HALFSPACE_PLOT_SCRIPT;
#endif
  throw InputError(fmt::format(
      "{}: the plotting tool halfspace_plot.py was not found (looked in <prefix>/share/halfspace beside the "
      "program and in the source tree); set HALFSPACE_PLOT_TOOL to its path, or {}",
      request.by, request.skip_hint));
}

// "#!/usr/bin/python3" -> {"/usr/bin/python3"}; "#!/usr/bin/env python3" ->
// {"/usr/bin/env", "python3"}.
std::vector<std::string> interpreter_of(const fs::path& script) {
  if (const char* given = std::getenv("HALFSPACE_PYTHON"); given != nullptr && *given != '\0') return {given};
  std::ifstream in(script);
  std::string first;
  std::getline(in, first);
  if (first.rfind("#!", 0) != 0) return {"python3"};
  std::istringstream words(first.substr(2));
  std::vector<std::string> interpreter;
  for (std::string word; words >> word;) interpreter.push_back(word);
  if (interpreter.empty()) return {"python3"};
  return interpreter;
}

// HALFSPACE_PLOT_TIMEOUT in seconds, else the default.
double plot_timeout(const PlotRequest& request) {
  const char* given = std::getenv("HALFSPACE_PLOT_TIMEOUT");
  if (given == nullptr || *given == '\0') return kDefaultPlotTimeoutSeconds;
  const std::string_view text(given);
  double seconds = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), seconds);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(seconds) || seconds < 0.0) {
    throw InputError(
        fmt::format("{}: HALFSPACE_PLOT_TIMEOUT={} is invalid: give the plotting tool's time limit in "
                    "seconds, or 0 for none",
                    request.by, text));
  }
  return seconds;
}

struct ChildStatus {
  int spawn_error = 0;     // errno of posix_spawnp, 0 if it started
  int exit_code = -1;      // -1 if killed by a signal
  bool timed_out = false;  // stopped after running `timeout` seconds
};

// Waits for `child`, the leader of its own process group; after `timeout`
// seconds (0: none) asks the whole group to stop (the tool's own children
// too: a python that forks a renderer), and kills the group if the child has
// not exited within a few seconds more. Once a timed-out child has exited,
// the rest of its group is killed before the child is reaped: until then its
// pid, the group's id, cannot be reused by another process.
int wait_for(pid_t child, double timeout, bool& timed_out) {
  using Clock = std::chrono::steady_clock;
  constexpr auto kPoll = std::chrono::milliseconds(20);
  constexpr auto kGrace = std::chrono::seconds(5);
  // At most about three years, so that the deadline cannot overflow the clock.
  const auto deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(std::min(timeout, 1e8)));
  bool killed = false;
  for (;;) {
    siginfo_t info{};
    const int options = WEXITED | WNOWAIT | (timeout > 0.0 && !killed ? WNOHANG : 0);
    const int waited = ::waitid(P_PID, static_cast<id_t>(child), &info, options);
    if (waited < 0 && errno == EINTR) continue;
    if (waited < 0 || info.si_pid == child) break;
    const auto now = Clock::now();
    if (!timed_out && now >= deadline) {
      ::kill(-child, SIGTERM);
      timed_out = true;
    } else if (timed_out && now >= deadline + kGrace) {
      ::kill(-child, SIGKILL);
      killed = true;  // and wait without polling
      continue;
    }
    std::this_thread::sleep_for(kPoll);
  }
  if (timed_out) ::kill(-child, SIGKILL);
  int wait_status = 0;
  while (::waitpid(child, &wait_status, 0) < 0 && errno == EINTR) {
  }
  return wait_status;
}

ChildStatus run_child(const std::vector<std::string>& arguments, bool silence_stdout, bool silence_stderr,
                      double timeout) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (silence_stdout) posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  if (silence_stderr) posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  // Its own process group (the child's pid), so that the time limit ends the
  // tool and whatever it started.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  // Our buffered output first, so that it is not overtaken by the child's.
  std::fflush(stdout);
  std::fflush(stderr);
  pid_t child = 0;
  ChildStatus status;
  status.spawn_error = posix_spawnp(&child, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (status.spawn_error != 0) return status;
  const int wait_status = wait_for(child, timeout, status.timed_out);
  if (WIFEXITED(wait_status)) status.exit_code = WEXITSTATUS(wait_status);
  return status;
}

}  // namespace

PlotTool find_plot_tool(const PlotRequest& request) {
  PlotTool tool{{}, locate_script(request), plot_timeout(request)};
  tool.interpreter = interpreter_of(tool.script);
  std::vector<std::string> check = tool.interpreter;
  check.insert(check.end(), {"-c", "import matplotlib, h5py, numpy"});
  const std::string shown = join_command_line(tool.interpreter);
  const ChildStatus status = run_child(check, true, true, tool.timeout_seconds);
  if (status.timed_out) {
    throw InputError(
        fmt::format("{}: {} did not finish importing {} within {:g} s and was stopped (set "
                    "HALFSPACE_PLOT_TIMEOUT to allow longer, 0 for no limit), or {}",
                    request.by, shown, kPackages, tool.timeout_seconds, request.skip_hint));
  }
  if (status.spawn_error != 0) {
    throw InputError(fmt::format("{}: the plotting tool's interpreter {} cannot be run ({}): {}", request.by, shown,
                                 std::strerror(status.spawn_error), install_hint(request)));
  }
  if (status.exit_code != 0) {
    throw InputError(fmt::format("{}: {} cannot import {}, which the plotting tool {} needs: {}", request.by, shown,
                                 kPackages, tool.script.string(), install_hint(request)));
  }
  return tool;
}

std::string run_plot_tool(const PlotTool& tool, std::string_view subcommand, const std::filesystem::path& file,
                          bool quiet) {
  std::vector<std::string> command = tool.interpreter;
  command.insert(command.end(), {tool.script.string(), std::string(subcommand), file.string()});
  const ChildStatus status = run_child(command, quiet, false, tool.timeout_seconds);
  if (status.timed_out) {
    return fmt::format(
        "'{}' did not finish within {:g} s and was stopped (set HALFSPACE_PLOT_TIMEOUT to allow longer, 0 for no "
        "limit)",
        join_command_line(command), tool.timeout_seconds);
  }
  if (status.spawn_error != 0) {
    return fmt::format("'{}' could not be started: {}", join_command_line(command), std::strerror(status.spawn_error));
  }
  if (status.exit_code != 0) {
    return fmt::format(
        "'{}' failed ({})", join_command_line(command),
        status.exit_code < 0 ? std::string("killed by a signal") : fmt::format("exit status {}", status.exit_code));
  }
  return {};
}

}  // namespace halfspace::app
