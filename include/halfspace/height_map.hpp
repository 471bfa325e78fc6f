// A surface height map in metres with its spacing, which points were measured,
// where it came from and what was done to it before the solve.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace halfspace {

struct HeightMap {
  int dimension = 2;       // 1 for a profile, 2 for a map
  std::size_t nx = 0;      // columns (points along x)
  std::size_t ny = 1;      // rows (points along y); 1 for a profile
  double dx = 0.0;         // m; 0 when the file does not say
  double dy = 0.0;         // m; 0 for a profile or when the file does not say
  Eigen::ArrayXd heights;  // m, (ny, nx) row-major: heights[j * nx + i]
  // Validity of each point, same layout as heights: 1 measured, 0 invalid (a
  // dropout marked by the file's mask or by a non-finite value; its height is
  // NaN). Empty means every point is valid.
  std::vector<std::uint8_t> valid;
  std::string source;  // "file.h5:/height", for the output's provenance
  // One line per preparation step applied after reading (window, invalid
  // points, detrending, resampling, padding), in order; written to the
  // result file.
  std::vector<std::string> preparation;

  std::size_t size() const { return nx * ny; }
  bool all_valid() const { return valid.empty(); }
  bool is_valid(std::size_t k) const { return valid.empty() || valid[k] != 0; }
};

}  // namespace halfspace
