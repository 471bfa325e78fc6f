// Helpers for the height-map reader tests: fixture paths, the di-5 reference
// crop, capturing a reader's FileError message, and writing damaged files.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/io/hdf5_height_map_reader.hpp"
#include "halfspace/io/height_map.hpp"

namespace halfspace::test {

inline const std::filesystem::path kFormatDataDir = HALFSPACE_TEST_DATA_DIR;
// The measured topographies: shared/ beside the repository (as CI lays it
// out), else the workplace's /work/shared.
inline std::filesystem::path find_topography_dir() {
  const std::filesystem::path beside = kFormatDataDir / ".." / ".." / ".." / "shared" / "data" / "topography";
  if (std::filesystem::exists(beside / "README.md")) return beside.lexically_normal();
  return "/work/shared/data/topography";
}
inline const std::filesystem::path kTopographyDir = find_topography_dir();

inline bool have_topography() {
  return std::filesystem::exists(kTopographyDir / "README.md");
}

// The 48 x 64 crop of di-5.h5 that every format fixture of the map readers
// was written from (tests/data/make_format_fixtures.py).
inline io::HeightMap di5_reference() {
  return io::read_hdf5_height_map(kFormatDataDir / "di-5-crop-48x64.h5");
}

inline double rms_about_mean(const Eigen::ArrayXd& h) {
  return std::sqrt((h - h.mean()).square().mean());
}

// The message of the FileError that `read` throws; any other exception
// escapes and fails the test, and no exception is reported as a failure.
template <class Read>
std::string file_error_of(Read&& read) {
  try {
    read();
  } catch (const FileError& error) {
    return error.what();
  }
  ADD_FAILURE() << "reading did not throw FileError";
  return {};
}

inline void expect_contains(const std::string& message, const std::vector<std::string>& parts) {
  for (const std::string& part : parts) {
    EXPECT_NE(message.find(part), std::string::npos) << "message: " << message << "\nexpected to contain: " << part;
  }
}

inline std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// Expects `map` to hold exactly the heights of `reference` (same shape),
// reporting the first difference.
inline void expect_same_heights(const io::HeightMap& map, const io::HeightMap& reference) {
  ASSERT_EQ(map.nx, reference.nx);
  ASSERT_EQ(map.ny, reference.ny);
  ASSERT_EQ(map.heights.size(), reference.heights.size());
  for (Eigen::Index k = 0; k < map.heights.size(); ++k) {
    if (map.heights[k] != reference.heights[k]) {
      ADD_FAILURE() << "first difference at (j, i) = (" << static_cast<std::size_t>(k) / map.nx << ", "
                    << static_cast<std::size_t>(k) % map.nx << "): " << map.heights[k] << " vs "
                    << reference.heights[k];
      return;
    }
  }
}

}  // namespace halfspace::test
