// The option table of `halfspace solve`: one entry per option drives the CLI11
// registration, the command-line conversion and the TOML merge, so the flag
// names and the config keys cannot drift apart.
#include "solve_options.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <variant>

#include "halfspace/error.hpp"
#include "value_parsing.hpp"

namespace halfspace::app {
namespace {

enum class Kind {
  number,      // double
  numbers,     // doubles: one number, a list "A,B,C" or a range "START:STOP:COUNT"; a TOML array too
  integer,     // long long
  text,        // string
  path,        // string; relative paths in a config file are relative to the file
  dimensions,  // string "N" or "AxB"; a config file may also give a bare number
  memory,      // string "8G", "512M" or bytes; a config file may also give a whole number of bytes
  flag,        // bool, no value
};

using Field = std::variant<std::optional<double> SolveOptions::*, std::optional<long long> SolveOptions::*,
                           std::optional<std::string> SolveOptions::*, bool SolveOptions::*,
                           std::optional<std::vector<double>> SolveOptions::*>;

struct OptionSpec {
  std::string_view key;  // the long flag without "--", and the config file key
  Field field;
  Kind kind;
  std::string_view group;
  std::string_view value_name;
  std::string_view help;
};

constexpr std::string_view kSurface = "Surface (exactly one of --height-map, --geometry)";
constexpr std::string_view kPreparation = "Height-map format and preparation (applied in this order)";
constexpr std::string_view kGrid = "Grid";
constexpr std::string_view kMaterial = "Material (E1, nu1, E2 and nu2, or E-star)";
constexpr std::string_view kCoating = "Coated half-space (all five, instead of the material; the surface is rigid)";
constexpr std::string_view kLoad = "Load (exactly one)";
constexpr std::string_view kInterface = "Interface law";
constexpr std::string_view kSolver = "Solver";
constexpr std::string_view kOutput = "Output";
constexpr std::string_view kStress = "Subsurface stresses (single solves)";
constexpr std::string_view kAdhesion = "Adhesion (a cohesive law beside the hard wall; --approach may be negative)";

const std::array kOptions{
    OptionSpec{"height-map", &SolveOptions::height_map, Kind::path, kSurface, "FILE",
               "HDF5 height map (m): a rank-1 profile or a (ny, nx) map; its grid is used"},
    OptionSpec{"dataset", &SolveOptions::dataset, Kind::text, kSurface, "PATH",
               "dataset in the height map file [/height]"},
    OptionSpec{"dx", &SolveOptions::dx, Kind::number, kSurface, "M",
               "height map spacing along x (m); overrides the file's dx attribute"},
    OptionSpec{"dy", &SolveOptions::dy, Kind::number, kSurface, "M",
               "height map spacing along y (m); overrides the file's dy attribute"},
    OptionSpec{"format", &SolveOptions::format, Kind::text, kPreparation, "NAME",
               "height map format: auto (by extension), hdf5, npy, matrix, profile, x3p or gsf [auto]"},
    OptionSpec{"unit", &SolveOptions::unit, Kind::text, kPreparation, "UNIT",
               "length unit of npy, text and unlabelled GSF files: m, mm, um, nm [m]"},
    OptionSpec{"window", &SolveOptions::window, Kind::text, kPreparation, "I0,J0,NX,NY",
               "use only columns I0..I0+NX-1 and rows J0..J0+NY-1 (0-based; I0,NX for a profile)"},
    OptionSpec{"invalid", &SolveOptions::invalid, Kind::text, kPreparation, "MODE",
               "invalid (masked or NaN) points: refuse, fill (harmonic) or crop (largest valid rectangle) [refuse]"},
    OptionSpec{"detrend", &SolveOptions::detrend, Kind::text, kPreparation, "MODE",
               "subtract a least-squares fit: none, mean, plane or curvature [none]"},
    OptionSpec{"pad", &SolveOptions::pad, Kind::number, kPreparation, "FACTOR",
               "free boundary only: embed the map in a FACTOR times larger grid at its lowest height [1]"},
    OptionSpec{"geometry", &SolveOptions::geometry, Kind::text, kSurface, "SHAPE",
               "built-in surface: sphere, cylinder, flat or wavy"},
    OptionSpec{"radius", &SolveOptions::radius, Kind::number, kSurface, "M", "sphere or cylinder radius (m)"},
    OptionSpec{"wavelength", &SolveOptions::wavelength, Kind::number, kSurface, "M", "wavy surface wavelength (m)"},
    OptionSpec{"amplitude", &SolveOptions::amplitude, Kind::number, kSurface, "M",
               "wavy surface amplitude A (m): h = -A (1 - cos ...)"},
    OptionSpec{"grid", &SolveOptions::grid, Kind::dimensions, kGrid, "N|NXxNY",
               "cells of a built-in geometry: N (1D) or NXxNY (2D)"},
    OptionSpec{"size", &SolveOptions::size, Kind::dimensions, kGrid, "L|LXxLY",
               "domain size of a built-in geometry (m); spacing = L / N"},
    OptionSpec{"boundary", &SolveOptions::boundary, Kind::text, kGrid, "TYPE", "periodic or free [free]"},
    OptionSpec{"E1", &SolveOptions::e1, Kind::number, kMaterial, "PA", "Young's modulus of body 1 (Pa)"},
    OptionSpec{"nu1", &SolveOptions::nu1, Kind::number, kMaterial, "NU", "Poisson's ratio of body 1"},
    OptionSpec{"E2", &SolveOptions::e2, Kind::number, kMaterial, "PA", "Young's modulus of body 2 (Pa)"},
    OptionSpec{"nu2", &SolveOptions::nu2, Kind::number, kMaterial, "NU", "Poisson's ratio of body 2"},
    OptionSpec{"E-star", &SolveOptions::e_star, Kind::number, kMaterial, "PA",
               "composite modulus E* (Pa), instead of E1, nu1, E2, nu2"},
    // Coated half-space (docs/usage.md#coated-half-space).
    OptionSpec{"layer-thickness", &SolveOptions::layer_thickness, Kind::number, kCoating, "M",
               "thickness t of the elastic layer bonded to the substrate (m)"},
    OptionSpec{"layer-E", &SolveOptions::layer_e, Kind::number, kCoating, "PA", "Young's modulus of the layer (Pa)"},
    OptionSpec{"layer-nu", &SolveOptions::layer_nu, Kind::number, kCoating, "NU", "Poisson's ratio of the layer"},
    OptionSpec{"substrate-E", &SolveOptions::substrate_e, Kind::number, kCoating, "PA",
               "Young's modulus of the substrate (Pa)"},
    OptionSpec{"substrate-nu", &SolveOptions::substrate_nu, Kind::number, kCoating, "NU",
               "Poisson's ratio of the substrate"},
    // Hardness cap (elastic-perfectly plastic surface, docs/theory.md#hardness-cap).
    OptionSpec{"hardness", &SolveOptions::hardness, Kind::number, kInterface, "PA",
               "hardness H (Pa): caps the pressure at H, cells at the cap flow plastically (every solver but lemke) "
               "[none: elastic]"},
    OptionSpec{"force", &SolveOptions::force, Kind::numbers, kLoad, "F",
               "total normal force: N (2D) or N/m (1D); a list F1,F2,... or a log range START:STOP:COUNT "
               "solves a sweep, each step warm-started from the previous one"},
    OptionSpec{"mean-pressure", &SolveOptions::mean_pressure, Kind::numbers, kLoad, "PA",
               "force over the domain area (Pa); a list or START:STOP:COUNT makes a sweep"},
    OptionSpec{"approach", &SolveOptions::approach, Kind::numbers, kLoad, "M",
               "imposed rigid-body approach (m): displacement control; a list or START:STOP:COUNT makes a sweep"},
    OptionSpec{
        "solver", &SolveOptions::solver, Kind::text, kSolver, "NAME",
        "contact solver: pk-multilevel (pk-fourier started from coarser grids), pk-fourier (Polonsky-Keer with "
        "Fourier preconditioner), pk (plain Polonsky-Keer), "
        "lemke (Lemke pivoting, dense, small grids), lcpquad (the paper's QP, dense, small grids) [pk-multilevel]"},
    OptionSpec{"tol", &SolveOptions::tol, Kind::number, kSolver, "X", "relative residual tolerance [1e-10]"},
    OptionSpec{"max-iter", &SolveOptions::max_iter, Kind::integer, kSolver, "N", "iteration limit [10000]"},
    OptionSpec{"threads", &SolveOptions::threads, Kind::integer, kSolver, "N",
               "threads for loops and FFTs [all cores]"},
    OptionSpec{"fft-planning", &SolveOptions::fft_planning, Kind::text, kSolver, "MODE",
               "FFTW planning effort: estimate, measure or patient [measure]"},
    OptionSpec{"deflation-block", &SolveOptions::deflation_block, Kind::integer, kSolver, "B",
               "coarse-grid correction on B x B blocks of the contact (pk-fourier, pk-multilevel's finest grid; "
               "2D grids whose nx and ny B divides, at least 3 blocks per axis); 0 for none "
               "[32 with pk-multilevel on grids of 2048^2 cells or more where it applies, else none]"},
    OptionSpec{"max-memory", &SolveOptions::max_memory, Kind::memory, kSolver, "SIZE",
               "refuse to start when the run's estimated peak memory exceeds SIZE: bytes, or K, M, G, T (powers of "
               "1024), e.g. 512M or 8G [the memory available: MemAvailable, or a cgroup's limit if lower]"},
    // Subsurface stresses: the /stress group of the result file.
    OptionSpec{"stress-depths", &SolveOptions::stress_depths, Kind::text, kStress, "LIST|START:STOP:COUNT",
               "also write the stresses below the contact at these depths (m, > 0): z1,z2,... or COUNT evenly "
               "spaced from START to STOP"},
    OptionSpec{"stress-nu", &SolveOptions::stress_nu, Kind::number, kStress, "NU",
               "Poisson's ratio of the body whose stresses are wanted [nu1 when --nu1 and --nu2 are equal]"},
    // Adhesion.
    OptionSpec{"adhesion", &SolveOptions::adhesion, Kind::text, kAdhesion, "LAW",
               "cohesive law: md (Maugis-Dugdale: stress sigma0 = w/h0 where 0 <= gap < h0) or exponential "
               "(traction -(w/rho) exp(-gap/rho)); solved by the adhesive solver (adhesive-spg) [none]"},
    OptionSpec{"work-of-adhesion", &SolveOptions::work_of_adhesion, Kind::number, kAdhesion, "W",
               "work of adhesion w (J/m^2), required with --adhesion"},
    OptionSpec{"adhesion-range", &SolveOptions::adhesion_range, Kind::number, kAdhesion, "M",
               "range of the law (m): h0 for md, rho for exponential; or --adhesion-stress for md"},
    OptionSpec{"adhesion-stress", &SolveOptions::adhesion_stress, Kind::number, kAdhesion, "PA",
               "md only: the Dugdale stress sigma0 (Pa) instead of --adhesion-range (h0 = w / sigma0)"},
    OptionSpec{"adhesion-precondition", &SolveOptions::adhesion_precondition, Kind::text, kAdhesion, "on|off",
               "on: the adhesive solver runs conjugate gradients preconditioned by the compliance (far fewer "
               "iterations on rough md contacts; docs/solvers.md); off: spectral projected gradients [off]"},
    OptionSpec{"output", &SolveOptions::output, Kind::path, kOutput, "FILE",
               "result file (HDF5), required; replaced if it exists"},
    OptionSpec{"quiet", &SolveOptions::quiet, Kind::flag, kOutput, "",
               "print nothing unless there is an error (no summary, no progress line)"},
    OptionSpec{"plot", &SolveOptions::plot, Kind::flag, kOutput, "",
               "draw PNG figures next to the output with scripts/halfspace_plot.py (maps; sweep curves)"},
};

// Options that exclude each other. Choosing an alternative on the command
// line (by one of its selectors) makes the config file's keys of the *other*
// alternatives of its group be ignored, so that `--approach 1e-6` overrides a
// file that sets `force`, and `--geometry` a file that sets `height-map` and
// `dx`. The surface is chosen only by its selectors: `--grid` alone must not
// silently drop a file's height map, it must be reported as a conflict.
struct Alternative {
  std::vector<std::string_view> selectors;  // keys that choose this alternative
  std::vector<std::string_view> keys;       // every key that belongs to it
};

const std::vector<std::vector<Alternative>> kAlternatives{
    {{{"force"}, {"force"}}, {{"mean-pressure"}, {"mean-pressure"}}, {{"approach"}, {"approach"}}},
    {{{"E-star"}, {"E-star"}},
     {{"E1", "nu1", "E2", "nu2"}, {"E1", "nu1", "E2", "nu2"}},
     {{"layer-thickness", "layer-E", "layer-nu", "substrate-E", "substrate-nu"},
      {"layer-thickness", "layer-E", "layer-nu", "substrate-E", "substrate-nu"}}},
    {{{"height-map"}, {"height-map", "dataset", "dx", "dy", "format", "unit", "window", "invalid", "detrend", "pad"}},
     {{"geometry"}, {"geometry", "radius", "wavelength", "amplitude", "grid", "size"}}},
};

const OptionSpec* find_spec(std::string_view key) {
  for (const OptionSpec& spec : kOptions) {
    if (spec.key == key) return &spec;
  }
  return nullptr;
}

bool is_set(const SolveOptions& options, const OptionSpec& spec) {
  return std::visit(
      [&](auto member) -> bool {
        if constexpr (std::is_same_v<decltype(member), bool SolveOptions::*>) {
          return options.*member;
        } else {
          return (options.*member).has_value();
        }
      },
      spec.field);
}

bool excluded_by(std::string_view key, const std::set<std::string, std::less<>>& given) {
  for (const auto& group : kAlternatives) {
    for (const Alternative& own : group) {
      if (std::find(own.keys.begin(), own.keys.end(), key) == own.keys.end()) continue;
      for (const Alternative& other : group) {
        if (&other == &own) continue;
        for (std::string_view selector : other.selectors) {
          if (given.contains(selector)) return true;
        }
      }
    }
  }
  return false;
}

// Stores a command-line value after converting it to the option's type.
void set_from_text(SolveOptions& options, const OptionSpec& spec, const std::string& text) {
  options.text.insert_or_assign(std::string(spec.key), text);
  const std::string what = options.describe(spec.key);
  switch (spec.kind) {
    case Kind::number:
      options.*std::get<std::optional<double> SolveOptions::*>(spec.field) = parse_number(text, what);
      break;
    case Kind::numbers:
      options.*std::get<std::optional<std::vector<double>> SolveOptions::*>(spec.field) = parse_number_list(text, what);
      break;
    case Kind::integer:
      options.*std::get<std::optional<long long> SolveOptions::*>(spec.field) = parse_integer(text, what);
      break;
    case Kind::text:
    case Kind::path:
    case Kind::dimensions:
    case Kind::memory:
      options.*std::get<std::optional<std::string> SolveOptions::*>(spec.field) = text;
      break;
    case Kind::flag:
      options.*std::get<bool SolveOptions::*>(spec.field) = true;
      break;
  }
}

std::string_view toml_type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a float";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    default:
      return "a date or time";
  }
}

