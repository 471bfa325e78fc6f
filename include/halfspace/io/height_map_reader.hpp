// One entry point for every height-map format: chooses the reader by the
// file's extension or an explicit format, and returns heights in metres.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "halfspace/height_map.hpp"
#include "halfspace/io/length_unit.hpp"

namespace halfspace::io {

enum class HeightMapFormat {
  automatic,    // by extension (see format_from_extension)
  hdf5,         // HDF5 and NetCDF-4 (read_hdf5_height_map)
  npy,          // NumPy .npy (read_npy_height_map)
  text_matrix,  // plain-text matrix (read_text_matrix)
  profile,      // text columns x, z or z alone (read_profile)
  x3p,          // ISO 25178-72 X3P (read_x3p_height_map)
  gsf,          // Gwyddion Simple Field (read_gsf_height_map)
};

// "auto", "hdf5", "npy", "matrix", "profile", "x3p", "gsf".
std::string_view to_string(HeightMapFormat format);
// Accepts the names above and the aliases h5, nc, netcdf (hdf5), text, txt,
// csv, dat (matrix). Throws InputError naming the value and the choices.
HeightMapFormat parse_height_map_format(std::string_view text);

// By extension, case-insensitively: .h5 .hdf5 .hdf .he5 .nc .nc4 -> hdf5;
// .npy -> npy; .txt .csv .dat .asc -> text matrix, or profile when the file
// starts like a Dektak export ("Scan Parameters"); .x3p -> x3p; .gsf -> gsf.
// Throws FileError naming the file and the known extensions otherwise.
HeightMapFormat format_from_extension(const std::filesystem::path& path);

struct ReadOptions {
  HeightMapFormat format = HeightMapFormat::automatic;
  // HDF5 only: the dataset to read; empty means "/height".
  std::string dataset;
  // Unit of lengths in files that state none (npy, text matrix, profile and
  // GSF columns without a unit); metres if not given. Not for HDF5 or X3P,
  // whose lengths are metres by definition.
  std::optional<LengthUnit> unit;
};

// Reads `path` with the reader of options.format (or of its extension).
// Every reader returns heights in metres, dx/dy in metres (0 when the file
// does not say), non-finite or masked points as invalid (HeightMap::valid),
// and a `source` naming the file and format. Throws InputError when an
// option does not apply to the format (a dataset for npy, a unit for X3P)
// and FileError, naming the file, for everything wrong with the file.
HeightMap read_height_map(const std::filesystem::path& path, const ReadOptions& options = {});

// The format read_height_map reads `path` in, after the same checks of the
// options against it (same exceptions): options.format, or the extension's.
HeightMapFormat checked_format(const std::filesystem::path& path, const ReadOptions& options);

// The HDF5 dataset read_height_map reads: options.dataset, or "/height".
std::string hdf5_dataset(const ReadOptions& options);

}  // namespace halfspace::io
