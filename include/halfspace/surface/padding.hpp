// Padding a height map with a non-contacting margin, for free boundaries.
#pragma once

#include "halfspace/height_map.hpp"

namespace halfspace::surface {

// Smallest and largest accepted padding factor.
inline constexpr double kMinPadFactor = 1.0;
inline constexpr double kMaxPadFactor = 16.0;

// Embeds the map in a grid `factor` times larger along each axis
// (ceil(factor * nx) x ceil(factor * ny); a profile only along x), centred,
// with the margin at the lowest height of the map. With free boundaries the
// half-space outside the grid already carries no pressure, so a margin that
// stays out of contact leaves the pressure on the map unchanged; what it adds
// is the surrounding surface in the result (the elastic displacement and gap
// around the contact patch). At the lowest measured level the margin cannot
// touch before the deepest valley of the map does. Requires a map without
// invalid points. Throws InputError for a factor outside [1, 16] or invalid
// points. Appends a line to map.preparation (none for factor 1).
void pad_for_free_boundary(HeightMap& map, double factor);

}  // namespace halfspace::surface
