// Reads a height map from a NumPy .npy file (format versions 1.0, 2.0, 3.0):
// a rank-1 array is a profile, a rank-2 array (ny, nx) a map.
#pragma once

#include <filesystem>

#include "halfspace/height_map.hpp"
#include "halfspace/io/length_unit.hpp"

namespace halfspace::io {

// Reads `path`. Accepted dtypes: float32 and float64 and the integer types
// (1 to 8 bytes, signed or unsigned), either byte order ('<', '>', '|', '=');
// C or Fortran order. The file holds no unit or spacing: heights are taken in
// `unit` (metres unless given) and dx = dy = 0 (the caller supplies them).
// Non-finite values become invalid points (HeightMap::valid). Throws
// FileError naming the file when the magic, the header or the dtype is
// wrong, or the data is shorter or longer than the header says.
HeightMap read_npy_height_map(const std::filesystem::path& path, const LengthUnit& unit = {"m", 1.0});

}  // namespace halfspace::io
