// Tests of read_gsf_height_map: the di-5 crop written as Gwyddion Simple
// Field in metres and in um/nm, and damaged headers and data.
#include "halfspace/io/gsf_reader.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <string>

#include "io/hdf5_test_support.hpp"
#include "io/reader_test_support.hpp"

namespace halfspace::io {
namespace {

namespace fs = std::filesystem;
using test::expect_contains;
using test::kFormatDataDir;
using test::TempDir;

// GSF stores float32: 2^-24 relative rounding, and the um/nm file adds the
// rounding of the scaling by 1e9 and back.
constexpr double kFloat32RelativeTolerance = 1.2e-7;

std::string gsf_error(const fs::path& path) {
  return test::file_error_of([&] { read_gsf_height_map(path); });
}

// A GSF file: header fields, NUL padding to a multiple of 4, float32 data.
std::string gsf_bytes(const std::string& fields, const std::vector<float>& values) {
  std::string bytes = "Gwyddion Simple Field 1.0\n" + fields;
  bytes.append(4 - bytes.size() % 4, '\0');
  for (float v : values) bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
  return bytes;
}

TEST(GsfReaderTest, ReadsMetreFileAsFloat32OfTheOriginal) {
  const HeightMap reference = test::di5_reference();
  const HeightMap map = read_gsf_height_map(kFormatDataDir / "di-5-crop-m.gsf");
  EXPECT_EQ(map.dimension, 2);
  EXPECT_EQ(map.nx, 64u);
  EXPECT_EQ(map.ny, 48u);
  EXPECT_EQ(map.dx, 64 * 1.953125e-9 / 64);  // XReal / XRes
  EXPECT_EQ(map.dy, 48 * 1.953125e-9 / 48);
  for (Eigen::Index k = 0; k < map.heights.size(); ++k) {
    ASSERT_EQ(map.heights[k], static_cast<double>(static_cast<float>(reference.heights[k]))) << "at k = " << k;
  }
  EXPECT_NE(map.source.find("'di-5 crop'"), std::string::npos) << map.source;
}

TEST(GsfReaderTest, ConvertsMicrometreAndNanometreUnits) {
  const HeightMap reference = test::di5_reference();
  const HeightMap map = read_gsf_height_map(kFormatDataDir / "di-5-crop-um-nm.gsf");
  EXPECT_NEAR(map.dx, 1.953125e-9, kFloat32RelativeTolerance * 1.953125e-9);
  double worst = 0.0;
  for (Eigen::Index k = 0; k < map.heights.size(); ++k) {
    worst = std::max(worst, std::abs(map.heights[k] / reference.heights[k] - 1.0));
  }
  EXPECT_LE(worst, kFloat32RelativeTolerance);
  EXPECT_EQ(map.heights[5 * 64 + 17], -3.165795593261719e-07);  // numpy: float32(h * 1e9) * 1e-9
}

TEST(GsfReaderTest, MissingRealSizesGiveNoSpacingAndNaNIsInvalid) {
  const TempDir dir;
  const fs::path path = dir / "plain.gsf";
  test::write_bytes(path, gsf_bytes("XRes = 2\nYRes = 2\n", {1.f, std::numeric_limits<float>::quiet_NaN(), 3.f, 4.f}));
  const HeightMap map = read_gsf_height_map(path);
  EXPECT_EQ(map.dx, 0.0);
  EXPECT_EQ(map.dy, 0.0);
  EXPECT_EQ(map.valid, (std::vector<std::uint8_t>{1, 0, 1, 1}));
}

TEST(GsfReaderTest, PaddingAlignsDataForEveryHeaderLength) {
  // Headers of length 4k+0..3 need 4, 3, 2, 1 NULs.
  const TempDir dir;
  for (int extra = 0; extra < 4; ++extra) {
    const fs::path path = dir / "pad.gsf";
    test::write_bytes(
        path, gsf_bytes("XRes = 2\nYRes = 1\nTitle = " + std::string(static_cast<std::size_t>(extra), 'x') + "\n",
                        {1.5f, -2.5f}));
    const HeightMap map = read_gsf_height_map(path);
    EXPECT_EQ(map.dimension, 1);
    EXPECT_EQ(map.heights[1], -2.5) << "title length " << extra;
  }
}

TEST(GsfReaderTest, RejectsWrongMagicNamingWhatTheFileIs) {
  const TempDir dir;
  const fs::path path = dir / "really-npy.gsf";
  fs::copy_file(kFormatDataDir / "di-5-crop-c-le-f8.npy", path);
  expect_contains(gsf_error(path), {path.string(), "Gwyddion Simple Field 1.0", "NumPy", "--format npy"});
}

TEST(GsfReaderTest, RejectsTruncatedData) {
  const TempDir dir;
  const fs::path path = dir / "cut.gsf";
  const std::string full = test::read_bytes(kFormatDataDir / "di-5-crop-m.gsf");
  test::write_bytes(path, full.substr(0, full.size() - 10));
  expect_contains(gsf_error(path), {"64 x 48 float32 values (12288 bytes)", "12278 data bytes", "truncated"});
}

TEST(GsfReaderTest, RejectsHeaderClaimingMorePointsThanPresent) {
  const TempDir dir;
  const fs::path path = dir / "claims.gsf";
  test::write_bytes(path, gsf_bytes("XRes = 100000\nYRes = 100000\n", {1.f, 2.f}));
  expect_contains(gsf_error(path), {"100000 x 100000", "8 data bytes"});
}

TEST(GsfReaderTest, RejectsMalformedHeaders) {
  const TempDir dir;
  const fs::path path = dir / "bad.gsf";
  test::write_bytes(path, gsf_bytes("XRes = 2\n", {1.f, 2.f}));
  expect_contains(gsf_error(path), {"no YRes"});
  test::write_bytes(path, gsf_bytes("XRes = two\nYRes = 1\n", {1.f, 2.f}));
  expect_contains(gsf_error(path), {"XRes = 'two' is invalid"});
  test::write_bytes(path, gsf_bytes("XRes = 2\nYRes = 1\nthis line has no equals sign\n", {1.f, 2.f}));
  expect_contains(gsf_error(path), {"header line 4", "name = value"});
  test::write_bytes(path, gsf_bytes("XRes = 2\nYRes = 1\nZUnits = V\n", {1.f, 2.f}));
  expect_contains(gsf_error(path), {"ZUnits = 'V' is not a length unit"});
  test::write_bytes(path, gsf_bytes("XRes = 2\nYRes = 1\nXReal = -1\n", {1.f, 2.f}));
  expect_contains(gsf_error(path), {"XReal = '-1' is invalid"});
  test::write_bytes(path, "Gwyddion Simple Field 1.0\nXRes = 2\nYRes = 1\n");
  expect_contains(gsf_error(path), {"not terminated by NUL padding"});
}

}  // namespace
}  // namespace halfspace::io
