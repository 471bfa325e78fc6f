// Tests of the height-map writer: what it writes reads back through the
// HDF5 height-map reader bit for bit, with its spacing and attributes.
#include "halfspace/io/height_map_writer.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/io/hdf5_height_map_reader.hpp"
#include "io/hdf5_test_support.hpp"

namespace halfspace::io {
namespace {

using test::TempDir;

TEST(HeightMapWriterTest, RoundTripsThroughTheReader) {
  const TempDir dir;
  const Grid grid = Grid::plane(5, 3, 2e-6, 3e-6, Boundary::periodic);
  std::vector<double> heights(15);
  for (std::size_t k = 0; k < heights.size(); ++k) heights[k] = 1e-7 * static_cast<double>(k) / 3.0;
  HeightMapMetadata metadata;
  metadata.source = "test";
  metadata.periodic = true;
  metadata.numbers = {{"hurst", 0.8}};
  metadata.integers = {{"seed", 9}};
  metadata.strings = {{"generator", "hand"}};
  write_height_map(dir / "map.h5", grid, heights, metadata);

  const HeightMap map = read_hdf5_height_map(dir / "map.h5");
  EXPECT_EQ(map.dimension, 2);
  EXPECT_EQ(map.nx, 5u);
  EXPECT_EQ(map.ny, 3u);
  EXPECT_EQ(map.dx, 2e-6);
  EXPECT_EQ(map.dy, 3e-6);
  EXPECT_EQ(std::vector<double>(map.heights.begin(), map.heights.end()), heights);

  const test::H5 file = test::open_file(dir / "map.h5");
  EXPECT_EQ(test::read_int64_attribute(file.get(), "periodic"), 1);
  EXPECT_EQ(test::read_int64_attribute(file.get(), "seed"), 9);
  EXPECT_EQ(test::read_double_attribute(file.get(), "hurst"), 0.8);
  EXPECT_EQ(test::read_string_attribute(file.get(), "generator"), "hand");
  EXPECT_EQ(test::read_string_attribute(file.get(), "unit"), "m");

  const Grid line = Grid::line(4, 1e-6, Boundary::free);
  write_height_map(dir / "profile.h5", line, std::vector<double>{1, 2, 3, 4}, HeightMapMetadata{});
  const HeightMap profile = read_hdf5_height_map(dir / "profile.h5");
  EXPECT_EQ(profile.dimension, 1);
  EXPECT_EQ(profile.nx, 4u);

  EXPECT_THROW(write_height_map(dir / "bad.h5", line, std::vector<double>{1, 2}, HeightMapMetadata{}), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.h5"));
}

// A FIFO at the output path (as a device node would be, as root) is refused
// by name and left as it is, not replaced by the renamed file.
TEST(HeightMapWriterTest, RefusesAFifoAtTheOutputPathAndLeavesIt) {
  const TempDir dir;
  const std::filesystem::path pipe = dir / "map.h5";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  const Grid grid = Grid::line(4, 1e-6, Boundary::free);
  try {
    write_height_map(pipe, grid, std::vector<double>(4, 0.0), HeightMapMetadata{});
    ADD_FAILURE() << "no FileError";
  } catch (const FileError& error) {
    EXPECT_NE(std::string(error.what()).find("'" + pipe.string() + "': it is a FIFO"), std::string::npos)
        << error.what();
  }
  EXPECT_EQ(std::filesystem::symlink_status(pipe).type(), std::filesystem::file_type::fifo);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"map.h5"});
}

}  // namespace
}  // namespace halfspace::io
