// Private: the writing conventions of the result file (attribute types,
// chunked and compressed field datasets, the root summary, the atomic
// temporary-and-rename write), defined once in result_writer.cpp and shared
// with the other writers (sweep results, generated height maps).
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string_view>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/io/result_writer.hpp"
#include "halfspace/solvers/solve_result.hpp"

namespace halfspace::io::detail {

// Scalar attributes: float64 LE, int64 LE, variable-length UTF-8 (invalid
// bytes replaced by U+FFFD). Throw FileError with the reason (no path).
void write_double_attribute(hid_t location, const char* name, double value);
void write_int64_attribute(hid_t location, const char* name, std::int64_t value);
void write_string_attribute(hid_t location, const char* name, std::string_view value);

// A dataset of shape `dims` under `location` (a file or group; `name` may be
// relative), contiguous up to 65536 elements, else chunked in whole rows
// with shuffle + deflate; `units` (may be null) becomes its string attribute.
void write_array_dataset(hid_t location, const char* name, const std::vector<hsize_t>& dims, hid_t file_type,
                         hid_t memory_type, const void* data, const char* units);

// The root attributes of a result file (format, grid, E*, load mode, the
// result's summary, provenance, statistics) for `result`.
void write_result_attributes(hid_t root, const Grid& grid, const SolveResult& result, const ResultMetadata& metadata);

// Checks the output's directory, assembles the file in memory by calling
// fill(file), writes it as <path>.tmp-<pid>, syncs and renames it onto
// `path`. Throws FileError "cannot write output '<path>': <reason>"; no
// partial file is left behind.
void write_file_atomically(const std::filesystem::path& path, const std::function<void(hid_t file)>& fill);

// The same for bytes already assembled (a CSV table).
void write_bytes_atomically(const std::filesystem::path& path, const std::vector<char>& bytes);

}  // namespace halfspace::io::detail
