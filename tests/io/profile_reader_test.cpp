// Tests of read_profile: the Dektak CSV export (the real instrument file),
// x/z columns with units in the header, z alone, and the uniform-spacing
// check that names the offending line.
#include "halfspace/io/profile_reader.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/hdf5_test_support.hpp"
#include "io/reader_test_support.hpp"

namespace halfspace::io {
namespace {

namespace fs = std::filesystem;
using test::expect_contains;
using test::kFormatDataDir;
using test::TempDir;

// The README quotes Sq to 3 significant digits: half a unit of the last one.
constexpr double kQuotedSqHalfUnit = 0.005e-6;
// The x [um] / z [nm] fixture prints x = k dx and z with %.17g, and the unit
// conversion multiplies by 1e-6 or 1e-9 once: a few roundings.
constexpr double kUnitConversionRelativeTolerance = 4 * std::numeric_limits<double>::epsilon();

std::string profile_error(const fs::path& path) {
  return test::file_error_of([&] { read_profile(path); });
}

fs::path write_text(const TempDir& dir, const std::string& name, const std::string& text) {
  const fs::path path = dir / name;
  test::write_bytes(path, text);
  return path;
}

TEST(ProfileReaderTest, ReadsDektakExportWithReadmeGridSpacingAndSq) {
  // README: 9600 points, dx = 1500 um / 9600 = 0.15625 um, raw Sq 4.76 um.
  const HeightMap map = read_profile(kFormatDataDir / "dektak-1.csv");
  EXPECT_EQ(map.dimension, 1);
  EXPECT_EQ(map.nx, 9600u);
  EXPECT_EQ(map.ny, 1u);
  EXPECT_EQ(map.dx, 1500e-6 / 9600);  // the header's Length / n, not the fit to the rounded x column
  EXPECT_TRUE(map.valid.empty());
  EXPECT_NEAR(test::rms_about_mean(map.heights), 4.76e-6, kQuotedSqHalfUnit);
  EXPECT_NE(map.source.find("Dektak"), std::string::npos) << map.source;
}

TEST(ProfileReaderTest, DektakHeightsEqualTheHdf5ConversionBitForBit) {
  const HeightMap map = read_profile(kFormatDataDir / "dektak-1.csv");
  const HeightMap crop = read_hdf5_height_map(kFormatDataDir / "dektak-1-crop-256.h5");
  for (std::size_t k = 0; k < crop.nx; ++k) {
    ASSERT_EQ(map.heights[static_cast<Eigen::Index>(k)], crop.heights[static_cast<Eigen::Index>(k)]) << "at i = " << k;
  }
  if (!test::have_topography()) GTEST_SKIP() << "no measured data at " << test::kTopographyDir;
  const HeightMap full = read_hdf5_height_map(test::kTopographyDir / "dektak-1.h5");
  test::expect_same_heights(map, full);
  EXPECT_EQ(map.dx, full.dx);
}

TEST(ProfileReaderTest, ReadsUnitsFromColumnNames) {
  // x [um] and z [nm] of the first 256 Dektak points.
  const HeightMap map = read_profile(kFormatDataDir / "dektak-1-crop-x-z.txt");
  const HeightMap crop = read_hdf5_height_map(kFormatDataDir / "dektak-1-crop-256.h5");
  EXPECT_EQ(map.nx, 256u);
  EXPECT_NEAR(map.dx, crop.dx, kUnitConversionRelativeTolerance * crop.dx);
  double worst = 0.0;
  for (Eigen::Index k = 0; k < crop.heights.size(); ++k) {
    worst = std::max(worst, std::abs(map.heights[k] - crop.heights[k]) / std::abs(crop.heights[k]));
  }
  EXPECT_LE(worst, kUnitConversionRelativeTolerance);
  expect_contains(map.source, {"x in um", "z in nm"});
}

TEST(ProfileReaderTest, ReadsZAloneWithoutSpacing) {
  const TempDir dir;
  const HeightMap map = read_profile(write_text(dir, "z.txt", "# z only\n1e-6\n2e-6\nnan\n4e-6\n"));
  EXPECT_EQ(map.nx, 4u);
  EXPECT_EQ(map.dx, 0.0);
  EXPECT_EQ(map.heights[1], 2e-6);
  EXPECT_EQ(map.valid, (std::vector<std::uint8_t>{1, 1, 0, 1}));
}

TEST(ProfileReaderTest, AppliesTheGivenUnitToUnlabelledColumns) {
  const TempDir dir;
  const HeightMap map = read_profile(write_text(dir, "xz.csv", "0,1\n0.5,2\n1.0,3\n"), LengthUnit{"um", 1e-6});
  EXPECT_EQ(map.dx, 0.5e-6);
  EXPECT_EQ(map.heights[2], 3e-6);
}

TEST(ProfileReaderTest, RejectsAUnitThatContradictsTheFile) {
  try {
    read_profile(kFormatDataDir / "dektak-1-crop-x-z.txt", LengthUnit{"m", 1.0});
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    expect_contains(error.what(), {"the unit m contradicts column 'x [um]'", "which is in um"});
  }
}

// Found by the fuzzer: a Dektak header whose 'Scan Data' line is the last,
// with no newline after it, read past the end of the text (an uncaught
// std::out_of_range); it must be a file without data rows.
TEST(ProfileReaderTest, ADektakHeaderEndingAtScanDataHasNoDataRows) {
  const TempDir dir;
  const fs::path path = write_text(dir, "header.csv", "Scan Parameters\r\nLength,1500.0 um\r\nScan Data");
  expect_contains(profile_error(path), {path.string(), "holds no data rows"});
}

TEST(ProfileReaderTest, ReportsNonUniformSpacingWithTheLine) {
  const TempDir dir;
  const fs::path path = write_text(dir, "gap.txt", "x z\n0.0 1\n0.1 2\n0.2 3\n0.5 4\n0.6 5\n0.7 6\n");
  expect_contains(profile_error(path), {path.string(), "not uniformly spaced", "line 4 (x = 0.2) to line 5 (x = 0.5)",
                                        "the precision x is printed with"});
}

// One displaced x (line 12) moved the least-squares slope by more than the
// printed precision, and the message blamed the first step, from line 2 to
// 3 (issue 32); it must name line 12.
TEST(ProfileReaderTest, NamesTheLineOfOneDisplacedX) {
  const TempDir dir;
  std::string text = "x z\n";
  for (int k = 0; k < 30; ++k) text += fmt::format("{:.6f} {:.3f}\n", 0.5 * k + (k == 10 ? 0.2 : 0.0), 0.1 * k);
  const fs::path path = write_text(dir, "displaced.txt", text);
  const std::string message = profile_error(path);
  expect_contains(message, {path.string(), "not uniformly spaced", "line 12 has x = 5.2", "after line 11 (x = 4.5)",
                            "before line 13 (x = 5.5)", "step by 0.5 (the median step)"});
  EXPECT_EQ(message.find("line 2 "), std::string::npos) << message;
}

// A space-separated header with units in brackets, as docs/usage.md shows
// it ("x [um]", "z (nm)"), names two columns, and its units are honoured
// (issue 32: "the header on line 1 names 4 columns but the data have 2").
TEST(ProfileReaderTest, ReadsBracketedUnitsOfASpaceSeparatedHeader) {
  const TempDir dir;
  for (const char* header : {"x [um] z [nm]", "x (um) z (nm)", "x [um]\tz [nm]"}) {
    SCOPED_TRACE(header);
    const HeightMap map = read_profile(write_text(dir, "units.txt", std::string(header) + "\n0 1\n0.5 2\n1.0 3\n"));
    EXPECT_EQ(map.nx, 3u);
    EXPECT_NEAR(map.dx, 0.5e-6, 1e-21);
    EXPECT_NEAR(map.heights[2], 3e-9, 1e-24);
    expect_contains(map.source, {"x in um", "z in nm"});
  }
}

TEST(ProfileReaderTest, AcceptsRoundingWithinThePrintedPrecision) {
  // x = k / 3 printed with 2 decimals: off the grid by up to 0.005.
  const TempDir dir;
  const HeightMap map = read_profile(write_text(dir, "third.txt", "0.00 1\n0.33 1\n0.67 1\n1.00 1\n1.33 1\n1.67 1\n"));
  EXPECT_NEAR(map.dx, 1.0 / 3.0, 0.01 / 5);  // the fitted slope of 6 points rounded to 0.01
}

TEST(ProfileReaderTest, RejectsDecreasingAndNonFiniteX) {
  const TempDir dir;
  expect_contains(profile_error(write_text(dir, "down.txt", "3 1\n2 1\n1 1\n")), {"x does not increase"});
  expect_contains(profile_error(write_text(dir, "nanx.txt", "0 1\nnan 1\n2 1\n")), {"line 2: x = nan is not finite"});
}

TEST(ProfileReaderTest, RejectsMatricesAndHeaderMismatch) {
  const TempDir dir;
  expect_contains(profile_error(write_text(dir, "three.txt", "1 2 3\n4 5 6\n")),
                  {"line 1 has 3 values", "z alone or x and z"});
  expect_contains(profile_error(write_text(dir, "names.txt", "x y z\n1 2\n3 4\n")),
                  {"header on line 1 names 3 columns but the data have 2"});
  expect_contains(profile_error(write_text(dir, "one.txt", "1 2\n")), {"1 data row"});
}

TEST(ProfileReaderTest, RejectsATruncatedDektakExport) {
  const TempDir dir;
  const std::string full = test::read_bytes(kFormatDataDir / "dektak-1.csv");
  expect_contains(profile_error(write_text(dir, "head.csv", full.substr(0, 500))), {"no 'Scan Data' line"});
  // Cut in the middle of a data line: "1499.7,16.5" loses its z.
  const std::size_t cut = full.find("1499.7,") + 7;
  expect_contains(profile_error(write_text(dir, "cut.csv", full.substr(0, cut))), {"line", "has 1 values"});
}

TEST(ProfileReaderTest, AZeroXDoesNotLoosenTheSpacingCheck) {
  // "0.000000e+00" printed with 6 decimals has a rounding step of 1e-6, the
  // whole spacing: x values 0.4 and 0.9 of a step off the grid were accepted.
  const TempDir dir;
  const std::string head = "0.000000e+00 1\n1.000000e-06 2\n2.000000e-06 3\n";
  for (const char* off : {"3.400000e-06", "3.900000e-06"}) {
    SCOPED_TRACE(off);
    const fs::path path =
        write_text(dir, "zero.txt", head + off + " 4\n4.000000e-06 5\n5.000000e-06 6\n6.000000e-06 7\n");
    expect_contains(profile_error(path), {path.string(), "not uniformly spaced", "line 4"});
  }
  // The same file on the grid is read, with dx from the fit.
  const HeightMap map = read_profile(write_text(dir, "on.txt", head + "3.000000e-06 4\n4.000000e-06 5\n"));
  EXPECT_NEAR(map.dx, 1e-6, 1e-18);
}

TEST(ProfileReaderTest, NoXMayBeHalfAStepOffWhateverItsPrecision) {
  // Integers printed for a step of 1: the printed precision (1) is a whole
  // step, so the tolerance is half a step.
  const TempDir dir;
  const fs::path path = write_text(dir, "int.txt", "0 1\n1 1\n2 1\n3.6 1\n4 1\n5 1\n");
  expect_contains(profile_error(path), {"not uniformly spaced"});
  EXPECT_EQ(read_profile(write_text(dir, "ok.txt", "0 1\n1 1\n2 1\n3 1\n4 1\n")).dx, 1.0);
}

TEST(ProfileReaderTest, ReadsDevZeroAndProcFilesWithAClearError) {
  expect_contains(profile_error("/dev/zero"), {"/dev/zero", "not text", "byte 0x00 at offset 0"});
  expect_contains(profile_error("/proc/self/mem"), {"/proc/self/mem", "cannot be read"});
}

TEST(ProfileReaderTest, EscapesControlBytesOfColumnNames) {
  const TempDir dir;
  const fs::path path = write_text(dir, "names.txt", "x\xc2\x9b (um)\tz [nm]\n0 1\n1 2\n");
  try {
    read_profile(path, LengthUnit{"m", 1.0});
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    const std::string message = error.what();
    expect_contains(message, {"contradicts column 'x\\xc2\\x9b (um)'"});
    EXPECT_EQ(message.find("\xc2\x9b"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace halfspace::io
