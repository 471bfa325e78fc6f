// --grid and --size into a Grid, with the spacing checked against the same
// range as the lengths: 1e-3 m over 1e9 cells is a spacing of 1e-12 m; a
// built-in shape's lengths.
#include "grid_options.hpp"

#include <fmt/format.h>

#include <cmath>
#include <initializer_list>
#include <utility>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/physical_ranges.hpp"
#include "value_parsing.hpp"

namespace halfspace::app {
namespace {

double spacing(std::string_view axis, double length, std::size_t cells, const std::string& grid_what,
               const std::string& size_what) {
  const double h = length / static_cast<double>(cells);
  return require_in_range(fmt::format("the spacing {} = {:g} m of {} over {}", axis, h, size_what, grid_what), h,
                          kMinLength, kMaxLength, "m");
}

}  // namespace

Grid grid_from_options(std::string_view grid_text, const std::string& grid_what, std::string_view size_text,
                       const std::string& size_what, Boundary boundary) {
  const std::vector<std::size_t> cells = parse_grid_shape(grid_text, grid_what);
  const std::vector<double> lengths = parse_domain_size(size_text, size_what);
  if (cells.size() == 1) {
    if (lengths.size() != 1) {
      throw InputError(fmt::format("{} is invalid for the 1D grid {}: give one length", size_what, grid_what));
    }
    return Grid::line(cells[0], spacing("dx", lengths[0], cells[0], grid_what, size_what), boundary);
  }
  const double length_y = lengths.size() == 2 ? lengths[1] : lengths[0];
  return Grid::plane(cells[0], cells[1], spacing("dx", lengths[0], cells[0], grid_what, size_what),
                     spacing("dy", length_y, cells[1], grid_what, size_what), boundary);
}

Grid grid_for_geometry(const GivenOptions& o, const std::optional<std::string>& grid,
                       const std::optional<std::string>& size, Boundary boundary) {
  if (!grid) throw InputError("--geometry needs --grid N (1D) or NXxNY (2D)");
  if (!size) throw InputError("--geometry needs --size L or LXxLY (domain size in m)");
  return grid_from_options(*grid, o.describe("grid"), *size, o.describe("size"), boundary);
}

double require_length(const GivenOptions& o, std::string_view key, double value) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InputError(fmt::format("{} is invalid: must be positive (m)", o.describe(key)));
  }
  return require_in_range(o.describe(key), value, kMinLength, kMaxLength, "m");
}

BuiltinShape builtin_shape_from(const GivenOptions& o, std::string_view shape_key, geometry::SurfaceShape shape,
                                const std::optional<double>& radius, const std::optional<double>& wavelength,
                                const std::optional<double>& amplitude) {
  const std::string shape_text = o.describe(shape_key);
  const auto refuse = [&](std::initializer_list<std::pair<std::string_view, bool>> keys) {
    for (const auto& [key, given] : keys) {
      if (given) throw InputError(fmt::format("{} does not apply to {}", o.name(key), shape_text));
    }
  };
  const auto require = [&](std::string_view key, const std::optional<double>& value) {
    if (!value) throw InputError(fmt::format("{} needs --{} (m)", shape_text, key));
    return require_length(o, key, *value);
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

}  // namespace halfspace::app
