// Shared reader helpers: errors, bounded reads, signatures, escaping, checked
// sizes, invalid points.
#include "reader_support.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include "halfspace/checked_size.hpp"
#include "halfspace/error.hpp"

namespace halfspace::io::detail {
namespace {

// Reads grow the buffer by at most this much at a time: a header that claims
// gigabytes costs only what the file really delivers.
constexpr std::size_t kReadChunk = std::size_t{16} << 20;
constexpr std::size_t kFirstPiece = std::size_t{64} << 10;

std::string type_of(const struct stat& status) {
  if (S_ISFIFO(status.st_mode)) return "a pipe (FIFO)";
  if (S_ISCHR(status.st_mode)) return "a character device";
  if (S_ISBLK(status.st_mode)) return "a block device";
  if (S_ISSOCK(status.st_mode)) return "a socket";
  return "not a regular file";
}

void check_exists(const ReadTarget& target) {
  std::error_code error;
  const auto status = std::filesystem::status(target.path, error);
  if (!std::filesystem::exists(status)) target.fail("the file does not exist");
  if (std::filesystem::is_directory(status)) target.fail("the path is a directory, not a file");
}

}  // namespace

void ReadTarget::fail(std::string_view what) const {
  throw FileError(fmt::format("cannot read height map '{}' as {}: {}", path.string(), format, what));
}

InputFile::InputFile(const ReadTarget& target) : target_(target) {
  check_exists(target);
  fd_ = ::open(target.path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) target.fail(fmt::format("the file cannot be opened: {}", std::strerror(errno)));
  struct stat status {};
  if (::fstat(fd_, &status) != 0) {
    const int error = errno;
    ::close(fd_);
    fd_ = -1;
    target.fail(fmt::format("the file cannot be examined: {}", std::strerror(error)));
  }
  if (S_ISDIR(status.st_mode)) {
    ::close(fd_);
    fd_ = -1;
    target.fail("the path is a directory, not a file");
  }
  regular_ = S_ISREG(status.st_mode);
  size_ = regular_ && status.st_size > 0 ? static_cast<std::uint64_t>(status.st_size) : 0;
}

InputFile::~InputFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::optional<std::uint64_t> InputFile::stated_size() const {
  if (!regular_ || size_ == 0) return std::nullopt;
  return size_;
}

std::size_t InputFile::read_some(char* buffer, std::size_t count) {
  std::size_t done = 0;
  while (done < count) {
    const ssize_t got = ::read(fd_, buffer + done, std::min<std::size_t>(count - done, kReadChunk));
    if (got < 0) {
      if (errno == EINTR) continue;
      target_.fail(fmt::format("the file cannot be read at byte {}: {}", done, std::strerror(errno)));
    }
    if (got == 0) break;
    done += static_cast<std::size_t>(got);
  }
  return done;
}

std::size_t InputFile::append(std::string& bytes, std::size_t count) {
  std::size_t done = 0;
  while (done < count) {
    // The buffer grows with what has arrived (at most doubling), not with
    // what was asked for: a request for more than the file holds is cheap.
    const std::size_t piece = std::min({count - done, kReadChunk, std::max(kFirstPiece, bytes.size())});
    const std::size_t old_size = bytes.size();
    bytes.resize(old_size + piece);
    const std::size_t got = read_some(bytes.data() + old_size, piece);
    bytes.resize(old_size + got);
    done += got;
    if (got < piece) break;
  }
  return done;
}

bool InputFile::at_end() {
  char byte = 0;
  return read_some(&byte, 1) == 0;
}

void require_regular_file(const ReadTarget& target) {
  check_exists(target);
  struct stat status {};
  if (::stat(target.path.c_str(), &status) != 0) {
    target.fail(fmt::format("the file cannot be examined: {}", std::strerror(errno)));
  }
  if (!S_ISREG(status.st_mode)) {
    target.fail(
        fmt::format("the path is {}; this format is read by seeking, so it must be a regular file (save "
                    "the data to a file first)",
                    type_of(status)));
  }
}

std::string read_text_file(const ReadTarget& target) {
  InputFile file(target);
  const std::size_t limit = file.is_regular()
                                ? std::max<std::size_t>(file.stated_size().value_or(0), kMaxStreamedTextBytes)
                                : kMaxStreamedTextBytes;
  std::string bytes;
  if (const auto size = file.stated_size())
    bytes.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(*size, limit)));
  while (bytes.size() <= limit) {
    const std::size_t before = bytes.size();
    const std::size_t got = file.append(bytes, std::min(kReadChunk, limit + 1 - before));
    check_is_text(std::string_view(bytes).substr(before), before, target);
    if (got == 0) return bytes;
  }
  target.fail(fmt::format("the file holds more than {} of text{}", byte_size_text(limit),
                          file.is_regular() ? " (it grew while being read)"
                                            : "; a pipe or device is read up to that size (save the data to a "
                                              "regular file to read more)"));
}

