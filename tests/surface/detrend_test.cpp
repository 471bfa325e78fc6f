// Tests of surface::detrend: exact removal of the mean, planes and quadrics
// (with a large offset, anisotropic spacing and invalid points), the record,
// and fits the valid points cannot determine.
#include "halfspace/surface/detrend.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "halfspace/error.hpp"
#include "support/height_map_fixtures.hpp"

namespace halfspace::surface {
namespace {

// Exact algebra: the residual of removing a polynomial that the fit can
// represent is rounding only; the brief asks for 1e-12 of the heights.
constexpr double kExactRelativeTolerance = 1e-12;

using testing::sampled_map;

// Largest |residual| over valid points, relative to the largest |height| before.
double worst_relative_residual(const HeightMap& after, double scale) {
  double worst = 0.0;
  for (std::size_t k = 0; k < after.size(); ++k) {
    if (after.is_valid(k)) worst = std::max(worst, std::abs(after.heights[static_cast<Eigen::Index>(k)]));
  }
  return worst / scale;
}

TEST(DetrendTest, RemovesPlaneWithLargeOffsetExactly) {
  // A tilted plane with an offset 10^4 times its relief, anisotropic cells.
  HeightMap map = sampled_map(97, 61, 2.0e-6, 3.5e-6, [](double x, double y) { return 1e-2 + 3e-3 * x - 7e-4 * y; });
  const double scale = map.heights.abs().maxCoeff();
  detrend(map, Detrend::plane);
  EXPECT_LE(worst_relative_residual(map, scale), kExactRelativeTolerance);
  ASSERT_EQ(map.preparation.size(), 1u);
  EXPECT_NE(map.preparation[0].find("dh/dx = 0.003"), std::string::npos) << map.preparation[0];
  EXPECT_NE(map.preparation[0].find("dh/dy = -0.0007"), std::string::npos) << map.preparation[0];
}

TEST(DetrendTest, RemovesQuadricExactly) {
  HeightMap map = sampled_map(80, 50, 1e-6, 2e-6, [](double x, double y) {
    return -5e-5 + 2e-2 * x + 1e-2 * y - (x * x + 0.5 * x * y + 3 * y * y) / (2 * 0.01);
  });
  const double scale = map.heights.abs().maxCoeff();
  detrend(map, Detrend::curvature);
  EXPECT_LE(worst_relative_residual(map, scale), kExactRelativeTolerance);
}

TEST(DetrendTest, RemovesProfileParabolaAndLine) {
  HeightMap parabola =
      sampled_map(300, 1, 1e-7, 0.0, [](double x, double) { return 4e-6 - x * x / (2 * 1e-3) + 0.1 * x; });
  const double scale = parabola.heights.abs().maxCoeff();
  detrend(parabola, Detrend::curvature);
  EXPECT_LE(worst_relative_residual(parabola, scale), kExactRelativeTolerance);
  HeightMap line = sampled_map(300, 1, 1e-7, 0.0, [](double x, double) { return 4e-6 + 0.1 * x; });
  detrend(line, Detrend::plane);
  EXPECT_LE(worst_relative_residual(line, 4e-6), kExactRelativeTolerance);
}

TEST(DetrendTest, FitsOnlyValidPointsAndKeepsInvalidOnesNaN) {
  HeightMap map = sampled_map(20, 10, 1e-6, 1e-6, [](double x, double y) { return 1e-6 + 0.01 * x + 0.02 * y; });
  map.valid.assign(map.size(), 1);
  for (std::size_t k : {3u, 47u, 150u}) {
    map.valid[k] = 0;
    map.heights[static_cast<Eigen::Index>(k)] = std::numeric_limits<double>::quiet_NaN();
  }
  detrend(map, Detrend::plane);
  EXPECT_LE(worst_relative_residual(map, 1e-6), kExactRelativeTolerance);
  EXPECT_TRUE(std::isnan(map.heights[47]));
  EXPECT_NE(map.preparation[0].find("over 197 valid points"), std::string::npos) << map.preparation[0];
}

TEST(DetrendTest, MeanRemovalLeavesZeroMeanAndPlaneRemovalLeavesRoughness) {
  // A plane plus a zero-mean, plane-orthogonal pattern: only the plane goes.
  HeightMap map = sampled_map(64, 64, 1.0, 1.0, [](double x, double y) {
    return 5.0 + 0.25 * x - 0.5 * y + std::cos(2 * M_PI * x / 8) * std::cos(2 * M_PI * y / 8);
  });
  HeightMap mean_only = map;
  detrend(mean_only, Detrend::mean);
  EXPECT_NEAR(mean_only.heights.mean(), 0.0, 1e-12 * 40.0);
  detrend(map, Detrend::plane);
  for (std::size_t j = 0; j < 64; j += 7) {
    for (std::size_t i = 0; i < 64; i += 5) {
      const double pattern =
          std::cos(2 * M_PI * static_cast<double>(i) / 8) * std::cos(2 * M_PI * static_cast<double>(j) / 8);
      EXPECT_NEAR(map.heights[static_cast<Eigen::Index>(j * 64 + i)], pattern, 1e-12 * 40.0);
    }
  }
}

TEST(DetrendTest, NoneChangesNothing) {
  HeightMap map = sampled_map(4, 3, 1.0, 1.0, [](double x, double y) { return x + y; });
  const Eigen::ArrayXd before = map.heights;
  detrend(map, Detrend::none);
  EXPECT_TRUE((map.heights == before).all());
  EXPECT_TRUE(map.preparation.empty());
}

TEST(DetrendTest, RejectsFitsTheValidPointsCannotDetermine) {
  HeightMap map = sampled_map(5, 4, 1.0, 1.0, [](double x, double) { return x; });
  map.valid.assign(map.size(), 0);
  for (std::size_t i = 0; i < 5; ++i) map.valid[2 * 5 + i] = 1;  // one row: no y slope
  try {
    detrend(map, Detrend::plane);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("5 valid points do not determine 3 coefficients"), std::string::npos)
        << error.what();
  }
}

TEST(DetrendTest, ParsesNamesAndAliases) {
  EXPECT_EQ(parse_detrend("none"), Detrend::none);
  EXPECT_EQ(parse_detrend("mean"), Detrend::mean);
  EXPECT_EQ(parse_detrend("tilt"), Detrend::plane);
  EXPECT_EQ(parse_detrend("quadratic"), Detrend::curvature);
  try {
    parse_detrend("cubic");
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("'cubic' is unknown"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace halfspace::surface
