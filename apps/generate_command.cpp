// The generate command: options -> surface spec -> heights -> height-map file.
// Options are read as text and parsed strictly (value_parsing.hpp), so the
// messages match those of `solve`.
#include "generate_command.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "activity.hpp"
#include "exit_codes.hpp"
#include "grid_options.hpp"
#include "halfspace/error.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/io/height_map_writer.hpp"
#include "halfspace/io/output_file.hpp"
#include "halfspace/memory_estimate.hpp"
#include "halfspace/surface/self_affine.hpp"
#include "halfspace/surface/statistics.hpp"
#include "halfspace/version.hpp"
#include "memory_check.hpp"
#include "physical_ranges.hpp"
#include "value_parsing.hpp"

namespace halfspace::app {
namespace {

// Every option but --quiet, as written; absent when not given.
using GivenOptions = std::map<std::string, std::string, std::less<>>;

struct OptionHelp {
  const char* key;
  const char* value_name;
  const char* help;
};

constexpr OptionHelp kOptions[] = {
    {"kind", "KIND", "self-affine, sphere, cylinder, wavy or flat (required)"},
    {"grid", "N|NXxNY", "cells: N (1D profile) or NXxNY (2D map), at least 2 per axis (required)"},
    {"size", "L|LXxLY", "domain size (m); spacing = L / N (required)"},
    {"hurst", "H", "self-affine: Hurst exponent in (0, 1] [0.8]"},
    {"cutoff-short", "M", "self-affine: shortest wavelength (m) [2 max(dx, dy)]"},
    {"rolloff", "M", "self-affine: the power law holds below this wavelength, flat above (m) [cutoff-long]"},
    {"cutoff-long", "M", "self-affine: longest wavelength (m) [the domain's longer side]"},
    {"rms-height", "M", "self-affine: rms height about the mean (m); exactly one of rms-height, rms-slope"},
    {"rms-slope", "X", "self-affine: rms of the gradient magnitude, sqrt(<|grad h|^2>) (spectral)"},
    {"seed", "N", "self-affine: random seed, 0 to 2^63-1 [0]; same seed, same surface"},
    {"radius", "M", "sphere, cylinder: radius (m)"},
    {"wavelength", "M", "wavy: wavelength (m)"},
    {"amplitude", "M", "wavy: amplitude A (m), h = -A (1 - cos ...)"},
    {"output", "FILE", "the height-map file (HDF5), required; replaced if it exists"},
    {"max-memory", "SIZE",
     "refuse to start when the estimated peak memory exceeds SIZE: bytes, or K, M, G, T (powers of 1024), e.g. "
     "512M [the memory available]"},
};

constexpr const char* kSelfAffineKeys[] = {"hurst",      "cutoff-short", "rolloff", "cutoff-long",
                                           "rms-height", "rms-slope",    "seed"};

struct Generated {
  Grid grid;
  Eigen::ArrayXd heights;
  io::HeightMapMetadata metadata;
};

std::string describe(const GivenOptions& given, std::string_view key) {
  return fmt::format("--{} {}", key, given.find(key)->second);
}

std::optional<double> number(const GivenOptions& given, std::string_view key) {
  const auto found = given.find(key);
  if (found == given.end()) return std::nullopt;
  return parse_number(found->second, describe(given, key));
}

// A length option of a built-in shape, within the program's range of lengths.
double length(const GivenOptions& given, std::string_view key) {
  const std::optional<double> value = number(given, key);
  if (!value) throw InputError(fmt::format("--kind {} needs --{} (m)", given.find("kind")->second, key));
  if (!(*value > 0.0)) throw InputError(fmt::format("{} is invalid: must be positive (m)", describe(given, key)));
  return require_in_range(describe(given, key), *value, kMinLength, kMaxLength, "m");
}

void reject(const GivenOptions& given, std::initializer_list<const char*> keys, std::string_view reason) {
  for (const char* key : keys) {
    if (given.contains(key)) throw InputError(fmt::format("--{} {}", key, reason));
  }
}

// The grid, once its generation is known to fit in memory.
Grid grid_from(const GivenOptions& given, Boundary boundary) {
  if (!given.contains("grid")) throw InputError("no grid given: pass --grid N (1D) or NXxNY (2D)");
  if (!given.contains("size")) throw InputError("no domain size given: pass --size L or LXxLY (m)");
  Grid grid = grid_from_options(given.find("grid")->second, describe(given, "grid"), given.find("size")->second,
                                describe(given, "size"), boundary);
  const auto max_memory = given.find("max-memory");
  const std::optional<MemoryLimit> limit =
      memory_limit(max_memory == given.end() ? std::nullopt : std::optional<std::string>(max_memory->second),
                   max_memory == given.end() ? std::string("--max-memory") : describe(given, "max-memory"));
  require_memory(fmt::format("{}: generating {} cells", describe(given, "grid"), grid.size()),
                 generate_memory_estimate(grid), limit);
  return grid;
}

Generated self_affine(const GivenOptions& given) {
  reject(given, {"radius", "wavelength", "amplitude"}, "does not apply to --kind self-affine");
  surface::SelfAffineSpec spec;
  spec.hurst = number(given, "hurst").value_or(spec.hurst);
  spec.short_cutoff = number(given, "cutoff-short").value_or(0.0);
  spec.rolloff = number(given, "rolloff").value_or(0.0);
  spec.long_cutoff = number(given, "cutoff-long").value_or(0.0);
  for (const char* key : {"cutoff-short", "rolloff", "cutoff-long", "rms-height"}) {
    if (given.contains(key) && !(*number(given, key) > 0.0)) {
      throw InputError(fmt::format("{} is invalid: must be positive (m)", describe(given, key)));
    }
    if (given.contains(key)) require_in_range(describe(given, key), *number(given, key), kMinLength, kMaxLength, "m");
  }
  spec.rms_height = number(given, "rms-height");
  spec.rms_slope = number(given, "rms-slope");
  if (spec.rms_height && spec.rms_slope) {
    throw InputError("--rms-height and --rms-slope cannot be combined: give exactly one");
  }
  if (!spec.rms_height && !spec.rms_slope) {
    throw InputError("--kind self-affine needs --rms-height (m) or --rms-slope");
  }
  if (const auto found = given.find("seed"); found != given.end()) {
    const long long seed = parse_integer(found->second, describe(given, "seed"));
    if (seed < 0) throw InputError(fmt::format("{} is invalid: the seed must be 0 or more", describe(given, "seed")));
    spec.seed = static_cast<std::uint64_t>(seed);
  }

  Grid grid = grid_from(given, Boundary::periodic);
  const Activity activity(fmt::format("generating the self-affine surface on the {} grid", grid.shape_string()));
  const surface::SelfAffineSpec resolved = spec.resolved(grid);
  Eigen::ArrayXd heights = surface::make_self_affine_surface(grid, spec);
  io::HeightMapMetadata metadata;
  metadata.periodic = true;
  metadata.source = fmt::format(
      "self-affine (H = {}, cutoff-short = {} m, rolloff = {} m, cutoff-long = {} m, {} = {}, seed = {})",
      resolved.hurst, resolved.short_cutoff, resolved.rolloff, resolved.long_cutoff,
      spec.rms_height ? "rms-height" : "rms-slope", spec.rms_height ? *spec.rms_height : *spec.rms_slope, spec.seed);
  metadata.strings = {{"generator", "self-affine"}};
  metadata.numbers = {{"hurst", resolved.hurst},
                      {"cutoff_short", resolved.short_cutoff},
                      {"rolloff", resolved.rolloff},
                      {"cutoff_long", resolved.long_cutoff}};
  metadata.integers = {{"seed", static_cast<std::int64_t>(spec.seed)}};
  return {std::move(grid), std::move(heights), std::move(metadata)};
}

// Whether a wavy surface fits the domain a whole number of times per axis.
bool whole_periods(const Grid& grid, double wavelength) {
  const auto whole = [&](double length) {
    const double periods = length / wavelength;
    return std::abs(periods - std::round(periods)) <= 1e-9 * std::max(1.0, periods);
  };
  const bool x = whole(static_cast<double>(grid.nx()) * grid.dx());
  return grid.dimension() == 1 ? x : x && whole(static_cast<double>(grid.ny()) * grid.dy());
}

Generated builtin(const GivenOptions& given, geometry::SurfaceShape shape) {
  const std::string kind = given.find("kind")->second;
  for (const char* key : kSelfAffineKeys) {
    if (given.contains(key)) throw InputError(fmt::format("--{} does not apply to --kind {}", key, kind));
  }
  geometry::SurfaceSpec spec;
  spec.shape = shape;
  std::string source(geometry::to_string(shape));
  switch (shape) {
    case geometry::SurfaceShape::sphere:
    case geometry::SurfaceShape::cylinder:
      reject(given, {"wavelength", "amplitude"}, fmt::format("does not apply to --kind {}", kind));
      spec.radius = length(given, "radius");
      source += fmt::format(" (radius = {} m)", spec.radius);
      break;
    case geometry::SurfaceShape::wavy:
      reject(given, {"radius"}, "does not apply to --kind wavy");
      spec.wavelength = length(given, "wavelength");
      spec.amplitude = length(given, "amplitude");
      source += fmt::format(" (wavelength = {} m, amplitude = {} m)", spec.wavelength, spec.amplitude);
      break;
    case geometry::SurfaceShape::flat:
      reject(given, {"radius", "wavelength", "amplitude"}, "does not apply to --kind flat");
      break;
  }
  // Only a wavy surface with whole periods repeats with the domain.
  Grid probe = grid_from(given, Boundary::free);
  const bool periodic = shape == geometry::SurfaceShape::wavy && whole_periods(probe, spec.wavelength);
  Grid grid = grid_from(given, periodic ? Boundary::periodic : Boundary::free);
  const Activity activity(fmt::format("generating the {} surface on the {} grid", kind, grid.shape_string()));
  Eigen::ArrayXd heights = geometry::make_surface_heights(grid, spec);
  io::HeightMapMetadata metadata;
  metadata.periodic = periodic;
  metadata.source = source;
  metadata.strings = {{"generator", std::string(geometry::to_string(shape))}};
  if (spec.radius > 0.0) metadata.numbers.emplace_back("radius", spec.radius);
  if (spec.wavelength > 0.0) metadata.numbers.emplace_back("wavelength", spec.wavelength);
  if (spec.amplitude > 0.0) metadata.numbers.emplace_back("amplitude", spec.amplitude);
  return {std::move(grid), std::move(heights), std::move(metadata)};
}

int run_generate(const GivenOptions& given, bool quiet, const std::vector<std::string>& argv) {
  if (!given.contains("kind")) {
    throw InputError("no surface kind given: pass --kind self-affine, sphere, cylinder, wavy or flat");
  }
  if (!given.contains("output")) throw InputError("no output file given: pass --output FILE.h5");
  // Refuse a device, FIFO or directory before generating, not after.
  io::check_output_path(given.find("output")->second);
  const std::string& kind = given.find("kind")->second;
  std::optional<geometry::SurfaceShape> shape;
  if (kind != "self-affine") {
    try {
      shape = geometry::parse_surface_shape(kind);
    } catch (const InputError&) {
      throw InputError(fmt::format("{} is invalid: the kind must be self-affine, sphere, cylinder, wavy or flat",
                                   describe(given, "kind")));
    }
  }
  Generated surface = shape ? builtin(given, *shape) : self_affine(given);
  surface.metadata.command_line = join_command_line(argv);

  const std::span<const double> heights(surface.heights.data(), static_cast<std::size_t>(surface.heights.size()));
  std::optional<Activity> activity(std::in_place,
                                   fmt::format("computing the statistics of the {} grid", surface.grid.shape_string()));
  const surface::SurfaceStatistics statistics = surface::surface_statistics(surface.grid, heights);
  activity.reset();
  surface.metadata.numbers.emplace_back("rms_height", statistics.rms_height);
  surface.metadata.numbers.emplace_back("rms_slope", statistics.rms_slope);
  const std::string output = given.find("output")->second;
  {
    const Activity activity(fmt::format("writing {}", output));
    io::write_height_map(output, surface.grid, heights, surface.metadata);
  }

  if (!quiet) {
    const Grid& grid = surface.grid;
    const auto row = [](std::string_view label, const std::string& value) {
      fmt::print("  {:<12} {}\n", label, value);
    };
    fmt::print("halfspace {} ({}) generate\n", kVersion, kGitHash);
    row("surface", surface.metadata.source);
    row("grid", grid.dimension() == 1 ? fmt::format("{} cells (1D), dx = {:.6g} m", grid.nx(), grid.dx())
                                      : fmt::format("{} cells (2D), dx = {:.6g} m, dy = {:.6g} m", grid.shape_string(),
                                                    grid.dx(), grid.dy()));
    row("periodic", surface.metadata.periodic ? "yes" : "no");
    row("rms height", fmt::format("{:.6g} m", statistics.rms_height));
    row("rms slope",
        fmt::format("{:.6g} ({})", statistics.rms_slope, grid.periodic() ? "spectral" : "finite differences"));
    row("output", output);
  }
  return kExitOk;
}

}  // namespace

Command add_generate_command(CLI::App& program) {
  CLI::App* generate = program.add_subcommand(
      "generate", "Write a synthetic surface (self-affine random, sphere, cylinder, wavy, flat) as an HDF5 height map");
  generate->footer("The file reads back with `halfspace solve --height-map FILE`; see docs/usage.md.");
  auto given = std::make_shared<GivenOptions>();
  auto quiet = std::make_shared<bool>(false);
  for (const OptionHelp& option : kOptions) {
    const std::string key = option.key;
    generate
        ->add_option_function<std::string>(
            fmt::format("--{}", key), [given, key](const std::string& value) { (*given)[key] = value; }, option.help)
        ->type_name(option.value_name);
  }
  generate->add_flag("--quiet", *quiet, "print nothing unless there is an error");
  return {generate,
          [given, quiet](const std::vector<std::string>& argv) { return run_generate(*given, *quiet, argv); }};
}

}  // namespace halfspace::app
