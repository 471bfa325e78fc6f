// Runs the real `halfspace` executable for the command-line tests: arguments
// quoted for /bin/sh, optional environment variables, stdout and stderr
// captured separately, the exit code returned.
#pragma once

#include <fmt/format.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace halfspace::testing {

struct ProgramRun {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

// `text` single-quoted for /bin/sh (' itself becomes '\'').
inline std::string shell_quoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  quoted += '\'';
  return quoted;
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs HALFSPACE_EXECUTABLE with `arguments` from `directory`, with the
// variables of `environment` set (NAME, value).
inline ProgramRun run_program(const std::vector<std::string>& arguments, const std::filesystem::path& directory,
                              const std::vector<std::pair<std::string, std::string>>& environment = {}) {
  const std::filesystem::path err_file = directory / "stderr.txt";
  std::string command = fmt::format("cd {} && ", shell_quoted(directory.string()));
  for (const auto& [name, value] : environment) command += fmt::format("{}={} ", name, shell_quoted(value));
  command += shell_quoted(HALFSPACE_EXECUTABLE);
  for (const std::string& argument : arguments) command += fmt::format(" {}", shell_quoted(argument));
  command += fmt::format(" 2> {}", shell_quoted(err_file.string()));

  ProgramRun result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  std::size_t count = 0;
  while ((count = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.out.append(buffer.data(), count);
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.err = read_text(err_file);
  std::filesystem::remove(err_file);
  return result;
}

}  // namespace halfspace::testing
