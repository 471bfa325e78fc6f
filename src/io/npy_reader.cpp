// NumPy .npy: "\x93NUMPY", version bytes, a little-endian header length
// (2 bytes in version 1, 4 in versions 2 and 3), then a Python dict literal
// {'descr': '<f8', 'fortran_order': False, 'shape': (ny, nx), } padded with
// spaces and a newline, then the raw array. Format description:
// numpy.lib.format (NEP 1).
#include "halfspace/io/npy_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "reader_support.hpp"

namespace halfspace::io {
namespace {

using detail::InputFile;
using detail::ReadTarget;

constexpr std::string_view kMagic = "\x93NUMPY";
constexpr std::size_t kPreambleV1 = 10;  // magic (6) + version (2) + header length (2)
constexpr std::size_t kPreambleV2 = 12;  // magic (6) + version (2) + header length (4)

struct Dtype {
  char kind = 'f';  // 'f' float, 'i' signed, 'u' unsigned
  std::size_t size = 8;
  bool big_endian = false;
};

struct Header {
  Dtype dtype;
  bool fortran_order = false;
  std::vector<std::uint64_t> shape;
};

// A minimal reader of the header's Python literal: a dict of string keys to
// strings, booleans and tuples of integers, which is all numpy writes.
class LiteralParser {
 public:
  LiteralParser(std::string_view text, const ReadTarget& target) : text_(text), target_(target) {}

  std::map<std::string, std::string> parse_dict() {
    std::map<std::string, std::string> entries;
    expect('{');
    while (true) {
      skip_space();
      if (peek() == '}') break;
      std::string key = parse_string();
      expect(':');
      skip_space();
      std::string value;
      if (peek() == '\'' || peek() == '"') {
        value = fmt::format("'{}'", parse_string());
      } else if (peek() == '(') {
        const std::size_t end = text_.find(')', pos_);
        if (end == std::string_view::npos) fail("a tuple is not closed");
        value = std::string(text_.substr(pos_, end + 1 - pos_));
        pos_ = end + 1;
      } else {
        const std::size_t begin = pos_;
        while (pos_ < text_.size() && std::isalnum(static_cast<unsigned char>(text_[pos_]))) ++pos_;
        value = std::string(text_.substr(begin, pos_ - begin));
      }
      entries[key] = value;
      skip_space();
      if (peek() == ',') {
        ++pos_;
      } else if (peek() != '}') {
        fail("expected ',' or '}'");
      }
    }
    return entries;
  }

 private:
  char peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  void expect(char c) {
    skip_space();
    if (peek() != c) fail(fmt::format("expected '{}'", c));
    ++pos_;
  }
  std::string parse_string() {
    skip_space();
    const char quote = peek();
    if (quote != '\'' && quote != '"') fail("expected a quoted key");
    const std::size_t end = text_.find(quote, pos_ + 1);
    if (end == std::string_view::npos) fail("a string is not closed");
    std::string value(text_.substr(pos_ + 1, end - pos_ - 1));
    pos_ = end + 1;
    return value;
  }
  [[noreturn]] void fail(std::string_view what) const {
    target_.fail(fmt::format("the header is not a valid dict literal ({} at character {}): '{}'", what, pos_,
                             detail::printable(text_, 120)));
  }

