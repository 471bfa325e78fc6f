// Reads a 1D profile from a text file of columns x, z or z alone, including
// the CSV export of Bruker Dektak stylus profilometers.
#pragma once

#include <filesystem>
#include <optional>

#include "halfspace/height_map.hpp"
#include "halfspace/io/length_unit.hpp"

namespace halfspace::io {

// Reads `path` as a profile (dimension 1). The data rows hold z alone or
// x and z, separated as in a text matrix (whitespace, ',' or ';'); '#'/'%'
// lines are comments. One header line of column names may precede the data;
// a unit in a name ("x [um]", "z (nm)", "Lateral um", "Raw Micrometer") is
// applied to that column. A file starting with the line "Scan Parameters" is
// read as a Dektak export: its data follow the line "Scan Data".
//
// With an x column, x must increase uniformly: the spacing is the least-
// squares slope of x against the row index, and every x must lie within the
// precision it is printed with (0.1 for "12.3") of that uniform grid; the
// first x that does not is reported with its line. A Dektak header's
// "Length" gives dx = Length / n when it agrees with the x column to that
// precision. Without an x column dx = 0 (the caller supplies it).
//
// `unit` applies to columns whose name states no unit (metres if not
// given); a unit that contradicts the file's is an InputError. Non-finite z
// values become invalid points; a non-finite x is an error. Throws FileError
// naming the file (and line) otherwise.
HeightMap read_profile(const std::filesystem::path& path, const std::optional<LengthUnit>& unit = std::nullopt);

}  // namespace halfspace::io
