// Reads back what the stresses of a solved contact need from a result file
// (docs/file-format.md#result-output): the grid and the pressure.
#pragma once

#include <filesystem>
#include <vector>

#include "halfspace/grid.hpp"

namespace halfspace::io {

struct ResultPressure {
  Grid grid;                     // shape and spacing from /pressure and dx, dy; boundary from the root attribute
  std::vector<double> pressure;  // Pa, (ny, nx) row-major
};

// Throws FileError naming the file and what is missing or wrong: not HDF5,
// no /pressure (rank 1 or 2, finite), no positive dx (and dy in 2D), no
// root attribute 'boundary' ("periodic" or "free").
ResultPressure read_result_pressure(const std::filesystem::path& path);

}  // namespace halfspace::io
