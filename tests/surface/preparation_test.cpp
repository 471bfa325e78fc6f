// Tests of window selection, padding for free boundaries and the order of the
// preparation steps with their record.
#include "halfspace/surface/preparation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "halfspace/error.hpp"
#include "halfspace/surface/padding.hpp"
#include "support/height_map_fixtures.hpp"

namespace halfspace::surface {
namespace {

// h[j][i] = 100 j + i, easy to recognise after cutting.
HeightMap index_map(std::size_t nx, std::size_t ny) {
  HeightMap map;
  map.dimension = ny == 1 ? 1 : 2;
  map.nx = nx;
  map.ny = ny;
  map.dx = 1e-6;
  map.dy = ny == 1 ? 0.0 : 2e-6;
  map.source = "index map";
  map.heights.resize(static_cast<Eigen::Index>(nx * ny));
  for (std::size_t k = 0; k < nx * ny; ++k) {
    map.heights[static_cast<Eigen::Index>(k)] = 100.0 * static_cast<double>(k / nx) + static_cast<double>(k % nx);
  }
  return map;
}

using testing::input_error_of;

TEST(WindowTest, ParsesMapAndProfileWindows) {
  const Window map = parse_window("10,20,128,64");
  EXPECT_EQ(map.i0, 10u);
  EXPECT_EQ(map.j0, 20u);
  EXPECT_EQ(map.nx, 128u);
  EXPECT_EQ(map.ny, 64u);
  const Window profile = parse_window("5, 100");
  EXPECT_EQ(profile.dimension, 1);
  EXPECT_EQ(profile.nx, 100u);
  for (const char* bad : {"1,2,3", "a,b,c,d", "-1,0,4,4", "", "1,,2,3"}) {
    EXPECT_NE(input_error_of([&] { parse_window(bad); }).find("expected I0,J0,NX,NY"), std::string::npos) << bad;
  }
}

TEST(WindowTest, CutsTheWindowAndKeepsSpacing) {
  HeightMap map = index_map(10, 8);
  select_window(map, parse_window("2,3,4,5"));
  EXPECT_EQ(map.nx, 4u);
  EXPECT_EQ(map.ny, 5u);
  EXPECT_EQ(map.dx, 1e-6);
  EXPECT_EQ(map.heights[0], 302.0);
  EXPECT_EQ(map.heights[19], 705.0);
  ASSERT_EQ(map.preparation.size(), 1u);
  EXPECT_EQ(map.preparation[0], "window: columns 2 to 5, rows 3 to 7 of the 10x8 map (i0 = 2, j0 = 3, nx = 4, ny = 5)");
}

TEST(WindowTest, BoundsErrorsNameTheValues) {
  HeightMap map = index_map(10, 8);
  EXPECT_NE(input_error_of([&] {
              select_window(map, parse_window("8,0,4,4"));
            }).find("window i0 = 8, j0 = 0, nx = 4, ny = 4 is invalid: it ends at column 11 but the 10x8 map"),
            std::string::npos);
  EXPECT_NE(input_error_of([&] { select_window(map, parse_window("0,5,4,4")); }).find("ends at row 8"),
            std::string::npos);
  EXPECT_NE(input_error_of([&] { select_window(map, parse_window("0,0,1,4")); }).find("at least 2 points"),
            std::string::npos);
  EXPECT_NE(input_error_of([&] { select_window(map, parse_window("0,4")); }).find("give I0,J0,NX,NY"),
            std::string::npos);
  HeightMap profile = index_map(50, 1);
  select_window(profile, parse_window("10,20"));
  EXPECT_EQ(profile.nx, 20u);
  EXPECT_EQ(profile.heights[0], 10.0);
}

TEST(WindowTest, WindowWithoutInvalidPointsDropsTheMask) {
  HeightMap map = index_map(6, 6);
  map.valid.assign(36, 1);
  map.valid[0] = 0;
  select_window(map, parse_window("1,1,4,4"));
  EXPECT_TRUE(map.valid.empty());
}

TEST(PaddingTest, CentresTheMapInAMarginAtItsLowestHeight) {
  HeightMap map = index_map(4, 3);
  pad_for_free_boundary(map, 2.0);
  EXPECT_EQ(map.nx, 8u);
  EXPECT_EQ(map.ny, 6u);
  EXPECT_EQ(map.dx, 1e-6);
  // The 4 x 3 map starts at (j, i) = (1, 2); the margin is at min = 0.
  EXPECT_EQ(map.heights[0], 0.0);
  EXPECT_EQ(map.heights[1 * 8 + 2], 0.0);
  EXPECT_EQ(map.heights[3 * 8 + 5], 203.0);
  EXPECT_EQ(map.heights[5 * 8 + 7], 0.0);
  EXPECT_NE(map.preparation[0].find("4x3 -> 8x6 points, the map at columns 2 to 5, rows 1 to 3"), std::string::npos)
      << map.preparation[0];
}

TEST(PaddingTest, PadsProfilesAlongXAndRejectsBadFactors) {
  HeightMap profile = index_map(10, 1);
  pad_for_free_boundary(profile, 1.5);
  EXPECT_EQ(profile.nx, 15u);
  EXPECT_EQ(profile.ny, 1u);
  EXPECT_EQ(profile.heights[2], 0.0);
  EXPECT_EQ(profile.heights[3], 1.0);
  HeightMap map = index_map(4, 4);
  for (double factor : {0.5, 17.0, std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_NE(input_error_of([&] { pad_for_free_boundary(map, factor); }).find("must be in [1, 16]"),
              std::string::npos);
  }
  map.valid.assign(16, 1);
  map.valid[3] = 0;
  EXPECT_NE(input_error_of([&] { pad_for_free_boundary(map, 2.0); }).find("fill or crop them first"),
            std::string::npos);
}

TEST(PreparationTest, AppliesWindowInvalidDetrendAndPadInOrder) {
  // A tilted plane with one invalid point inside the window and one outside.
  HeightMap map = index_map(12, 10);
  map.valid.assign(120, 1);
  for (std::size_t k : {std::size_t{0}, std::size_t{5 * 12 + 6}}) {
    map.valid[k] = 0;
    map.heights[static_cast<Eigen::Index>(k)] = std::numeric_limits<double>::quiet_NaN();
  }
  PreparationOptions options;
  options.window = parse_window("2,2,8,6");
  options.invalid = InvalidPoints::fill;
  options.detrend = Detrend::plane;
  options.pad_factor = 2.0;
  prepare_height_map(map, options);
  ASSERT_EQ(map.preparation.size(), 4u);
  EXPECT_EQ(map.preparation[0].rfind("window:", 0), 0u);
  EXPECT_EQ(map.preparation[1].rfind("detrend plane:", 0), 0u);
  EXPECT_EQ(map.preparation[2].rfind("invalid points: filled 1 of 48", 0), 0u);
  EXPECT_EQ(map.preparation[3].rfind("pad 2x", 0), 0u);
  EXPECT_EQ(map.nx, 16u);
  EXPECT_EQ(map.ny, 12u);
  // The plane is gone everywhere, the filled point included, and so is the margin's level.
  EXPECT_LE(map.heights.abs().maxCoeff(), 1e-12 * 1000.0);
}

TEST(PreparationTest, RefusesInvalidPointsByDefaultButNotOutsideTheWindow) {
  HeightMap map = index_map(8, 8);
  map.valid.assign(64, 1);
  map.valid[0] = 0;
  map.heights[0] = std::numeric_limits<double>::quiet_NaN();
  HeightMap whole = map;
  EXPECT_THROW(prepare_height_map(whole, {}), FileError);
  PreparationOptions window;
  window.window = parse_window("1,1,6,6");
  EXPECT_NO_THROW(prepare_height_map(map, window));
}

TEST(PreparationTest, CropThenDetrendFitsTheCroppedRegion) {
  HeightMap map = index_map(8, 6);
  map.valid.assign(48, 1);
  map.valid[7] = 0;  // (0, 7)
  map.heights[7] = std::numeric_limits<double>::quiet_NaN();
  PreparationOptions options;
  options.invalid = InvalidPoints::crop;
  options.detrend = Detrend::mean;
  prepare_height_map(map, options);
  EXPECT_EQ(map.nx * map.ny, 42u);  // 7 x 6 beats 8 x 5
  EXPECT_NEAR(map.heights.mean(), 0.0, 1e-12 * 500.0);
}

}  // namespace
}  // namespace halfspace::surface
