// The options of `halfspace solve` as given, before validation: registered
// with CLI11, read from the command line, and merged with a TOML config file
// whose keys are the long flag names without the leading dashes (through the
// option table, option_table.hpp).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "halfspace/problem.hpp"
#include "halfspace/surface/surface_options.hpp"
#include "option_table.hpp"

namespace halfspace::app {

// Everything `halfspace solve` accepts. An empty optional was given neither on
// the command line nor in the config file; defaults are applied later, in
// make_solve_setup, so that "not given" stays distinguishable from "default".
struct SolveOptions : GivenOptions, SurfaceOptions, ProblemOptions {
  // The surface (a height map file or a built-in geometry) is SurfaceOptions'
  // (halfspace/surface/surface_options.hpp); the boundary of its grid.
  std::optional<std::string> boundary;
  // The body, interface law, loads and solver settings are ProblemOptions'
  // (halfspace/problem.hpp), under the same names.
  std::optional<std::string> max_memory;  // "8G", "512M" or bytes, as written
  // Subsurface stresses written into the result (docs/usage.md#stress).
  std::optional<std::string> stress_depths;  // "z1,z2,..." or "START:STOP:COUNT" (m), as written
  std::optional<double> stress_nu;
  std::optional<std::string> stress_body;  // "1" or "2"
  // Friction's tangential load steps as written ("QX[,QY];..." or ranges,
  // parsed into ProblemOptions' tangential_force and tangential_displacement
  // by problem_options), and --no-coupling (ProblemOptions' coupling "off");
  // mu, --sliding and the rest are ProblemOptions' (docs/usage.md#friction).
  std::optional<std::string> tangential_force_text;
  std::optional<std::string> tangential_displacement_text;
  bool no_coupling = false;
  // Output.
  std::optional<std::string> output;
  bool quiet = false;
  bool plot = false;  // draw figures with the plotting tool after writing
};

// Registers every option of `solve` (grouped as in --help) with CLI11.
void add_solve_options(CLI::App& solve);

// Reads the options given on the command line after `solve` parsed it.
// Throws InputError naming the flag when a value is not of its type.
SolveOptions solve_options_from_command_line(const CLI::App& solve, const std::vector<std::string>& argv);

// If options.config is set, reads that TOML file and fills every option the
// command line left unset. A command-line option also discards the file's
// keys of the alternatives it excludes (e.g. --approach drops the file's
// force). Throws FileError if the file cannot be read and InputError for a
// TOML syntax error, an unknown key or a value of the wrong type, naming the
// key and the file.
void merge_config_file(SolveOptions& options);

// The problem as given: the ProblemOptions part of `options`, where --tol
// is the adhesive solver's tolerance too, the tangential steps are parsed
// (throws InputError naming the flag for their syntax) and --no-coupling is
// coupling "off".
ProblemOptions problem_options(const SolveOptions& options);

// The program's spelling of the problem's options (problem.hpp): the flag or
// config key of each ("adhesion_tol" is --tol) and its value as written.
class FlagSpelling : public GivenSpelling {
 public:
  explicit FlagSpelling(const SolveOptions& options);

 protected:
  std::string key(std::string_view option) const override;
};

}  // namespace halfspace::app
