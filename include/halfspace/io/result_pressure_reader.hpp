// Reads back what the stresses of a solved contact need from a result file
// (docs/file-format.md#result-output): the grid and the pressure.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/layered_material.hpp"

namespace halfspace::io {

struct ResultPressure {
  Grid grid;                     // shape and spacing from /pressure and dx, dy; boundary from the root attribute
  std::vector<double> pressure;  // Pa, (ny, nx) row-major
  std::optional<LayeredMaterial> coating;  // a coated half-space's five root attributes, if recorded
};

// Throws FileError naming the file and what is missing or wrong: not HDF5,
// no /pressure (rank 1 or 2, finite), no positive dx (and dy in 2D), no
// root attribute 'boundary' ("periodic" or "free"), some but not all of the
// coating's attributes, or coating attributes out of range.
ResultPressure read_result_pressure(const std::filesystem::path& path);

}  // namespace halfspace::io
