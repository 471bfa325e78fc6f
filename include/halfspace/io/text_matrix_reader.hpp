// Reads a height map from a plain-text matrix: one line per row of the map
// (y), numbers separated by whitespace, commas or semicolons.
#pragma once

#include <filesystem>

#include "halfspace/height_map.hpp"
#include "halfspace/io/length_unit.hpp"

namespace halfspace::io {

// Reads `path`: line r of the data is row j = r (y), field c is column i = c
// (x), so the file looks like the map printed row by row. Lines starting with
// '#' or '%' are comments; blank lines are skipped; numbers are read exactly
// (a file written with %.17g reads back bit for bit); "nan" and "inf" become
// invalid points. Heights are in `unit` (metres unless given); dx = dy = 0
// (the caller supplies them). A single row or a single column is a profile
// (dimension 1). Throws FileError naming the file and the line for binary
// content, a field that is not a number, an empty field, rows of different
// lengths, or fewer than 2 points.
HeightMap read_text_matrix(const std::filesystem::path& path, const LengthUnit& unit = {"m", 1.0});

}  // namespace halfspace::io
