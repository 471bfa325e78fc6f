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
  expect_contains(gsf_error(path), {path.string(), "Gwyddion Simple Field 1.0", "NumPy", "set the format to npy"});
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
  test::write_bytes(path, gsf_bytes("XRes = 1000\nYRes = 1000\n", {1.f, 2.f}));
  expect_contains(gsf_error(path), {"1000 x 1000", "(4000000 bytes) but 8 data bytes"});
  // 74.5 GiB of heights: refused before anything is read, whatever the machine.
  test::write_bytes(path, gsf_bytes("XRes = 100000\nYRes = 100000\n", {1.f, 2.f}));
  expect_contains(gsf_error(path), {"100000 x 100000", "for its heights alone"});
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

TEST(GsfReaderTest, RefusesADuplicateHeaderName) {
  // A second XRes used to be ignored silently (the first one won).
  const TempDir dir;
  const fs::path path = dir / "twice.gsf";
  test::write_bytes(path, gsf_bytes("XRes = 2\nYRes = 1\nXRes = 1\n", {1.0F, 2.0F}));
  expect_contains(gsf_error(path), {path.string(), "header line 4 sets 'XRes' a second time"});
}

TEST(GsfReaderTest, RefusesAUnitThatContradictsTheHeader) {
  // di-5-crop-m.gsf states ZUnits = m; --unit nm used to be ignored silently.
  try {
    read_gsf_height_map(kFormatDataDir / "di-5-crop-m.gsf", LengthUnit{"nm", 1e-9});
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    expect_contains(error.what(), {"di-5-crop-m.gsf", "the unit nm contradicts", "= m in the file's header"});
  }
  // The same unit as the header's is no contradiction.
  EXPECT_EQ(read_gsf_height_map(kFormatDataDir / "di-5-crop-m.gsf", LengthUnit{"m", 1.0}).nx, 64u);
  // A header without units takes the given unit.
  const TempDir dir;
  const fs::path path = dir / "bare.gsf";
  test::write_bytes(path, gsf_bytes("XRes = 2\nYRes = 1\n", {1.0F, 2.0F}));
  EXPECT_EQ(read_gsf_height_map(path, LengthUnit{"nm", 1e-9}).heights[1], 2e-9);
}

TEST(GsfReaderTest, BoundsTheHeaderAndTheDataItReads) {
  const TempDir dir;
  // /dev/zero used to be read until memory ran out.
  expect_contains(gsf_error("/dev/zero"), {"/dev/zero", "does not start with the line 'Gwyddion Simple Field 1.0'"});
  // A header with no NUL for 2 MiB is not a GSF header.
  const fs::path path = dir / "long.gsf";
  test::write_bytes(path, "Gwyddion Simple Field 1.0\n" + std::string(2 << 20, 'a'));
  expect_contains(gsf_error(path), {path.string(), "no NUL ends the header within its first 1048576 bytes"});
  // Endless data after a valid header: read the 8 declared bytes, not the pipe.
  const fs::path pipe_path = dir / "pipe.gsf";
  test::EndlessPipe pipe(pipe_path, gsf_bytes("XRes = 2\nYRes = 1\n", {1.0F, 2.0F}), std::string(1 << 16, '\0'),
                         std::size_t{64} << 20);
  expect_contains(gsf_error(pipe_path), {"more than the 8 data bytes"});
  EXPECT_LT(pipe.written(), std::size_t{4} << 20);
}

TEST(GsfReaderTest, EscapesControlBytesFromTheHeader) {
  const TempDir dir;
  const fs::path path = dir / "escape.gsf";
  test::write_bytes(path, gsf_bytes("XRes = 2\x1b[2J\nYRes = 1\n", {1.0F, 2.0F}));
  const std::string message = gsf_error(path);
  expect_contains(message, {"XRes = '2\\x1b[2J' is invalid"});
  EXPECT_EQ(message.find('\x1b'), std::string::npos) << message;
  test::write_bytes(path, gsf_bytes("XRes = 2\nYRes = 1\nTitle = a\x07"
                                    "b\n",
                                    {1.0F, 2.0F}));
  EXPECT_NE(read_gsf_height_map(path).source.find("'a\\x07b'"), std::string::npos);
}

}  // namespace
}  // namespace halfspace::io