// A config value as it would be written in the file, for error messages.
std::string toml_text(const toml::node& node) {
  if (const toml::array* array = node.as_array()) {
    std::string text = "[";
    for (std::size_t k = 0; k < array->size(); ++k) text += (k == 0 ? "" : ", ") + toml_text(*array->get(k));
    return text + "]";
  }
  if (node.is_string()) return fmt::format("\"{}\"", *node.value<std::string>());
  if (node.is_integer()) return fmt::format("{}", *node.value<long long>());
  if (node.is_floating_point()) return fmt::format("{}", *node.value<double>());
  if (node.is_boolean()) return *node.value<bool>() ? "true" : "false";
  return std::string(toml_type_name(node));
}

// Stores a config file value after checking its TOML type.
void set_from_toml(SolveOptions& options, const OptionSpec& spec, const toml::node& node,
                   const std::filesystem::path& file) {
  const auto wrong_type = [&](std::string_view expected) {
    return InputError(fmt::format("key '{}' in config file {} must be {} (got {})", spec.key, file.string(), expected,
                                  toml_type_name(node)));
  };
  switch (spec.kind) {
    case Kind::number: {
      if (!node.is_number()) throw wrong_type("a number");
      options.*std::get<std::optional<double> SolveOptions::*>(spec.field) = *node.value<double>();
      break;
    }
    case Kind::numbers: {
      const std::string what = fmt::format("{} = {} in {}", spec.key, toml_text(node), file.string());
      std::vector<double> values;
      if (node.is_number()) {
        values.push_back(*node.value<double>());
      } else if (node.is_string()) {
        values = parse_number_list(*node.value<std::string>(), what);
      } else if (const toml::array* array = node.as_array(); array != nullptr && !array->empty()) {
        for (const toml::node& element : *array) {
          if (!element.is_number())
            throw wrong_type("a number, an array of numbers or a string such as \"1e5:1e7:10\"");
          values.push_back(*element.value<double>());
        }
      } else {
        throw wrong_type("a number, an array of numbers or a string such as \"1e5:1e7:10\"");
      }
      options.*std::get<std::optional<std::vector<double>> SolveOptions::*>(spec.field) = values;
      break;
    }
    case Kind::integer: {
      if (!node.is_integer()) throw wrong_type("an integer");
      options.*std::get<std::optional<long long> SolveOptions::*>(spec.field) = *node.value<long long>();
      break;
    }
    case Kind::text:
    case Kind::path: {
      if (!node.is_string()) throw wrong_type("a string");
      std::string text = *node.value<std::string>();
      const std::filesystem::path relative_to = file.parent_path();
      if (spec.kind == Kind::path && !text.empty() && std::filesystem::path(text).is_relative() &&
          !relative_to.empty()) {
        text = (relative_to / text).string();
      }
      options.*std::get<std::optional<std::string> SolveOptions::*>(spec.field) = text;
      break;
    }
    case Kind::dimensions: {
      std::string text;
      if (node.is_string()) {
        text = *node.value<std::string>();
      } else if (node.is_integer()) {
        text = fmt::format("{}", *node.value<long long>());
      } else if (node.is_floating_point()) {
        text = fmt::format("{}", *node.value<double>());  // shortest form that reads back exactly
      } else {
        throw wrong_type("a number or a string such as \"256x256\"");
      }
      options.*std::get<std::optional<std::string> SolveOptions::*>(spec.field) = text;
      break;
    }
    case Kind::memory: {
      std::string text;
      if (node.is_string()) {
        text = *node.value<std::string>();
      } else if (node.is_integer()) {
        text = fmt::format("{}", *node.value<long long>());
      } else {
        throw wrong_type("a string such as \"8G\" or a whole number of bytes");
      }
      options.*std::get<std::optional<std::string> SolveOptions::*>(spec.field) = text;
      break;
    }
    case Kind::flag: {
      if (!node.is_boolean()) throw wrong_type("true or false");
      options.*std::get<bool SolveOptions::*>(spec.field) = *node.value<bool>();
      break;
    }
  }
}

