// Tests of resampling height maps: planes kept exactly, a wave's samples on
// a refined grid against the wave, a coarsened map's cell means against the
// exact integrals, lengths kept, the record, and the refusals.
#include "halfspace/surface/resample.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include "halfspace/error.hpp"
#include "halfspace/surface/preparation.hpp"
#include "support/height_map_fixtures.hpp"

namespace halfspace::surface {
namespace {

using testing::input_error_of;

// Heights f(x, y) at the cell centres of an nx x ny map of spacing dx, dy.
HeightMap sampled_map(std::size_t nx, std::size_t ny, double dx, double dy,
                      const std::function<double(double, double)>& f) {
  return testing::sampled_map(nx, ny, dx, dy, f, 0.5);
}

double plane(double x, double y) {
  return 1e-6 + 0.3 * x - 0.7 * y;
}

TEST(ResampleTest, ParsesMapsAndProfiles) {
  const Resample map = parse_resample("1024x768");
  EXPECT_EQ(map.nx, 1024u);
  EXPECT_EQ(map.ny, 768u);
  EXPECT_EQ(map.dimension, 2);
  const Resample profile = parse_resample("300");
  EXPECT_EQ(profile.nx, 300u);
  EXPECT_EQ(profile.dimension, 1);
  for (const char* bad : {"", "x", "12x", "x12", "1.5x4", "-3x4", "4x4x4", "12 x 4", "1e3"}) {
    EXPECT_NE(input_error_of([&] { parse_resample(bad); }).find("expected NXxNY"), std::string::npos) << bad;
  }
}

// Refined, coarsened, and refined along one axis while coarsened along the
// other (x 40 -> 97, y 30 -> 11): the plane at the new centres to rounding,
// up to the edges (the outer half cells extend the interpolant linearly).
TEST(ResampleTest, KeepsAPlaneExactly) {
  const double dx = 2e-6, dy = 3e-6;
  for (const auto& [nx, ny] : {std::pair<std::size_t, std::size_t>{97, 71}, {13, 11}, {97, 11}, {40, 30}}) {
    HeightMap map = sampled_map(40, 30, dx, dy, plane);
    resample(map, Resample{nx, ny, 2});
    ASSERT_EQ(map.nx, nx);
    ASSERT_EQ(map.ny, ny);
    EXPECT_DOUBLE_EQ(map.dx * static_cast<double>(nx), 40 * dx);
    EXPECT_DOUBLE_EQ(map.dy * static_cast<double>(ny), 30 * dy);
    const HeightMap expected = sampled_map(nx, ny, map.dx, map.dy, plane);
    EXPECT_LT((map.heights - expected.heights).abs().maxCoeff(), 1e-15) << nx << "x" << ny;
  }
}

// A wave of 16 old cells per wavelength refined 4x: linear interpolation's
// error is at most (dx^2 / 8) |f''| = (pi / 16)^2 / 2 = 1.9 % of the
// amplitude; inside the map it must stay below that, and it must not be
// the old map's nearest values (whose error is up to sin(pi / 16) = 19.5 %).
TEST(ResampleTest, RefinesAWaveWithinLinearInterpolationsError) {
  const double dx = 1e-6, wavelength = 16 * dx;
  const auto wave = [&](double x, double /*y*/) { return std::sin(2.0 * std::numbers::pi * x / wavelength); };
  HeightMap map = sampled_map(64, 1, dx, 0.0, wave);
  resample(map, Resample{256, 1, 1});
  ASSERT_EQ(map.nx, 256u);
  const double bound = 0.5 * std::pow(std::numbers::pi / 16.0, 2);
  double worst = 0.0;
  for (std::size_t k = 2; k + 2 < map.nx; ++k) {
    const double x = (static_cast<double>(k) + 0.5) * map.dx;
    worst = std::max(worst, std::abs(map.heights[static_cast<Eigen::Index>(k)] - wave(x, 0.0)));
  }
  EXPECT_LT(worst, bound);
  EXPECT_GT(worst, 0.1 * bound);  // an interpolation, not the wave itself
}

// Coarsening 12 -> 5 cells (2.4 old cells per new one, cells cut across):
// each new cell is the mean over it of the interpolant through the old
// centres, checked against a midpoint sum on 12000 sub-intervals of that
// interpolant evaluated independently.
TEST(ResampleTest, CoarsensToTheInterpolantsCellMeans) {
  const double dx = 1.0;
  const auto f = [](double x, double /*y*/) { return std::cos(x) + 0.1 * x * x; };
  HeightMap map = sampled_map(12, 1, dx, 0.0, f);
  const Eigen::ArrayXd old = map.heights;
  resample(map, Resample{5, 1, 1});
  ASSERT_EQ(map.nx, 5u);
  EXPECT_DOUBLE_EQ(map.dx, 2.4);
  const auto interpolant = [&](double x) {
    const double t = std::clamp(x - 0.5, 0.0, 10.999999);
    const auto i = static_cast<Eigen::Index>(std::floor(t));
    const double u = x - 0.5 - static_cast<double>(i);
    return (1.0 - u) * old[i] + u * old[i + 1];
  };
  for (int k = 0; k < 5; ++k) {
    const double a = 2.4 * k, b = 2.4 * (k + 1);
    const int parts = 12000;
    double sum = 0.0;
    for (int m = 0; m < parts; ++m) sum += interpolant(a + (m + 0.5) * (b - a) / parts);
    EXPECT_NEAR(map.heights[k], sum / parts, 1e-8) << k;
  }
}

TEST(ResampleTest, LeavesEqualCountsAloneAndRecordsTheStep) {
  HeightMap map = sampled_map(8, 6, 1e-6, 1e-6, [](double x, double y) { return std::sin(1e6 * x) * y; });
  const Eigen::ArrayXd before = map.heights;
  resample(map, Resample{8, 6, 2});
  EXPECT_TRUE((map.heights == before).all());
  EXPECT_TRUE(map.preparation.empty());
  resample(map, Resample{16, 12, 2});
  ASSERT_EQ(map.preparation.size(), 1u);
  EXPECT_NE(map.preparation[0].find("8x6 map to 16x12"), std::string::npos) << map.preparation[0];
}

// In prepare_height_map it follows the fill (it needs every point) and
// precedes the padding.
TEST(ResampleTest, RunsAfterTheFillAndBeforeThePadding) {
  HeightMap map = sampled_map(10, 10, 1e-6, 1e-6, plane);
  map.valid.assign(100, 1);
  map.valid[55] = 0;
  map.heights[55] = std::numeric_limits<double>::quiet_NaN();
  PreparationOptions options;
  options.invalid = InvalidPoints::fill;
  options.resample = Resample{20, 20, 2};
  options.pad_factor = 2.0;
  prepare_height_map(map, options);
  EXPECT_EQ(map.nx, 40u);
  EXPECT_EQ(map.ny, 40u);
  EXPECT_TRUE(map.heights.allFinite());
  ASSERT_GE(map.preparation.size(), 3u);
  EXPECT_NE(map.preparation[map.preparation.size() - 2].find("resample"), std::string::npos);
}

TEST(ResampleTest, RefusesWhatItCannotDo) {
  const auto refusal = [](HeightMap map, Resample to) { return input_error_of([&] { resample(map, to); }); };
  const HeightMap map = sampled_map(10, 8, 1e-6, 1e-6, plane);
  EXPECT_NE(refusal(map, Resample{1, 8, 2}).find("at least 2 cells along x"), std::string::npos);
  EXPECT_NE(refusal(map, Resample{10, 129, 2}).find("more than 16 times (at most 128 cells)"), std::string::npos);
  HeightMap largest = map;
  EXPECT_NO_THROW(resample(largest, Resample{160, 128, 2}));
  EXPECT_NE(refusal(map, Resample{20, 1, 1}).find("give NXxNY"), std::string::npos);
  HeightMap holes = map;
  holes.valid.assign(80, 1);
  holes.valid[3] = 0;
  EXPECT_NE(refusal(holes, Resample{20, 16, 2}).find("invalid points; fill or crop them first"), std::string::npos);
  HeightMap no_spacing = map;
  no_spacing.dx = 0.0;
  EXPECT_NE(refusal(no_spacing, Resample{20, 16, 2}).find("no spacing"), std::string::npos);
  EXPECT_NE(refusal(map, Resample{std::size_t{1} << 40, 1u << 20, 2}).find("resample"), std::string::npos);
}

}  // namespace
}  // namespace halfspace::surface
