// Turns the options as given into a checked SolveSetup. The checks run in the
// order a reader scans the command line (surface, material, load, solver,
// output) and the height map is read last, so cheap mistakes are found first.
#include "solve_setup.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/io/height_map_reader.hpp"
#include "halfspace/material.hpp"
#include "halfspace/surface/padding.hpp"
#include "halfspace/surface/preparation.hpp"
#include "value_parsing.hpp"

namespace halfspace::app {
namespace {

namespace fs = std::filesystem;

// Keys paired with whether they were given.
using Presence = std::initializer_list<std::pair<std::string_view, bool>>;

std::vector<std::string> given_names(const SolveOptions& options, Presence keys) {
  std::vector<std::string> names;
  for (const auto& [key, given] : keys) {
    if (given) names.push_back(options.name(key));
  }
  return names;
}

std::string join_names(const std::vector<std::string>& names) {
  return fmt::format("{}", fmt::join(names, ", "));
}

// Re-throws a library InputError with the option it came from in front.
template <class Function>
auto in_context(const std::string& context, Function&& function) {
  try {
    return function();
  } catch (const FileError&) {
    throw;
  } catch (const InputError& error) {
    throw InputError(fmt::format("{}: {}", context, error.what()));
  }
}

double require_positive(const SolveOptions& options, std::string_view key, double value, std::string_view unit) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InputError(fmt::format("{} is invalid: must be positive ({})", options.describe(key), unit));
  }
  return value;
}

void check_surface_choice(const SolveOptions& options) {
  if (options.height_map && options.geometry) {
    throw InputError(fmt::format("{} and {} cannot be combined: give exactly one surface", options.name("height-map"),
                                 options.name("geometry")));
  }
  if (!options.height_map && !options.geometry) {
    throw InputError("no surface given: pass --height-map FILE or --geometry sphere|cylinder|flat|wavy");
  }
}

double material_from(const SolveOptions& o) {
  const Presence constants{
      {"E1", o.e1.has_value()}, {"nu1", o.nu1.has_value()}, {"E2", o.e2.has_value()}, {"nu2", o.nu2.has_value()}};
  const std::vector<std::string> given = given_names(o, constants);
  if (o.e_star && !given.empty()) {
    throw InputError(fmt::format("{} cannot be combined with {}: give either E-star or all of E1, nu1, E2, nu2",
                                 o.name("E-star"), join_names(given)));
  }
  if (o.e_star) return checked_composite_modulus(*o.e_star);
  if (given.empty()) {
    throw InputError("no material given: pass --E-star, or --E1, --nu1, --E2 and --nu2");
  }
  if (given.size() < 4) {
    std::vector<std::string> missing;
    for (const auto& [key, present] : constants) {
      if (!present) missing.push_back(fmt::format("--{}", key));
    }
    throw InputError(
        fmt::format("incomplete material: missing {} (give all of E1, nu1, E2, nu2, or E-star)", join_names(missing)));
  }
  return composite_modulus({*o.e1, *o.nu1}, {*o.e2, *o.nu2});
}

// The load mode and every value of the load (one for a single solve, more for
// a sweep); a single value keeps the message "--force -1 is invalid: ...".
std::pair<Loading, std::vector<double>> loading_from(const SolveOptions& o) {
  const std::vector<std::string> given = given_names(o, {{"force", o.force.has_value()},
                                                         {"mean-pressure", o.mean_pressure.has_value()},
                                                         {"approach", o.approach.has_value()}});
  if (given.empty()) {
    throw InputError("no load given: pass one of --force, --mean-pressure, --approach");
  }
  if (given.size() > 1) {
    throw InputError(fmt::format("{} cannot be combined: give exactly one of --force, --mean-pressure, --approach",
                                 fmt::join(given, " and ")));
  }
  const auto [key, mode, unit, values] =
      o.force           ? std::tuple{"force", ControlMode::force, "N in 2D, N/m in 1D", *o.force}
      : o.mean_pressure ? std::tuple{"mean-pressure", ControlMode::mean_pressure, "Pa", *o.mean_pressure}
                        : std::tuple{"approach", ControlMode::approach, "m", *o.approach};
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (values.size() == 1) {
      require_positive(o, key, values[k], unit);
    } else if (!(std::isfinite(values[k]) && values[k] > 0.0)) {
      throw InputError(fmt::format("{} is invalid: every value must be positive ({}); value {} is {}", o.describe(key),
                                   unit, k + 1, values[k]));
    }
  }
  const Loading loading{mode, values.front()};
  loading.validate();
  return {loading, values};
}

