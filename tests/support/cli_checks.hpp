// What every command-line test shares: the program's exit codes (the
// program's own constants, apps/exit_codes.hpp), running it in a temporary
// directory, building an argument list from (flag, value) pairs, and the
// check that bad input gives exactly one "error: " line and no output file.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <concepts>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "exit_codes.hpp"
#include "io/hdf5_test_support.hpp"
#include "support/program_run.hpp"

namespace halfspace::testing {

using app::kExitInputError;
using app::kExitNotConverged;
using app::kExitOk;
using app::kExitPlotFailed;

// (flag, value) pairs; an empty value is a flag without one ("--quiet").
using OptionPairs = std::vector<std::pair<std::string, std::string>>;

// Runs the executable with `arguments`, from `directory`.
inline ProgramRun run(const std::vector<std::string>& arguments, const test::TempDir& directory) {
  return run_program(arguments, directory.path());
}

// `command` (e.g. "solve") followed by the flags and values of `options`.
inline std::vector<std::string> command_arguments(const std::string& command, const OptionPairs& options) {
  std::vector<std::string> arguments{command};
  for (const auto& [flag, value] : options) {
    arguments.push_back(flag);
    if (!value.empty()) arguments.push_back(value);
  }
  return arguments;
}

// Expects an input error: exit 1, nothing on stdout, exactly one stderr line
// starting "error: " and holding every part of `expected`, and no `output`
// (when given).
inline void expect_input_error(const ProgramRun& result, const std::vector<std::string>& expected,
                               const std::filesystem::path& output = {}) {
  EXPECT_EQ(result.exit_code, kExitInputError) << result.err;
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err.rfind("error: ", 0), 0U) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  for (const std::string& part : expected) {
    EXPECT_NE(result.err.find(part), std::string::npos) << "expected '" << part << "' in: " << result.err;
  }
  if (!output.empty()) {
    EXPECT_FALSE(std::filesystem::exists(output)) << output;
  }
}

// The same for one expected part (a template, so that a braced list of
// strings always means the overload above).
template <class Text>
requires std::convertible_to<const Text&, std::string_view>
void expect_input_error(const ProgramRun& result, const Text& expected, const std::filesystem::path& output = {}) {
  expect_input_error(result, std::vector<std::string>{std::string(std::string_view(expected))}, output);
}

}  // namespace halfspace::testing
