// Reads back what the stresses of a solved contact need from a result file
// (docs/file-format.md#result-output): the grid, the pressure and, from a
// friction solve, the shear tractions.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/material.hpp"

namespace halfspace::io {

struct ResultPressure {
  Grid grid;                     // shape and spacing from /pressure and dx, dy; boundary from the root attribute
  std::vector<double> pressure;  // Pa, (ny, nx) row-major
  std::optional<LayeredMaterial> coating;            // a coated half-space's five root attributes, if recorded
  std::optional<std::array<ElasticBody, 2>> bodies;  // both bodies' four root attributes, if recorded
  // A friction result's shear tractions /shear_x, /shear_y (Pa, the traction
  // body 1 exerts on body 2, like the pressure's layout); empty if absent.
  std::vector<double> shear_x;
  std::vector<double> shear_y;

  bool has_shear() const { return !shear_x.empty(); }
};

// Throws FileError naming the file and what is missing or wrong: not HDF5,
// no /pressure (rank 1 or 2, finite), no positive dx (and dy in 2D), no
// root attribute 'boundary' ("periodic" or "free"), some but not all of the
// coating's attributes, or coating attributes out of range (likewise both
// bodies' body1_E, body1_nu, body2_E, body2_nu); and for one of
// /shear_x, /shear_y without the other, or either not finite or not of the
// pressure's shape.
ResultPressure read_result_pressure(const std::filesystem::path& path);

}  // namespace halfspace::io
