// Tests of read_hdf5_height_map: the committed fixtures (measured crops and
// synthetic float32/int16 files made by tests/data/make_io_fixtures.py), files
// built here with the HDF5 C API, and every rejected input with its message.
#include "halfspace/io/hdf5_height_map_reader.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "io/hdf5_test_support.hpp"
#include "io/reader_test_support.hpp"

namespace halfspace::io {
namespace {

namespace fs = std::filesystem;
using test::add_double_attribute;
using test::add_double_dataset;
using test::create_file;
using test::TempDir;

const fs::path kDataDir = HALFSPACE_TEST_DATA_DIR;
const fs::path& kTopographyDir = test::kTopographyDir;

// Our rms sums in a different order from numpy's pairwise sum, and the di-5
// heights carry an offset 500x their rms, so cancellation amplifies rounding.
constexpr double kRmsRelativeTolerance = 1e-10;
// The topography README quotes Sq to 7 significant digits.
constexpr double kQuotedSqRelativeTolerance = 1e-6;

double rms_about_mean(const Eigen::ArrayXd& h) {
  return std::sqrt((h - h.mean()).square().mean());
}

// The message of the FileError that reading throws; any other exception
// escapes and fails the test, no exception is reported as a failure.
std::string read_error(const fs::path& path, const std::string& dataset = "/height") {
  try {
    read_hdf5_height_map(path, dataset);
  } catch (const FileError& error) {
    return error.what();
  }
  ADD_FAILURE() << "reading " << path << " dataset " << dataset << " did not throw FileError";
  return {};
}

void expect_contains(const std::string& message, const std::vector<std::string>& parts) {
  for (const std::string& part : parts) {
    EXPECT_NE(message.find(part), std::string::npos) << "message: " << message << "\nexpected to contain: " << part;
  }
}

// A file holding only /height as float64 of the given shape.
fs::path write_height_file(const TempDir& dir, const std::vector<hsize_t>& dims, const std::vector<double>& values) {
  const fs::path path = dir / "height.h5";
  const auto file = create_file(path);
  add_double_dataset(file.get(), "/height", dims, values);
  return path;
}

TEST(Hdf5HeightMapReaderTest, ReadsMeasuredMapCropWithSpacingAndRms) {
  // di-5-crop-48x64.h5: rows 100:148, columns 200:264 of the Bruker AFM map
  // di-5.h5. Reference values from numpy in make_io_fixtures.py:
  //   rms about mean 6.343056140613005e-10, h[0,0] -3.17137734822813e-07,
  //   h[47,63] -3.1766867405433544e-07, h[5,17] -3.1657954420154e-07.
  const fs::path path = kDataDir / "di-5-crop-48x64.h5";
  const HeightMap map = read_hdf5_height_map(path);

  EXPECT_EQ(map.dimension, 2);
  EXPECT_EQ(map.nx, 64u);
  EXPECT_EQ(map.ny, 48u);
  ASSERT_EQ(map.heights.size(), 48 * 64);
  EXPECT_EQ(map.dx, 1.953125e-9);  // 1 um / 512, exact in binary
  EXPECT_EQ(map.dy, 1.953125e-9);
  EXPECT_EQ(map.source, path.string() + ":/height");
  // Row-major (ny, nx): element (j, i) is heights[j * nx + i].
  EXPECT_EQ(map.heights[0], -3.17137734822813e-07);
  EXPECT_EQ(map.heights[47 * 64 + 63], -3.1766867405433544e-07);
  EXPECT_EQ(map.heights[5 * 64 + 17], -3.1657954420154e-07);
  EXPECT_NEAR(rms_about_mean(map.heights), 6.343056140613005e-10, kRmsRelativeTolerance * 6.343056140613005e-10);
}

TEST(Hdf5HeightMapReaderTest, ReadsMeasuredProfileCrop) {
  // dektak-1-crop-256.h5: points 0:256 of the stylus line scan dektak-1.h5.
  // numpy: rms about mean 1.3326401673040194e-07, h[0] -9.33e-09, h[255] 4.4809e-07.
  const fs::path path = kDataDir / "dektak-1-crop-256.h5";
  const HeightMap map = read_hdf5_height_map(path);

  EXPECT_EQ(map.dimension, 1);
  EXPECT_EQ(map.nx, 256u);
  EXPECT_EQ(map.ny, 1u);
  EXPECT_EQ(map.dx, 1.5625e-7);
  EXPECT_EQ(map.dy, 0.0);
  EXPECT_EQ(map.heights[0], -9.33e-09);
  EXPECT_EQ(map.heights[255], 4.4809e-07);
  EXPECT_NEAR(rms_about_mean(map.heights), 1.3326401673040194e-07, kRmsRelativeTolerance * 1.3326401673040194e-07);
}

TEST(Hdf5HeightMapReaderTest, ConvertsFloat32MapAndNumericSpacingAttributes) {
  // height-float32-3x5.h5: float32 (3, 5) with h[j, i] = (10 j + i) / 2 - 3,
  // dx a float32 attribute 2.5e-6, dy an int64 attribute 2.
  const HeightMap map = read_hdf5_height_map(kDataDir / "height-float32-3x5.h5");
  EXPECT_EQ(map.dimension, 2);
  EXPECT_EQ(map.nx, 5u);
  EXPECT_EQ(map.ny, 3u);
  EXPECT_EQ(map.dx, static_cast<double>(2.5e-6f));
  EXPECT_EQ(map.dy, 2.0);
  ASSERT_EQ(map.heights.size(), 15);
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 5; ++i)
      EXPECT_EQ(map.heights[j * 5 + i], (10 * j + i) * 0.5 - 3.0) << "at (j, i) = (" << j << ", " << i << ")";
  }
}

