// Reads a height map from an HDF5 file: a rank-1 (profile) or rank-2 (ny, nx)
// float dataset in metres, spacing from the root attributes dx and dy.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>

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

// How one of several processes reads its rows of a map with the parallel
// HDF5 (src/mpi/parallel_height_map_reader.cpp sets it up).
struct Hdf5RowReading {
  std::int64_t file_access = 0;  // hid_t of a file access property list (an MPI-IO one); 0 is H5P_DEFAULT
  std::int64_t transfer = 0;     // hid_t of a dataset transfer property list (collective)
  // The rows {first_row, rows} of an (ny, nx) map this process reads.
  std::function<std::pair<std::size_t, std::size_t>(std::size_t nx, std::size_t ny)> rows;
};

// A map of which this process holds some rows: map.nx, map.ny, spacing and
// source are the whole map's; map.heights and map.valid hold `rows` rows
// from first_row on.
struct HeightMapRows {
  HeightMap map;
  std::size_t first_row = 0;
  std::size_t rows = 0;
};

// read_hdf5_height_map(path, dataset, NonFiniteHeights::mark_invalid) with
// `reading`'s property lists, reading only the rows reading.rows picks (of a
// profile, every process reads it all). Every check is the serial reader's,
// with its messages. Collective when the property lists are: every process
// calls it with the same file.
HeightMapRows read_hdf5_height_map_rows(const std::filesystem::path& path, const std::string& dataset,
                                        const Hdf5RowReading& reading);

}  // namespace halfspace::io
