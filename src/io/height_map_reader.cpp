// The format dispatcher: extension table, format names, option checks.
#include "halfspace/io/height_map_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <fstream>
#include <system_error>
#include <utility>

#include "halfspace/error.hpp"
#include "halfspace/io/gsf_reader.hpp"
#include "halfspace/io/hdf5_height_map_reader.hpp"
#include "halfspace/io/npy_reader.hpp"
#include "halfspace/io/profile_reader.hpp"
#include "halfspace/io/text_matrix_reader.hpp"
#include "halfspace/io/x3p_reader.hpp"

namespace halfspace::io {
namespace {

constexpr std::array<std::pair<std::string_view, HeightMapFormat>, 17> kNames{{
    {"auto", HeightMapFormat::automatic},
    {"hdf5", HeightMapFormat::hdf5},
    {"h5", HeightMapFormat::hdf5},
    {"nc", HeightMapFormat::hdf5},
    {"netcdf", HeightMapFormat::hdf5},
    {"npy", HeightMapFormat::npy},
    {"matrix", HeightMapFormat::text_matrix},
    {"text", HeightMapFormat::text_matrix},
    {"txt", HeightMapFormat::text_matrix},
    {"csv", HeightMapFormat::text_matrix},
    {"dat", HeightMapFormat::text_matrix},
    {"profile", HeightMapFormat::profile},
    {"x3p", HeightMapFormat::x3p},
    {"gsf", HeightMapFormat::gsf},
    {"asc", HeightMapFormat::text_matrix},
    {"hdf", HeightMapFormat::hdf5},
    {"nc4", HeightMapFormat::hdf5},
}};

constexpr std::array<std::pair<std::string_view, HeightMapFormat>, 13> kExtensions{{
    {".h5", HeightMapFormat::hdf5},
    {".hdf5", HeightMapFormat::hdf5},
    {".hdf", HeightMapFormat::hdf5},
    {".he5", HeightMapFormat::hdf5},
    {".nc", HeightMapFormat::hdf5},
    {".nc4", HeightMapFormat::hdf5},
    {".npy", HeightMapFormat::npy},
    {".txt", HeightMapFormat::text_matrix},
    {".csv", HeightMapFormat::text_matrix},
    {".dat", HeightMapFormat::text_matrix},
    {".asc", HeightMapFormat::text_matrix},
    {".x3p", HeightMapFormat::x3p},
    {".gsf", HeightMapFormat::gsf},
}};

std::string lower(std::string_view text) {
  std::string result(text);
  std::transform(result.begin(), result.end(), result.begin(),
                 [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
  return result;
}

// A Dektak CSV export is a profile whatever its extension says.
bool starts_like_dektak_export(const std::filesystem::path& path) {
  // Only a regular file can be looked into and then read again from its start.
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;
  std::ifstream in(path, std::ios::binary);
  std::string head(15, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  return in.gcount() == static_cast<std::streamsize>(head.size()) && head == "Scan Parameters";
}

}  // namespace

std::string_view to_string(HeightMapFormat format) {
  switch (format) {
    case HeightMapFormat::automatic:
      return "auto";
    case HeightMapFormat::hdf5:
      return "hdf5";
    case HeightMapFormat::npy:
      return "npy";
    case HeightMapFormat::text_matrix:
      return "matrix";
    case HeightMapFormat::profile:
      return "profile";
    case HeightMapFormat::x3p:
      return "x3p";
    case HeightMapFormat::gsf:
      return "gsf";
  }
  return "unknown";
}

HeightMapFormat parse_height_map_format(std::string_view text) {
  const std::string name = lower(text);
  for (const auto& [known, format] : kNames) {
    if (name == known) return format;
  }
  throw InputError(
      fmt::format("height-map format '{}' is unknown: use auto, hdf5 (h5, nc), npy, matrix (txt, csv, "
                  "dat), profile, x3p or gsf",
                  text));
}

HeightMapFormat format_from_extension(const std::filesystem::path& path) {
  const std::string extension = lower(path.extension().string());
  for (const auto& [known, format] : kExtensions) {
    if (extension != known) continue;
    if (format == HeightMapFormat::text_matrix && starts_like_dektak_export(path)) return HeightMapFormat::profile;
    return format;
  }
  throw FileError(
      fmt::format("cannot read height map '{}': the extension '{}' does not say the format; known "
                  "extensions are .h5 .hdf5 .nc (HDF5), .npy, .txt .csv .dat .asc (text matrix), .x3p "
                  "and .gsf; set the format",
                  path.string(), path.extension().string()));
}

HeightMapFormat checked_format(const std::filesystem::path& path, const ReadOptions& options) {
  const HeightMapFormat format =
      options.format == HeightMapFormat::automatic ? format_from_extension(path) : options.format;
  if (!options.dataset.empty() && format != HeightMapFormat::hdf5) {
    throw InputError(fmt::format("height map '{}': a dataset ('{}') applies only to HDF5 files, not to the {} format",
                                 path.string(), options.dataset, to_string(format)));
  }
  if (options.unit && (format == HeightMapFormat::hdf5 || format == HeightMapFormat::x3p)) {
    throw InputError(
        fmt::format("height map '{}': a unit ({}) does not apply to the {} format, whose lengths are "
                    "always metres",
                    path.string(), options.unit->name, to_string(format)));
  }
  return format;
}

std::string hdf5_dataset(const ReadOptions& options) {
  return options.dataset.empty() ? "/height" : options.dataset;
}

HeightMap read_height_map(const std::filesystem::path& path, const ReadOptions& options) {
  const HeightMapFormat format = checked_format(path, options);
  const LengthUnit unit = options.unit.value_or(LengthUnit{"m", 1.0});
  switch (format) {
    case HeightMapFormat::hdf5:
      return read_hdf5_height_map(path, hdf5_dataset(options), NonFiniteHeights::mark_invalid);
    case HeightMapFormat::npy:
      return read_npy_height_map(path, unit);
    case HeightMapFormat::text_matrix: {
      HeightMap map = read_text_matrix(path, unit);
      // Two columns are almost always x and z, not a map two points wide:
      // refuse to guess when the format was only inferred from the extension.
      if (options.format == HeightMapFormat::automatic && map.dimension == 2 && map.nx == 2) {
        throw FileError(
            fmt::format("cannot read height map '{}': it has 2 columns and {} rows; set the format to "
                        "profile to read it as x, z or to matrix to read it as a map 2 points wide",
                        path.string(), map.ny));
      }
      return map;
    }
    case HeightMapFormat::profile:
      return read_profile(path, options.unit);
    case HeightMapFormat::x3p:
      return read_x3p_height_map(path);
    case HeightMapFormat::gsf:
      return read_gsf_height_map(path, options.unit);
    case HeightMapFormat::automatic:
      break;
  }
  throw InputError("read_height_map: no format");
}

}  // namespace halfspace::io
