// Built-in deterministic surfaces: sphere (paraboloid), cylinder, flat punch,
// wavy (sinusoid). Heights are the rigid surface's elevation towards the
// half-space (peaks positive), centred on the grid.
#pragma once

#include <Eigen/Core>
#include <string_view>

#include "halfspace/grid.hpp"

namespace halfspace::geometry {

enum class SurfaceShape { sphere, cylinder, flat, wavy };

std::string_view to_string(SurfaceShape shape);
// Parses "sphere", "cylinder", "flat" or "wavy"; throws InputError otherwise.
SurfaceShape parse_surface_shape(std::string_view text);

struct SurfaceSpec {
  SurfaceShape shape = SurfaceShape::sphere;
  double radius = 0.0;      // m, sphere and cylinder
  double wavelength = 0.0;  // m, wavy
  double amplitude = 0.0;   // m, wavy: h = -amplitude (1 - cos(...)), see below
};

// Heights (m) on `grid`, (ny, nx) row-major, with coordinates measured from
// the grid centre xc = (nx - 1) dx / 2 (yc likewise):
//   sphere:   -(x^2 + y^2) / (2R)        (1D: -x^2 / (2R))
//   cylinder: -x^2 / (2R)                (axis along y)
//   flat:      0
//   wavy:     -A (1 - cos(2 pi x / lambda))                     in 1D,
//             -A (1 - cos(2 pi x / lambda) cos(2 pi y / lambda)) in 2D.
// Throws InputError naming the parameter if a needed one is not positive.
Eigen::ArrayXd make_surface_heights(const Grid& grid, const SurfaceSpec& spec);

// The same heights for rows first_row .. first_row + rows - 1 of a 2D grid
// only ((rows, nx) row-major), each from its global coordinates, so that the
// slabs of a distributed run put together are make_surface_heights's
// values. Throws InputError as above, or for rows beyond the grid.
Eigen::ArrayXd make_surface_rows(const Grid& grid, const SurfaceSpec& spec, std::size_t first_row, std::size_t rows);

}  // namespace halfspace::geometry
