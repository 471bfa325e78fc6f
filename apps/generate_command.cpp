// The generate command: options -> surface spec -> heights -> height-map file.
// Options come from a table (option_table.hpp) as those of `solve` do: flags,
// config keys and value types from one list, so the messages match.
#include "generate_command.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "activity.hpp"
#include "exit_codes.hpp"
#include "halfspace/error.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/io/height_map_writer.hpp"
#include "halfspace/io/output_file.hpp"
#include "halfspace/io/xdmf_writer.hpp"
#include "halfspace/memory_estimate.hpp"
#include "halfspace/physical_ranges.hpp"
#include "halfspace/surface/self_affine.hpp"
#include "halfspace/surface/statistics.hpp"
#include "halfspace/surface/surface_options.hpp"
#include "halfspace/version.hpp"
#include "memory_check.hpp"
#include "option_table.hpp"
#include "processes.hpp"

namespace halfspace::app {
namespace {

// Everything `halfspace generate` accepts; an empty optional was not given.
struct GenerateOptions : GivenOptions {
  std::optional<std::string> kind;
  std::optional<std::string> grid;
  std::optional<std::string> size;
  std::optional<double> hurst;
  std::optional<double> cutoff_short;
  std::optional<double> rolloff;
  std::optional<double> cutoff_long;
  std::optional<double> rms_height;
  std::optional<double> rms_slope;
  std::optional<long long> seed;
  std::optional<double> radius;
  std::optional<double> wavelength;
  std::optional<double> amplitude;
  std::optional<std::string> output;
  std::optional<std::string> max_memory;
  bool quiet = false;
};

using GenerateOption = OptionSpec<GenerateOptions>;
using Kind = OptionKind;

constexpr std::string_view kSurface = "Surface";
constexpr std::string_view kSelfAffine = "Self-affine surface (--kind self-affine)";
constexpr std::string_view kShape = "Built-in shapes (--kind sphere, cylinder, wavy)";
constexpr std::string_view kOutput = "Output";

const std::array kOptions{
    GenerateOption{"kind", &GenerateOptions::kind, Kind::text, kSurface, "KIND",
                   "self-affine, sphere, cylinder, wavy or flat (required)"},
    GenerateOption{"grid", &GenerateOptions::grid, Kind::dimensions, kSurface, "N|NXxNY",
                   "cells: N (1D profile) or NXxNY (2D map), at least 2 per axis (required)"},
    GenerateOption{"size", &GenerateOptions::size, Kind::dimensions, kSurface, "L|LXxLY",
                   "domain size (m); spacing = L / N (required)"},
    GenerateOption{"hurst", &GenerateOptions::hurst, Kind::number, kSelfAffine, "H", "Hurst exponent in (0, 1] [0.8]"},
    GenerateOption{"cutoff-short", &GenerateOptions::cutoff_short, Kind::number, kSelfAffine, "M",
                   "shortest wavelength (m) [2 max(dx, dy)]"},
    GenerateOption{"rolloff", &GenerateOptions::rolloff, Kind::number, kSelfAffine, "M",
                   "the power law holds below this wavelength, flat above (m) [cutoff-long]"},
    GenerateOption{"cutoff-long", &GenerateOptions::cutoff_long, Kind::number, kSelfAffine, "M",
                   "longest wavelength (m) [the domain's longer side]"},
    GenerateOption{"rms-height", &GenerateOptions::rms_height, Kind::number, kSelfAffine, "M",
                   "rms height about the mean (m); exactly one of rms-height, rms-slope"},
    GenerateOption{"rms-slope", &GenerateOptions::rms_slope, Kind::number, kSelfAffine, "X",
                   "rms of the gradient magnitude, sqrt(<|grad h|^2>) (spectral)"},
    GenerateOption{"seed", &GenerateOptions::seed, Kind::integer, kSelfAffine, "N",
                   "random seed, 0 to 2^63-1 [0]; same seed, same surface"},
    GenerateOption{"radius", &GenerateOptions::radius, Kind::number, kShape, "M", "sphere, cylinder: radius (m)"},
    GenerateOption{"wavelength", &GenerateOptions::wavelength, Kind::number, kShape, "M", "wavy: wavelength (m)"},
    GenerateOption{"amplitude", &GenerateOptions::amplitude, Kind::number, kShape, "M",
                   "wavy: amplitude A (m), h = -A (1 - cos ...)"},
    GenerateOption{"output", &GenerateOptions::output, Kind::path, kOutput, "FILE",
                   "the height-map file (HDF5), required; replaced if it exists"},
    GenerateOption{"max-memory", &GenerateOptions::max_memory, Kind::memory, kOutput, "SIZE",
                   "refuse to start when the estimated peak memory exceeds SIZE: bytes, or K, M, G, T (powers of "
                   "1024), e.g. 512M [the memory available]"},
    GenerateOption{"quiet", &GenerateOptions::quiet, Kind::flag, kOutput, "", "print nothing unless there is an error"},
};

constexpr const char* kSelfAffineKeys[] = {"hurst",      "cutoff-short", "rolloff", "cutoff-long",
                                           "rms-height", "rms-slope",    "seed"};

// The heights are made here by the process that makes them whole
// (makes_whole); on several processes a 2D map's rows are made and written
// by each later (generate_distributed), from `source`.
struct Generated {
  Grid grid;
  Eigen::ArrayXd heights;
  io::HeightMapMetadata metadata;
  SurfaceSource source;
};

// The program's spelling of the library's checks of these options.
GivenSpelling flags(const GenerateOptions& o) {
  return {o, std::span<const GenerateOption>(kOptions)};
}

// A length option (checked_length), if given.
std::optional<double> length(const GenerateOptions& o, std::string_view key, const std::optional<double>& value) {
  if (!value) return std::nullopt;
  return checked_length(key, *value, flags(o));
}

void reject(const GenerateOptions& o, std::initializer_list<const char*> keys, std::string_view reason) {
  for (const char* key : keys) {
    if (o.given(key)) throw InputError(fmt::format("{} {}", o.name(key), reason));
  }
}

// Whether this process makes the heights whole: the only one; on several,
// the first for a 1D profile (one row, which slabs of rows cannot split),
// while a 2D map is made in slabs later (generate_distributed).
bool makes_whole(const Grid& grid) {
  return process_count() == 1 || (grid.dimension() == 1 && prints_messages());
}

// The grid, once its generation is known to fit in memory.
Grid grid_from(const GenerateOptions& o, Boundary boundary) {
  if (!o.grid) throw InputError("no grid given: pass --grid N (1D) or NXxNY (2D)");
  if (!o.size) throw InputError("no domain size given: pass --size L or LXxLY (m)");
  Grid grid = grid_from_text(*o.grid, *o.size, boundary, flags(o));
  const std::optional<MemoryLimit> limit =
      memory_limit(o.max_memory, o.max_memory ? o.describe("max-memory") : std::string("--max-memory"));
  require_memory(fmt::format("{}: generating {} cells", o.describe("grid"), grid.size()),
                 generate_memory_estimate(grid), limit);
  return grid;
}

Generated self_affine(const GenerateOptions& o) {
  reject(o, {"radius", "wavelength", "amplitude"}, "does not apply to --kind self-affine");
  surface::SelfAffineSpec spec;
  spec.hurst = o.hurst.value_or(spec.hurst);
  spec.short_cutoff = length(o, "cutoff-short", o.cutoff_short).value_or(0.0);
  spec.rolloff = length(o, "rolloff", o.rolloff).value_or(0.0);
  spec.long_cutoff = length(o, "cutoff-long", o.cutoff_long).value_or(0.0);
  spec.rms_height = length(o, "rms-height", o.rms_height);
  spec.rms_slope = o.rms_slope;
  if (spec.rms_height && spec.rms_slope) {
    throw InputError("--rms-height and --rms-slope cannot be combined: give exactly one");
  }
  if (!spec.rms_height && !spec.rms_slope) {
    throw InputError("--kind self-affine needs --rms-height (m) or --rms-slope");
  }
  if (o.seed) {
    if (*o.seed < 0) throw InputError(fmt::format("{} is invalid: the seed must be 0 or more", o.describe("seed")));
    spec.seed = static_cast<std::uint64_t>(*o.seed);
  }

  Grid grid = grid_from(o, Boundary::periodic);
  const surface::SelfAffineSpec resolved = spec.resolved(grid);
  Eigen::ArrayXd heights;
  if (makes_whole(grid)) {
    const Activity activity(fmt::format("generating the self-affine surface on the {} grid", grid.shape_string()));
    heights = surface::make_self_affine_surface(grid, spec);
  }
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
  return {std::move(grid), std::move(heights), std::move(metadata), spec};
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

Generated builtin(const GenerateOptions& o, geometry::SurfaceShape shape) {
  const std::string& kind = *o.kind;
  for (const char* key : kSelfAffineKeys) {
    if (o.given(key)) throw InputError(fmt::format("{} does not apply to --kind {}", o.name(key), kind));
  }
  auto [spec, source] = builtin_shape("kind", kind, shape, o.radius, o.wavelength, o.amplitude, flags(o));
  // Only a wavy surface with whole periods repeats with the domain.
  Grid probe = grid_from(o, Boundary::free);
  const bool periodic = shape == geometry::SurfaceShape::wavy && whole_periods(probe, spec.wavelength);
  Grid grid = grid_from(o, periodic ? Boundary::periodic : Boundary::free);
  Eigen::ArrayXd heights;
  if (makes_whole(grid)) {
    const Activity activity(fmt::format("generating the {} surface on the {} grid", kind, grid.shape_string()));
    heights = geometry::make_surface_heights(grid, spec);
  }
  io::HeightMapMetadata metadata;
  metadata.periodic = periodic;
  metadata.source = source;
  metadata.strings = {{"generator", std::string(geometry::to_string(shape))}};
  if (spec.radius > 0.0) metadata.numbers.emplace_back("radius", spec.radius);
  if (spec.wavelength > 0.0) metadata.numbers.emplace_back("wavelength", spec.wavelength);
  if (spec.amplitude > 0.0) metadata.numbers.emplace_back("amplitude", spec.amplitude);
  return {std::move(grid), std::move(heights), std::move(metadata), spec};
}

int run_generate(const GenerateOptions& o) {
  if (!o.kind) throw InputError("no surface kind given: pass --kind self-affine, sphere, cylinder, wavy or flat");
  if (!o.output) throw InputError("no output file given: pass --output FILE.h5");
  const std::string& kind = *o.kind;
  // On several processes every one checks the options; all fail, with the
  // first failure's message, if any does.
  std::optional<Generated> made;
  agree_everywhere([&] {
    // Refuse a device, FIFO or directory before generating, not after.
    io::check_output_path(*o.output);
    io::check_xdmf_sidecar_path(*o.output);
    std::optional<geometry::SurfaceShape> shape;
    if (kind != "self-affine") {
      try {
        shape = geometry::parse_surface_shape(kind);
      } catch (const InputError&) {
        throw InputError(fmt::format("{} is invalid: the kind must be self-affine, sphere, cylinder, wavy or flat",
                                     o.describe("kind")));
      }
    }
    made.emplace(shape ? builtin(o, *shape) : self_affine(o));
  });
  Generated& surface = *made;
  surface.metadata.command_line = o.command_line;
  const std::string& output = *o.output;

  surface::SurfaceStatistics statistics;
  if (process_count() > 1 && surface.grid.dimension() == 2) {
    // Each process its rows, made, measured and written at once.
    const Activity activity(fmt::format("generating the {} surface on the {} grid and writing {}", kind,
                                        surface.grid.shape_string(), output));
    statistics = generate_distributed(surface.grid, surface.source, surface.metadata, output);
  } else {
    // The process that made the heights measures and writes them, any other waiting.
    agree_everywhere([&] {
      if (!makes_whole(surface.grid)) return;
      const std::span<const double> heights(surface.heights.data(), static_cast<std::size_t>(surface.heights.size()));
      std::optional<Activity> activity(
          std::in_place, fmt::format("computing the statistics of the {} grid", surface.grid.shape_string()));
      statistics = surface::surface_statistics(surface.grid, heights);
      activity.reset();
      surface.metadata.numbers.emplace_back("rms_height", statistics.rms_height);
      surface.metadata.numbers.emplace_back("rms_slope", statistics.rms_slope);
      const Activity writing(fmt::format("writing {}", output));
      io::write_height_map(output, surface.grid, heights, surface.metadata);
    });
  }

  if (!o.quiet && prints_messages()) {
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
  return {generate,
          table_command(*generate, std::span<const GenerateOption>(kOptions), "rms-slope = 0.1", run_generate)};
}

}  // namespace halfspace::app
