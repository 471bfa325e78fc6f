// Padding with a margin at the map's lowest level (see padding.hpp for why
// that level and why the pressure on the map does not change).
#include "halfspace/surface/padding.hpp"

#include <fmt/format.h>

#include <cmath>

#include "halfspace/error.hpp"
#include "halfspace/surface/invalid_points.hpp"

namespace halfspace::surface {

void pad_for_free_boundary(HeightMap& map, double factor) {
  if (!(std::isfinite(factor) && factor >= kMinPadFactor && factor <= kMaxPadFactor)) {
    throw InputError(
        fmt::format("padding factor {} is invalid: must be in [{}, {}] (the padded grid is factor times "
                    "larger along each axis)",
                    factor, kMinPadFactor, kMaxPadFactor));
  }
  if (count_invalid(map) > 0) {
    throw InputError(
        fmt::format("height map {}: cannot pad a map with invalid points; fill or crop them first", map.source));
  }
  const auto grown = [factor](std::size_t n) {
    return static_cast<std::size_t>(std::ceil(factor * static_cast<double>(n) - 1e-9));
  };
  const std::size_t nx = grown(map.nx);
  const std::size_t ny = map.dimension == 1 ? 1 : grown(map.ny);
  if (nx == map.nx && ny == map.ny) return;
  const std::size_t i0 = (nx - map.nx) / 2;
  const std::size_t j0 = (ny - map.ny) / 2;
  const double level = map.heights.minCoeff();

  Eigen::ArrayXd heights = Eigen::ArrayXd::Constant(static_cast<Eigen::Index>(nx * ny), level);
  for (std::size_t j = 0; j < map.ny; ++j) {
    for (std::size_t i = 0; i < map.nx; ++i) {
      heights[static_cast<Eigen::Index>((j0 + j) * nx + i0 + i)] =
          map.heights[static_cast<Eigen::Index>(j * map.nx + i)];
    }
  }
  map.preparation.push_back(
      map.dimension == 1
          ? fmt::format("pad {}x for free boundaries: {} -> {} points, the profile at i = {} to {}, margin at its "
                        "lowest height {:.6g} m",
                        factor, map.nx, nx, i0, i0 + map.nx - 1, level)
          : fmt::format("pad {}x for free boundaries: {}x{} -> {}x{} points, the map at columns {} to {}, rows {} to "
                        "{}, margin at its lowest height {:.6g} m",
                        factor, map.nx, map.ny, nx, ny, i0, i0 + map.nx - 1, j0, j0 + map.ny - 1, level));
  map.heights = std::move(heights);
  map.valid.clear();
  map.nx = nx;
  map.ny = ny;
}

}  // namespace halfspace::surface