// The solver flags mapped onto SolverOptions, whose validate() holds every
// rule; a broken one is restated with the flag (or config key) it came from.
template <class Function>
auto with_solver_flags(const SolveOptions& o, Function&& function) {
  try {
    return function();
  } catch (const solvers::SolverOptionError& error) {
    const std::string& option = error.option();
    const std::string_view key = option == "tolerance"             ? "tol"
                                 : option == "max_iterations"      ? "max-iter"
                                 : option.starts_with("deflation") ? "deflation-block"
                                                                   : "solver";
    throw InputError(fmt::format("{} {}", o.describe(key), error.rule()));
  }
}

solvers::SolverOptions solver_options_from(const SolveOptions& o) {
  solvers::SolverOptions solver;
  with_solver_flags(o, [&] {
    if (o.solver) solver.type = solvers::parse_solver_type(*o.solver);
    if (o.tol) solver.tolerance = *o.tol;
    // Beyond int, a limit is no limit: validate() sees the nearest int.
    if (o.max_iter) solver.max_iterations = static_cast<int>(std::clamp<long long>(*o.max_iter, INT_MIN, INT_MAX));
    if (o.deflation_block) {
      // 0 turns the correction off; a negative B wraps to a size validate() refuses.
      solver.deflation.mode =
          *o.deflation_block == 0 ? solvers::DeflationOptions::Mode::off : solvers::DeflationOptions::Mode::on;
      if (*o.deflation_block != 0) solver.deflation.block = static_cast<std::size_t>(*o.deflation_block);
    }
    solver.validate();
  });
  return solver;
}

int threads_from(const SolveOptions& o) {
  if (!o.threads) {
    return static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  }
  if (*o.threads < 1 || *o.threads > INT_MAX) {
    throw InputError(fmt::format("{} is invalid: need at least 1 thread", o.describe("threads")));
  }
  return static_cast<int>(*o.threads);
}

// The output is checked before solving so that a typo in the path does not
// cost a long solve; the writer itself is atomic, so no partial file appears.
fs::path output_from(const SolveOptions& o) {
  if (!o.output) {
    throw InputError("no output file given: pass --output FILE.h5");
  }
  const fs::path path = *o.output;
  const std::string what = o.describe("output");
  std::error_code error;
  if (path.empty()) {
    throw InputError(fmt::format("{} is invalid: the file name is empty", what));
  }
  if (fs::is_directory(path, error)) {
    throw FileError(fmt::format("{} is invalid: it is a directory, not a file", what));
  }
  const fs::path directory = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  if (!fs::exists(directory, error)) {
    throw FileError(fmt::format("{} is invalid: directory {} does not exist", what, directory.string()));
  }
  if (!fs::is_directory(directory, error)) {
    throw FileError(fmt::format("{} is invalid: {} is not a directory", what, directory.string()));
  }
  if (::access(directory.c_str(), W_OK) != 0) {
    throw FileError(fmt::format("{} is invalid: directory {} is not writable", what, directory.string()));
  }
  return path;
}

struct Surface {
  Grid grid;
  Eigen::ArrayXd heights;
  std::string source;
  std::vector<std::string> preparation;  // one line per preparation step of a height map
};

void reject_given(const SolveOptions& o, Presence keys, std::string_view reason) {
  const std::vector<std::string> given = given_names(o, keys);
  if (!given.empty()) {
    throw InputError(fmt::format("{} {}", given.front(), reason));
  }
}

Grid grid_for_geometry(const SolveOptions& o, Boundary boundary) {
  if (!o.grid) throw InputError("--geometry needs --grid N (1D) or NXxNY (2D)");
  if (!o.size) throw InputError("--geometry needs --size L or LXxLY (domain size in m)");
  const std::vector<std::size_t> cells = parse_grid_shape(*o.grid, o.describe("grid"));
  const std::vector<double> lengths = parse_domain_size(*o.size, o.describe("size"));
  if (cells.size() == 1) {
    if (lengths.size() != 1) {
      throw InputError(
          fmt::format("{} is invalid for the 1D grid {}: give one length", o.describe("size"), o.describe("grid")));
    }
    return Grid::line(cells[0], lengths[0] / static_cast<double>(cells[0]), boundary);
  }
  // One length on a 2D grid means a square domain.
  const double length_y = lengths.size() == 2 ? lengths[1] : lengths[0];
  return Grid::plane(cells[0], cells[1], lengths[0] / static_cast<double>(cells[0]),
                     length_y / static_cast<double>(cells[1]), boundary);
}

