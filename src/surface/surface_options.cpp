// The surface's options into a height-map file to read or a built-in shape
// on its grid, with every rule and message in one place (the program's
// solve and lubricate, and Python's reader, map onto them).
#include "halfspace/surface/surface_options.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <charconv>
#include <cmath>
#include <system_error>
#include <tuple>
#include <utility>
#include <vector>

#include "../problem_rules.hpp"
#include "halfspace/checked_size.hpp"
#include "halfspace/error.hpp"
#include "halfspace/physical_ranges.hpp"
#include "halfspace/surface/padding.hpp"

namespace halfspace {
namespace {

// Splits "AxB" at 'x' or 'X'; a single part when there is none.
std::vector<std::string_view> split_dimensions(std::string_view text) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (std::size_t k = 0; k <= text.size(); ++k) {
    if (k == text.size() || text[k] == 'x' || text[k] == 'X') {
      parts.push_back(text.substr(start, k - start));
      start = k + 1;
    }
  }
  return parts;
}

std::vector<std::size_t> grid_shape(std::string_view text, const std::string& what) {
  const std::vector<std::string_view> parts = split_dimensions(text);
  std::vector<std::size_t> counts;
  for (std::string_view part : parts) {
    std::size_t n = 0;
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), n);
    if (parts.size() > 2 || part.empty() || error != std::errc() || end != part.data() + part.size()) {
      throw InputError(
          fmt::format("{} is invalid: expected N cells (1D) or NXxNY cells (2D), e.g. 256 or 256x128", what));
    }
    counts.push_back(n);
  }
  for (std::size_t axis = 0; axis < counts.size(); ++axis) {
    if (counts[axis] < 2) {
      const char* name = counts.size() == 1 ? "n" : (axis == 0 ? "nx" : "ny");
      throw InputError(
          fmt::format("{} is invalid: need at least 2 cells along each axis (got {} = {})", what, name, counts[axis]));
    }
  }
  const std::size_t rows = counts.size() == 2 ? counts[1] : 1;
  const std::optional<std::size_t> cells = checked_multiply(counts[0], rows);
  if (!cells || *cells > kMaxGridCells) {
    throw InputError(fmt::format("{} is invalid: {:.4g} cells is more than the {:.4g} a grid can have", what,
                                 static_cast<double>(counts[0]) * static_cast<double>(rows),
                                 static_cast<double>(kMaxGridCells)));
  }
  return counts;
}

std::vector<double> domain_size(std::string_view text, const std::string& what) {
  const std::vector<std::string_view> parts = split_dimensions(text);
  if (parts.size() > 2) {
    throw InputError(fmt::format("{} is invalid: expected L or LXxLY in m, e.g. 1e-3 or 2e-3x1e-3", what));
  }
  std::vector<double> lengths;
  for (std::string_view part : parts) {
    // A leading '+' is accepted, as the program's numbers accept it.
    const std::string_view digits = part.size() > 1 && part.front() == '+' ? part.substr(1) : part;
    double length = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), length);
    if (digits.empty() || error != std::errc() || end != digits.data() + digits.size() || !std::isfinite(length)) {
      throw InputError(fmt::format("{} is invalid: expected a finite number", what));
    }
    if (!(length >= kMinLength && length <= kMaxLength)) {
      throw InputError(fmt::format("{} is invalid: each length of the domain must be in [{:g}, {:g}] m (got {:g})",
                                   what, kMinLength, kMaxLength, length));
    }
    lengths.push_back(length);
  }
  return lengths;
}

}  // namespace

double checked_length(std::string_view option, double value, const OptionSpelling& spelling) {
  return detail::spelled_errors(spelling, [&] { return detail::Checks(spelling).length(option, value); });
}

Grid grid_from_text(std::string_view cells, std::string_view size, Boundary boundary, const OptionSpelling& spelling,
                    std::string_view cells_option, std::string_view size_option) {
  const std::string grid_what = spelling.describe(cells_option, cells);
  const std::string size_what = spelling.describe(size_option, size);
  const std::vector<std::size_t> counts = grid_shape(cells, grid_what);
  const std::vector<double> lengths = domain_size(size, size_what);
  // The spacing, in the range of the lengths themselves: 1e-3 m over 1e9
  // cells would be a spacing of 1e-12 m.
  const auto spacing = [&](std::string_view axis, double length, std::size_t n) {
    const double h = length / static_cast<double>(n);
    return require_in_range(fmt::format("the spacing {} = {:g} m of {} over {}", axis, h, size_what, grid_what), h,
                            kMinLength, kMaxLength, "m");
  };
  if (counts.size() == 1) {
    if (lengths.size() != 1) {
      throw InputError(fmt::format("{} is invalid for the 1D grid {}: give one length", size_what, grid_what));
    }
    return Grid::line(counts[0], spacing("dx", lengths[0], counts[0]), boundary);
  }
  const double length_y = lengths.size() == 2 ? lengths[1] : lengths[0];
  return Grid::plane(counts[0], counts[1], spacing("dx", lengths[0], counts[0]), spacing("dy", length_y, counts[1]),
                     boundary);
}

