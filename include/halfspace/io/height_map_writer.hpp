// Writes a height map in the layout the readers accept (and the measured
// files in shared/data/topography use): dataset /height with root attributes
// dx, dy, so that `halfspace solve --height-map FILE` reads it directly.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "halfspace/grid.hpp"

namespace halfspace::io {

class Hdf5Node;

struct HeightMapMetadata {
  std::string source;        // what the surface is, e.g. "self-affine (H = 0.8, seed = 1)"
  std::string command_line;  // the command that made it
  bool periodic = false;     // whether the map repeats with the domain
  // Further root attributes, e.g. the generator's parameters.
  std::vector<std::pair<std::string, double>> numbers;
  std::vector<std::pair<std::string, std::int64_t>> integers;
  std::vector<std::pair<std::string, std::string>> strings;
};

// /height: float64, shape (nx,) in 1D or (ny, nx) in 2D, units "m". Root
// attributes dx, dy (float64, m; dy = 0 in 1D), nx, ny (int64), unit ("m"),
// layout, periodic (int64 0/1), source, command_line, halfspace_version, and
// those of `metadata`. Written atomically (temporary name, then rename).
// Throws InputError if the heights do not match the grid, FileError naming
// the path if the file cannot be written.
void write_height_map(const std::filesystem::path& path, const Grid& grid, std::span<const double> heights,
                      const HeightMapMetadata& metadata);

// The same contents under `root`, with `rows` the heights of the rows from
// `first_row` on (all of them for the serial file; a process's slab when
// several write one file collectively, each calling this alike).
void write_height_map_contents(const Hdf5Node& root, const Grid& grid, std::size_t first_row,
                               std::span<const double> rows, const HeightMapMetadata& metadata);

}  // namespace halfspace::io
