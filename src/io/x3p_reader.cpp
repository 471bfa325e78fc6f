// X3P (ISO 25178-72): the zip container through libzip, main.xml through
// pugixml, the point data decoded here. Layout as in ISO 5436-2 XML / the
// openGPS reference implementation: Record1 axes, Record3 data (link or
// list), Record4 checksum file.
#include "halfspace/io/x3p_reader.hpp"

#include <fmt/format.h>
#include <zip.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <memory>
#include <optional>
#include <pugixml.hpp>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "md5.hpp"
#include "reader_support.hpp"

namespace halfspace::io {
namespace {

using detail::ReadTarget;

// |R - I| below this counts as no rotation: writers print the identity with
// a few digits, sometimes as 0.99999999.
constexpr double kIdentityTolerance = 1e-6;

struct ZipCloser {
  void operator()(zip_t* archive) const { zip_discard(archive); }
};
using Archive = std::unique_ptr<zip_t, ZipCloser>;

struct ZipFileCloser {
  void operator()(zip_file_t* file) const { zip_fclose(file); }
};

Archive open_archive(const ReadTarget& target) {
  // A zip archive is read from its end (the central directory): a pipe or a
  // device cannot be, and /dev/zero must not be read at all.
  detail::require_regular_file(target);
  int code = 0;
  zip_t* archive = zip_open(target.path.c_str(), ZIP_RDONLY | ZIP_CHECKCONS, &code);
  if (archive == nullptr) {
    zip_error_t zip_error;
    zip_error_init_with_code(&zip_error, code);
    std::string reason = zip_error_strerror(&zip_error);
    zip_error_fini(&zip_error);
    const std::string head = detail::read_file_head(target, 16);
    if (head.starts_with("PK\x03\x04")) {
      // A zip archive's table of contents is at its end: a cut file loses it.
      target.fail(
          fmt::format("the zip archive is truncated or damaged ({}): its table of contents, at the end of "
                      "the file, cannot be read",
                      reason));
    }
    target.fail(fmt::format("the file is not a zip archive, which every X3P file is ({}){}", reason,
                            detail::signature_hint(head)));
  }
  return Archive(archive);
}

// The most main.xml may hold. Real files hold a few kilobytes; a DataList
// (points written as text) of a few hundred thousand points fits.
constexpr std::uint64_t kMaxMainXmlBytes = std::uint64_t{32} << 20;
// Deflate codes at most 258 bytes in about two bits: no member expands more
// than about 1032 times (zlib's technical notes), whatever its directory says.
constexpr std::uint64_t kMaxDeflateRatio = 1032;
// Members are decompressed in pieces of this size.
constexpr std::uint64_t kStreamChunkBytes = std::uint64_t{1} << 20;

// The size of a member, from the central directory, checked against what
// the member's compressed bytes can hold.
std::uint64_t member_size(zip_t* archive, const std::string& name, const ReadTarget& target) {
  zip_stat_t stat;
  zip_stat_init(&stat);
  if (zip_stat(archive, name.c_str(), 0, &stat) != 0) {
    target.fail(fmt::format("the archive has no member '{}'", detail::printable(name)));
  }
  if ((stat.valid & ZIP_STAT_SIZE) == 0) {
    target.fail(fmt::format("the size of member '{}' is unknown", detail::printable(name)));
  }
  if ((stat.valid & ZIP_STAT_COMP_SIZE) != 0 && (stat.valid & ZIP_STAT_COMP_METHOD) != 0) {
    const bool stored = stat.comp_method == ZIP_CM_STORE;
    const bool deflated = stat.comp_method == ZIP_CM_DEFLATE;
    if ((stored && stat.size != stat.comp_size) || (deflated && stat.size / kMaxDeflateRatio > stat.comp_size)) {
      target.fail(
          fmt::format("the zip directory says member '{}' holds {} bytes, which its {} {} bytes cannot: "
                      "the archive is damaged",
                      detail::printable(name), stat.size, stored ? "stored" : "compressed", stat.comp_size));
    }
  }
  return stat.size;
}

// Decompresses a member a chunk at a time, handing each chunk to `consume`,
// and fails unless exactly `size` bytes come out with the right CRC.
template <class Consume>
void stream_member(zip_t* archive, const std::string& name, std::uint64_t size, const ReadTarget& target,
                   Consume&& consume) {
  std::unique_ptr<zip_file_t, ZipFileCloser> file(zip_fopen(archive, name.c_str(), 0));
  if (!file) {
    target.fail(fmt::format("member '{}' cannot be opened: {}", detail::printable(name), zip_strerror(archive)));
  }
  std::vector<char> chunk(static_cast<std::size_t>(std::min<std::uint64_t>(size, kStreamChunkBytes)) + 1);
  std::uint64_t done = 0;
  while (done < size) {
    const std::uint64_t want = std::min<std::uint64_t>(size - done, chunk.size() - 1);
    const zip_int64_t count = zip_fread(file.get(), chunk.data(), want);
    if (count < 0) {
      target.fail(fmt::format("member '{}' is damaged: {}", detail::printable(name), zip_file_strerror(file.get())));
    }
    if (count == 0) {
      target.fail(fmt::format("member '{}' ends after {} of {} bytes", detail::printable(name), done, size));
    }
    consume(std::string_view(chunk.data(), static_cast<std::size_t>(count)));
    done += static_cast<std::uint64_t>(count);
  }
  // Reading to the end makes libzip compare the CRC.
  const zip_int64_t beyond = zip_fread(file.get(), chunk.data(), 1);
  if (beyond < 0) {
    target.fail(fmt::format("member '{}' is damaged: {}", detail::printable(name), zip_file_strerror(file.get())));
  }
  if (beyond > 0) {
    target.fail(
        fmt::format("member '{}' holds more than the {} bytes the zip directory states: the archive is "
                    "damaged",
                    detail::printable(name), size));
  }
}

// One small member of the archive (main.xml, the checksum file, the validity
// bits), in full; its size is checked against `limit` before anything is
// decompressed.
std::string read_member(zip_t* archive, const std::string& name, const ReadTarget& target, std::uint64_t limit,
                        std::string_view what) {
  const std::uint64_t size = member_size(archive, name, target);
  if (size > limit) {
    target.fail(fmt::format("member '{}' holds {} bytes, more than the {} {} may hold", detail::printable(name), size,
                            detail::byte_size_text(limit), what));
  }
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(size));
  stream_member(archive, name, size, target, [&](std::string_view chunk) { bytes.append(chunk); });
  return bytes;
}

// "md5checksum.hex" holds a digest and a file name: a line.
constexpr std::uint64_t kMaxChecksumFileBytes = 4096;

// The one main.xml of the archive: at its top, or alone in a folder (some
// tools pack "sample-land/main.xml" with "sample-land/bindata/..."). Two are
// ambiguous.
std::string find_main_xml(zip_t* archive, const ReadTarget& target) {
  const zip_int64_t entries = zip_get_num_entries(archive, 0);
  std::vector<std::string> found;
  for (zip_int64_t k = 0; k < entries; ++k) {
    const char* name = zip_get_name(archive, static_cast<zip_uint64_t>(k), 0);
    if (name == nullptr) continue;
    const std::string_view text(name);
    if (text == "main.xml" || text.ends_with("/main.xml")) found.emplace_back(text);
  }
  if (found.empty()) target.fail("the archive has no member 'main.xml' (at its top or in a folder)");
  if (found.size() > 1) {
    std::string names;
    for (std::size_t k = 0; k < found.size() && k < 4; ++k) {
      names += fmt::format("{}'{}'", k == 0 ? "" : ", ", detail::printable(found[k]));
    }
    target.fail(
        fmt::format("the archive holds {} files named main.xml ({}{}); which one describes the surface is "
                    "ambiguous",
                    found.size(), names, found.size() > 4 ? ", ..." : ""));
  }
  return found.front();
}

// A member that main.xml links to: relative to main.xml's folder, else (for
// writers that store full paths) as written.
std::string member_name(zip_t* archive, const std::string& folder, const std::string& link) {
  if (folder.empty()) return link;
  const std::string relative = folder + link;
  if (zip_name_locate(archive, relative.c_str(), 0) >= 0) return relative;
  if (zip_name_locate(archive, link.c_str(), 0) >= 0) return link;
  return relative;
}

std::string_view local_name(const char* name) {
  std::string_view text(name);
  const std::size_t colon = text.find(':');
  return colon == std::string_view::npos ? text : text.substr(colon + 1);
}

pugi::xml_node child(pugi::xml_node node, std::string_view name) {
  for (pugi::xml_node c = node.first_child(); c; c = c.next_sibling()) {
    if (c.type() == pugi::node_element && local_name(c.name()) == name) return c;
  }
  return {};
}

std::string text_of(pugi::xml_node node) {
  std::string text = node.child_value();
  const auto blank = [](unsigned char c) { return std::isspace(c) != 0; };
  while (!text.empty() && blank(static_cast<unsigned char>(text.back()))) text.pop_back();
  std::size_t begin = 0;
  while (begin < text.size() && blank(static_cast<unsigned char>(text[begin]))) ++begin;
  return text.substr(begin);
}

// The path of elements below the root, for messages: "Record1/Axes/CX".
class Xml {
 public:
  Xml(pugi::xml_node root, const ReadTarget& target) : root_(root), target_(target) {}

