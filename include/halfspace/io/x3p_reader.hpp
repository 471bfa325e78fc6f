// Reads a height map from an ISO 25178-72 (ISO 5436-2) .x3p file: a zip
// archive holding main.xml and the binary point data.
#pragma once

#include <filesystem>

#include "halfspace/height_map.hpp"

namespace halfspace::io {

// Reads `path`: a surface (FeatureType SUR) or profile (PRF) on a regular
// grid (incremental CX and CY axes), one layer, with z stored in bindata
// (Record3 DataLink, DataType I int16, L int32, F float32 or D float64,
// little-endian, x fastest) or as text (Record3 DataList). Heights are
// z = CZ.Increment * stored + CZ.Offset in metres; dx, dy are the CX and CY
// increments. Invalid points, marked by the validity bit mask (ValidPointsLink,
// one bit per point, least significant bit first, 1 = valid), by non-finite
// float values or by empty text data, are returned in HeightMap::valid with
// the full grid; cropping or filling them is preparation. The MD5 checksums
// that the file states (of main.xml in Record4's checksum file, of the data
// and validity files in Record3) are verified. Throws FileError naming the
// file and what is wrong: not a zip archive, a damaged archive or member,
// malformed XML, a missing element, an unsupported layout (point cloud,
// absolute x/y axes, several layers, a rotation), a data file of the wrong
// size, or a checksum mismatch.
HeightMap read_x3p_height_map(const std::filesystem::path& path);

}  // namespace halfspace::io
