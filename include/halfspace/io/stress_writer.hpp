// Writes a stress volume (halfspace/stress/stress_volume.hpp) to HDF5: the
// `/stress` group of a result file, or a file of its own made by the `stress`
// command (layout in docs/file-format.md#stress-output).
#pragma once

#include <filesystem>
#include <span>
#include <string>

#include "halfspace/grid.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/stress/stress_volume.hpp"

namespace halfspace::io {

// Under `root`: the group `stress` with `depths` (m, (nz)) and sigma_xx,
// sigma_yy, sigma_zz, sigma_xy, sigma_xz, sigma_yz, von_mises, max_shear,
// hydrostatic (Pa, (nz, ny, nx); 1D (nz, n)), the group attribute
// poisson_ratio, and the root attributes max_von_mises (Pa) and its position
// max_von_mises_x, _y, _z (m). Below a coating also `in_layer` ((nz), 1 for a
// depth in the layer, 0 in the substrate) and the attributes layer_thickness
// (m), layer_poisson_ratio and substrate_poisson_ratio.
void write_stress_group(const Hdf5Node& root, const Grid& grid, const stress::StressVolume& volume, double nu);

struct StressFileMetadata {
  std::string source;        // the result file the pressure came from
  std::string command_line;  // the full command line
};

// A file of its own: root attributes format ("halfspace-stress"), the grid
// (dimension, nx, ny, dx, dy, boundary) and provenance, the `/pressure` the
// stresses come from, and the `/stress` group. Atomic, like every output
// (output_file.hpp); throws FileError naming the path.
void write_stress_file(const std::filesystem::path& path, const Grid& grid, std::span<const double> pressure,
                       const stress::StressVolume& volume, double nu, const StressFileMetadata& metadata);

}  // namespace halfspace::io