BuiltinShape builtin_shape(std::string_view shape_option, std::string_view shape_text, geometry::SurfaceShape shape,
                           const std::optional<double>& radius, const std::optional<double>& wavelength,
                           const std::optional<double>& amplitude, const OptionSpelling& spelling) {
  const std::string chosen = spelling.describe(shape_option, shape_text);
  const auto refuse = [&](const detail::Presence& options) {
    for (const auto& [option, given] : options) {
      if (given) throw InputError(fmt::format("{} does not apply to {}", spelling.name(option), chosen));
    }
  };
  const auto require = [&](std::string_view option, const std::optional<double>& value) {
    if (!value) throw InputError(fmt::format("{} needs {} (m)", chosen, spelling.name(option)));
    return checked_length(option, *value, spelling);
  };
  BuiltinShape made{{.shape = shape}, std::string(geometry::to_string(shape))};
  geometry::SurfaceSpec& spec = made.spec;
  switch (shape) {
    case geometry::SurfaceShape::sphere:
    case geometry::SurfaceShape::cylinder:
      refuse({{"wavelength", wavelength.has_value()}, {"amplitude", amplitude.has_value()}});
      spec.radius = require("radius", radius);
      made.source += fmt::format(" (radius = {} m)", spec.radius);
      break;
    case geometry::SurfaceShape::wavy:
      refuse({{"radius", radius.has_value()}});
      spec.wavelength = require("wavelength", wavelength);
      spec.amplitude = require("amplitude", amplitude);
      made.source += fmt::format(" (wavelength = {} m, amplitude = {} m)", spec.wavelength, spec.amplitude);
      break;
    case geometry::SurfaceShape::flat:
      refuse({{"radius", radius.has_value()},
              {"wavelength", wavelength.has_value()},
              {"amplitude", amplitude.has_value()}});
      break;
  }
  return made;
}

surface::PreparationOptions checked_preparation(const SurfaceOptions& o, Boundary boundary,
                                                const OptionSpelling& spelling) {
  surface::PreparationOptions prepare;
  if (o.window) prepare.window = in_context(spelling.name("window"), [&] { return surface::parse_window(*o.window); });
  if (o.invalid) {
    prepare.invalid = in_context(spelling.name("invalid"), [&] { return surface::parse_invalid_points(*o.invalid); });
  }
  if (o.detrend)
    prepare.detrend = in_context(spelling.name("detrend"), [&] { return surface::parse_detrend(*o.detrend); });
  if (o.resample) {
    prepare.resample = in_context(spelling.name("resample"), [&] { return surface::parse_resample(*o.resample); });
  }
  if (o.pad) {
    const std::string pad = spelling.describe("pad", format_number(*o.pad));
    if (boundary == Boundary::periodic) {
      throw InputError(
          fmt::format("{} cannot be combined with {}: padding is for free boundaries (a periodic surface repeats "
                      "without a margin)",
                      pad, spelling.describe("boundary", "periodic")));
    }
    if (!(*o.pad >= surface::kMinPadFactor && *o.pad <= surface::kMaxPadFactor)) {
      throw InputError(fmt::format("{} is invalid: the factor must be in [{}, {}]", pad, surface::kMinPadFactor,
                                   surface::kMaxPadFactor));
    }
    prepare.pad_factor = *o.pad;
  }
  return prepare;
}