TEST(Hdf5HeightMapReaderTest, ReadsIntegerProfileFromNamedDatasetWithoutSpacing) {
  const fs::path path = kDataDir / "profile-int16.h5";
  const HeightMap map = read_hdf5_height_map(path, "profile");
  EXPECT_EQ(map.dimension, 1);
  EXPECT_EQ(map.nx, 6u);
  EXPECT_EQ(map.ny, 1u);
  EXPECT_EQ(map.dx, 0.0);  // no attribute: the caller must supply it
  EXPECT_EQ(map.dy, 0.0);
  EXPECT_EQ(map.source, path.string() + ":profile");
  const std::vector<double> expected{-3, 0, 7, 12, -32768, 32767};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(map.heights[i], expected[static_cast<std::size_t>(i)]) << "at i = " << i;
}

TEST(Hdf5HeightMapReaderTest, RoundTripsMapWrittenWithTheCApiBitExactly) {
  const TempDir dir;
  const std::size_t nx = 7;
  const std::size_t ny = 4;
  std::vector<double> values(nx * ny);
  for (std::size_t k = 0; k < values.size(); ++k) values[k] = std::sin(0.37 * static_cast<double>(k)) * 1e-6;
  const fs::path path = dir / "map.h5";
  {
    const auto file = create_file(path);
    const test::H5 group(H5Gcreate2(file.get(), "surface", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group");
    add_double_dataset(file.get(), "/surface/h", {ny, nx}, values);  // in a group
    add_double_attribute(file.get(), "dx", 1e-6);
    add_double_attribute(file.get(), "dy", 3e-6);
  }
  const HeightMap map = read_hdf5_height_map(path, "/surface/h");
  EXPECT_EQ(map.nx, nx);
  EXPECT_EQ(map.ny, ny);
  EXPECT_EQ(map.dx, 1e-6);
  EXPECT_EQ(map.dy, 3e-6);
  for (std::size_t k = 0; k < values.size(); ++k) EXPECT_EQ(map.heights[static_cast<Eigen::Index>(k)], values[k]);
}

TEST(Hdf5HeightMapReaderTest, ConvertsBigEndianIntegersAndOneElementSpacingArrays) {
  const TempDir dir;
  const fs::path path = dir / "big-endian.h5";
  const std::vector<std::int32_t> values{-70000, 0, 1, 2, 3, 70000};  // beyond the int16 range
  {
    const auto file = create_file(path);
    test::add_dataset(file.get(), "height", {2, 3}, H5T_STD_I32BE, H5T_NATIVE_INT32, values.data());
    const hsize_t one = 1;
    const test::H5 space(H5Screate_simple(1, &one, nullptr), H5Sclose, "1-element dataspace");
    const test::H5 dx(H5Acreate2(file.get(), "dx", H5T_IEEE_F32BE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                      "dx");
    const float spacing = 0.5f;
    test::check(H5Awrite(dx.get(), H5T_NATIVE_FLOAT, &spacing), "write dx");
  }
  const HeightMap map = read_hdf5_height_map(path);
  EXPECT_EQ(map.nx, 3u);
  EXPECT_EQ(map.ny, 2u);
  EXPECT_EQ(map.dx, 0.5);
  EXPECT_EQ(map.dy, 0.0);  // absent
  for (std::size_t k = 0; k < values.size(); ++k) {
    EXPECT_EQ(map.heights[static_cast<Eigen::Index>(k)], static_cast<double>(values[k]));
  }
}

TEST(Hdf5HeightMapReaderTest, IgnoresDyOfAProfile) {
  const TempDir dir;
  const fs::path path = write_height_file(dir, {3}, {1.0, 2.0, 3.0});
  {
    const auto file = test::H5(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose, "reopen");
    add_double_attribute(file.get(), "dx", 0.5);
    add_double_attribute(file.get(), "dy", -1.0);  // meaningless for a profile
  }
  const HeightMap map = read_hdf5_height_map(path);
  EXPECT_EQ(map.dx, 0.5);
  EXPECT_EQ(map.dy, 0.0);
}

TEST(Hdf5HeightMapReaderTest, ReadsFullMeasuredFilesWhenAvailable) {
  if (!fs::exists(kTopographyDir / "di-5.h5")) GTEST_SKIP() << "no measured data at " << kTopographyDir;
  // Sq quoted in the topography README, from the SurfaceTopography tests.
  const HeightMap di5 = read_hdf5_height_map(kTopographyDir / "di-5.h5");
  EXPECT_EQ(di5.nx, 512u);
  EXPECT_EQ(di5.ny, 512u);
  EXPECT_NEAR(rms_about_mean(di5.heights), 5.831926e-9, kQuotedSqRelativeTolerance * 5.831926e-9);

  const HeightMap dektak = read_hdf5_height_map(kTopographyDir / "dektak-1.h5");
  EXPECT_EQ(dektak.dimension, 1);
  EXPECT_EQ(dektak.nx, 9600u);

  // dx and dy differ in the 5th digit; a reader that copies one into the
  // other would pass every square-pixel file.
  const HeightMap rubber = read_hdf5_height_map(kTopographyDir / "KautschukInfiniteFocus.h5");
  EXPECT_EQ(rubber.nx, 857u);
  EXPECT_EQ(rubber.ny, 631u);
  EXPECT_NE(rubber.dx, rubber.dy);
  EXPECT_NEAR(rubber.dx, 2.279984e-6, 1e-12);
  EXPECT_NEAR(rubber.dy, 2.279795e-6, 1e-12);
}

// The shared layout's /valid (1 measured, 0 filled in): its zeros become
// invalid points, and the heights stored there are kept for the preparation
// step to refuse, refill or crop.
fs::path write_masked_file(const TempDir& dir, const std::vector<std::uint8_t>& valid,
                           const std::vector<hsize_t>& valid_dims) {
  const fs::path path = dir / "masked.h5";
  const auto file = create_file(path);
  add_double_dataset(file.get(), "/height", {2, 3}, {0.0, 1.0, 2.0, 3.0, 4.0, 5.0});
  test::add_dataset(file.get(), "/valid", valid_dims, H5T_STD_U8LE, H5T_NATIVE_UINT8, valid.data());
  return path;
}

TEST(Hdf5HeightMapReaderTest, MarksPointsThatTheValidMaskFlagsAsFilledIn) {
  const TempDir dir;
  const HeightMap map = read_hdf5_height_map(write_masked_file(dir, {1, 1, 1, 1, 0, 1}, {2, 3}));
  ASSERT_EQ(map.valid.size(), 6u);
  EXPECT_EQ(map.valid, (std::vector<std::uint8_t>{1, 1, 1, 1, 0, 1}));
  EXPECT_EQ(map.heights[4], 4.0);  // the file's own fill is kept, only marked
}

TEST(Hdf5HeightMapReaderTest, AllOnesMaskLeavesEveryPointValid) {
  const TempDir dir;
  EXPECT_TRUE(read_hdf5_height_map(write_masked_file(dir, {1, 1, 1, 1, 1, 1}, {2, 3})).all_valid());
}

TEST(Hdf5HeightMapReaderTest, ReadsTheMaskNextToADatasetInAGroup) {
  const TempDir dir;
  const fs::path path = dir / "grouped.h5";
  {
    const auto file = create_file(path);
    const test::H5 group(H5Gcreate2(file.get(), "/scan", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group");
    add_double_dataset(file.get(), "/scan/z", {2, 2}, {0.0, 1.0, 2.0, 3.0});
    const std::vector<std::uint8_t> valid{0, 1, 1, 1};
    test::add_dataset(file.get(), "/scan/valid", {2, 2}, H5T_STD_U8LE, H5T_NATIVE_UINT8, valid.data());
  }
  const HeightMap map = read_hdf5_height_map(path, "/scan/z");
  EXPECT_EQ(map.valid, (std::vector<std::uint8_t>{0, 1, 1, 1}));
}

// A process's rows of a map (the reading of an MPI run, here with the
// serial HDF5's default property lists): the whole map's rows, with their
// mask, and the whole map's shape, spacing and source.
TEST(Hdf5HeightMapReaderTest, ReadsTheRowsAProcessAsksFor) {
  const TempDir dir;
  const fs::path path = dir / "rows.h5";
  std::vector<double> heights(5 * 4);
  for (std::size_t k = 0; k < heights.size(); ++k) heights[k] = 0.5 * static_cast<double>(k);
  std::vector<std::uint8_t> valid(heights.size(), 1);
  valid[2 * 4 + 3] = 0;                                           // row 2
  heights[3 * 4 + 1] = std::numeric_limits<double>::quiet_NaN();  // row 3
  {
    const auto file = create_file(path);
    add_double_dataset(file.get(), "/height", {5, 4}, heights);
    test::add_dataset(file.get(), "/valid", {5, 4}, H5T_STD_U8LE, H5T_NATIVE_UINT8, valid.data());
    add_double_attribute(file.get(), "dx", 2e-6);
    add_double_attribute(file.get(), "dy", 3e-6);
  }
  const HeightMap whole = read_hdf5_height_map(path, "/height", NonFiniteHeights::mark_invalid);
  Hdf5RowReading reading;
  std::size_t asked_nx = 0, asked_ny = 0;
  reading.rows = [&](std::size_t nx, std::size_t ny) {
    asked_nx = nx;
    asked_ny = ny;
    return std::pair<std::size_t, std::size_t>{2, 2};
  };
  const HeightMapRows part = read_hdf5_height_map_rows(path, "/height", reading);
  EXPECT_EQ(asked_nx, 4u);
  EXPECT_EQ(asked_ny, 5u);
  EXPECT_EQ(part.first_row, 2u);
  EXPECT_EQ(part.rows, 2u);
  EXPECT_EQ(part.map.nx, 4u);
  EXPECT_EQ(part.map.ny, 5u);
  EXPECT_EQ(part.map.dx, 2e-6);
  EXPECT_EQ(part.map.dy, 3e-6);
  EXPECT_EQ(part.map.source, whole.source);
  ASSERT_EQ(part.map.heights.size(), 8);
  ASSERT_EQ(part.map.valid.size(), 8u);
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_EQ(part.map.valid[k], whole.valid[8 + k]) << k;
    if (whole.is_valid(8 + k)) {
      EXPECT_EQ(part.map.heights[static_cast<Eigen::Index>(k)], heights[8 + k]) << k;
    }
  }
  EXPECT_EQ(part.map.valid[3], 0);  // the mask's zero
  EXPECT_EQ(part.map.valid[5], 0);  // the NaN

  // A process without rows reads nothing, and still learns the shape.
  reading.rows = [](std::size_t, std::size_t) { return std::pair<std::size_t, std::size_t>{5, 0}; };
  const HeightMapRows none = read_hdf5_height_map_rows(path, "/height", reading);
  EXPECT_EQ(none.map.heights.size(), 0);
  EXPECT_EQ(none.map.ny, 5u);
  EXPECT_TRUE(none.map.all_valid());
}

TEST(Hdf5HeightMapReaderTest, RowReadingChecksTheFileAsTheWholeReading) {
  const TempDir dir;
  const fs::path path = write_masked_file(dir, {1, 1, 1, 1, 0, 1}, {3, 2});
  Hdf5RowReading reading;
  reading.rows = [](std::size_t, std::size_t) { return std::pair<std::size_t, std::size_t>{0, 1}; };
  try {
    read_hdf5_height_map_rows(path, "/height", reading);
    ADD_FAILURE() << "a mask of another shape was accepted";
  } catch (const FileError& error) {
    EXPECT_EQ(std::string(error.what()), read_error(path));
  }
}

TEST(Hdf5HeightMapReaderTest, RejectsValidMaskOfAnotherShape) {
  const TempDir dir;
  const fs::path path = write_masked_file(dir, {1, 1, 1, 1, 0, 1}, {3, 2});
  expect_contains(read_error(path), {path.string(), "'/valid'", "shape (3, 2)", "heights '/height' have shape (2, 3)"});
}

TEST(Hdf5HeightMapReaderTest, RejectsValidMaskThatIsNotIntegers) {
  const TempDir dir;
  const fs::path path = dir / "float-mask.h5";
  {
    const auto file = create_file(path);
    add_double_dataset(file.get(), "/height", {2, 2}, {0.0, 1.0, 2.0, 3.0});
    add_double_dataset(file.get(), "/valid", {2, 2}, {1.0, 1.0, 0.0, 1.0});
  }
  expect_contains(read_error(path), {"'/valid'", "must hold integers"});
}

TEST(Hdf5HeightMapReaderTest, RejectsMissingFile) {
  const TempDir dir;
  const fs::path path = dir / "absent.h5";
  expect_contains(read_error(path), {path.string(), "/height", "does not exist"});
}

TEST(Hdf5HeightMapReaderTest, RejectsDirectory) {
  const TempDir dir;
  expect_contains(read_error(dir.path()), {dir.path().string(), "is a directory"});
}

TEST(Hdf5HeightMapReaderTest, RejectsFileThatIsNotHdf5) {
  const TempDir dir;
  const fs::path path = dir / "heights.csv";
  std::ofstream(path) << "0.0,1.0\n2.0,3.0\n";
  expect_contains(read_error(path), {path.string(), "not an HDF5 file"});
}

TEST(Hdf5HeightMapReaderTest, RejectsMissingDatasetAndListsRootDatasets) {
  const TempDir dir;
  const fs::path path = dir / "many.h5";
  {
    const auto file = create_file(path);
    for (int k = 0; k < 12; ++k) add_double_dataset(file.get(), fmt::format("d{}", 100 + k), {2}, {0.0, 1.0});
    const test::H5 group(H5Gcreate2(file.get(), "a_group", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group");
  }
  const std::string message = read_error(path, "/heigth");
  expect_contains(message, {path.string(), "'/heigth'", "does not exist", "'/d100'", "'/d109'", "and 2 more"});
  EXPECT_EQ(message.find("d110"), std::string::npos) << message;     // only ten are listed
  EXPECT_EQ(message.find("a_group"), std::string::npos) << message;  // groups are not datasets
}

TEST(Hdf5HeightMapReaderTest, RejectsDatasetInMissingGroup) {
  const TempDir dir;
  const fs::path path = write_height_file(dir, {2}, {0.0, 1.0});
  expect_contains(read_error(path, "/no/such/height"), {"'/no/such/height'", "does not exist", "'/height'"});
}

TEST(Hdf5HeightMapReaderTest, RejectsGroupInsteadOfDataset) {
  const TempDir dir;
  const fs::path path = dir / "group.h5";
  {
    const auto file = create_file(path);
    const test::H5 group(H5Gcreate2(file.get(), "height", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group");
  }
  expect_contains(read_error(path), {"group, not a dataset"});
}

TEST(Hdf5HeightMapReaderTest, RejectsRankThree) {
  const TempDir dir;
  const fs::path path = write_height_file(dir, {2, 3, 4}, std::vector<double>(24, 0.0));
  expect_contains(read_error(path), {path.string(), "rank 3", "(2, 3, 4)", "expected rank 1"});
}

TEST(Hdf5HeightMapReaderTest, RejectsScalarDataset) {
  const TempDir dir;
  const fs::path path = write_height_file(dir, {}, {1.0});
  expect_contains(read_error(path), {"scalar (rank 0)"});
}

TEST(Hdf5HeightMapReaderTest, RejectsFewerThanTwoPointsAlongAnAxis) {
  const TempDir dir;
  const fs::path map_path = write_height_file(dir, {1, 5}, std::vector<double>(5, 0.0));
  expect_contains(read_error(map_path), {"shape (1, 5)", "1 point(s) along y", "at least 2"});

  const TempDir other;
  const fs::path profile_path = write_height_file(other, {1}, {0.0});
  expect_contains(read_error(profile_path), {"shape (1,)", "1 point(s) along x"});
}

TEST(Hdf5HeightMapReaderTest, RejectsNonFiniteHeightsNamingTheFirst) {
  const TempDir dir;
  std::vector<double> values(12, 0.0);  // shape (3, 4)
  values[1 * 4 + 2] = std::numeric_limits<double>::quiet_NaN();
  values[2 * 4 + 0] = std::numeric_limits<double>::infinity();
  const fs::path path = write_height_file(dir, {3, 4}, values);
  expect_contains(read_error(path), {path.string(), "2 of 12 heights are not finite", "(j, i) = (1, 2)", "nan"});
}

TEST(Hdf5HeightMapReaderTest, RejectsNonFiniteProfileNamingTheIndex) {
  const TempDir dir;
  const fs::path path = write_height_file(dir, {5}, {0.0, 1.0, 2.0, -std::numeric_limits<double>::infinity(), 4.0});
  expect_contains(read_error(path), {"1 of 5 heights are not finite", "index i = 3", "-inf"});
}

TEST(Hdf5HeightMapReaderTest, RejectsStringDataset) {
  const TempDir dir;
  const fs::path path = dir / "text.h5";
  {
    const auto file = create_file(path);
    const test::H5 type(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
    H5Tset_size(type.get(), 4);
    const char text[3][4] = {{'a', 'b', 'c', 'd'}, {'e', 'f', 'g', 'h'}, {'i', 'j', 'k', 'l'}};
    test::add_dataset(file.get(), "height", {3}, type.get(), type.get(), text);
  }
  expect_contains(read_error(path), {path.string(), "string data, not numbers"});
}

TEST(Hdf5HeightMapReaderTest, RejectsCompoundDataset) {
  const TempDir dir;
  const fs::path path = dir / "compound.h5";
  struct Point {
    double x;
    double z;
  };
  {
    const auto file = create_file(path);
    const test::H5 type(H5Tcreate(H5T_COMPOUND, sizeof(Point)), H5Tclose, "compound type");
    H5Tinsert(type.get(), "x", HOFFSET(Point, x), H5T_NATIVE_DOUBLE);
    H5Tinsert(type.get(), "z", HOFFSET(Point, z), H5T_NATIVE_DOUBLE);
    const Point points[2] = {{0.0, 1.0}, {1.0, 2.0}};
    test::add_dataset(file.get(), "height", {2}, type.get(), type.get(), points);
  }
  expect_contains(read_error(path), {"compound data, not numbers"});
}

TEST(Hdf5HeightMapReaderTest, RejectsNegativeSpacing) {
  const TempDir dir;
  const fs::path path = write_height_file(dir, {2, 2}, {0.0, 1.0, 2.0, 3.0});
  {
    const auto file = test::H5(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose, "reopen");
    add_double_attribute(file.get(), "dx", -1e-9);
  }
  expect_contains(read_error(path), {path.string(), "'dx' = -1e-09", "finite and >= 0"});
}

TEST(Hdf5HeightMapReaderTest, RejectsNonFiniteSpacing) {
  const TempDir dir;
  const fs::path path = write_height_file(dir, {2, 2}, {0.0, 1.0, 2.0, 3.0});
  {
    const auto file = test::H5(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose, "reopen");
    add_double_attribute(file.get(), "dx", 1e-9);
    add_double_attribute(file.get(), "dy", std::numeric_limits<double>::quiet_NaN());
  }
  expect_contains(read_error(path), {"'dy' = nan", "finite and >= 0"});
}

TEST(Hdf5HeightMapReaderTest, RejectsNonNumericSpacing) {
  const TempDir dir;
  const fs::path path = write_height_file(dir, {2, 2}, {0.0, 1.0, 2.0, 3.0});
  {
    const auto file = test::H5(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose, "reopen");
    test::add_string_attribute(file.get(), "dx", "1 nm");
  }
  expect_contains(read_error(path), {"'dx' is of string type", "expected a number"});
}

// The library never prints: HDF5's own error stack stays silent during a
// failed read, and the caller's HDF5 error-printing setting is restored.
TEST(Hdf5HeightMapReaderTest, FailsSilentlyAndRestoresHdf5ErrorPrinting) {
  const TempDir dir;
  const fs::path path = write_height_file(dir, {2}, {0.0, 1.0});
  H5E_auto2_t before = nullptr;
  void* before_data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &before, &before_data);
  ASSERT_NE(before, nullptr) << "HDF5 should print errors by default";

  testing::internal::CaptureStderr();
  const std::string message = read_error(path, "/missing");
  const std::string printed = testing::internal::GetCapturedStderr();
  EXPECT_FALSE(message.empty());
  EXPECT_EQ(printed, "");

  H5E_auto2_t after = nullptr;
  void* after_data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &after, &after_data);
  EXPECT_EQ(after, before);
  EXPECT_EQ(after_data, before_data);
}

TEST(Hdf5HeightMapReaderTest, RefusesDatasetsWhoseDataAreNotStoredInTheFile) {
  const TempDir dir;
  // 30000 x 30000 points never written: a 2 KB file that used to cost 7.2 GB
  // of fill values.
  const fs::path unwritten = dir / "unwritten.h5";
  {
    const test::H5 file = create_file(unwritten);
    const hsize_t dims[2] = {30000, 30000};
    const test::H5 space(H5Screate_simple(2, dims, nullptr), H5Sclose, "space");
    const test::H5 data(
        H5Dcreate2(file.get(), "height", H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
        "create");
  }
  const std::size_t before = test::peak_resident_bytes();
  expect_contains(read_error(unwritten), {unwritten.string(), "holds no stored data"});
  EXPECT_LT(test::peak_resident_bytes(), before + test::kRefusalMemoryAllowance);

  // Raw data in an external file, here /dev/zero: used to be read from there.
  const fs::path external = dir / "external.h5";
  {
    const test::H5 file = create_file(external);
    const test::H5 creation(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "dcpl");
    test::check(H5Pset_external(creation.get(), "/dev/zero", 0, 4 * sizeof(double)), "external");
    const hsize_t dims[2] = {2, 2};
    const test::H5 space(H5Screate_simple(2, dims, nullptr), H5Sclose, "space");
    const test::H5 data(
        H5Dcreate2(file.get(), "height", H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, creation.get(), H5P_DEFAULT),
        H5Dclose, "create");
  }
  expect_contains(read_error(external), {external.string(), "external files"});
}

TEST(Hdf5HeightMapReaderTest, RefusesAChunkedDatasetOfWhichOnlySomeChunksWereWritten) {
  const TempDir dir;
  // 16000 x 16000 points in 4 x 4 chunks, one of them written: a 4 KB file
  // on which libhdf5's per-chunk bookkeeping used more than 20 GB.
  const fs::path partial = dir / "partial.h5";
  {
    const test::H5 file = create_file(partial);
    const test::H5 creation(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "dcpl");
    const hsize_t chunk[2] = {4, 4};
    test::check(H5Pset_chunk(creation.get(), 2, chunk), "chunk");
    const hsize_t dims[2] = {16000, 16000};
    const test::H5 space(H5Screate_simple(2, dims, nullptr), H5Sclose, "space");
    const test::H5 data(
        H5Dcreate2(file.get(), "height", H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, creation.get(), H5P_DEFAULT),
        H5Dclose, "create");
    const hsize_t start[2] = {0, 0};
    test::check(H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start, nullptr, chunk, nullptr), "select");
    const test::H5 memory(H5Screate_simple(2, chunk, nullptr), H5Sclose, "memory");
    const std::vector<double> values(16, 1.0);
    test::check(H5Dwrite(data.get(), H5T_NATIVE_DOUBLE, memory.get(), space.get(), H5P_DEFAULT, values.data()),
                "write");
  }
  const std::size_t before = test::peak_resident_bytes();
  expect_contains(read_error(partial), {partial.string(), "only partly written", "1 of its 16000000 chunks"});
  EXPECT_LT(test::peak_resident_bytes(), before + test::kRefusalMemoryAllowance);
}

TEST(Hdf5HeightMapReaderTest, RefusesADatasetDeclaringMoreDataThanTheFileHolds) {
  const TempDir dir;
  // A 3 x 3 contiguous dataset whose header is then made to declare
  // 16000 x 16000 points and 2 GB of data at the same address: named before
  // any buffer for it is made.
  const fs::path path = dir / "declares-more.h5";
  haddr_t address = 0;
  {
    const test::H5 file = create_file(path);
    const hsize_t dims[2] = {3, 3};
    const test::H5 space(H5Screate_simple(2, dims, nullptr), H5Sclose, "space");
    const test::H5 data(
        H5Dcreate2(file.get(), "height", H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
        "create");
    const std::vector<double> values(9, 1e-6);
    test::check(H5Dwrite(data.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "write");
    address = H5Dget_offset(data.get());
  }
  std::vector<char> bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const auto u64 = [&](std::size_t at) {
    std::uint64_t value = 0;
    for (std::size_t k = 0; k < 8; ++k) value |= std::uint64_t(static_cast<unsigned char>(bytes[at + k])) << (8 * k);
    return value;
  };
  const auto put = [&](std::size_t at, std::uint64_t value) {
    for (std::size_t k = 0; k < 8; ++k) bytes[at + k] = static_cast<char>((value >> (8 * k)) & 0xff);
  };
  std::size_t patched_dims = 0;
  std::size_t patched_size = 0;
  for (std::size_t at = 0; at + 8 <= bytes.size(); ++at) {
    // The dataspace's dimensions (and maximum dimensions), 3 each; the
    // layout's size of the data, 72 bytes, after its address.
    if (u64(at) == 3 && at + 16 <= bytes.size() && u64(at + 8) == 3) {
      put(at, 16000);
      put(at + 8, 16000);
      patched_dims += 2;
      at += 15;
    } else if (u64(at) == 72 && at >= 8 && u64(at - 8) == address) {
      put(at, std::uint64_t{16000} * 16000 * 8);
      ++patched_size;
      at += 7;
    }
  }
  ASSERT_GE(patched_dims, 2u);
  ASSERT_EQ(patched_size, 1u);
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  const std::size_t before = test::peak_resident_bytes();
  expect_contains(read_error(path), {path.string(), "declares 2048000000 bytes of stored data",
                                     fmt::format("the file has only {} bytes", bytes.size())});
  EXPECT_LT(test::peak_resident_bytes(), before + test::kRefusalMemoryAllowance);
}

TEST(Hdf5HeightMapReaderTest, ReadsAChunkedCompressedDatasetWithEveryChunkWritten) {
  const TempDir dir;
  const fs::path path = dir / "chunked.h5";
  const hsize_t dims[2] = {5, 7};
  std::vector<double> values(35);
  for (std::size_t k = 0; k < values.size(); ++k) values[k] = 1e-6 * static_cast<double>(k % 11);
  {
    const test::H5 file = create_file(path);
    const test::H5 creation(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "dcpl");
    const hsize_t chunk[2] = {2, 3};  // partial chunks at the edges
    test::check(H5Pset_chunk(creation.get(), 2, chunk), "chunk");
    test::check(H5Pset_deflate(creation.get(), 4), "deflate");
    const test::H5 space(H5Screate_simple(2, dims, nullptr), H5Sclose, "space");
    const test::H5 data(
        H5Dcreate2(file.get(), "height", H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, creation.get(), H5P_DEFAULT),
        H5Dclose, "create");
    test::check(H5Dwrite(data.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "write");
  }
  const HeightMap map = read_hdf5_height_map(path);
  ASSERT_EQ(map.nx, 7u);
  ASSERT_EQ(map.ny, 5u);
  for (std::size_t k = 0; k < values.size(); ++k) EXPECT_EQ(map.heights[static_cast<Eigen::Index>(k)], values[k]);
}

TEST(Hdf5HeightMapReaderTest, ADamagedFileLeavesHdf5ErrorPrintingOff) {
  // One byte of an object address changed: H5Fopen fails ("addr overflow")
  // and leaves HDF5 unable to close its internals, so that at exit it printed
  // "HDF5: infinite loop closing library" and a line of interface names
  // after halfspace's message, unless error printing is off by then
  // (hostile_input_cli_test checks what a user sees).
  const TempDir dir;
  std::string bytes = test::read_bytes(kDataDir / "di-5-crop-48x64.h5");
  bytes[1410] = '\x94';
  const fs::path path = dir / "damaged.h5";
  H5E_auto2_t saved_printer = nullptr;
  void* saved_data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &saved_printer, &saved_data);
  test::write_bytes(path, bytes);
  ::testing::internal::CaptureStderr();
  const std::string message = read_error(path);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  expect_contains(message, {path.string(), "cannot be opened"});
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  H5E_auto2_t printer = nullptr;
  void* data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &printer, &data);
  EXPECT_EQ(printer, nullptr) << "HDF5's error printing was turned back on";
  H5Eset_auto2(H5E_DEFAULT, saved_printer, saved_data);  // as it was, for the other tests
}

}  // namespace
// A 140-byte file the fuzzer found: its metadata declares an entry of
// 40 GiB, which libhdf5 tries to allocate
// while opening. The allocation fails and must end in a FileError naming the
// file, not a crash.
TEST(Hdf5HeightMapReaderTest, AMetadataEntryTooLargeToAllocateIsAFileError) {
  const TempDir dir;
  const fs::path path = dir / "huge-entry.h5";
  const std::vector<unsigned char> bytes{
      0x89, 0x48, 0x44, 0x46, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x00, 0x00, 0x08, 0x08, 0x00, 0x04, 0x00,
      0x10, 0x00, 0x00, 0x00, 0x00, 0x00, 0x7e, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xff, 0xff, 0xff, 0xff,
      0xff, 0xff, 0xff, 0xff, 0x0a, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff,
      0xff, 0xff, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x01, 0x00, 0x00, 0x00, 0x00, 0x04, 0x00, 0x00, 0x88, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xa8, 0x02,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x01, 0x00, 0x01, 0x00, 0x00, 0x00, 0x18, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x10, 0x00, 0x10, 0x00, 0x00, 0x00, 0x00, 0x00, 0x88, 0x00, 0x00, 0x00, 0x89, 0x48,
      0x44, 0x46, 0x00, 0x00, 0x00, 0x00, 0x0a, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  };
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  expect_contains(read_error(path), {path.string(), "cannot be opened"});
}

}  // namespace halfspace::io

namespace halfspace::io {
namespace {

// A 50-byte file the fuzzer found: a version 0 superblock, cut short, whose
// reserved byte 15 is 0xf9. libhdf5 1.10 read it as a size and allocated
// 4 GiB (16 MiB per unit of the byte) for 12 s before failing; the reserved
// fields are now checked before HDF5 sees the file (hdf5_superblock.hpp).
TEST(Hdf5HeightMapReaderTest, ASuperblockWithAReservedByteSetIsRefusedBeforeHdf5ReadsIt) {
  const TempDir dir;
  const fs::path path = dir / "reserved.h5";
  const std::vector<unsigned char> bytes{0x89, 0x48, 0x44, 0x46, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x00, 0x00,
                                         0x08, 0x08, 0xf9, 0x03, 0x3b, 0x4f, 0x10, 0x00, 0x00, 0x00, 0x48, 0x00, 0x00,
                                         0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff,
                                         0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x08, 0x00};
  test::write_bytes(path, std::string(bytes.begin(), bytes.end()));
  expect_contains(read_error(path), {path.string(), "damaged", "reserved byte 15 is 249 (must be 0)"});
}

// Each fixed field of a good file's superblock, spoiled in turn.
TEST(Hdf5HeightMapReaderTest, DamagedSuperblockFieldsAreNamed) {
  const TempDir dir;
  const std::string good = test::read_bytes(write_height_file(dir, {2, 3}, {1, 2, 3, 4, 5, 6}));
  ASSERT_EQ(good.substr(0, 4), "\x89HDF");
  const unsigned version = static_cast<unsigned char>(good[8]);
  ASSERT_LE(version, 3u);
  const std::size_t offsets_at = version <= 1 ? 13 : 9;
  struct Case {
    std::size_t at;
    char value;
    std::string expected;
  };
  for (const Case& c : {Case{8, '\x09', "superblock version 9"}, Case{offsets_at, '\x03', "size of offsets is 3"},
                        Case{offsets_at + 1, '\x05', "size of lengths is 5"},
                        Case{offsets_at, '\x10', "size of offsets is 16 bytes (2, 4 or 8 are read)"}}) {
    std::string bytes = good;
    bytes[c.at] = c.value;
    const fs::path path = dir / "spoiled.h5";
    test::write_bytes(path, bytes);
    expect_contains(read_error(path), {path.string(), "damaged", c.expected});
  }
  const fs::path path = dir / "cut.h5";
  test::write_bytes(path, good.substr(0, 40));
  expect_contains(read_error(path), {path.string(), "damaged", "cut short"});
}

// The signature may follow a user block (512, 1024, ... bytes): the check
// finds it there and reads the file.
TEST(Hdf5HeightMapReaderTest, ReadsAFileWithAUserBlock) {
  const TempDir dir;
  const fs::path path = dir / "user-block.h5";
  {
    const hid_t create = H5Pcreate(H5P_FILE_CREATE);
    ASSERT_GE(H5Pset_userblock(create, 1024), 0);
    const test::H5 file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, create, H5P_DEFAULT), H5Fclose, "create");
    H5Pclose(create);
    add_double_dataset(file.get(), "/height", {2, 2}, {1.0, 2.0, 3.0, 4.0});
  }
  ASSERT_EQ(test::read_bytes(path).substr(1024, 4), "\x89HDF") << "no user block written";
  const HeightMap map = read_hdf5_height_map(path, "/height");
  EXPECT_EQ(map.heights[3], 4.0);
}

}  // namespace
}  // namespace halfspace::io

namespace halfspace::io {
namespace {

// A 97-byte file the fuzzer found next: its driver information block
// states 1.6 GiB of information, which libhdf5 1.10 allocated before reading.
TEST(Hdf5HeightMapReaderTest, ADriverInformationBlockLargerThanTheFileIsRefused) {
  const TempDir dir;
  const fs::path path = dir / "driver-info.h5";
  const std::vector<unsigned char> bytes{
      0x89, 0x48, 0x44, 0x46, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x00, 0x00, 0x08, 0x08, 0x00, 0x65,
      0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x53, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x64, 0xe1, 0xfb, 0x00, 0xff, 0x2a, 0x00,
  };
  test::write_bytes(path, std::string(bytes.begin(), bytes.end()));
  expect_contains(read_error(path), {path.string(), "damaged", "driver information block (at byte 83) does not fit"});
}

}  // namespace
}  // namespace halfspace::io
