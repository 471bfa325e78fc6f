// Tests of read_height_map: format choice by extension and by name, options
// that do not apply, and every measured file of ../shared/data/topography
// against the grid, spacing and Sq of its README (skipped without the data).
#include "halfspace/io/height_map_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
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

TEST(HeightMapReaderTest, ChoosesTheReaderByExtension) {
  EXPECT_EQ(format_from_extension("a.h5"), HeightMapFormat::hdf5);
  EXPECT_EQ(format_from_extension("a.NC"), HeightMapFormat::hdf5);
  EXPECT_EQ(format_from_extension("a.npy"), HeightMapFormat::npy);
  EXPECT_EQ(format_from_extension("a.txt"), HeightMapFormat::text_matrix);
  EXPECT_EQ(format_from_extension("a.csv"), HeightMapFormat::text_matrix);
  EXPECT_EQ(format_from_extension("a.x3p"), HeightMapFormat::x3p);
  EXPECT_EQ(format_from_extension("a.gsf"), HeightMapFormat::gsf);
  // A Dektak export is a profile whatever its extension says.
  EXPECT_EQ(format_from_extension(kFormatDataDir / "dektak-1.csv"), HeightMapFormat::profile);
  try {
    format_from_extension("scan.sur");
    ADD_FAILURE() << "no error";
  } catch (const FileError& error) {
    expect_contains(error.what(), {"scan.sur", "'.sur'", "set the format"});
  }
}

TEST(HeightMapReaderTest, ParsesFormatNamesAndRejectsUnknownOnes) {
  EXPECT_EQ(parse_height_map_format("hdf5"), HeightMapFormat::hdf5);
  EXPECT_EQ(parse_height_map_format("nc"), HeightMapFormat::hdf5);
  EXPECT_EQ(parse_height_map_format("matrix"), HeightMapFormat::text_matrix);
  EXPECT_EQ(parse_height_map_format("Profile"), HeightMapFormat::profile);
  for (HeightMapFormat format : {HeightMapFormat::hdf5, HeightMapFormat::npy, HeightMapFormat::text_matrix,
                                 HeightMapFormat::profile, HeightMapFormat::x3p, HeightMapFormat::gsf}) {
    EXPECT_EQ(parse_height_map_format(to_string(format)), format);
  }
  try {
    parse_height_map_format("sur");
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    expect_contains(error.what(), {"'sur' is unknown", "npy", "x3p"});
  }
}

TEST(HeightMapReaderTest, ReadsEveryFixtureFormatToTheSameHeights) {
  const HeightMap reference = test::di5_reference();
  for (const char* name : {"di-5-crop-48x64.h5", "di-5-crop-c-be-f8.npy", "di-5-crop-f-le-f8.npy",
                           "di-5-crop-space.txt", "di-5-crop-comma.csv"}) {
    SCOPED_TRACE(name);
    test::expect_same_heights(read_height_map(kFormatDataDir / name), reference);
  }
}

TEST(HeightMapReaderTest, ExplicitFormatOverridesTheExtension) {
  const TempDir dir;
  const fs::path path = dir / "surface.bin";
  fs::copy_file(kFormatDataDir / "di-5-crop-c-le-f8.npy", path);
  ReadOptions options;
  options.format = HeightMapFormat::npy;
  test::expect_same_heights(read_height_map(path, options), test::di5_reference());
  options.format = HeightMapFormat::profile;
  const HeightMap profile = read_height_map(kFormatDataDir / "dektak-1-crop-x-z.txt", options);
  EXPECT_EQ(profile.dimension, 1);
}

TEST(HeightMapReaderTest, TwoColumnTextNeedsAnExplicitFormat) {
  const TempDir dir;
  const fs::path path = dir / "xz.csv";
  test::write_bytes(path, "0,1\n1,2\n2,3\n3,4\n");
  try {
    read_height_map(path);
    ADD_FAILURE() << "no error";
  } catch (const FileError& error) {
    expect_contains(error.what(), {"xz.csv", "2 columns and 4 rows", "format to profile", "to matrix"});
  }
  ReadOptions profile;
  profile.format = HeightMapFormat::profile;
  EXPECT_EQ(read_height_map(path, profile).nx, 4u);
  ReadOptions matrix;
  matrix.format = HeightMapFormat::text_matrix;
  EXPECT_EQ(read_height_map(path, matrix).nx, 2u);
}

