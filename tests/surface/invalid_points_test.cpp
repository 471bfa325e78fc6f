// Tests of the invalid-point steps: refusal message, harmonic filling (exact
// for planes, border trimming, anisotropic weights) and cropping to the
// largest valid rectangle (with its tie rule).
#include "halfspace/surface/invalid_points.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "halfspace/error.hpp"

namespace halfspace::surface {
namespace {

// A plane is discrete-harmonic, so the fill reproduces it to rounding; the
// sparse solve's rounding grows with the hole size, far below this.
constexpr double kPlaneFillTolerance = 1e-12;

// An nx x ny map of h = 1 + 2 i + 3 j with the points listed by the mask
// string ('.' valid, 'x' invalid, rows top to bottom) marked invalid.
HeightMap masked_plane(const std::vector<std::string>& rows) {
  HeightMap map;
  map.ny = rows.size();
  map.nx = rows.front().size();
  map.dimension = map.ny == 1 ? 1 : 2;
  map.source = "masked";
  map.heights.resize(static_cast<Eigen::Index>(map.nx * map.ny));
  map.valid.assign(map.nx * map.ny, 1);
  for (std::size_t j = 0; j < map.ny; ++j) {
    for (std::size_t i = 0; i < map.nx; ++i) {
      const std::size_t k = j * map.nx + i;
      map.heights[static_cast<Eigen::Index>(k)] = 1.0 + 2.0 * static_cast<double>(i) + 3.0 * static_cast<double>(j);
      if (rows[j][i] == 'x') {
        map.valid[k] = 0;
        map.heights[static_cast<Eigen::Index>(k)] = std::numeric_limits<double>::quiet_NaN();
      }
    }
  }
  return map;
}

TEST(InvalidPointsTest, RefusalNamesTheCountAndTheFirstPoint) {
  const HeightMap map = masked_plane({"....", "..x.", "x..."});
  EXPECT_EQ(count_invalid(map), 2u);
  try {
    refuse_invalid_points(map);
    ADD_FAILURE() << "no error";
  } catch (const FileError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("masked: 2 of 12 heights are invalid"), std::string::npos) << message;
    EXPECT_NE(message.find("(j, i) = (1, 2)"), std::string::npos) << message;
    EXPECT_NE(message.find("not finite"), std::string::npos) << message;
  }
  EXPECT_NO_THROW(refuse_invalid_points(masked_plane({"...", "..."})));
}

TEST(InvalidPointsTest, FillReproducesAPlaneInInteriorHoles) {
  // Interior holes: a plane is discrete-harmonic. (Holes on the edge see the
  // zero-flux condition, which a tilted plane does not satisfy; the next test
  // checks them against the equation itself.)
  HeightMap map = masked_plane({".......", "..xx...", "..xxx..", ".......", "......."});
  fill_invalid_points(map);
  EXPECT_TRUE(map.valid.empty());
  for (Eigen::Index k = 0; k < map.heights.size(); ++k) {
    const double expected = 1.0 + 2.0 * static_cast<double>(k % 7) + 3.0 * static_cast<double>(k / 7);
    EXPECT_NEAR(map.heights[k], expected, kPlaneFillTolerance * 40.0) << "at k = " << k;
  }
  ASSERT_EQ(map.preparation.size(), 1u);
  EXPECT_NE(map.preparation[0].find("filled 5 of 35 points"), std::string::npos) << map.preparation[0];
}

TEST(InvalidPointsTest, FilledEdgePointsSatisfyTheZeroFluxLaplaceEquation) {
  HeightMap map = masked_plane({"x....", ".....", "....x"});
  map.dx = 1.0;
  map.dy = 2.0;  // weights 1 and 1/4
  fill_invalid_points(map);
  // At (0, 0): neighbours (0, 1) [x] and (1, 0) [y]: (h01 - h00) + (h10 - h00) / 4 = 0.
  const double h00 = map.heights[0];
  EXPECT_NEAR((map.heights[1] - h00) + (map.heights[5] - h00) / 4.0, 0.0, 1e-12);
}

TEST(InvalidPointsTest, FillCutsFullyInvalidBorderRowsAndColumns) {
  HeightMap map = masked_plane({"xxxxxx", "xx...x", "xx.x.x", "xx...x", "xxxxxx"});
  fill_invalid_points(map);
  EXPECT_EQ(map.nx, 3u);
  EXPECT_EQ(map.ny, 3u);
  EXPECT_NEAR(map.heights[4], 1.0 + 2.0 * 3 + 3.0 * 2, kPlaneFillTolerance * 20.0);  // (j, i) = (2, 3) of the original
  EXPECT_NE(map.preparation[0].find(
                "after cutting the fully invalid border, keeping columns 2 to 4 and rows 1 to 3 of the 6x5 map"),
            std::string::npos)
      << map.preparation[0];
}

TEST(InvalidPointsTest, FillOfAProfileInterpolatesLinearly) {
  HeightMap map = masked_plane({".xx.x"});
  map.dimension = 1;
  fill_invalid_points(map);
  EXPECT_EQ(map.nx, 4u);  // the invalid last point is an end: cut
  EXPECT_NEAR(map.heights[1], 3.0, 1e-13);
  EXPECT_NEAR(map.heights[2], 5.0, 1e-13);
}

TEST(InvalidPointsTest, FillWithoutValidPointsIsAnError) {
  HeightMap map = masked_plane({"xx", "xx"});
  EXPECT_THROW(fill_invalid_points(map), InputError);
}

TEST(InvalidPointsTest, CropKeepsTheLargestValidRectangle) {
  HeightMap map = masked_plane({
      "x.......",
      "...x....",
      "........",
      "........",
      "x......x",
  });
  crop_to_valid_points(map);
  // Candidates: rows 2-3 full width (16), columns 4-7 rows 0-3 (16), rows 2-4
  // columns 1-6 (18), rows 1-4 cols 4-6 (12)... the largest is 3 x 6 = 18.
  EXPECT_EQ(map.nx, 6u);
  EXPECT_EQ(map.ny, 3u);
  EXPECT_EQ(map.heights[0], 1.0 + 2.0 * 1 + 3.0 * 2);
  EXPECT_TRUE(map.valid.empty());
  EXPECT_NE(map.preparation[0].find("columns 1 to 6 and rows 2 to 4 of the 8x5 map"), std::string::npos)
      << map.preparation[0];
}

TEST(InvalidPointsTest, CropBreaksTiesByTopRowThenLeftColumn) {
  HeightMap map = masked_plane({"..x..", "..x..", "xxxxx", "..x.."});
  crop_to_valid_points(map);
  EXPECT_EQ(map.nx, 2u);
  EXPECT_EQ(map.ny, 2u);
  EXPECT_EQ(map.heights[0], 1.0);  // (0, 0): top-left of the four 2 x 2 candidates
}

TEST(InvalidPointsTest, CropRefusesARectangleTooSmall) {
  HeightMap map = masked_plane({".x.", "x.x", ".x."});
  try {
    crop_to_valid_points(map);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("largest rectangle of valid points is"), std::string::npos)
        << error.what();
  }
}

TEST(InvalidPointsTest, ParsesPolicies) {
  EXPECT_EQ(parse_invalid_points("refuse"), InvalidPoints::refuse);
  EXPECT_EQ(parse_invalid_points("fill"), InvalidPoints::fill);
  EXPECT_EQ(parse_invalid_points("crop"), InvalidPoints::crop);
  EXPECT_THROW(parse_invalid_points("interpolate"), InputError);
}

}  // namespace
}  // namespace halfspace::surface
