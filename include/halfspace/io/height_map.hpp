// A surface height map in metres with its spacing and where it came from.
#pragma once

#include <cstddef>
#include <string>

#include <Eigen/Core>

namespace halfspace::io {

struct HeightMap {
  int dimension = 2;      // 1 for a profile, 2 for a map
  std::size_t nx = 0;     // columns (points along x)
  std::size_t ny = 1;     // rows (points along y); 1 for a profile
  double dx = 0.0;        // m; 0 when the file does not say
  double dy = 0.0;        // m; 0 for a profile or when the file does not say
  Eigen::ArrayXd heights; // m, (ny, nx) row-major: heights[j * nx + i]
  std::string source;     // "file.h5:/height", for the output's provenance
};

}  // namespace halfspace::io