TEST(HeightMapReaderTest, Hdf5NonFiniteHeightsBecomeInvalidPoints) {
  const TempDir dir;
  const fs::path path = dir / "holes.h5";
  {
    const auto file = test::create_file(path);
    test::add_double_dataset(file.get(), "/height", {2, 3}, {1, 2, std::nan(""), 4, 5, 6});
  }
  const HeightMap map = read_height_map(path);
  EXPECT_EQ(map.valid, (std::vector<std::uint8_t>{1, 1, 0, 1, 1, 1}));
}

TEST(HeightMapReaderTest, RejectsOptionsThatDoNotApplyToTheFormat) {
  ReadOptions dataset;
  dataset.dataset = "/topography";
  EXPECT_THROW(read_height_map(kFormatDataDir / "di-5-crop-space.txt", dataset), InputError);
  ReadOptions unit;
  unit.unit = LengthUnit{"um", 1e-6};
  try {
    read_height_map(kFormatDataDir / "di-5-crop-48x64.h5", unit);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    expect_contains(error.what(), {"unit (um) does not apply to the hdf5 format"});
  }
}

TEST(HeightMapReaderTest, ReadsNetcdf4FilesAsHdf5) {
  // NetCDF-4 is HDF5 underneath: a variable is a dataset.
  const TempDir dir;
  const fs::path path = dir / "surface.nc";
  fs::copy_file(kFormatDataDir / "di-5-crop-48x64.h5", path);
  test::expect_same_heights(read_height_map(path), test::di5_reference());
}

TEST(HeightMapReaderTest, EveryTruncationOfABinaryFixtureIsAFileError) {
  // Cut each binary fixture at 40 lengths spread over the file (and one byte
  // short): every read must fail with a FileError, never crash or return heights.
  const TempDir dir;
  for (const char* name : {"di-5-crop-48x64.h5", "di-5-crop-f-be-f8.npy", "di-5-crop-m.gsf", "kautschuk-crop-40x56.x3p",
                           "int16-mask-5x3.x3p"}) {
    const std::string bytes = test::read_bytes(kFormatDataDir / name);
    const fs::path path = dir / (std::string("cut-") + name);
    for (std::size_t step = 0; step <= 40; ++step) {
      const std::size_t length = step == 40 ? bytes.size() - 1 : bytes.size() * step / 40;
      test::write_bytes(path, bytes.substr(0, length));
      SCOPED_TRACE(std::string(name) + " cut to " + std::to_string(length) + " bytes");
      EXPECT_THROW(read_height_map(path), FileError);
    }
  }
}

TEST(HeightMapReaderTest, DamagedX3pIsAnErrorOrReadsTheSameHeights) {
  // Flip one byte at 60 places of the X3P crop: its checksums and the zip's
  // CRCs must catch every change that would alter the heights.
  const TempDir dir;
  const std::string bytes = test::read_bytes(kFormatDataDir / "kautschuk-crop-40x56.x3p");
  const HeightMap original = read_height_map(kFormatDataDir / "kautschuk-crop-40x56.x3p");
  const fs::path path = dir / "flipped.x3p";
  std::size_t errors = 0;
  for (std::size_t step = 0; step < 60; ++step) {
    std::string damaged = bytes;
    const std::size_t at = damaged.size() * step / 60;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x20);
    test::write_bytes(path, damaged);
    SCOPED_TRACE("byte " + std::to_string(at) + " flipped");
    try {
      const HeightMap map = read_height_map(path);
      ASSERT_EQ(map.heights.size(), original.heights.size());
      for (Eigen::Index k = 0; k < map.heights.size(); ++k) {
        ASSERT_TRUE(map.heights[k] == original.heights[k] ||
                    (std::isnan(map.heights[k]) && std::isnan(original.heights[k])))
            << "silently different height at k = " << k;
      }
    } catch (const FileError&) {
      ++errors;
    }
  }
  EXPECT_GT(errors, 40u);  // most bytes of a compressed archive matter
}