// "E_star" -> "E-star": the spellings people try first for a key that exists.
std::string unknown_key_message(std::string_view key, const std::filesystem::path& file) {
  std::string message = fmt::format("unknown key '{}' in config file {}", key, file.string());
  if (key == "config") {
    return message + " (a config file cannot name another one)";
  }
  for (const OptionSpec& spec : kOptions) {
    if (spec.key.size() != key.size()) continue;
    bool similar = true;
    for (std::size_t k = 0; k < key.size() && similar; ++k) {
      const auto fold = [](char c) {
        c = c == '_' ? '-' : c;
        return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
      };
      similar = fold(key[k]) == fold(spec.key[k]);
    }
    if (similar) return message + fmt::format(" (did you mean '{}'?)", spec.key);
  }
  return message + " (the keys are the long option names of 'halfspace solve' without '--')";
}

constexpr std::size_t kMaxConfigBytes = std::size_t{1} << 20;

std::string read_text_file(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    throw FileError(fmt::format("config file {} does not exist", path.string()));
  }
  if (std::filesystem::is_directory(path, error)) {
    throw FileError(fmt::format("config file {} is a directory", path.string()));
  }
  // A config file holds a few options: read at most kMaxConfigBytes (plus
  // one to tell), so that /dev/zero or a huge file cannot exhaust memory.
  std::ifstream in(path, std::ios::binary);
  std::string text;
  std::array<char, 1 << 16> piece{};
  while (in && text.size() <= kMaxConfigBytes) {
    in.read(piece.data(), static_cast<std::streamsize>(piece.size()));
    text.append(piece.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad() || (!in.eof() && text.size() <= kMaxConfigBytes)) {
    throw FileError(fmt::format("config file {} cannot be read", path.string()));
  }
  if (text.size() > kMaxConfigBytes) {
    throw FileError(fmt::format("config file {} is larger than {} bytes (1 MiB); a config file holds a few options",
                                path.string(), kMaxConfigBytes));
  }
  return text;
}

}  // namespace