Surface builtin_surface(const SolveOptions& o, Boundary boundary) {
  reject_given(o,
               {{"dataset", o.dataset.has_value()},
                {"dx", o.dx.has_value()},
                {"dy", o.dy.has_value()},
                {"format", o.format.has_value()},
                {"unit", o.unit.has_value()},
                {"window", o.window.has_value()},
                {"invalid", o.invalid.has_value()},
                {"detrend", o.detrend.has_value()},
                {"pad", o.pad.has_value()}},
               "applies only to --height-map; a built-in geometry takes its spacing from --grid and --size");
  geometry::SurfaceSpec spec;
  spec.shape = in_context(o.name("geometry"), [&] { return geometry::parse_surface_shape(*o.geometry); });
  const std::string shape_name = o.describe("geometry");
  const auto require = [&](std::string_view key, const std::optional<double>& value) {
    if (!value) throw InputError(fmt::format("{} needs --{} (m)", shape_name, key));
    return require_positive(o, key, *value, "m");
  };
  const auto unused = [&](Presence keys) { reject_given(o, keys, fmt::format("does not apply to {}", shape_name)); };
  std::string source = std::string(geometry::to_string(spec.shape));
  switch (spec.shape) {
    case geometry::SurfaceShape::sphere:
    case geometry::SurfaceShape::cylinder:
      unused({{"wavelength", o.wavelength.has_value()}, {"amplitude", o.amplitude.has_value()}});
      spec.radius = require("radius", o.radius);
      source += fmt::format(" (radius = {} m)", spec.radius);
      break;
    case geometry::SurfaceShape::wavy:
      unused({{"radius", o.radius.has_value()}});
      spec.wavelength = require("wavelength", o.wavelength);
      spec.amplitude = require("amplitude", o.amplitude);
      source += fmt::format(" (wavelength = {} m, amplitude = {} m)", spec.wavelength, spec.amplitude);
      break;
    case geometry::SurfaceShape::flat:
      unused({{"radius", o.radius.has_value()},
              {"wavelength", o.wavelength.has_value()},
              {"amplitude", o.amplitude.has_value()}});
      break;
  }
  Grid grid = grid_for_geometry(o, boundary);
  Eigen::ArrayXd heights = geometry::make_surface_heights(grid, spec);
  return {std::move(grid), std::move(heights), std::move(source), {}};
}

// The spacing along one axis: the option if given, else the file attribute
// (0 when the file has none; the reader rejects negative ones).
std::optional<double> height_map_spacing(const SolveOptions& o, std::string_view key,
                                         const std::optional<double>& option, double attribute) {
  if (option) return require_positive(o, key, *option, "m");
  if (attribute > 0.0) return attribute;
  return std::nullopt;
}

// Both spacings are named at once when both are missing, so one retry suffices.
void require_spacings(const std::string& file, const std::vector<std::string_view>& missing) {
  if (missing.empty()) return;
  std::vector<std::string> flags;
  for (std::string_view key : missing) flags.push_back(fmt::format("--{}", key));
  throw FileError(fmt::format("height map {} does not state its spacing {}: pass {} (m)", file,
                              fmt::join(missing, " and "), fmt::join(flags, " and ")));
}

io::ReadOptions read_options_from(const SolveOptions& o) {
  io::ReadOptions read;
  if (o.format) read.format = in_context(o.name("format"), [&] { return io::parse_height_map_format(*o.format); });
  if (o.dataset) read.dataset = *o.dataset;
  if (o.unit) read.unit = in_context(o.name("unit"), [&] { return io::require_length_unit(*o.unit, "unit"); });
  return read;
}

