// The plotting tool runs as a child process (posix_spawn, no shell), so file
// names need no quoting and the program keeps its own exit code.
#include "plot_tool.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

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

struct ChildStatus {
  int spawn_error = 0;  // errno of posix_spawnp, 0 if it started
  int exit_code = -1;   // -1 if killed by a signal
};

ChildStatus run_child(const std::vector<std::string>& arguments, bool silence_stdout, bool silence_stderr) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (silence_stdout) posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  if (silence_stderr) posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  // Our buffered output first, so that it is not overtaken by the child's.
  std::fflush(stdout);
  std::fflush(stderr);
  pid_t child = 0;
  ChildStatus status;
  status.spawn_error = posix_spawnp(&child, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (status.spawn_error != 0) return status;
  int wait_status = 0;
  while (::waitpid(child, &wait_status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(wait_status)) status.exit_code = WEXITSTATUS(wait_status);
  return status;
}

}  // namespace

PlotTool find_plot_tool(const PlotRequest& request) {
  PlotTool tool{{}, locate_script(request)};
  tool.interpreter = interpreter_of(tool.script);
  std::vector<std::string> check = tool.interpreter;
  check.insert(check.end(), {"-c", "import matplotlib, h5py, numpy"});
  const std::string shown = join_command_line(tool.interpreter);
  const ChildStatus status = run_child(check, true, true);
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
  const ChildStatus status = run_child(command, quiet, false);
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