std::string SolveOptions::describe(std::string_view key) const {
  const auto found = text.find(key);
  const std::string_view value = found == text.end() ? std::string_view() : std::string_view(found->second);
  if (from_config.contains(key)) {
    return fmt::format("{} = {} in {}", key, value, config.value_or(""));
  }
  return fmt::format("--{} {}", key, value);
}

std::string SolveOptions::name(std::string_view key) const {
  if (from_config.contains(key)) {
    return fmt::format("{} (in {})", key, config.value_or(""));
  }
  return fmt::format("--{}", key);
}

void add_solve_options(CLI::App& solve) {
  solve.add_option("--config")
      ->type_name("FILE")
      ->description(
          "TOML file of options: keys are the long option names without '--' "
          "(e.g. E-star = 1e11); options given on the command line override it");
  for (const OptionSpec& spec : kOptions) {
    const std::string flag = fmt::format("--{}", spec.key);
    CLI::Option* option = spec.kind == Kind::flag ? solve.add_flag(flag) : solve.add_option(flag);
    option->description(std::string(spec.help));
    option->group(std::string(spec.group));
    if (spec.kind != Kind::flag) option->type_name(std::string(spec.value_name));
  }
}

SolveOptions solve_options_from_command_line(const CLI::App& solve, const std::vector<std::string>& argv) {
  SolveOptions options;
  options.command_line = join_command_line(argv);
  if (const CLI::Option* config = solve.get_option("--config"); config->count() > 0) {
    options.config = config->as<std::string>();
  }
  for (const OptionSpec& spec : kOptions) {
    const CLI::Option* option = solve.get_option(fmt::format("--{}", spec.key));
    if (option->count() == 0) continue;
    set_from_text(options, spec, spec.kind == Kind::flag ? std::string() : option->as<std::string>());
  }
  return options;
}

void merge_config_file(SolveOptions& options) {
  if (!options.config) return;
  const std::filesystem::path file = *options.config;
  options.config_text = read_text_file(file);

  toml::table table;
  try {
    table = toml::parse(options.config_text, file.string());
  } catch (const toml::parse_error& error) {
    throw InputError(fmt::format("config file {} is not valid TOML: {} (line {}, column {})", file.string(),
                                 error.description(), error.source().begin.line, error.source().begin.column));
  }

  std::set<std::string, std::less<>> given;
  for (const OptionSpec& spec : kOptions) {
    if (is_set(options, spec)) given.emplace(spec.key);
  }
  for (auto&& [key, node] : table) {
    const OptionSpec* spec = find_spec(key.str());
    if (spec == nullptr) throw InputError(unknown_key_message(key.str(), file));
    if (given.contains(spec->key) || excluded_by(spec->key, given)) continue;
    set_from_toml(options, *spec, node, file);
    options.from_config.emplace(spec->key);
    options.text.insert_or_assign(std::string(spec->key), toml_text(node));
  }
}

}  // namespace halfspace::app
