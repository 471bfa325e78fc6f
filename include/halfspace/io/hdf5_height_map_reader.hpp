// Reads a height map from an HDF5 file: a rank-1 (profile) or rank-2 (ny, nx)
// float dataset in metres, spacing from the root attributes dx and dy.
#pragma once

#include <filesystem>
#include <string>

#include "halfspace/height_map.hpp"

namespace halfspace::io {

// What a non-finite height (NaN, inf) means: an error, or an invalid point
// (HeightMap::valid) for the preparation step to fill, crop or refuse.
enum class NonFiniteHeights { reject, mark_invalid };

// Reads `dataset` (default "/height") of `path`. dx/dy are taken from root
// attributes "dx"/"dy" when present (else 0, to be supplied by the caller).
// Throws FileError naming the file and dataset when the file is missing or
// not HDF5, the dataset is missing, of rank other than 1 or 2, not numeric,
// has fewer than 2 points per axis, or (with NonFiniteHeights::reject) holds
// a non-finite value (naming its index). A dataset "valid" next to the
// heights (the shared layout: 1 measured, 0 filled in) marks its zeros as
// invalid points, keeping their stored heights; it must be an integer array
// of the same shape.
HeightMap read_hdf5_height_map(const std::filesystem::path& path, const std::string& dataset = "/height",
                               NonFiniteHeights non_finite = NonFiniteHeights::reject);

}  // namespace halfspace::io
