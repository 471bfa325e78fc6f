// Resampling a height map onto another number of cells over the same
// domain: a finer grid for a solve at a finer resolution than the
// instrument's, a coarser one to bring a large scan within reach.
#pragma once

#include <cstddef>
#include <string_view>

#include "halfspace/height_map.hpp"

namespace halfspace::surface {

// The resampled grid: nx x ny cells (nx for a profile).
struct Resample {
  std::size_t nx = 0;
  std::size_t ny = 1;
  int dimension = 2;  // 1 when parsed from "N"
};

// The largest refinement along an axis (the new cells per old cell): beyond
// it the map holds no information the interpolation did not invent, and a
// mistyped count would ask for hundreds of times the memory.
inline constexpr std::size_t kMaxResampleRefinement = 16;

// "NXxNY" (a map) or "N" (a profile), positive integers. Throws InputError
// naming the text and the expected form.
Resample parse_resample(std::string_view text);

// Replaces the map's heights by their values on nx x ny cells spanning the
// same lengths (nx dx by ny dy; the spacing becomes L / n), axis by axis
// through the piecewise-linear interpolant of the heights at the old cells'
// centres, its first and last pieces extended over the outer half cells:
// where an axis is refined, the interpolant at the new centres; where it is
// coarsened, its mean over each new cell (no aliasing of the wavelengths the
// new grid cannot hold); an equal count is left alone. Both keep a plane
// that plane exactly. Throws InputError naming the counts and the
// map when the map has invalid points or no spacing, a count is below 2 or
// refines an axis more than kMaxResampleRefinement times, or the dimension
// differs; throws when the new map does not fit in the memory available.
// Appends a line to map.preparation.
void resample(HeightMap& map, const Resample& resample);

}  // namespace halfspace::surface
