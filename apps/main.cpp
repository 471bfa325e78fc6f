// Entry point of the `halfspace` program: `--version`, `--help` and the
// `solve` command. Every error ends here as one "error: ..." line on stderr.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <string>
#include <vector>

#include "exit_codes.hpp"
#include "halfspace/error.hpp"
#include "halfspace/version.hpp"
#include "solve_command.hpp"
#include "solve_options.hpp"
#include "solve_setup.hpp"

namespace {

using halfspace::app::kExitInputError;

int solve_command(const CLI::App& solve, const std::vector<std::string>& arguments) {
  halfspace::app::SolveOptions options = halfspace::app::solve_options_from_command_line(solve, arguments);
  halfspace::app::merge_config_file(options);
  const halfspace::app::SolveSetup setup = halfspace::app::make_solve_setup(options);
  return halfspace::app::run_solve(setup);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"halfspace: frictionless normal contact of an elastic half-space with a rigid rough surface",
               "halfspace"};
  app.set_version_flag("--version", fmt::format("halfspace {} ({})", halfspace::kVersion, halfspace::kGitHash));
  app.footer("Exit codes: 0 converged, 1 bad input or file error, 2 solved but not converged.");
  CLI::App* solve = app.add_subcommand(
      "solve", "Solve one contact problem and write the pressure, gap and displacement to an HDF5 file");
  solve->footer("Options can also come from --config FILE.toml; see docs/usage.md.");
  halfspace::app::add_solve_options(*solve);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& success) {
    return app.exit(success);  // --help or --version: printed to stdout, exit 0
  } catch (const CLI::ParseError& error) {
    fmt::print(stderr, "error: {} (see halfspace --help)\n", error.what());
    return kExitInputError;
  }
  if (!solve->parsed()) {
    fmt::print(stderr, "error: no command given: try 'halfspace solve --help'\n");
    return kExitInputError;
  }

  try {
    return solve_command(*solve, std::vector<std::string>(argv, argv + argc));
  } catch (const halfspace::InputError& error) {
    fmt::print(stderr, "error: {}\n", error.what());
  } catch (const std::exception& error) {
    // Not an input mistake we foresaw (e.g. out of memory for a huge grid);
    // still one line, still a failure.
    fmt::print(stderr, "error: {}\n", error.what());
  }
  return kExitInputError;
}
