// Private helpers shared by the height-map readers: one error format naming
// the file and the format, whole-file reading, recognising what a mislabelled
// file really is, and marking non-finite heights as invalid points.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "halfspace/io/height_map.hpp"

namespace halfspace::io::detail {

// What is being read; every message starts "cannot read height map '<path>'
// as <format>: " so that it can be found in the log of a batch run.
struct ReadTarget {
  const std::filesystem::path& path;
  std::string_view format;  // "a NumPy .npy file", "a text matrix", ...

  [[noreturn]] void fail(std::string_view what) const;
};

// The whole file. Throws FileError when it is missing, a directory, or
// cannot be read (with the operating system's reason).
std::string read_file_bytes(const ReadTarget& target);

// What the first bytes say the file is ("an HDF5 file", "a zip archive (X3P
// files are zip archives)", ...), or an empty string when they say nothing.
std::string describe_signature(std::string_view bytes);

// " (the file looks like <what>; pass --format <name>)" when the signature is
// recognised, else "". Appended to "wrong magic" messages.
std::string signature_hint(std::string_view bytes);

// Up to `count` leading bytes, printable ASCII kept and the rest escaped.
std::string quoted_bytes(std::string_view bytes, std::size_t count);

// Marks every non-finite height invalid (valid = 0, height NaN), keeping
// points already marked; leaves `valid` empty when every point is valid.
void mark_non_finite_invalid(HeightMap& map);

// nx * ny, or a FileError when a header's sizes overflow or cannot fit in
// memory as doubles.
std::size_t checked_point_count(std::uint64_t nx, std::uint64_t ny, const ReadTarget& target);

// "(j, i) = (3, 7)" for a map, "i = 7" for a profile.
std::string point_text(std::size_t index, std::size_t nx, int dimension);

}  // namespace halfspace::io::detail