  pugi::xml_node find(std::string_view path) const {
    pugi::xml_node node = root_;
    std::size_t begin = 0;
    while (node && begin <= path.size()) {
      std::size_t end = path.find('/', begin);
      if (end == std::string_view::npos) end = path.size();
      node = child(node, path.substr(begin, end - begin));
      begin = end + 1;
    }
    return node;
  }
  pugi::xml_node require(std::string_view path) const {
    pugi::xml_node node = find(path);
    if (!node) target_.fail(fmt::format("main.xml has no element {}", path));
    return node;
  }
  std::optional<std::string> text(std::string_view path) const {
    const pugi::xml_node node = find(path);
    if (!node) return std::nullopt;
    return text_of(node);
  }
  double number(std::string_view path, double fallback) const {
    const std::optional<std::string> value = text(path);
    // An empty element (<Offset/>, written by some tools) states nothing.
    if (!value || value->empty()) return fallback;
    char* end = nullptr;
    const double result = std::strtod(value->c_str(), &end);
    if (value->empty() || end != value->c_str() + value->size() || !std::isfinite(result)) {
      target_.fail(fmt::format("main.xml element {} = '{}' is not a number", path, detail::printable(*value, 60)));
    }
    return result;
  }
  std::uint64_t size(std::string_view path) const {
    const std::string value = text_of(require(path));
    std::uint64_t result = 0;
    const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), result);
    if (error != std::errc() || end != value.data() + value.size()) {
      target_.fail(
          fmt::format("main.xml element {} = '{}' is not a non-negative integer", path, detail::printable(value, 60)));
    }
    return result;
  }

 private:
  pugi::xml_node root_;
  const ReadTarget& target_;
};