// A measured file and what the topography README says of it: the grid, the
// spacings and Sq as quoted, with half a unit of the last quoted digit as the
// allowed difference.
struct ReadmeRow {
  const char* file;
  int dimension;
  std::size_t ny, nx;
  double dx, dx_half_unit;
  double dy, dy_half_unit;
  double sq, sq_half_unit;
  std::size_t invalid;  // points the file itself marks invalid (or, in the HDF5 form, marks filled in /valid)
};

const std::vector<ReadmeRow> kReadme{
    {"dektak-1.h5", 1, 1, 9600, 0.15625e-6, 0.000005e-6, 0.0, 0.0, 4.76e-6, 0.005e-6, 0},
    {"dektak-1.csv", 1, 1, 9600, 0.15625e-6, 0.000005e-6, 0.0, 0.0, 4.76e-6, 0.005e-6, 0},
    {"di-5.h5", 2, 512, 512, 1.953125e-9, 0.0000005e-9, 1.953125e-9, 0.0000005e-9, 5.831926e-9, 0.0000005e-9, 0},
    {"spot_1-1000nm.h5", 2, 256, 256, 78.431e-9, 0.0005e-9, 78.431e-9, 0.0005e-9, 110e-9, 0.5e-9, 0},
    {"opd-1.h5", 2, 480, 640, 196.733e-9, 0.0005e-9, 196.733e-9, 0.0005e-9, 8.37e-9, 0.005e-9, 116},
    {"metropro-1.h5", 2, 480, 640, 1.09825e-6, 0.000005e-6, 1.09825e-6, 0.000005e-6, 7.528822e-8, 0.0000005e-8, 0},
    {"sur-2.h5", 2, 484, 563, 3.484e-6, 0.0005e-6, 3.484e-6, 0.0005e-6, 31.2e-9, 0.05e-9, 0},
    {"plu-1.h5", 2, 576, 768, 1.66e-6, 0.005e-6, 1.66e-6, 0.005e-6, 2.834391e-6, 0.0000005e-6, 0},
    {"KautschukInfiniteFocus.h5", 2, 631, 857, 2.279984e-6, 0.0000005e-6, 2.279795e-6, 0.0000005e-6, 3.40e-6, 0.005e-6,
     823},
    {"KautschukInfiniteFocus.x3p", 2, 634, 860, 2.279984e-6, 0.0000005e-6, 2.279795e-6, 0.0000005e-6, 0.0, 0.0, 5296},
};

TEST(HeightMapReaderTest, MeasuredFilesMatchTheReadme) {
  if (!test::have_topography()) GTEST_SKIP() << "no measured data at " << test::kTopographyDir;
  for (const ReadmeRow& row : kReadme) {
    SCOPED_TRACE(row.file);
    const HeightMap map = read_height_map(test::kTopographyDir / row.file);
    EXPECT_EQ(map.dimension, row.dimension);
    EXPECT_EQ(map.ny, row.ny);
    EXPECT_EQ(map.nx, row.nx);
    EXPECT_NEAR(map.dx, row.dx, row.dx_half_unit);
    EXPECT_NEAR(map.dy, row.dy, row.dy_half_unit);
    EXPECT_EQ(surface::count_invalid(map), row.invalid);
    // The raw x3p has +inf border points; its Sq is checked after filling (x3p_reader_test).
    if (row.sq > 0.0) {
      EXPECT_NEAR(test::rms_about_mean(map.heights), row.sq, row.sq_half_unit);
    }
  }
}

TEST(HeightMapReaderTest, ReadsANamedPipeWithoutLookingIntoItFirst) {
  // The .csv extension makes the dispatcher check for a Dektak export; on a
  // pipe that check used to consume the data, and the reader then waited
  // for a writer that was gone.
  const test::TempDir dir;
  const std::filesystem::path path = dir / "map.csv";
  const std::string text = "1 2 3\n4 5 6\n";
  test::EndlessPipe pipe(path, text, "", text.size());
  const HeightMap map = read_height_map(path);
  EXPECT_EQ(map.nx, 3u);
  EXPECT_EQ(map.ny, 2u);
  EXPECT_EQ(map.heights[4], 5.0);
}

}  // namespace
}  // namespace halfspace::io
