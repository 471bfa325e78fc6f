// Windows of height maps: parsing "I0,J0,NX,NY" and cutting the sub-grid.
#include "halfspace/surface/window.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <optional>
#include <string>
#include <vector>

#include "halfspace/checked_size.hpp"
#include "halfspace/error.hpp"

namespace halfspace::surface {
namespace {

// Where a window that does not fit goes past the map along one axis: "it
// ends at column 99"; "it starts at column 5000" when the start is already
// outside, and "it has 2^64 - 1 columns" when the end is not even countable
// (computed unchecked, it wraps round to a small column).
std::string extent(std::string_view axis, std::size_t first, std::size_t count, std::size_t available) {
  if (first >= available) return fmt::format("it starts at {} {}", axis, first);
  if (const std::optional<std::size_t> end = checked_add(first, count - 1)) {
    return fmt::format("it ends at {} {}", axis, *end);
  }
  return fmt::format("it has {} {}s", count, axis);
}

}  // namespace

Window parse_window(std::string_view text) {
  std::vector<std::size_t> values;
  std::size_t begin = 0;
  const auto invalid = [&] {
    return InputError(
        fmt::format("window '{}' is invalid: expected I0,J0,NX,NY (first column, first row, columns, "
                    "rows; 0-based) for a map or I0,NX for a profile",
                    text));
  };
  while (begin <= text.size()) {
    std::size_t end = text.find(',', begin);
    if (end == std::string_view::npos) end = text.size();
    std::string_view field = text.substr(begin, end - begin);
    while (!field.empty() && field.front() == ' ') field.remove_prefix(1);
    while (!field.empty() && field.back() == ' ') field.remove_suffix(1);
    std::size_t value = 0;
    const auto [stop, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (field.empty() || error != std::errc() || stop != field.data() + field.size()) throw invalid();
    values.push_back(value);
    begin = end + 1;
  }
  if (values.size() == 2) return Window{values[0], 0, values[1], 1, 1};
  if (values.size() == 4) return Window{values[0], values[1], values[2], values[3], 2};
  throw invalid();
}

void extract_window(HeightMap& map, std::size_t i0, std::size_t j0, std::size_t nx, std::size_t ny) {
  Eigen::ArrayXd heights(static_cast<Eigen::Index>(nx * ny));
  std::vector<std::uint8_t> valid;
  if (!map.valid.empty()) valid.resize(nx * ny);
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t from = (j0 + j) * map.nx + (i0 + i);
      heights[static_cast<Eigen::Index>(j * nx + i)] = map.heights[static_cast<Eigen::Index>(from)];
      if (!valid.empty()) valid[j * nx + i] = map.valid[from];
    }
  }
  map.heights = std::move(heights);
  map.valid = std::move(valid);
  map.nx = nx;
  map.ny = ny;
  // An all-valid window needs no mask.
  if (std::find(map.valid.begin(), map.valid.end(), std::uint8_t{0}) == map.valid.end()) map.valid.clear();
}

void select_window(HeightMap& map, const Window& window) {
  const std::string shape =
      map.dimension == 1 ? fmt::format("{}-point profile", map.nx) : fmt::format("{}x{} map (nx x ny)", map.nx, map.ny);
  const std::string named = window.dimension == 1 ? fmt::format("window i0 = {}, nx = {}", window.i0, window.nx)
                                                  : fmt::format("window i0 = {}, j0 = {}, nx = {}, ny = {}", window.i0,
                                                                window.j0, window.nx, window.ny);
  if (window.dimension != map.dimension && !(map.dimension == 1 && window.j0 == 0 && window.ny == 1)) {
    throw InputError(fmt::format("{} is invalid for the {} of {}: give {}", named, shape, map.source,
                                 map.dimension == 1 ? "I0,NX" : "I0,J0,NX,NY"));
  }
  if (window.nx < 2 || (map.dimension == 2 && window.ny < 2)) {
    throw InputError(fmt::format("{} is invalid: need at least 2 points along each axis", named));
  }
  if (window.i0 >= map.nx || window.nx > map.nx - window.i0) {
    throw InputError(fmt::format("{} is invalid: {} but the {} of {} has columns 0 to {}", named,
                                 extent("column", window.i0, window.nx, map.nx), shape, map.source, map.nx - 1));
  }
  if (window.j0 >= map.ny || window.ny > map.ny - window.j0) {
    throw InputError(fmt::format("{} is invalid: {} but the {} of {} has rows 0 to {}", named,
                                 extent("row", window.j0, window.ny, map.ny), shape, map.source, map.ny - 1));
  }
  const std::size_t old_nx = map.nx;
  const std::size_t old_ny = map.ny;
  extract_window(map, window.i0, window.j0, window.nx, window.ny);
  map.preparation.push_back(
      map.dimension == 1
          ? fmt::format("window: points {} to {} of {} (i0 = {}, nx = {})", window.i0, window.i0 + window.nx - 1,
                        old_nx, window.i0, window.nx)
          : fmt::format("window: columns {} to {}, rows {} to {} of the {}x{} map (i0 = {}, j0 = {}, nx = {}, ny = {})",
                        window.i0, window.i0 + window.nx - 1, window.j0, window.j0 + window.ny - 1, old_nx, old_ny,
                        window.i0, window.j0, window.nx, window.ny));
}

}  // namespace halfspace::surface