struct ZAxis {
  char type = 'D';  // I int16, L int32, F float32, D float64
  double increment = 1.0;
  double offset = 0.0;

  std::size_t bytes() const { return type == 'I' ? 2 : type == 'L' || type == 'F' ? 4 : 8; }
  bool is_float() const { return type == 'F' || type == 'D'; }
};

std::string line_of_offset(std::string_view text, std::ptrdiff_t offset) {
  const auto end = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(offset, 0, std::ssize(text)));
  return fmt::format("line {}", 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
}

// md5checksum.hex may read "<hex> *main.xml"; only the digest counts.
void check_md5_digest(const std::string& computed, std::string stated, std::string_view what,
                      const ReadTarget& target) {
  stated = stated.substr(0, std::min<std::size_t>(stated.find_first_of(" \t\r\n*"), stated.size()));
  std::transform(stated.begin(), stated.end(), stated.begin(),
                 [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
  if (stated != computed) {
    target.fail(fmt::format("{} does not match its MD5 checksum (stated {}, computed {}): the file is damaged", what,
                            detail::printable(stated, 40), computed));
  }
}

void check_md5(std::string_view bytes, const std::string& stated, std::string_view what, const ReadTarget& target) {
  check_md5_digest(detail::md5_hex(bytes), stated, what, target);
}

void check_axes(const Xml& xml, const std::string& feature, const ReadTarget& target) {
  if (feature == "PCL") target.fail("FeatureType PCL (a point cloud) is not a height map; need SUR or PRF");
  if (feature != "SUR" && feature != "PRF") {
    target.fail(fmt::format("FeatureType '{}' is unknown; need SUR (surface) or PRF (profile)",
                            detail::printable(feature, 40)));
  }
  for (const char* axis : {"CX", "CY"}) {
    const std::string type = xml.text(fmt::format("Record1/Axes/{}/AxisType", axis)).value_or("");
    if (type != "I") {
      target.fail(
          fmt::format("axis {} has AxisType '{}': only incremental (I) x and y axes, a regular grid, are "
                      "supported",
                      axis, detail::printable(type, 40)));
    }
  }
  if (const pugi::xml_node rotation = xml.find("Record1/Axes/Rotation")) {
    for (int r = 1; r <= 3; ++r) {
      for (int c = 1; c <= 3; ++c) {
        const double value = xml.number(fmt::format("Record1/Axes/Rotation/r{}{}", r, c), r == c ? 1.0 : 0.0);
        if (std::abs(value - (r == c ? 1.0 : 0.0)) > kIdentityTolerance) {
          target.fail(
              fmt::format("Record1/Axes/Rotation is not the identity (r{}{} = {}); rotated data are not "
                          "supported",
                          r, c, value));
        }
      }
    }
  }
}

ZAxis z_axis(const Xml& xml, const ReadTarget& target) {
  ZAxis z;
  const std::string type = xml.text("Record1/Axes/CZ/DataType").value_or("D");
  if (type.size() != 1 || std::string_view("ILFD").find(type[0]) == std::string_view::npos) {
    target.fail(fmt::format("CZ DataType '{}' is unknown; expected I, L, F or D", detail::printable(type, 40)));
  }
  z.type = type[0];
  z.increment = xml.number("Record1/Axes/CZ/Increment", 1.0);
  z.offset = xml.number("Record1/Axes/CZ/Offset", 0.0);
  if (!(z.increment > 0.0))
    target.fail(fmt::format("CZ Increment = {} is invalid: must be positive", format_number(z.increment)));
  return z;
}

double decode(const char* p, char type) {
  const auto load = [p]<class T>(T) {
    std::array<char, sizeof(T)> raw;
    std::memcpy(raw.data(), p, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(raw.begin(), raw.end());
    return std::bit_cast<T>(raw);
  };
  switch (type) {
    case 'I':
      return load(std::int16_t{});
    case 'L':
      return load(std::int32_t{});
    case 'F':
      return static_cast<double>(load(float{}));
    default:
      return load(double{});
  }
}

// The validity file may be padded to a whole 64-bit word.
constexpr std::size_t kValidityPaddingBytes = 8;

// z from the binary data file, and the validity bits when linked. Member
// names are relative to the folder holding main.xml.
void read_linked_points(zip_t* archive, const std::string& folder, const Xml& xml, const ZAxis& z, HeightMap& map,
                        const ReadTarget& target) {
  const std::size_t count = map.size();
  const std::string data_link = xml.text("Record3/DataLink/PointDataLink").value_or("");
  if (data_link.empty()) target.fail("Record3/DataLink has no PointDataLink");
  const std::string data_name = member_name(archive, folder, data_link);
  const std::uint64_t data_bytes = detail::checked_product(count, z.bytes(), "the point data size", target);
  const std::uint64_t stored = member_size(archive, data_name, target);
  if (stored != data_bytes) {
    target.fail(fmt::format("member '{}' holds {} bytes but main.xml describes {} bytes", detail::printable(data_name),
                            stored, data_bytes));
  }
  const std::optional<std::string> stated_md5 = xml.text("Record3/DataLink/MD5ChecksumPointData");
  const std::string data_what = fmt::format("the point data '{}'", detail::printable(data_name));
  // The values are decoded straight into the heights, a chunk at a time, so
  // that the member is never held whole; the heights' pages are touched only
  // as data arrive, so a member that ends early costs little. A value may
  // straddle two chunks: its bytes are gathered first.
  map.heights.resize(static_cast<Eigen::Index>(count));
  detail::Md5 digest;
  std::array<char, 8> partial{};
  std::size_t partial_size = 0;
  std::size_t k = 0;
  stream_member(archive, data_name, data_bytes, target, [&](std::string_view chunk) {
    digest.update(chunk);
    while (!chunk.empty()) {
      const std::size_t take = std::min(chunk.size(), z.bytes() - partial_size);
      if (partial_size == 0 && take == z.bytes()) {
        map.heights[static_cast<Eigen::Index>(k++)] = decode(chunk.data(), z.type);
      } else {
        std::memcpy(partial.data() + partial_size, chunk.data(), take);
        partial_size += take;
        if (partial_size == z.bytes()) {
          map.heights[static_cast<Eigen::Index>(k++)] = decode(partial.data(), z.type);
          partial_size = 0;
        }
      }
      chunk.remove_prefix(take);
    }
  });
  if (stated_md5) check_md5_digest(digest.hex(), *stated_md5, data_what, target);

  const std::optional<std::string> valid_link = xml.text("Record3/DataLink/ValidPointsLink");
  if (!valid_link || valid_link->empty()) return;
  const std::string valid_name = member_name(archive, folder, *valid_link);
  const std::size_t needed = (count + 7) / 8;
  const std::string bits = read_member(archive, valid_name, target, needed + kValidityPaddingBytes,
                                       fmt::format("validity bits of {} points", count));
  if (bits.size() < needed) {
    target.fail(fmt::format("the validity file '{}' holds {} bytes, too few for {} points ({} needed)",
                            detail::printable(valid_name), bits.size(), count, needed));
  }
  if (const auto stated = xml.text("Record3/DataLink/MD5ChecksumValidPoints")) {
    check_md5(bits, *stated, fmt::format("the validity file '{}'", detail::printable(valid_name)), target);
  }
  map.valid.assign(count, 1);
  for (std::size_t k = 0; k < count; ++k) {
    map.valid[k] = static_cast<std::uint8_t>((static_cast<unsigned char>(bits[k / 8]) >> (k % 8)) & 1U);
  }
}

// z written as text, one Datum per point; an empty Datum is an invalid point.
void read_listed_points(const Xml& xml, HeightMap& map, const ReadTarget& target) {
  const pugi::xml_node list = xml.require("Record3/DataList");
  const auto is_datum = [](pugi::xml_node node) {
    return node.type() == pugi::node_element && local_name(node.name()) == "Datum";
  };
  // Counted before the heights are allocated: the grid's size is only a claim.
  std::size_t listed = 0;
  for (pugi::xml_node datum = list.first_child(); datum; datum = datum.next_sibling()) listed += is_datum(datum);
  if (listed != map.size()) {
    target.fail(fmt::format("Record3/DataList holds {} points but the grid has {}", listed, map.size()));
  }
  std::size_t k = 0;
  map.heights.resize(static_cast<Eigen::Index>(map.size()));
  map.valid.assign(map.size(), 1);
  for (pugi::xml_node datum = list.first_child(); datum; datum = datum.next_sibling()) {
    if (!is_datum(datum)) continue;
    const std::string text = text_of(datum);
    if (text.empty()) {
      map.valid[k] = 0;
    } else {
      char* end = nullptr;
      map.heights[static_cast<Eigen::Index>(k)] = std::strtod(text.c_str(), &end);
      if (end != text.c_str() + text.size()) {
        target.fail(fmt::format("Record3/DataList Datum {} = '{}' is not a number", k, detail::printable(text, 60)));
      }
    }
    ++k;
  }
}

}  // namespace

HeightMap read_x3p_height_map(const std::filesystem::path& path) {
  const ReadTarget target{path, "an X3P file"};
  const Archive archive = open_archive(target);
  const std::string main_name = find_main_xml(archive.get(), target);
  const std::string folder = main_name.substr(0, main_name.size() - std::string_view("main.xml").size());
  const std::string main_xml =
      read_member(archive.get(), main_name, target, kMaxMainXmlBytes, "main.xml of an X3P file");

  pugi::xml_document document;
  const pugi::xml_parse_result parsed = document.load_buffer(main_xml.data(), main_xml.size());
  if (!parsed) {
    target.fail(fmt::format("main.xml is not well-formed XML: {} at {}", parsed.description(),
                            line_of_offset(main_xml, parsed.offset)));
  }
  const pugi::xml_node root = document.document_element();
  // ISO5436_2 is the standard's name; some writers use the older ISO5436.
  if (local_name(root.name()) != "ISO5436_2" && local_name(root.name()) != "ISO5436") {
    target.fail(fmt::format("main.xml has root element '{}', not ISO5436_2", detail::printable(root.name(), 60)));
  }
  const Xml xml(root, target);
  if (const auto checksum_file = xml.text("Record4/ChecksumFile"); checksum_file && !checksum_file->empty()) {
    const std::string stated = read_member(archive.get(), member_name(archive.get(), folder, *checksum_file), target,
                                           kMaxChecksumFileBytes, "checksum file");
    check_md5(main_xml, stated, "main.xml", target);
  }

  const std::string feature = text_of(xml.require("Record1/FeatureType"));
  check_axes(xml, feature, target);
  const ZAxis z = z_axis(xml, target);
  if (xml.find("Record3/ListDimension")) target.fail("Record3 has a ListDimension (a point list), not a matrix");
  const std::uint64_t size_x = xml.size("Record3/MatrixDimension/SizeX");
  const std::uint64_t size_y = xml.size("Record3/MatrixDimension/SizeY");
  const std::uint64_t size_z = xml.size("Record3/MatrixDimension/SizeZ");
  if (size_z != 1) target.fail(fmt::format("SizeZ = {}: only a single layer is supported", size_z));
  if (size_x < 2) target.fail(fmt::format("SizeX = {}: need at least 2 points along x", size_x));
  if (feature == "PRF" && size_y != 1) target.fail(fmt::format("a profile (PRF) must have SizeY = 1, not {}", size_y));
  if (size_y == 0) target.fail("SizeY = 0: the grid is empty");

  HeightMap map;
  map.dimension = size_y == 1 ? 1 : 2;
  map.nx = static_cast<std::size_t>(size_x);
  map.ny = static_cast<std::size_t>(size_y);
  detail::checked_point_count(size_x, size_y, target);
  map.dx = xml.number("Record1/Axes/CX/Increment", 0.0);
  map.dy = map.dimension == 2 ? xml.number("Record1/Axes/CY/Increment", 0.0) : 0.0;
  if (map.dx < 0.0 || map.dy < 0.0) target.fail("a CX or CY Increment is negative");

  if (xml.find("Record3/DataLink")) {
    read_linked_points(archive.get(), folder, xml, z, map, target);
  } else if (xml.find("Record3/DataList")) {
    read_listed_points(xml, map, target);
  } else {
    target.fail("Record3 has neither a DataLink nor a DataList");
  }
  for (std::size_t k = 0; k < map.size(); ++k) {
    double& h = map.heights[static_cast<Eigen::Index>(k)];
    h = z.increment * h + z.offset;
  }
  detail::mark_non_finite_invalid(map);
  map.source =
      fmt::format("{} (X3P {}, {} x {} points, CZ data type {})", path.string(), feature, size_x, size_y, z.type);
  return map;
}

}  // namespace halfspace::io
