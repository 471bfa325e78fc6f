// The options of `halfspace solve` as given, before validation: registered
// with CLI11, read from the command line, and merged with a TOML config file
// whose keys are the long flag names without the leading dashes (through the
// option table, option_table.hpp).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "option_table.hpp"

namespace halfspace::app {

// Everything `halfspace solve` accepts. An empty optional was given neither on
// the command line nor in the config file; defaults are applied later, in
// make_solve_setup, so that "not given" stays distinguishable from "default".
struct SolveOptions : GivenOptions {
  // Surface: a height map file, or a built-in geometry.
  std::optional<std::string> height_map;
  std::optional<std::string> dataset;
  std::optional<double> dx;
  std::optional<double> dy;
  // Height-map format and preparation (docs/usage.md#height-map-formats-and-preparation).
  std::optional<std::string> format;
  std::optional<std::string> unit;
  std::optional<std::string> window;
  std::optional<std::string> invalid;
  std::optional<std::string> detrend;
  std::optional<double> pad;
  std::optional<std::string> geometry;
  std::optional<double> radius;
  std::optional<double> wavelength;
  std::optional<double> amplitude;
  // Grid of a built-in geometry.
  std::optional<std::string> grid;
  std::optional<std::string> size;
  std::optional<std::string> boundary;
  // Material: four constants, or E* directly.
  std::optional<double> e1;
  std::optional<double> nu1;
  std::optional<double> e2;
  std::optional<double> nu2;
  std::optional<double> e_star;
  // Coated half-space (all five, instead of the material above): a layer
  // bonded to a substrate, against a rigid surface.
  std::optional<double> layer_thickness;
  std::optional<double> layer_e;
  std::optional<double> layer_nu;
  std::optional<double> substrate_e;
  std::optional<double> substrate_nu;
  // Interface law: a hardness cap p <= H (Pa).
  std::optional<double> hardness;
  // Load: exactly one; more than one value makes a load sweep.
  std::optional<std::vector<double>> force;
  std::optional<std::vector<double>> mean_pressure;
  std::optional<std::vector<double>> approach;
  // Solver.
  std::optional<std::string> solver;
  std::optional<double> tol;
  std::optional<long long> max_iter;
  std::optional<long long> threads;
  std::optional<std::string> fft_planning;
  std::optional<long long> deflation_block;
  std::optional<std::string> active_set;  // on or off
  std::optional<std::string> max_memory;  // "8G", "512M" or bytes, as written
  // Subsurface stresses written into the result (docs/usage.md#stress).
  std::optional<std::string> stress_depths;  // "z1,z2,..." or "START:STOP:COUNT" (m), as written
  std::optional<double> stress_nu;
  // Adhesion (docs/usage.md#adhesion): a cohesive law beside the hard wall.
  std::optional<std::string> adhesion;  // md or exponential
  std::optional<double> work_of_adhesion;
  std::optional<double> adhesion_range;
  std::optional<double> adhesion_stress;
  std::optional<std::string> adhesion_precondition;  // on or off
  // Friction (docs/usage.md#friction): Coulomb's coefficient and the
  // tangential load steps ("QX[,QY];..." or ranges, as written) or a sliding
  // direction "X,Y".
  std::optional<double> friction;
  std::optional<std::string> tangential_force;
  std::optional<std::string> tangential_displacement;
  std::optional<std::string> sliding;
  std::optional<double> tangential_tol;
  std::optional<long long> tangential_max_iter;
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

}  // namespace halfspace::app
