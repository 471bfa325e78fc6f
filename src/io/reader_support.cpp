// Shared reader helpers: errors, whole-file reads, signatures, invalid points.
#include "reader_support.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <system_error>

#include "halfspace/error.hpp"

namespace halfspace::io::detail {

void ReadTarget::fail(std::string_view what) const {
  throw FileError(fmt::format("cannot read height map '{}' as {}: {}", path.string(), format, what));
}

std::string read_file_bytes(const ReadTarget& target) {
  std::error_code error;
  const auto status = std::filesystem::status(target.path, error);
  if (!std::filesystem::exists(status)) target.fail("the file does not exist");
  if (std::filesystem::is_directory(status)) target.fail("the path is a directory, not a file");
  std::ifstream in(target.path, std::ios::binary);
  if (!in) target.fail(fmt::format("the file cannot be opened: {}", std::strerror(errno)));
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) target.fail(fmt::format("the file cannot be read: {}", std::strerror(errno)));
  return bytes;
}

std::string describe_signature(std::string_view bytes) {
  const auto starts = [&](std::string_view magic) { return bytes.substr(0, magic.size()) == magic; };
  using namespace std::string_view_literals;
  if (starts("\x89HDF\r\n\x1a\n"sv)) return "an HDF5 file";
  if (starts("PK\x03\x04"sv)) return "a zip archive (X3P files are zip archives)";
  if (starts("\x93NUMPY"sv)) return "a NumPy .npy file";
  if (starts("Gwyddion Simple Field"sv)) return "a Gwyddion Simple Field (.gsf) file";
  if (starts("CDF\x01"sv) || starts("CDF\x02"sv)) {
    return "a classic NetCDF-3 file (only NetCDF-4, which is HDF5, is read)";
  }
  return {};
}

std::string signature_hint(std::string_view bytes) {
  const std::string what = describe_signature(bytes);
  if (what.empty()) return {};
  std::string format;
  if (what.starts_with("an HDF5")) format = "hdf5";
  if (what.starts_with("a zip")) format = "x3p";
  if (what.starts_with("a NumPy")) format = "npy";
  if (what.starts_with("a Gwyddion")) format = "gsf";
  if (format.empty()) return fmt::format(" (the file looks like {})", what);
  return fmt::format(" (the file looks like {}; pass --format {})", what, format);
}

std::string quoted_bytes(std::string_view bytes, std::size_t count) {
  std::string text;
  for (const char c : bytes.substr(0, count)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f && c != '\\') {
      text.push_back(c);
    } else {
      text += fmt::format("\\x{:02x}", byte);
    }
  }
  return text;
}

void mark_non_finite_invalid(HeightMap& map) {
  const std::size_t count = static_cast<std::size_t>(map.heights.size());
  bool any_invalid = false;
  for (std::size_t k = 0; k < count && !any_invalid; ++k) {
    any_invalid = !map.is_valid(k) || !std::isfinite(map.heights[static_cast<Eigen::Index>(k)]);
  }
  if (!any_invalid) {
    map.valid.clear();
    return;
  }
  if (map.valid.empty()) map.valid.assign(count, 1);
  for (std::size_t k = 0; k < count; ++k) {
    double& h = map.heights[static_cast<Eigen::Index>(k)];
    if (!std::isfinite(h)) map.valid[k] = 0;
    if (map.valid[k] == 0) h = std::numeric_limits<double>::quiet_NaN();
  }
}

std::size_t checked_point_count(std::uint64_t nx, std::uint64_t ny, const ReadTarget& target) {
  const std::uint64_t limit = static_cast<std::uint64_t>(std::numeric_limits<Eigen::Index>::max()) / sizeof(double);
  if (nx != 0 && ny > limit / nx) {
    target.fail(fmt::format("a grid of {} x {} points is too large to hold in memory", nx, ny));
  }
  return static_cast<std::size_t>(nx * ny);
}

std::string point_text(std::size_t index, std::size_t nx, int dimension) {
  if (dimension == 1) return fmt::format("i = {}", index);
  return fmt::format("(j, i) = ({}, {})", index / nx, index % nx);
}

}  // namespace halfspace::io::detail