SurfaceChoice make_surface_choice(const SurfaceOptions& o, Boundary boundary, const OptionSpelling& spelling) {
  const auto name = [&](std::string_view option) { return spelling.name(option); };
  if (o.height_map && o.geometry) {
    throw InputError(
        fmt::format("{} and {} cannot be combined: give exactly one surface", name("height_map"), name("geometry")));
  }
  if (!o.height_map && !o.geometry) {
    throw InputError(fmt::format("no surface given: pass {} FILE or {} sphere|cylinder|flat|wavy", name("height_map"),
                                 name("geometry")));
  }
  const auto refuse = [&](const detail::Presence& options, const std::string& reason) {
    for (const auto& [option, given] : options) {
      if (given) throw InputError(fmt::format("{} {}", name(option), reason));
    }
  };
  if (o.geometry) {
    refuse({{"dataset", o.dataset.has_value()},
            {"dx", o.dx.has_value()},
            {"dy", o.dy.has_value()},
            {"format", o.format.has_value()},
            {"unit", o.unit.has_value()},
            {"window", o.window.has_value()},
            {"invalid", o.invalid.has_value()},
            {"detrend", o.detrend.has_value()},
            {"resample", o.resample.has_value()},
            {"pad", o.pad.has_value()}},
           fmt::format("applies only to {}; a built-in geometry takes its spacing from {} and {}", name("height_map"),
                       name("grid"), name("size")));
    const geometry::SurfaceShape shape =
        in_context(spelling.name("geometry"), [&] { return geometry::parse_surface_shape(*o.geometry); });
    BuiltinShape made = builtin_shape("geometry", *o.geometry, shape, o.radius, o.wavelength, o.amplitude, spelling);
    if (!o.grid) throw InputError(fmt::format("{} needs {} N (1D) or NXxNY (2D)", name("geometry"), name("grid")));
    if (!o.size) {
      throw InputError(fmt::format("{} needs {} L or LXxLY (domain size in m)", name("geometry"), name("size")));
    }
    return BuiltinSurface{std::move(made), grid_from_text(*o.grid, *o.size, boundary, spelling)};
  }
  refuse({{"radius", o.radius.has_value()},
          {"wavelength", o.wavelength.has_value()},
          {"amplitude", o.amplitude.has_value()},
          {"grid", o.grid.has_value()},
          {"size", o.size.has_value()}},
         fmt::format("cannot be used with {}: it applies only to {}; the grid and its spacing come from the file",
                     name("height_map"), name("geometry")));
  HeightMapFile file{.path = *o.height_map};
  if (o.format)
    file.read.format = in_context(spelling.name("format"), [&] { return io::parse_height_map_format(*o.format); });
  if (o.dataset) file.read.dataset = *o.dataset;
  if (o.unit)
    file.read.unit = in_context(spelling.name("unit"), [&] { return io::require_length_unit(*o.unit, "unit"); });
  file.prepare = checked_preparation(o, boundary, spelling);
  if (o.dx) file.dx = checked_length("dx", *o.dx, spelling);
  if (o.dy) file.dy = checked_length("dy", *o.dy, spelling);
  return file;
}

void set_spacing(HeightMap& map, const HeightMapFile& file, const OptionSpelling& spelling) {
  if (map.dimension == 1 && file.dy) {
    throw InputError(fmt::format("{} does not apply to the 1D profile in {}", spelling.name("dy"), file.path));
  }
  map.dx = file.dx.value_or(map.dx);
  map.dy = map.dimension == 1 ? 0.0 : file.dy.value_or(map.dy);
  // Both spacings are named at once when both are missing, so one retry
  // suffices; those from the file's attributes get the options' range.
  std::vector<std::string_view> missing;
  std::vector<std::string> options;
  const std::array<std::tuple<std::string_view, double, bool>, 2> axes{
      {{"dx", map.dx, file.dx.has_value()}, {"dy", map.dy, file.dy.has_value() || map.dimension == 1}}};
  for (const auto& [axis, value, given] : axes) {
    if (!given && !(value > 0.0)) {
      missing.push_back(axis);
      options.push_back(spelling.name(axis));
    }
  }
  if (!missing.empty()) {
    throw FileError(fmt::format("height map {} does not state its spacing {}: pass {} (m)", file.path,
                                fmt::join(missing, " and "), fmt::join(options, " and ")));
  }
  for (const auto& [axis, value, given] : axes) {
    if (given) continue;
    require_in_range(fmt::format("the spacing {} = {:g} m of height map {} (override it with {})", axis, value,
                                 file.path, spelling.name(axis)),
                     value, kMinLength, kMaxLength, "m");
  }
}

HeightMap read_height_map_file(const HeightMapFile& file, const OptionSpelling& spelling) {
  HeightMap map = io::read_height_map(file.path, file.read);
  set_spacing(map, file, spelling);
  try {
    surface::prepare_height_map(map, file.prepare);
  } catch (const FileError& error) {
    // Only the refusal of invalid points is a FileError here.
    throw with_invalid_points_hint(error, spelling);
  }
  return map;
}

FileError with_invalid_points_hint(const FileError& error, const OptionSpelling& spelling) {
  const std::string invalid = spelling.name("invalid");
  return FileError(fmt::format("{} (pass {} fill or {} crop)", error.what(), invalid, invalid));
}

}  // namespace halfspace
