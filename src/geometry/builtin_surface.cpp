// Built-in deterministic surfaces (sphere, cylinder, flat punch, wavy) sampled
// at the cell centres of a grid, and the initial gap they define.
#include "halfspace/geometry/builtin_surface.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "halfspace/error.hpp"

namespace halfspace::geometry {
namespace {

// The parameter must be positive and finite for `shape` to be defined.
void require_positive(SurfaceShape shape, std::string_view parameter, double value) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InputError(fmt::format("{} needs {} > 0 m (got {})", to_string(shape), parameter, format_number(value)));
  }
}

void validate(const SurfaceSpec& spec) {
  switch (spec.shape) {
    case SurfaceShape::sphere:
    case SurfaceShape::cylinder:
      require_positive(spec.shape, "radius", spec.radius);
      break;
    case SurfaceShape::wavy:
      require_positive(spec.shape, "wavelength", spec.wavelength);
      require_positive(spec.shape, "amplitude", spec.amplitude);
      break;
    case SurfaceShape::flat:
      break;
  }
}

// Height at (x, y) measured from the grid centre; y is 0 on a 1D grid.
double height_at(const SurfaceSpec& spec, int dimension, double x, double y) {
  switch (spec.shape) {
    case SurfaceShape::sphere:
      return -(x * x + y * y) / (2.0 * spec.radius);
    case SurfaceShape::cylinder:
      return -(x * x) / (2.0 * spec.radius);
    case SurfaceShape::flat:
      return 0.0;
    case SurfaceShape::wavy: {
      const double k = 2.0 * std::numbers::pi / spec.wavelength;
      const double profile = dimension == 1 ? std::cos(k * x) : std::cos(k * x) * std::cos(k * y);
      return -spec.amplitude * (1.0 - profile);
    }
  }
  return 0.0;
}

}  // namespace

std::string_view to_string(SurfaceShape shape) {
  switch (shape) {
    case SurfaceShape::sphere:
      return "sphere";
    case SurfaceShape::cylinder:
      return "cylinder";
    case SurfaceShape::flat:
      return "flat";
    case SurfaceShape::wavy:
      return "wavy";
  }
  return "unknown";
}

SurfaceShape parse_surface_shape(std::string_view text) {
  for (SurfaceShape shape : {SurfaceShape::sphere, SurfaceShape::cylinder, SurfaceShape::flat, SurfaceShape::wavy}) {
    if (text == to_string(shape)) return shape;
  }
  throw InputError(fmt::format("surface shape '{}' is not known: use sphere, cylinder, flat or wavy", text));
}

Eigen::ArrayXd make_surface_heights(const Grid& grid, const SurfaceSpec& spec) {
  return make_surface_rows(grid, spec, 0, grid.ny());
}

Eigen::ArrayXd make_surface_rows(const Grid& grid, const SurfaceSpec& spec, std::size_t first_row, std::size_t rows) {
  validate(spec);
  if (first_row > grid.ny() || rows > grid.ny() - first_row) {
    throw InputError(
        fmt::format("rows {} to {} are not all rows of the {} grid", first_row, first_row + rows, grid.shape_string()));
  }
  // Centring on (n - 1) h / 2 puts the apex of a sphere or cylinder on a cell
  // for odd n and symmetrically between two cells for even n, so the sampled
  // surface is mirror-symmetric about the grid centre either way.
  const double xc = 0.5 * static_cast<double>(grid.nx() - 1) * grid.dx();
  const double yc = 0.5 * static_cast<double>(grid.ny() - 1) * grid.dy();
  Eigen::ArrayXd heights(static_cast<Eigen::Index>(rows * grid.nx()));
  for (std::size_t r = 0; r < rows; ++r) {
    const double y = static_cast<double>(first_row + r) * grid.dy() - yc;
    for (std::size_t i = 0; i < grid.nx(); ++i) {
      const double x = static_cast<double>(i) * grid.dx() - xc;
      heights[static_cast<Eigen::Index>(r * grid.nx() + i)] = height_at(spec, grid.dimension(), x, y);
    }
  }
  return heights;
}

}  // namespace halfspace::geometry
