// Gwyddion Simple Field, as documented in the Gwyddion user guide ("Simple
// Field Files"): text header, NUL padding to a multiple of 4, float32 LE data.
#include "halfspace/io/gsf_reader.hpp"

#include <fmt/format.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>

#include "halfspace/error.hpp"
#include "reader_support.hpp"

namespace halfspace::io {
namespace {

using detail::InputFile;
using detail::ReadTarget;

constexpr std::string_view kMagic = "Gwyddion Simple Field 1.0\n";
constexpr std::size_t kAlignment = 4;
// Gwyddion writes headers of a few hundred bytes; a title or comment may
// make one longer, but not a megabyte.
constexpr std::size_t kMaxHeaderBytes = std::size_t{1} << 20;
constexpr std::size_t kHeaderPiece = 4096;

std::string_view trim(std::string_view text) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (!text.empty() && blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && blank(text.back())) text.remove_suffix(1);
  return text;
}

std::map<std::string, std::string, std::less<>> parse_header(std::string_view header, const ReadTarget& target) {
  std::map<std::string, std::string, std::less<>> fields;
  std::size_t begin = 0;
  std::size_t line = 1;  // the magic line is line 1
  while (begin < header.size()) {
    std::size_t end = header.find('\n', begin);
    if (end == std::string_view::npos) end = header.size();
    const std::string_view text = trim(header.substr(begin, end - begin));
    begin = end + 1;
    ++line;
    if (text.empty()) continue;
    const std::size_t equals = text.find('=');
    if (equals == std::string_view::npos) {
      target.fail(
          fmt::format("header line {} '{}' is not of the form 'name = value'", line, detail::printable(text, 60)));
    }
    const std::string name(trim(text.substr(0, equals)));
    if (!fields.emplace(name, std::string(trim(text.substr(equals + 1)))).second) {
      target.fail(fmt::format("header line {} sets '{}' a second time; each name may appear once", line,
                              detail::printable(name, 60)));
    }
  }
  return fields;
}

std::uint64_t resolution(const std::map<std::string, std::string, std::less<>>& fields, const char* name,
                         const ReadTarget& target) {
  const auto it = fields.find(name);
  if (it == fields.end()) target.fail(fmt::format("the header has no {} (it is required)", name));
  std::uint64_t value = 0;
  const std::string& text = it->second;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value == 0) {
    target.fail(fmt::format("{} = '{}' is invalid: must be a positive integer", name, detail::printable(text, 60)));
  }
  return value;
}

// XReal/YReal: a positive length, or 0 when absent (spacing not given).
double real_size(const std::map<std::string, std::string, std::less<>>& fields, const char* name,
                 const ReadTarget& target) {
  const auto it = fields.find(name);
  if (it == fields.end()) return 0.0;
  char* end = nullptr;
  const double value = std::strtod(it->second.c_str(), &end);
  if (end != it->second.c_str() + it->second.size() || !std::isfinite(value) || value <= 0.0) {
    target.fail(
        fmt::format("{} = '{}' is invalid: must be a positive number", name, detail::printable(it->second, 60)));
  }
  return value;
}

// The unit the header states for `name`, else the caller's, else metres. A
// caller's unit that contradicts the header's is an error, as for profiles.
LengthUnit unit_of(const std::map<std::string, std::string, std::less<>>& fields, const char* name,
                   const std::optional<LengthUnit>& fallback, const ReadTarget& target) {
  const auto it = fields.find(name);
  if (it == fields.end() || it->second.empty()) return fallback.value_or(LengthUnit{"m", 1.0});
  const std::optional<LengthUnit> unit = parse_length_unit(it->second);
  if (!unit) {
    target.fail(
        fmt::format("{} = '{}' is not a length unit; heights and spacings must be lengths (m, mm, um, nm, "
                    "...)",
                    name, detail::printable(it->second, 60)));
  }
  if (fallback && fallback->metres != unit->metres) {
    throw InputError(fmt::format("height map '{}': the unit {} contradicts {} = {} in the file's header",
                                 target.path.string(), fallback->name, name, unit->name));
  }
  return *unit;
}

}  // namespace

