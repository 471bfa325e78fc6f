// Reads a height map from a Gwyddion Simple Field (.gsf) file.
#pragma once

#include <filesystem>
#include <optional>

#include "halfspace/height_map.hpp"
#include "halfspace/io/length_unit.hpp"

namespace halfspace::io {

// Reads `path`: the magic line "Gwyddion Simple Field 1.0", "name = value"
// header lines, 1 to 4 NUL bytes aligning the data to a multiple of 4, then
// XRes * YRes little-endian float32 values, row by row (row j = y, from the
// top as Gwyddion shows it). XRes and YRes are required; dx = XReal / XRes
// and dy = YReal / YRes converted from XYUnits, heights from ZUnits (m, mm,
// um, nm, ... ; see length_unit.hpp). Without XReal/YReal the spacing is 0
// (the caller supplies it); without XYUnits/ZUnits the lengths are taken in
// `unit` (metres if not given). YRes = 1 gives a profile. NaN values become
// invalid points. Throws FileError naming the file for a wrong magic, a
// malformed or truncated header, a non-length unit, or data shorter or
// longer than XRes * YRes values.
HeightMap read_gsf_height_map(const std::filesystem::path& path, const std::optional<LengthUnit>& unit = std::nullopt);

}  // namespace halfspace::io
