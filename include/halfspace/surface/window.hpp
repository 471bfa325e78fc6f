// Selecting a rectangular window (a sub-grid) of a height map.
#pragma once

#include <cstddef>
#include <string_view>

#include "halfspace/height_map.hpp"

namespace halfspace::surface {

// The window's first column i0 and row j0 (0-based) and its size nx x ny.
// A profile uses i0 and nx; j0 = 0, ny = 1.
struct Window {
  std::size_t i0 = 0;
  std::size_t j0 = 0;
  std::size_t nx = 0;
  std::size_t ny = 1;
  int dimension = 2;  // 1 when parsed from "I0,NX"
};

// "I0,J0,NX,NY" (a map) or "I0,NX" (a profile), non-negative integers.
// Throws InputError naming the text and the expected form.
Window parse_window(std::string_view text);

// Replaces the map by the window (heights, validity), keeping dx and dy.
// Throws InputError naming the window and the map's size when the window
// is smaller than 2 points along an axis, extends past the map, or does not
// match its dimension. Appends a line to map.preparation.
void select_window(HeightMap& map, const Window& window);

// The sub-grid [i0, i0 + nx) x [j0, j0 + ny) without checks or a record, for
// other preparation steps.
void extract_window(HeightMap& map, std::size_t i0, std::size_t j0, std::size_t nx, std::size_t ny);

}  // namespace halfspace::surface