HeightMap read_gsf_height_map(const std::filesystem::path& path, const std::optional<LengthUnit>& unit) {
  const ReadTarget target{path, "a Gwyddion Simple Field (.gsf) file"};
  InputFile file(target);
  std::string bytes;
  file.append(bytes, kMagic.size());
  if (!std::string_view(bytes).starts_with(kMagic)) {
    target.fail(fmt::format("the file does not start with the line 'Gwyddion Simple Field 1.0' but with '{}'{}",
                            detail::quoted_bytes(bytes, 26), detail::signature_hint(bytes)));
  }
  // The header ends at the first NUL; read it in small pieces, up to a cap.
  std::size_t header_end = std::string::npos;
  while (header_end == std::string::npos) {
    const std::size_t before = bytes.size();
    if (before > kMaxHeaderBytes) {
      target.fail(
          fmt::format("no NUL ends the header within its first {} bytes (a GSF header is a few lines; the "
                      "file is damaged or not binary GSF)",
                      kMaxHeaderBytes));
    }
    if (file.append(bytes, kHeaderPiece) == 0) {
      target.fail("the header is not terminated by NUL padding (the file is truncated or not binary GSF)");
    }
    header_end = bytes.find('\0', before);
  }
  // One to four NULs, so that the data start at a multiple of 4.
  const std::size_t data_offset = (header_end / kAlignment + 1) * kAlignment;
  if (bytes.size() < data_offset) file.append(bytes, data_offset - bytes.size());
  if (bytes.size() < data_offset) target.fail("the file is truncated inside the NUL padding of the header");
  for (std::size_t k = header_end; k < data_offset; ++k) {
    if (bytes[k] != '\0') {
      target.fail(fmt::format("the header padding at offset {} is byte 0x{:02x}, not NUL: the header is corrupted", k,
                              static_cast<unsigned char>(bytes[k])));
    }
  }
  const auto fields = parse_header(std::string_view(bytes).substr(kMagic.size(), header_end - kMagic.size()), target);
  const std::uint64_t x_res = resolution(fields, "XRes", target);
  const std::uint64_t y_res = resolution(fields, "YRes", target);
  if (x_res < 2) target.fail(fmt::format("XRes = {}: need at least 2 points along x", x_res));
  const std::size_t count = detail::checked_point_count(x_res, y_res, target);
  const std::uint64_t data_bytes = detail::checked_product(count, sizeof(float), "the data size", target);
  const auto size_mismatch = [&](std::uint64_t available) {
    target.fail(
        fmt::format("the header claims XRes x YRes = {} x {} float32 values ({} bytes) but {} data bytes "
                    "follow the header{}",
                    x_res, y_res, data_bytes, available, available < data_bytes ? " (the file is truncated)" : ""));
  };
  // A regular file says its size: compare before reading the data.
  if (const std::optional<std::uint64_t> size = file.stated_size()) {
    const std::uint64_t available = *size - std::min<std::uint64_t>(*size, data_offset);
    if (available != data_bytes) size_mismatch(available);
  }
  const auto too_many = [&] {
    target.fail(fmt::format("more than the {} data bytes of XRes x YRes = {} x {} float32 values follow the header",
                            data_bytes, x_res, y_res));
  };
  const std::size_t already = bytes.size() - data_offset;
  if (already > data_bytes) too_many();
  const std::size_t got = already + file.append(bytes, static_cast<std::size_t>(data_bytes) - already);
  if (got < data_bytes) size_mismatch(got);
  if (!file.at_end()) too_many();
  const LengthUnit xy_unit = unit_of(fields, "XYUnits", unit, target);
  const LengthUnit z_unit = unit_of(fields, "ZUnits", unit, target);

  HeightMap map;
  map.dimension = y_res == 1 ? 1 : 2;
  map.nx = static_cast<std::size_t>(x_res);
  map.ny = static_cast<std::size_t>(y_res);
  map.dx = real_size(fields, "XReal", target) / static_cast<double>(x_res) * xy_unit.metres;
  map.dy = map.dimension == 1 ? 0.0 : real_size(fields, "YReal", target) / static_cast<double>(y_res) * xy_unit.metres;
  map.heights.resize(static_cast<Eigen::Index>(count));
  const char* data = bytes.data() + data_offset;
  for (std::size_t k = 0; k < count; ++k) {
    std::uint32_t raw = 0;
    std::memcpy(&raw, data + k * sizeof(float), sizeof(float));
    if constexpr (std::endian::native == std::endian::big) raw = __builtin_bswap32(raw);
    map.heights[static_cast<Eigen::Index>(k)] = static_cast<double>(std::bit_cast<float>(raw)) * z_unit.metres;
  }
  detail::mark_non_finite_invalid(map);
  const auto title = fields.find("Title");
  map.source =
      fmt::format("{} (Gwyddion Simple Field{}, z in {}, x/y in {})", path.string(),
                  title != fields.end() ? fmt::format(" '{}'", detail::printable(title->second, 80)) : std::string(),
                  z_unit.name, xy_unit.name);
  return map;
}

}  // namespace halfspace::io
