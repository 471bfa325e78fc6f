// Tests of read_npy_height_map: the di-5 crop saved by numpy in C and Fortran
// order, both byte orders, float64 and float32, against the HDF5 original bit
// for bit, and every malformed file with its message.
#include "halfspace/io/npy_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "io/hdf5_test_support.hpp"
#include "io/reader_test_support.hpp"

namespace halfspace::io {
namespace {

namespace fs = std::filesystem;
using test::expect_contains;
using test::file_error_of;
using test::kFormatDataDir;
using test::TempDir;

std::string npy_error(const fs::path& path) {
  return file_error_of([&] { read_npy_height_map(path); });
}

// A version 1.0 .npy file with the given header dict and data bytes; the
// header is padded with spaces to a multiple of 64 bytes as numpy does.
std::string npy_bytes(const std::string& dict, const std::string& data) {
  std::string header = dict;
  while ((10 + header.size() + 1) % 64 != 0) header.push_back(' ');
  header.push_back('\n');
  std::string bytes("\x93NUMPY\x01\x00", 8);
  bytes.push_back(static_cast<char>(header.size() & 0xff));
  bytes.push_back(static_cast<char>(header.size() >> 8));
  return bytes + header + data;
}

std::string doubles(std::initializer_list<double> values) {
  std::string data;
  for (double v : values) data.append(reinterpret_cast<const char*>(&v), sizeof v);
  return data;
}

void expect_matches_reference(const fs::path& path) {
  const HeightMap reference = test::di5_reference();
  const HeightMap map = read_npy_height_map(path);
  EXPECT_EQ(map.dimension, 2);
  EXPECT_EQ(map.dx, 0.0);  // .npy stores no spacing
  EXPECT_EQ(map.dy, 0.0);
  EXPECT_TRUE(map.valid.empty());
  test::expect_same_heights(map, reference);
}

TEST(NpyReaderTest, ReadsCOrderLittleEndianBitExactly) {
  expect_matches_reference(kFormatDataDir / "di-5-crop-c-le-f8.npy");
}

TEST(NpyReaderTest, ReadsCOrderBigEndianBitExactly) {
  expect_matches_reference(kFormatDataDir / "di-5-crop-c-be-f8.npy");
}

TEST(NpyReaderTest, ReadsFortranOrderLittleEndianBitExactly) {
  expect_matches_reference(kFormatDataDir / "di-5-crop-f-le-f8.npy");
}

TEST(NpyReaderTest, ReadsFortranOrderBigEndian) {
  expect_matches_reference(kFormatDataDir / "di-5-crop-f-be-f8.npy");
}

TEST(NpyReaderTest, ReadsFloat32AsTheFloat32RoundingOfTheOriginal) {
  const HeightMap reference = test::di5_reference();
  const HeightMap map = read_npy_height_map(kFormatDataDir / "di-5-crop-c-le-f4.npy");
  ASSERT_EQ(map.heights.size(), reference.heights.size());
  for (Eigen::Index k = 0; k < map.heights.size(); ++k) {
    ASSERT_EQ(map.heights[k], static_cast<double>(static_cast<float>(reference.heights[k]))) << "at k = " << k;
  }
  EXPECT_EQ(map.heights[5 * 64 + 17], -3.1657953059038846e-07);  // numpy's float32 value
}

TEST(NpyReaderTest, ScalesByTheGivenUnit) {
  const HeightMap reference = test::di5_reference();
  const HeightMap map = read_npy_height_map(kFormatDataDir / "di-5-crop-c-le-f8.npy", {"nm", 1e-9});
  EXPECT_EQ(map.heights[7], reference.heights[7] * 1e-9);
  EXPECT_NE(map.source.find("heights in nm"), std::string::npos) << map.source;
}

TEST(NpyReaderTest, ReadsProfileIntegersAndMarksNaNInvalid) {
  const TempDir dir;
  const fs::path profile = dir / "profile.npy";
  std::string data;
  for (std::int16_t v : {-3, 0, 7, 12}) data.append(reinterpret_cast<const char*>(&v), sizeof v);
  test::write_bytes(profile, npy_bytes("{'descr': '<i2', 'fortran_order': False, 'shape': (4,), }", data));
  const HeightMap map = read_npy_height_map(profile);
  EXPECT_EQ(map.dimension, 1);
  EXPECT_EQ(map.nx, 4u);
  EXPECT_EQ(map.heights[2], 7.0);

  const fs::path holes = dir / "holes.npy";
  const double nan = std::numeric_limits<double>::quiet_NaN();
  test::write_bytes(holes, npy_bytes("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2), }",
                                     doubles({1.0, nan, 3.0, std::numeric_limits<double>::infinity()})));
  const HeightMap with_holes = read_npy_height_map(holes);
  ASSERT_EQ(with_holes.valid.size(), 4u);
  EXPECT_EQ(with_holes.valid, (std::vector<std::uint8_t>{1, 0, 1, 0}));
  EXPECT_TRUE(std::isnan(with_holes.heights[3]));
}

TEST(NpyReaderTest, RejectsTextMislabelledAsNpy) {
  const TempDir dir;
  const fs::path path = dir / "really-text.npy";
  test::write_bytes(path, "1 2 3\n4 5 6\n");
  expect_contains(npy_error(path), {path.string(), "NumPy", "magic", "'1 2 3"});
}

TEST(NpyReaderTest, NamesTheRealFormatOfAnHdf5FileMislabelledAsNpy) {
  const TempDir dir;
  const fs::path path = dir / "surface.npy";
  fs::copy_file(kFormatDataDir / "di-5-crop-48x64.h5", path);
  expect_contains(npy_error(path), {"HDF5", "set the format to hdf5"});
}

TEST(NpyReaderTest, RejectsTruncatedData) {
  const TempDir dir;
  const fs::path path = dir / "truncated.npy";
  const std::string full = test::read_bytes(kFormatDataDir / "di-5-crop-c-le-f8.npy");
  test::write_bytes(path, full.substr(0, full.size() - 100));
  expect_contains(npy_error(path), {path.string(), "truncated", "24576 data bytes", "24476"});
}

TEST(NpyReaderTest, RejectsTruncatedHeader) {
  const TempDir dir;
  const fs::path path = dir / "header.npy";
  test::write_bytes(path, test::read_bytes(kFormatDataDir / "di-5-crop-c-le-f8.npy").substr(0, 40));
  expect_contains(npy_error(path), {"truncated", "header claims"});
}

TEST(NpyReaderTest, RejectsHeaderClaimingMoreDataThanPresent) {
  const TempDir dir;
  const fs::path path = dir / "claims.npy";
  test::write_bytes(
      path, npy_bytes("{'descr': '<f8', 'fortran_order': False, 'shape': (3, 4), }", doubles({1, 2, 3, 4, 5, 6})));
  expect_contains(npy_error(path), {"shape (3, 4)", "96 data bytes", "48 follow"});
}

TEST(NpyReaderTest, RejectsTrailingBytes) {
  const TempDir dir;
  const fs::path path = dir / "trailing.npy";
  test::write_bytes(path,
                    npy_bytes("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2), }", doubles({1, 2, 3, 4, 5})));
  expect_contains(npy_error(path), {"8 bytes follow the data"});
}

TEST(NpyReaderTest, RejectsUnsupportedDtypes) {
  const TempDir dir;
  for (const std::string descr : {"<c16", "|b1", "<U5", "<f2", "|O"}) {
    const fs::path path = dir / "dtype.npy";
    test::write_bytes(path, npy_bytes("{'descr': '" + descr + "', 'fortran_order': False, 'shape': (2, 2), }",
                                      std::string(64, '\0')));
    expect_contains(npy_error(path), {"dtype '" + descr + "' is not supported"});
  }
  const fs::path structured = dir / "structured.npy";
  test::write_bytes(structured,
                    npy_bytes("{'descr': [('x', '<f8')], 'fortran_order': False, 'shape': (2,), }", doubles({1, 2})));
  expect_contains(npy_error(structured), {"header"});
}

TEST(NpyReaderTest, RejectsWrongRankAndTooFewPoints) {
  const TempDir dir;
  const fs::path cube = dir / "cube.npy";
  test::write_bytes(cube, npy_bytes("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2, 2), }",
                                    doubles({1, 2, 3, 4, 5, 6, 7, 8})));
  expect_contains(npy_error(cube), {"shape (2, 2, 2)", "(ny, nx)"});
  const fs::path row = dir / "row.npy";
  test::write_bytes(row, npy_bytes("{'descr': '<f8', 'fortran_order': False, 'shape': (1, 3), }", doubles({1, 2, 3})));
  expect_contains(npy_error(row), {"shape (1, 3)", "at least 2 points"});
}

TEST(NpyReaderTest, RejectsMissingFileAndUnknownVersion) {
  const TempDir dir;
  expect_contains(npy_error(dir / "missing.npy"), {"missing.npy", "does not exist"});
  const fs::path version = dir / "v9.npy";
  std::string bytes = npy_bytes("{'descr': '<f8', 'fortran_order': False, 'shape': (2,), }", doubles({1, 2}));
  bytes[6] = 9;
  test::write_bytes(version, bytes);
  expect_contains(npy_error(version), {"format version 9.0"});
}

TEST(NpyReaderTest, RefusesDevZeroAtItsFirstBytes) {
  // Used to read /dev/zero to the end of memory.
  expect_contains(npy_error("/dev/zero"), {"/dev/zero", "magic", "\\x00"});
}

TEST(NpyReaderTest, ReadsFromAPipeNoMoreThanTheHeaderDeclares) {
  // A valid 2 x 2 float64 array, then endless bytes: the reader must stop
  // after the 32 data bytes and one more, not read the pipe to its end.
  const TempDir dir;
  const fs::path path = dir / "pipe.npy";
  constexpr std::size_t kCap = std::size_t{64} << 20;
  test::EndlessPipe pipe(
      path, npy_bytes("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2), }", doubles({1, 2, 3, 4})),
      std::string(1 << 16, '\x01'), kCap);
  expect_contains(npy_error(path), {path.string(), "more bytes follow the data of shape (2, 2)"});
  EXPECT_LT(pipe.written(), std::size_t{4} << 20) << "the reader read on after the declared data";
}

TEST(NpyReaderTest, ReadsAWholeArrayFromAPipe) {
  const TempDir dir;
  const fs::path path = dir / "pipe.npy";
  const std::string bytes = npy_bytes("{'descr': '<f8', 'fortran_order': False, 'shape': (3,), }", doubles({1, 2, 3}));
  test::EndlessPipe pipe(path, bytes, "", bytes.size());
  const HeightMap map = read_npy_height_map(path);
  ASSERT_EQ(map.nx, 3u);
  EXPECT_EQ(map.heights[2], 3.0);
}

TEST(NpyReaderTest, RefusesHeadersAndShapesThatClaimTooMuch) {
  const TempDir dir;
  const fs::path path = dir / "claims.npy";
  // Version 2.0 with a header length of 4 GiB - 1.
  test::write_bytes(path, std::string("\x93NUMPY\x02\x00\xff\xff\xff\xff{}", 14));
  expect_contains(npy_error(path), {path.string(), "the header claims 4294967295 bytes"});
  // A shape whose product overflows 64 bits.
  test::write_bytes(path, npy_bytes("{'descr': '<f8', 'fortran_order': False, 'shape': (4294967296, 4294967296), }",
                                    doubles({1, 2})));
  expect_contains(npy_error(path), {"4294967296 x 4294967296", "too large"});
  // A shape beyond the machine's memory, from a 100-byte file.
  test::write_bytes(
      path, npy_bytes("{'descr': '<f8', 'fortran_order': False, 'shape': (1000000000, 100000), }", doubles({1, 2})));
  expect_contains(npy_error(path), {"100000 x 1000000000", "memory"});
}

TEST(NpyReaderTest, EscapesControlBytesFromTheHeader) {
  const TempDir dir;
  const fs::path path = dir / "escape.npy";
  test::write_bytes(path,
                    npy_bytes("{'descr': '<f\x1b[31m', 'fortran_order': False, 'shape': (2,), }", doubles({1, 2})));
  const std::string message = npy_error(path);
  expect_contains(message, {"dtype '<f\\x1b[31m'"});
  EXPECT_EQ(message.find('\x1b'), std::string::npos) << message;
}

}  // namespace
}  // namespace halfspace::io
