// Tests of read_x3p_height_map: a re-packed crop of the Alicona X3P file
// (float32 with +inf invalid points), an int16 surface with a validity bit
// mask, a text-data profile, the full instrument file when ../shared is
// there, and damaged archives, XML, data and checksums.
#include "halfspace/io/x3p_reader.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <zip.h>

#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "halfspace/surface/invalid_points.hpp"
#include "io/hdf5_test_support.hpp"
#include "io/reader_test_support.hpp"

namespace halfspace::io {
namespace {

namespace fs = std::filesystem;
using test::expect_contains;
using test::kFormatDataDir;
using test::TempDir;

// The README's Kautschuk fill ran Jacobi iterations until the largest change
// fell below 1e-12 of the largest |height|; ours is a direct solve. Jacobi
// leaves an error of about that change over (1 - spectral radius), which for
// the strip of invalid points along the first interior row (hundreds of
// points, one side with zero flux) is ~1e5-1e6: 1e-5 of the largest height.
constexpr double kJacobiFillTolerance = 1e-5;
// Half a unit of the README's last quoted digit of Sq (3.40 um).
constexpr double kQuotedSqHalfUnit = 0.005e-6;
// Our sum of squares runs in another order than numpy's pairwise sum.
constexpr double kRmsRelativeTolerance = 1e-12;

using Members = std::vector<std::pair<std::string, std::string>>;

Members read_members(const fs::path& path) {
  int error = 0;
  zip_t* archive = zip_open(path.c_str(), ZIP_RDONLY, &error);
  Members members;
  if (archive == nullptr) {
    ADD_FAILURE() << "cannot open " << path;
    return members;
  }
  for (zip_int64_t k = 0; k < zip_get_num_entries(archive, 0); ++k) {
    zip_stat_t stat;
    zip_stat_index(archive, static_cast<zip_uint64_t>(k), 0, &stat);
    std::string bytes(stat.size, '\0');
    zip_file_t* file = zip_fopen_index(archive, static_cast<zip_uint64_t>(k), 0);
    zip_fread(file, bytes.data(), bytes.size());
    zip_fclose(file);
    members.emplace_back(stat.name, bytes);
  }
  zip_discard(archive);
  return members;
}

void write_members(const fs::path& path, const Members& members) {
  int error = 0;
  zip_t* archive = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  ASSERT_NE(archive, nullptr);
  for (const auto& [name, bytes] : members) {
    zip_source_t* source = zip_source_buffer(archive, bytes.data(), bytes.size(), 0);
    ASSERT_GE(zip_file_add(archive, name.c_str(), source, ZIP_FL_OVERWRITE), 0);
  }
  ASSERT_EQ(zip_close(archive), 0);
}

std::string& member(Members& members, const std::string& name) {
  for (auto& [key, bytes] : members) {
    if (key == name) return bytes;
  }
  ADD_FAILURE() << "no member " << name;
  static std::string none;
  return none;
}

void replace(std::string& text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

std::string x3p_error(const fs::path& path) {
  return test::file_error_of([&] { read_x3p_height_map(path); });
}

// A minimal SUR file of float64 z, without checksums, with `axes_extra` XML
// spliced into Record1/Axes and `record3` as Record3.
std::string minimal_xml(const std::string& x_type, const std::string& record3, const std::string& feature = "SUR") {
  return "<?xml version=\"1.0\"?><p:ISO5436_2 xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\"><Record1>"
         "<Revision>ISO5436 - 2000</Revision><FeatureType>" +
         feature + "</FeatureType><Axes><CX><AxisType>" + x_type +
         "</AxisType><DataType>D</DataType><Increment>1e-6</Increment><Offset>0</Offset></CX>"
         "<CY><AxisType>I</AxisType><DataType>D</DataType><Increment>1e-6</Increment><Offset>0</Offset></CY>"
         "<CZ><AxisType>A</AxisType><DataType>D</DataType></CZ></Axes></Record1><Record3>" +
         record3 + "</Record3></p:ISO5436_2>";
}

std::string doubles(std::initializer_list<double> values) {
  std::string data;
  for (double v : values) data.append(reinterpret_cast<const char*>(&v), sizeof v);
  return data;
}

TEST(X3pReaderTest, ReadsCroppedInstrumentFileWithInvalidPoints) {
  // kautschuk-crop-40x56.x3p: rows 0:40, columns 520:576 of KautschukInfiniteFocus.x3p
  // with the original main.xml (sizes and checksums updated). numpy: 85 invalid
  // points (+inf; row 0 and the start of row 1), h[39,55] = 3.1057400065037655e-06,
  // rms of the valid points about their mean 2.4938288932796473e-06.
  const HeightMap map = read_x3p_height_map(kFormatDataDir / "kautschuk-crop-40x56.x3p");
  EXPECT_EQ(map.dimension, 2);
  EXPECT_EQ(map.nx, 56u);
  EXPECT_EQ(map.ny, 40u);
  EXPECT_EQ(map.dx, 2.279984215e-6);
  EXPECT_EQ(map.dy, 2.279794519e-6);
  ASSERT_EQ(map.valid.size(), 56u * 40u);
  EXPECT_EQ(surface::count_invalid(map), 85u);
  EXPECT_EQ(map.valid[0], 0);  // row 0 is fully invalid in the instrument file
  EXPECT_TRUE(std::isnan(map.heights[0]));
  EXPECT_EQ(map.heights[39 * 56 + 55], 3.1057400065037655e-06);
  EXPECT_EQ(map.heights[1 * 56 + 29], 2.439256377329002e-06);
  EXPECT_EQ(map.valid[1 * 56 + 28], 0);
  Eigen::ArrayXd valid(static_cast<Eigen::Index>(map.size() - 85));
  Eigen::Index n = 0;
  for (std::size_t k = 0; k < map.size(); ++k) {
    if (map.is_valid(k)) valid[n++] = map.heights[static_cast<Eigen::Index>(k)];
  }
  EXPECT_NEAR(test::rms_about_mean(valid), 2.4938288932796473e-06, kRmsRelativeTolerance * 2.4938288932796473e-06);
}

TEST(X3pReaderTest, ReadsInt16WithIncrementOffsetAndValidityBits) {
  // int16-mask-5x3.x3p: stored -700, -600, ..., 700 (x fastest), CZ increment
  // 1e-9 m and offset 2e-6 m; points 1, 8 and 14 invalid in valid.bin (LSB first).
  const HeightMap map = read_x3p_height_map(kFormatDataDir / "int16-mask-5x3.x3p");
  EXPECT_EQ(map.nx, 5u);
  EXPECT_EQ(map.ny, 3u);
  EXPECT_EQ(map.dx, 1.5e-6);
  EXPECT_EQ(map.dy, 2.5e-6);
  const std::vector<std::uint8_t> expected_valid{1, 0, 1, 1, 1, 1, 1, 1, 0, 1, 1, 1, 1, 1, 0};
  EXPECT_EQ(map.valid, expected_valid);
  for (std::size_t k = 0; k < 15; ++k) {
    if (!expected_valid[k]) continue;
    const double stored = -700.0 + 100.0 * static_cast<double>(k);
    EXPECT_EQ(map.heights[static_cast<Eigen::Index>(k)], 1e-9 * stored + 2e-6) << "at k = " << k;
  }
}

TEST(X3pReaderTest, ReadsTextDataProfileWithEmptyDatumInvalid) {
  const HeightMap map = read_x3p_height_map(kFormatDataDir / "profile-datalist-5.x3p");
  EXPECT_EQ(map.dimension, 1);
  EXPECT_EQ(map.nx, 5u);
  EXPECT_EQ(map.dx, 5e-7);
  EXPECT_EQ(map.dy, 0.0);
  EXPECT_EQ(map.valid, (std::vector<std::uint8_t>{1, 0, 1, 1, 1}));
  EXPECT_EQ(map.heights[2], -2.25e-07);
}

TEST(X3pReaderTest, FullInstrumentFileMatchesReadmeAfterFilling) {
  if (!test::have_topography()) GTEST_SKIP() << "no measured data at " << test::kTopographyDir;
  // README: 634 x 860 raw; after cutting the fully invalid border 631 x 857
  // with 823 interior points filled; dx 2.279984 um, dy 2.279795 um; Sq 3.40 um.
  HeightMap map = read_x3p_height_map(test::kTopographyDir / "KautschukInfiniteFocus.x3p");
  EXPECT_EQ(map.nx, 860u);
  EXPECT_EQ(map.ny, 634u);
  EXPECT_NEAR(map.dx, 2.279984e-6, 0.5e-12);
  EXPECT_NEAR(map.dy, 2.279795e-6, 0.5e-12);
  EXPECT_EQ(surface::count_invalid(map), 5296u);

  surface::fill_invalid_points(map);
  ASSERT_EQ(map.nx, 857u);
  ASSERT_EQ(map.ny, 631u);
  ASSERT_EQ(map.preparation.size(), 1u);
  expect_contains(map.preparation[0], {"filled 823 of 540767 points", "columns 2 to 858 and rows 1 to 631"});
  EXPECT_NEAR(test::rms_about_mean(map.heights), 3.40e-6, kQuotedSqHalfUnit);

  const HeightMap converted = read_hdf5_height_map(test::kTopographyDir / "KautschukInfiniteFocus.h5");
  ASSERT_EQ(converted.heights.size(), map.heights.size());
  const test::H5 file = test::open_file(test::kTopographyDir / "KautschukInfiniteFocus.h5");
  const std::vector<std::uint8_t> measured = test::read_dataset<std::uint8_t>(file.get(), "valid", H5T_NATIVE_UINT8);
  ASSERT_EQ(measured.size(), map.size());
  const double scale = converted.heights.abs().maxCoeff();
  double worst_filled = 0.0;
  std::size_t filled = 0;
  for (std::size_t k = 0; k < map.size(); ++k) {
    const auto e = static_cast<Eigen::Index>(k);
    if (measured[k] != 0) {
      ASSERT_EQ(map.heights[e], converted.heights[e]) << "measured point " << k << " differs";
    } else {
      worst_filled = std::max(worst_filled, std::abs(map.heights[e] - converted.heights[e]));
      ++filled;
    }
  }
  EXPECT_EQ(filled, 823u);
  EXPECT_LE(worst_filled, kJacobiFillTolerance * scale) << "largest difference to the README's filled points";
}

TEST(X3pReaderTest, RejectsFilesThatAreNotZipArchives) {
  const TempDir dir;
  const fs::path text = dir / "text.x3p";
  test::write_bytes(text, "not a zip archive at all\n");
  expect_contains(x3p_error(text), {text.string(), "not a zip archive, which every X3P file is"});
  const fs::path hdf5 = dir / "hdf5.x3p";
  fs::copy_file(kFormatDataDir / "di-5-crop-48x64.h5", hdf5);
  expect_contains(x3p_error(hdf5), {"HDF5", "set the format to hdf5"});
  expect_contains(x3p_error(dir / "missing.x3p"), {"does not exist"});
}

TEST(X3pReaderTest, RejectsTruncatedArchive) {
  const TempDir dir;
  const fs::path path = dir / "cut.x3p";
  const std::string full = test::read_bytes(kFormatDataDir / "kautschuk-crop-40x56.x3p");
  test::write_bytes(path, full.substr(0, full.size() / 2));
  expect_contains(x3p_error(path), {path.string(), "the zip archive is truncated or damaged", "table of contents"});
}

TEST(X3pReaderTest, RejectsCorruptedCompressedData) {
  const TempDir dir;
  const fs::path path = dir / "flipped.x3p";
  std::string bytes = test::read_bytes(kFormatDataDir / "kautschuk-crop-40x56.x3p");
  // Flip bytes inside the deflated data.bin (the first member, after its header).
  for (std::size_t k = 200; k < 260; ++k) bytes[k] = static_cast<char>(bytes[k] ^ 0x5a);
  test::write_bytes(path, bytes);
  const std::string message = x3p_error(path);
  expect_contains(message, {path.string()});
  EXPECT_TRUE(message.find("damaged") != std::string::npos || message.find("checksum") != std::string::npos) << message;
}

TEST(X3pReaderTest, RejectsMalformedXmlNamingTheLine) {
  const TempDir dir;
  Members members = read_members(kFormatDataDir / "kautschuk-crop-40x56.x3p");
  replace(member(members, "main.xml"), "</Record1>", "</Record>");
  const fs::path path = dir / "xml.x3p";
  write_members(path, members);
  expect_contains(x3p_error(path), {"main.xml is not well-formed XML", "line 25"});
}

TEST(X3pReaderTest, RejectsMainXmlThatDoesNotMatchItsChecksum) {
  const TempDir dir;
  Members members = read_members(kFormatDataDir / "kautschuk-crop-40x56.x3p");
  replace(member(members, "main.xml"), "<SizeX>56</SizeX>", "<SizeX>28</SizeX>");
  const fs::path path = dir / "edited.x3p";
  write_members(path, members);
  expect_contains(x3p_error(path), {"main.xml does not match its MD5 checksum", "damaged"});
}

TEST(X3pReaderTest, RejectsPointDataThatDoesNotMatchItsChecksum) {
  const TempDir dir;
  Members members = read_members(kFormatDataDir / "kautschuk-crop-40x56.x3p");
  member(members, "bindata/data.bin")[1000] ^= 1;
  const fs::path path = dir / "data.x3p";
  write_members(path, members);
  expect_contains(x3p_error(path), {"the point data 'bindata/data.bin' does not match its MD5 checksum"});
}

TEST(X3pReaderTest, RejectsDataOfTheWrongSizeAndMissingMembers) {
  const TempDir dir;
  const fs::path path = dir / "short.x3p";
  const std::string link = "<DataLink><PointDataLink>bindata/data.bin</PointDataLink></DataLink>";
  write_members(path, {{"main.xml", minimal_xml("I",
                                                "<MatrixDimension><SizeX>3</SizeX><SizeY>2</SizeY><SizeZ>1"
                                                "</SizeZ></MatrixDimension>" +
                                                    link)},
                       {"bindata/data.bin", doubles({1, 2, 3, 4, 5})}});
  expect_contains(x3p_error(path), {"member 'bindata/data.bin' holds 40 bytes but main.xml describes 48 bytes"});
  write_members(path, {{"main.xml", minimal_xml("I",
                                                "<MatrixDimension><SizeX>3</SizeX><SizeY>2</SizeY><SizeZ>1"
                                                "</SizeZ></MatrixDimension>" +
                                                    link)}});
  expect_contains(x3p_error(path), {"the archive has no member 'bindata/data.bin'"});
  write_members(path, {{"data.xml", "<x/>"}});
  expect_contains(x3p_error(path), {"no member 'main.xml'"});
}

TEST(X3pReaderTest, RejectsUnsupportedLayouts) {
  const TempDir dir;
  const fs::path path = dir / "layout.x3p";
  const std::string matrix =
      "<MatrixDimension><SizeX>2</SizeX><SizeY>2</SizeY><SizeZ>1</SizeZ></MatrixDimension>"
      "<DataList><Datum>1</Datum><Datum>2</Datum><Datum>3</Datum><Datum>4</Datum></DataList>";
  write_members(path, {{"main.xml", minimal_xml("A", matrix)}});
  expect_contains(x3p_error(path), {"axis CX has AxisType 'A'", "regular grid"});
  write_members(path, {{"main.xml", minimal_xml("I", matrix, "PCL")}});
  expect_contains(x3p_error(path), {"point cloud"});
  std::string layers = matrix;
  replace(layers, "<SizeZ>1</SizeZ>", "<SizeZ>2</SizeZ>");
  write_members(path, {{"main.xml", minimal_xml("I", layers)}});
  expect_contains(x3p_error(path), {"SizeZ = 2"});
  std::string too_few = matrix;
  replace(too_few, "<Datum>4</Datum>", "");
  write_members(path, {{"main.xml", minimal_xml("I", too_few)}});
  expect_contains(x3p_error(path), {"DataList holds 3 points but the grid has 4"});
  write_members(path, {{"main.xml", minimal_xml("I",
                                                "<MatrixDimension><SizeX>2</SizeX><SizeY>2</SizeY>"
                                                "</MatrixDimension>")}});
  expect_contains(x3p_error(path), {"no element Record3/MatrixDimension/SizeZ"});
  write_members(path, {{"main.xml", "<?xml version=\"1.0\"?><ISO5436_3/>"}});
  expect_contains(x3p_error(path), {"root element 'ISO5436_3'"});
}

// Rewrites the uncompressed size that the local header and the central
// directory state for `name`, leaving the data as they are: an archive that
// lies about a member's size.
void claim_member_size(std::string& zip, const std::string& name, std::uint32_t size) {
  const auto put = [&](std::size_t at) {
    for (int b = 0; b < 4; ++b) zip[at + b] = static_cast<char>((size >> (8 * b)) & 0xffU);
  };
  int patched = 0;
  for (std::size_t at = zip.find("PK\x03\x04"); at != std::string::npos; at = zip.find("PK\x03\x04", at + 4)) {
    if (zip.compare(at + 30, name.size(), name) == 0) {
      put(at + 22);
      ++patched;
    }
  }
  for (std::size_t at = zip.find("PK\x01\x02"); at != std::string::npos; at = zip.find("PK\x01\x02", at + 4)) {
    if (zip.compare(at + 46, name.size(), name) == 0) {
      put(at + 24);
      ++patched;
    }
  }
  ASSERT_EQ(patched, 2) << "member " << name << " not found in both headers";
}

std::string link_record3(std::size_t nx, std::size_t ny, const std::string& valid_link = "") {
  return fmt::format(
      "<MatrixDimension><SizeX>{}</SizeX><SizeY>{}</SizeY><SizeZ>1</SizeZ></MatrixDimension>"
      "<DataLink><PointDataLink>bindata/data.bin</PointDataLink>{}</DataLink>",
      nx, ny, valid_link.empty() ? "" : "<ValidPointsLink>" + valid_link + "</ValidPointsLink>");
}

TEST(X3pReaderTest, RefusesAMainXmlWhoseStatedSizeItsBytesCannotHoldBeforeAllocating) {
  // The zip directory claims a 3.75 GiB main.xml in a file of a few hundred
  // bytes; reading it used to allocate (and zero) the claimed size.
  const TempDir dir;
  const fs::path path = dir / "huge-main.x3p";
  write_members(
      path, {{"main.xml", minimal_xml("I", link_record3(3, 2))}, {"bindata/data.bin", doubles({1, 2, 3, 4, 5, 6})}});
  std::string zip = test::read_bytes(path);
  claim_member_size(zip, "main.xml", 0xF0000000U);
  test::write_bytes(path, zip);
  const std::size_t before = test::peak_resident_bytes();
  expect_contains(x3p_error(path),
                  {path.string(), "member 'main.xml' holds 4026531840 bytes", "the archive is damaged"});
  EXPECT_LT(test::peak_resident_bytes(), before + test::kRefusalMemoryAllowance);
}

TEST(X3pReaderTest, RefusesPointDataWhoseStatedSizeItsBytesCannotHoldBeforeAllocating) {
  // main.xml claims 20000 x 20000 float64 points and the directory agrees
  // (3.2e9 bytes), but the member holds 48 bytes: used to cost 6 GB (the
  // heights, then the member) before the read failed.
  const TempDir dir;
  const fs::path path = dir / "huge-grid.x3p";
  write_members(path, {{"main.xml", minimal_xml("I", link_record3(20000, 20000))},
                       {"bindata/data.bin", doubles({1, 2, 3, 4, 5, 6})}});
  std::string zip = test::read_bytes(path);
  claim_member_size(zip, "bindata/data.bin", 3'200'000'000U);
  test::write_bytes(path, zip);
  const std::size_t before = test::peak_resident_bytes();
  expect_contains(x3p_error(path), {path.string(), "member 'bindata/data.bin' holds 3200000000 bytes", "damaged"});
  EXPECT_LT(test::peak_resident_bytes(), before + test::kRefusalMemoryAllowance);
}

TEST(X3pReaderTest, RefusesValidityBitsLargerThanTheGridNeeds) {
  // 3 x 2 points need 1 byte of bits (8 of padding allowed); a 3 GB valid.bin
  // used to be read in full. Here its real 100 bytes, and then a lying size.
  const TempDir dir;
  const fs::path path = dir / "valid.x3p";
  write_members(path, {{"main.xml", minimal_xml("I", link_record3(3, 2, "bindata/valid.bin"))},
                       {"bindata/data.bin", doubles({1, 2, 3, 4, 5, 6})},
                       {"bindata/valid.bin", std::string(100, '\xff')}});
  expect_contains(x3p_error(path),
                  {path.string(), "member 'bindata/valid.bin' holds 100 bytes", "validity bits of 6 points"});
  std::string zip = test::read_bytes(path);
  claim_member_size(zip, "bindata/valid.bin", 3'000'000'000U);
  test::write_bytes(path, zip);
  const std::size_t before = test::peak_resident_bytes();
  expect_contains(x3p_error(path), {"member 'bindata/valid.bin' holds 3000000000 bytes"});
  EXPECT_LT(test::peak_resident_bytes(), before + test::kRefusalMemoryAllowance);
}

TEST(X3pReaderTest, RefusesDevicesAndPipes) {
  expect_contains(x3p_error("/dev/zero"), {"/dev/zero", "character device", "regular file"});
}

// The members of `source` moved into `folder`, as some tools pack them.
Members in_folder(const Members& source, const std::string& folder) {
  Members moved;
  for (const auto& [name, bytes] : source) moved.emplace_back(folder + name, bytes);
  return moved;
}

void expect_same_map(const HeightMap& map, const HeightMap& reference) {
  ASSERT_EQ(map.nx, reference.nx);
  ASSERT_EQ(map.ny, reference.ny);
  EXPECT_EQ(map.dx, reference.dx);
  EXPECT_EQ(map.dy, reference.dy);
  ASSERT_EQ(map.valid, reference.valid);
  for (std::size_t k = 0; k < map.size(); ++k) {
    if (reference.is_valid(k)) {
      EXPECT_EQ(map.heights[static_cast<Eigen::Index>(k)], reference.heights[static_cast<Eigen::Index>(k)]) << k;
    }
  }
}

TEST(X3pReaderTest, ReadsAMainXmlInASubfolderWithItsMembersRelativeToIt) {
  const TempDir dir;
  const Members original = read_members(kFormatDataDir / "int16-mask-5x3.x3p");
  const fs::path path = dir / "sample-land.x3p";
  write_members(path, in_folder(original, "sample-land/"));
  expect_same_map(read_x3p_height_map(path), read_x3p_height_map(kFormatDataDir / "int16-mask-5x3.x3p"));

  // Two main.xml: which one describes the surface cannot be told.
  Members twice = in_folder(original, "a/");
  for (auto& member : in_folder(original, "b/")) twice.push_back(member);
  write_members(path, twice);
  expect_contains(x3p_error(path), {"2 files named main.xml", "'a/main.xml'", "'b/main.xml'", "ambiguous"});
}

TEST(X3pReaderTest, AcceptsTheOlderRootNameAndEmptyOffsets) {
  const TempDir dir;
  const fs::path path = dir / "old.x3p";
  std::string xml =
      minimal_xml("I",
                  "<MatrixDimension><SizeX>2</SizeX><SizeY>2</SizeY><SizeZ>1</SizeZ></MatrixDimension>"
                  "<DataList><Datum>1</Datum><Datum>2</Datum><Datum>3</Datum><Datum>4</Datum></DataList>");
  replace(xml, "<p:ISO5436_2 xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\">", "<ISO5436>");
  replace(xml, "</p:ISO5436_2>", "</ISO5436>");
  replace(xml, "<Offset>0</Offset>", "<Offset/>");
  replace(xml, "<CZ><AxisType>A</AxisType>", "<CZ><AxisType>A</AxisType><Increment>1e-9</Increment><Offset/>");
  write_members(path, {{"main.xml", xml}});
  const HeightMap map = read_x3p_height_map(path);
  EXPECT_EQ(map.nx, 2u);
  EXPECT_EQ(map.dx, 1e-6);
  EXPECT_EQ(map.heights[3], 4e-9);  // 4 x increment 1e-9 + an empty, zero, offset
}

TEST(X3pReaderTest, EscapesControlBytesFromTheFileInMessages) {
  const TempDir dir;
  const fs::path path = dir / "escape.x3p";
  std::string xml = minimal_xml("I", link_record3(3, 2), "S\x1b[2JUR");
  write_members(path, {{"main.xml", xml}});
  const std::string message = x3p_error(path);
  expect_contains(message, {"FeatureType 'S\\x1b[2JUR'"});
  EXPECT_EQ(message.find('\x1b'), std::string::npos) << message;
}

}  // namespace
}  // namespace halfspace::io