surface::PreparationOptions preparation_from(const SolveOptions& o, Boundary boundary) {
  surface::PreparationOptions prepare;
  if (o.window) prepare.window = in_context(o.name("window"), [&] { return surface::parse_window(*o.window); });
  if (o.invalid) {
    prepare.invalid = in_context(o.name("invalid"), [&] { return surface::parse_invalid_points(*o.invalid); });
  }
  if (o.detrend) prepare.detrend = in_context(o.name("detrend"), [&] { return surface::parse_detrend(*o.detrend); });
  if (o.pad) {
    if (boundary == Boundary::periodic) {
      throw InputError(
          fmt::format("{} cannot be combined with --boundary periodic: padding is for free boundaries "
                      "(a periodic surface repeats without a margin)",
                      o.describe("pad")));
    }
    if (o.mean_pressure) {
      throw InputError(
          fmt::format("{} cannot be combined with {}: the mean pressure would be taken over the padded "
                      "area; give --force instead",
                      o.describe("pad"), o.name("mean-pressure")));
    }
    if (!(*o.pad >= surface::kMinPadFactor && *o.pad <= surface::kMaxPadFactor)) {
      throw InputError(fmt::format("{} is invalid: the factor must be in [{}, {}]", o.describe("pad"),
                                   surface::kMinPadFactor, surface::kMaxPadFactor));
    }
    prepare.pad_factor = *o.pad;
  }
  return prepare;
}

Surface height_map_surface(const SolveOptions& o, Boundary boundary) {
  reject_given(o,
               {{"radius", o.radius.has_value()},
                {"wavelength", o.wavelength.has_value()},
                {"amplitude", o.amplitude.has_value()},
                {"grid", o.grid.has_value()},
                {"size", o.size.has_value()}},
               "cannot be used with --height-map: the grid and its spacing come from the file");
  const std::string& file = *o.height_map;
  const io::ReadOptions read = read_options_from(o);
  const surface::PreparationOptions prepare = preparation_from(o, boundary);
  io::HeightMap map = io::read_height_map(file, read);
  std::string source = map.source.empty() ? file : map.source;

  const std::optional<double> dx = height_map_spacing(o, "dx", o.dx, map.dx);
  std::optional<double> dy;
  if (map.dimension == 1) {
    if (o.dy) throw InputError(fmt::format("{} does not apply to the 1D profile in {}", o.name("dy"), file));
    require_spacings(file, dx ? std::vector<std::string_view>{} : std::vector<std::string_view>{"dx"});
  } else {
    dy = height_map_spacing(o, "dy", o.dy, map.dy);
    std::vector<std::string_view> missing;
    if (!dx) missing.push_back("dx");
    if (!dy) missing.push_back("dy");
    require_spacings(file, missing);
  }
  map.dx = *dx;
  map.dy = dy.value_or(0.0);

  try {
    surface::prepare_height_map(map, prepare);
  } catch (const FileError& error) {
    // Only the refusal of invalid points is a FileError here: say how to proceed.
    throw FileError(fmt::format("{} (pass --invalid fill or --invalid crop)", error.what()));
  }
  Grid grid =
      map.dimension == 1 ? Grid::line(map.nx, map.dx, boundary) : Grid::plane(map.nx, map.ny, map.dx, map.dy, boundary);
  return {std::move(grid), std::move(map.heights), std::move(source), std::move(map.preparation)};
}

}  // namespace

SolveSetup make_solve_setup(const SolveOptions& options) {
  check_surface_choice(options);
  const double e_star = material_from(options);
  auto [loading, load_values] = loading_from(options);
  solvers::SolverOptions solver = solver_options_from(options);
  const int threads = threads_from(options);
  if (options.fft_planning) {
    solver.fft_planning =
        in_context(options.name("fft-planning"), [&] { return parse_fft_planning(*options.fft_planning); });
  }
  const Boundary boundary =
      in_context(options.name("boundary"), [&] { return parse_boundary(options.boundary.value_or("free")); });
  fs::path output = output_from(options);

  Surface surface = options.geometry ? builtin_surface(options, boundary) : height_map_surface(options, boundary);
  if (static_cast<std::size_t>(surface.heights.size()) != surface.grid.size()) {
    throw InputError(fmt::format("surface {} has {} heights for a {} grid", surface.source, surface.heights.size(),
                                 surface.grid.shape_string()));
  }
  with_solver_flags(options, [&] { solver.validate(surface.grid); });
  return SolveSetup{std::move(surface.grid),
                    std::move(surface.heights),
                    std::move(surface.source),
                    std::move(surface.preparation),
                    e_star,
                    loading,
                    std::move(solver),
                    threads,
                    std::move(output),
                    options.quiet,
                    options.command_line,
                    options.config_text,
                    std::move(load_values),
                    options.plot};
}

}  // namespace halfspace::app
