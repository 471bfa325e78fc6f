// Private helpers shared by the height-map readers: one error format naming
// the file and the format, bounded file reading that names the file in every
// failure, recognising what a mislabelled file really is, escaping file bytes
// for messages, checked size arithmetic, and marking non-finite heights as
// invalid points.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "halfspace/height_map.hpp"

namespace halfspace::io::detail {

// What is being read; every message starts "cannot read height map '<path>'
// as <format>: " so that it can be found in the log of a batch run.
struct ReadTarget {
  const std::filesystem::path& path;
  std::string_view format;  // "a NumPy .npy file", "a text matrix", ...

  [[noreturn]] void fail(std::string_view what) const;
};

// The most a text file that is not a regular file (a pipe, a device, a
// process substitution) is read to: such a source can be endless.
inline constexpr std::size_t kMaxStreamedTextBytes = std::size_t{1} << 30;

// A file opened for reading through the operating system's calls, so that
// every failure (including EIO from /proc/self/mem) names the file and the
// reason, and so that nothing is read beyond what the caller asks for.
class InputFile {
 public:
  // Fails when the path does not exist, is a directory, or cannot be opened.
  explicit InputFile(const ReadTarget& target);
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  ~InputFile();

  bool is_regular() const { return regular_; }
  // The size the file system states, for a regular file; std::nullopt for a
  // pipe or device, and for the zero-size files of /proc, whose size says nothing.
  std::optional<std::uint64_t> stated_size() const;

  // Reads up to `count` bytes into `buffer`; fewer only at the end of the file.
  std::size_t read_some(char* buffer, std::size_t count);
  // Appends up to `count` bytes to `bytes`, growing it with the data that
  // actually arrive (a lying header costs only what the file holds).
  std::size_t append(std::string& bytes, std::size_t count);
  // True when no byte is left (consumes one byte otherwise).
  bool at_end();

 private:
  const ReadTarget& target_;
  int fd_ = -1;
  bool regular_ = false;
  std::uint64_t size_ = 0;
};

// Fails unless the path is a regular file: the formats read by seeking (HDF5,
// zip archives) cannot be read from a pipe or a device.
void require_regular_file(const ReadTarget& target);

// A whole text file. A regular file is read to its end; a pipe or device up
// to kMaxStreamedTextBytes. Each piece is checked to be text as it arrives, so
// that /dev/zero or a binary file fails within its first bytes.
std::string read_text_file(const ReadTarget& target);

// Fails naming the first byte that text files do not contain (NUL or another
// control byte than tab, CR, LF, FF, VT); `offset` is that of text[0] in the file.
void check_is_text(std::string_view text, std::size_t offset, const ReadTarget& target);

// The first `count` bytes of the file, or fewer when it is shorter; for
// recognising what a file is after its own format failed to open it.
std::string read_file_head(const ReadTarget& target, std::size_t count);

// What the first bytes say the file is ("an HDF5 file", "a zip archive (X3P
// files are zip archives)", ...), or an empty string when they say nothing.
std::string describe_signature(std::string_view bytes);

// " (the file looks like <what>; set the format to <name>)" when the signature is
// recognised, else "". Appended to "wrong magic" messages.
std::string signature_hint(std::string_view bytes);

// Up to `count` leading bytes, printable ASCII kept and the rest escaped.
std::string quoted_bytes(std::string_view bytes, std::size_t count);

// Text taken from a file, made safe to print: control bytes (C0, DEL, the C1
// range) and bytes that are not UTF-8 become \xNN, a backslash becomes \x5c;
// UTF-8 letters (um as "\u00b5m") are kept. At most `count` bytes are shown,
// "..." marks a cut.
std::string printable(std::string_view text, std::size_t count = 200);

// Marks every non-finite height invalid (valid = 0, height NaN), keeping
// points already marked; leaves `valid` empty when every point is valid.
void mark_non_finite_invalid(HeightMap& map);

// nx * ny, or a FileError when a header's sizes overflow or when the heights
// alone (8 bytes a point) would exceed the machine's physical memory.
std::size_t checked_point_count(std::uint64_t nx, std::uint64_t ny, const ReadTarget& target);

// The machine's physical memory in bytes (the largest 64-bit value when the
// system does not say).
std::uint64_t physical_memory_bytes();

// a * b, or a FileError naming `what` when the product overflows 64 bits.
std::uint64_t checked_product(std::uint64_t a, std::uint64_t b, std::string_view what, const ReadTarget& target);

// "1.5 GiB", "300 MiB", "12 bytes": sizes in messages.
std::string byte_size_text(std::uint64_t bytes);

}  // namespace halfspace::io::detail
