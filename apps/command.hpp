// A subcommand of the `halfspace` program: its CLI11 parser and what runs it
// once parsing succeeded. Each command lives in its own file and is listed in
// main.cpp.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace halfspace::app {

struct Command {
  CLI::App* parser = nullptr;
  // Runs the parsed command with the full argv (for provenance); returns the
  // exit code, throws InputError for bad input.
  std::function<int(const std::vector<std::string>& argv)> run;
};

}  // namespace halfspace::app