  std::string_view text_;
  const ReadTarget& target_;
  std::size_t pos_ = 0;
};

Dtype parse_dtype(const std::string& quoted, const ReadTarget& target) {
  const std::string descr = quoted.size() >= 2 && quoted.front() == '\'' ? quoted.substr(1, quoted.size() - 2) : quoted;
  const auto unsupported = [&](std::string_view why) {
    target.fail(fmt::format("dtype '{}' is not supported ({}); heights must be float32, float64 or integers",
                            detail::printable(descr), why));
  };
  if (descr.size() < 3) unsupported("not a simple numeric type");
  Dtype dtype;
  const char order = descr[0];
  if (order == '>') {
    dtype.big_endian = true;
  } else if (order == '<' || order == '|') {
    dtype.big_endian = false;
  } else if (order == '=') {
    dtype.big_endian = std::endian::native == std::endian::big;
  } else {
    unsupported("unknown byte order");
  }
  dtype.kind = descr[1];
  const auto [end, error] = std::from_chars(descr.data() + 2, descr.data() + descr.size(), dtype.size);
  if (error != std::errc() || end != descr.data() + descr.size()) unsupported("not a simple numeric type");
  const bool is_float = dtype.kind == 'f' && (dtype.size == 4 || dtype.size == 8);
  const bool is_integer = (dtype.kind == 'i' || dtype.kind == 'u') &&
                          (dtype.size == 1 || dtype.size == 2 || dtype.size == 4 || dtype.size == 8);
  if (dtype.kind == 'f' && !is_float) unsupported("only 4- and 8-byte floats");
  if (dtype.kind == 'c') unsupported("complex numbers");
  if (dtype.kind == 'b') unsupported("booleans");
  if (!is_float && !is_integer) unsupported("not a number type");
  return dtype;
}

std::vector<std::uint64_t> parse_shape(const std::string& tuple, const ReadTarget& target) {
  std::vector<std::uint64_t> shape;
  std::size_t pos = 1;  // after '('
  while (pos < tuple.size()) {
    while (pos < tuple.size() && (tuple[pos] == ' ' || tuple[pos] == ',')) ++pos;
    if (pos >= tuple.size() || tuple[pos] == ')') break;
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(tuple.data() + pos, tuple.data() + tuple.size(), value);
    if (error != std::errc())
      target.fail(fmt::format("the header's shape {} is not a tuple of sizes", detail::printable(tuple)));
    shape.push_back(value);
    pos = static_cast<std::size_t>(end - tuple.data());
  }
  return shape;
}

// numpy writes headers of a few hundred bytes (and refuses to read more
// than 10000 by default); anything much larger is not a header.
constexpr std::size_t kMaxHeaderBytes = std::size_t{1} << 20;

// Reads the preamble and the header dict into `bytes`, so that the data
// start at bytes.size(); the header's length is checked before it is read.
Header read_header(InputFile& file, std::string& bytes, const ReadTarget& target) {
  file.append(bytes, kPreambleV1);
  if (!std::string_view(bytes).starts_with(kMagic)) {
    target.fail(fmt::format("the file does not start with the .npy magic \\x93NUMPY but with '{}'{}",
                            detail::quoted_bytes(bytes, 8), detail::signature_hint(bytes)));
  }
  if (bytes.size() < kPreambleV1) target.fail(fmt::format("the file is truncated: {} bytes, no header", bytes.size()));
  const auto major = static_cast<unsigned char>(bytes[6]);
  std::size_t header_length = 0;
  std::size_t preamble = 0;
  const auto byte = [&](std::size_t k) { return static_cast<std::size_t>(static_cast<unsigned char>(bytes[k])); };
  if (major == 1) {
    preamble = kPreambleV1;
    header_length = byte(8) | byte(9) << 8;
  } else if (major == 2 || major == 3) {
    if (file.append(bytes, kPreambleV2 - kPreambleV1) < kPreambleV2 - kPreambleV1) {
      target.fail("the file is truncated inside the header length");
    }
    preamble = kPreambleV2;
    header_length = byte(8) | byte(9) << 8 | byte(10) << 16 | byte(11) << 24;
  } else {
    target.fail(fmt::format("format version {}.{} is not supported (1.0, 2.0 and 3.0 are)", major, byte(7)));
  }
  if (header_length > kMaxHeaderBytes) {
    target.fail(fmt::format("the header claims {} bytes; an .npy header holds a few hundred (at most {} are read)",
                            header_length, kMaxHeaderBytes));
  }
  const std::size_t got = file.append(bytes, header_length);
  if (got < header_length) {
    target.fail(
        fmt::format("the file is truncated: the header claims {} bytes but only {} follow", header_length, got));
  }
  LiteralParser parser(std::string_view(bytes).substr(preamble, header_length), target);
  const std::map<std::string, std::string> entries = parser.parse_dict();
  for (const char* key : {"descr", "fortran_order", "shape"}) {
    if (!entries.contains(key)) target.fail(fmt::format("the header has no '{}' entry", key));
  }
  Header header;
  header.dtype = parse_dtype(entries.at("descr"), target);
  const std::string& order = entries.at("fortran_order");
  if (order != "True" && order != "False") {
    target.fail(fmt::format("the header's fortran_order is {}, not True or False", detail::printable(order)));
  }
  header.fortran_order = order == "True";
  header.shape = parse_shape(entries.at("shape"), target);
  return header;
}

template <class T>
T load(const char* p, bool swap) {
  std::array<char, sizeof(T)> raw;
  std::memcpy(raw.data(), p, sizeof(T));
  if (swap) std::reverse(raw.begin(), raw.end());
  T value;
  std::memcpy(&value, raw.data(), sizeof(T));
  return value;
}

double load_value(const char* p, const Dtype& dtype) {
  const bool swap = dtype.big_endian != (std::endian::native == std::endian::big);
  switch (dtype.kind) {
    case 'f':
      return dtype.size == 4 ? static_cast<double>(load<float>(p, swap)) : load<double>(p, swap);
    case 'i':
      switch (dtype.size) {
        case 1:
          return load<std::int8_t>(p, swap);
        case 2:
          return load<std::int16_t>(p, swap);
        case 4:
          return load<std::int32_t>(p, swap);
        default:
          return static_cast<double>(load<std::int64_t>(p, swap));
      }
    default:
      switch (dtype.size) {
        case 1:
          return load<std::uint8_t>(p, swap);
        case 2:
          return load<std::uint16_t>(p, swap);
        case 4:
          return load<std::uint32_t>(p, swap);
        default:
          return static_cast<double>(load<std::uint64_t>(p, swap));
      }
  }
}

}  // namespace

HeightMap read_npy_height_map(const std::filesystem::path& path, const LengthUnit& unit) {
  const ReadTarget target{path, "a NumPy .npy file"};
  InputFile file(target);
  std::string bytes;
  const Header header = read_header(file, bytes, target);
  const std::size_t offset = bytes.size();

  const std::vector<std::uint64_t>& shape = header.shape;
  const std::string shape_text = fmt::format("({}{})", fmt::join(shape, ", "), shape.size() == 1 ? "," : "");
  if (shape.size() != 1 && shape.size() != 2) {
    target.fail(fmt::format("the array has shape {}; expected (n,) for a profile or (ny, nx) for a map", shape_text));
  }
  for (const std::uint64_t n : shape) {
    if (n < 2) target.fail(fmt::format("the array has shape {}; need at least 2 points along each axis", shape_text));
  }
  HeightMap map;
  map.dimension = static_cast<int>(shape.size());
  map.nx = static_cast<std::size_t>(shape.back());
  map.ny = map.dimension == 1 ? 1 : static_cast<std::size_t>(shape[0]);
  const std::size_t count = detail::checked_point_count(shape.back(), map.dimension == 1 ? 1 : shape[0], target);
  const std::uint64_t data_bytes = detail::checked_product(count, header.dtype.size, "the data size", target);
  // A regular file says its size: compare before reading anything more.
  if (const std::optional<std::uint64_t> size = file.stated_size()) {
    const std::uint64_t available = *size - std::min<std::uint64_t>(*size, offset);
    if (available < data_bytes) {
      target.fail(
          fmt::format("the file is truncated: shape {} of {}-byte values needs {} data bytes but {} follow the "
                      "header",
                      shape_text, header.dtype.size, data_bytes, available));
    }
    if (available > data_bytes) {
      target.fail(fmt::format("{} bytes follow the data of shape {}; the file is not a single .npy array",
                              available - data_bytes, shape_text));
    }
    bytes.reserve(offset + static_cast<std::size_t>(data_bytes));
  }
  // A pipe or device delivers what it delivers: read no more than the shape needs.
  const std::size_t got = file.append(bytes, static_cast<std::size_t>(data_bytes));
  if (got < data_bytes) {
    target.fail(
        fmt::format("the file is truncated: shape {} of {}-byte values needs {} data bytes but {} follow the "
                    "header",
                    shape_text, header.dtype.size, data_bytes, got));
  }
  if (!file.at_end()) {
    target.fail(fmt::format("more bytes follow the data of shape {}; the file is not a single .npy array", shape_text));
  }

  map.heights.resize(static_cast<Eigen::Index>(count));
  const char* data = bytes.data() + offset;
  for (std::size_t j = 0; j < map.ny; ++j) {
    for (std::size_t i = 0; i < map.nx; ++i) {
      // Fortran order stores columns contiguously: element (j, i) at i * ny + j.
      const std::size_t stored = header.fortran_order ? i * map.ny + j : j * map.nx + i;
      map.heights[static_cast<Eigen::Index>(j * map.nx + i)] =
          load_value(data + stored * header.dtype.size, header.dtype) * unit.metres;
    }
  }
  detail::mark_non_finite_invalid(map);
  map.source = fmt::format("{} (npy, {}{}, {} order, heights in {})", path.string(), header.dtype.kind,
                           header.dtype.size * 8, header.fortran_order ? "Fortran" : "C", unit.name);
  return map;
}

}  // namespace halfspace::io