void check_is_text(std::string_view text, std::size_t offset, const ReadTarget& target) {
  for (std::size_t k = 0; k < text.size(); ++k) {
    const auto byte = static_cast<unsigned char>(text[k]);
    if (byte < 0x20 && byte != '\t' && byte != '\r' && byte != '\n' && byte != '\f' && byte != '\v') {
      const std::string hint = offset == 0 ? signature_hint(text) : std::string();
      target.fail(fmt::format("the file is not text: byte 0x{:02x} at offset {}{}", byte, offset + k,
                              hint.empty() ? " (a binary file of a format that is not read here?)" : hint));
    }
  }
}

std::string read_file_head(const ReadTarget& target, std::size_t count) {
  InputFile file(target);
  std::string bytes;
  file.append(bytes, count);
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
  return fmt::format(" (the file looks like {}; set the format to {})", what, format);
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

std::string printable(std::string_view text, std::size_t count) {
  const bool cut = text.size() > count;
  text = text.substr(0, count);
  std::string result;
  std::size_t k = 0;
  while (k < text.size()) {
    const auto byte = static_cast<unsigned char>(text[k]);
    if (byte >= 0x20 && byte < 0x7f && byte != '\\') {
      result.push_back(text[k++]);
      continue;
    }
    // A well-formed UTF-8 sequence of 2 to 4 bytes outside the C1 controls
    // (U+0080..U+009F, which some terminals obey) is kept as it is.
    const std::size_t length = byte >= 0xc2 && byte <= 0xdf   ? 2
                               : byte >= 0xe0 && byte <= 0xef ? 3
                               : byte >= 0xf0 && byte <= 0xf4 ? 4
                                                              : 0;
    bool keep =
        length != 0 && k + length <= text.size() && !(byte == 0xc2 && static_cast<unsigned char>(text[k + 1]) < 0xa0);
    for (std::size_t m = 1; keep && m < length; ++m) {
      keep = (static_cast<unsigned char>(text[k + m]) & 0xc0) == 0x80;
    }
    if (keep) {
      result.append(text.substr(k, length));
      k += length;
    } else {
      result += fmt::format("\\x{:02x}", byte);
      ++k;
    }
  }
  if (cut) result += "...";
  return result;
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
  const std::uint64_t count = nx * ny;
  const std::uint64_t memory = physical_memory_bytes();
  if (count > memory / sizeof(double)) {
    target.fail(
        fmt::format("a grid of {} x {} points needs {} for its heights alone, more than the {} of "
                    "memory this machine has",
                    nx, ny, byte_size_text(count * sizeof(double)), byte_size_text(memory)));
  }
  return static_cast<std::size_t>(count);
}

std::uint64_t physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return std::numeric_limits<std::uint64_t>::max();
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size);
}

std::uint64_t checked_product(std::uint64_t a, std::uint64_t b, std::string_view what, const ReadTarget& target) {
  static_assert(sizeof(std::size_t) == sizeof(std::uint64_t));
  const std::optional<std::size_t> product = checked_multiply(a, b);
  if (!product) target.fail(fmt::format("{} ({} x {}) overflows a 64-bit size", what, a, b));
  return *product;
}

std::string byte_size_text(std::uint64_t bytes) {
  constexpr std::array<const char*, 4> kUnits{"KiB", "MiB", "GiB", "TiB"};
  if (bytes < 1024) return fmt::format("{} bytes", bytes);
  double value = static_cast<double>(bytes) / 1024.0;
  std::size_t unit = 0;
  while (value >= 1024.0 && unit + 1 < kUnits.size()) {
    value /= 1024.0;
    ++unit;
  }
  return fmt::format("{:.3g} {}", value, kUnits[unit]);
}

}  // namespace halfspace::io::detail
