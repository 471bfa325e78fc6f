// Tests of the built-in surfaces: values at known points, mirror symmetry about
// the grid centre, parameter validation and the initial gap.
#include "halfspace/geometry/builtin_surface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "halfspace/error.hpp"
#include "halfspace/solvers/surface_solve.hpp"

namespace halfspace::geometry {
namespace {

// Heights are a few floating-point operations on O(1) numbers.
constexpr double kExactTolerance = 1e-14;

double at(const Eigen::ArrayXd& h, const Grid& grid, std::size_t i, std::size_t j) {
  return h[static_cast<Eigen::Index>(j * grid.nx() + i)];
}

TEST(GeometryTest, SphereMatchesParaboloidAtKnownPoints) {
  // 5 x 5 cells: the centre is cell (2, 2), i.e. x = 2 dx, y = 2 dy.
  const Grid grid = Grid::plane(5, 5, 1.0, 2.0, Boundary::free);
  const Eigen::ArrayXd h = make_surface_heights(grid, {SurfaceShape::sphere, 10.0, 0.0, 0.0});
  ASSERT_EQ(h.size(), 25);
  EXPECT_NEAR(at(h, grid, 2, 2), 0.0, kExactTolerance);
  // Corner: x = -2, y = -4, so h = -(4 + 16) / 20.
  EXPECT_NEAR(at(h, grid, 0, 0), -1.0, kExactTolerance);
  // (3, 2): x = 1, y = 0, so h = -1 / 20.
  EXPECT_NEAR(at(h, grid, 3, 2), -0.05, kExactTolerance);
}

TEST(GeometryTest, SphereOnLineIsParabola) {
  const Grid grid = Grid::line(3, 0.5, Boundary::free);
  const Eigen::ArrayXd h = make_surface_heights(grid, {SurfaceShape::sphere, 2.0, 0.0, 0.0});
  ASSERT_EQ(h.size(), 3);
  EXPECT_NEAR(h[0], -0.0625, kExactTolerance);  // x = -0.5: -0.25 / 4
  EXPECT_NEAR(h[1], 0.0, kExactTolerance);
  EXPECT_NEAR(h[2], -0.0625, kExactTolerance);
}

TEST(GeometryTest, EvenGridIsMirrorSymmetricAboutCentre) {
  const Grid grid = Grid::plane(6, 4, 0.3, 0.7, Boundary::free);
  for (SurfaceShape shape : {SurfaceShape::sphere, SurfaceShape::cylinder, SurfaceShape::wavy}) {
    const Eigen::ArrayXd h = make_surface_heights(grid, {shape, 1.5, 2.5, 0.1});
    for (std::size_t j = 0; j < grid.ny(); ++j) {
      for (std::size_t i = 0; i < grid.nx(); ++i) {
        const double value = at(h, grid, i, j);
        EXPECT_NEAR(value, at(h, grid, grid.nx() - 1 - i, j), kExactTolerance)
            << to_string(shape) << " at (" << i << ", " << j << ")";
        EXPECT_NEAR(value, at(h, grid, i, grid.ny() - 1 - j), kExactTolerance)
            << to_string(shape) << " at (" << i << ", " << j << ")";
      }
    }
  }
}

TEST(GeometryTest, CylinderIsConstantAlongY) {
  const Grid grid = Grid::plane(5, 3, 1.0, 1.0, Boundary::free);
  const Eigen::ArrayXd h = make_surface_heights(grid, {SurfaceShape::cylinder, 4.0, 0.0, 0.0});
  for (std::size_t i = 0; i < grid.nx(); ++i) {
    const double x = static_cast<double>(i) - 2.0;
    for (std::size_t j = 0; j < grid.ny(); ++j) {
      EXPECT_NEAR(at(h, grid, i, j), -x * x / 8.0, kExactTolerance) << "at (" << i << ", " << j << ")";
    }
  }
}

TEST(GeometryTest, FlatIsZero) {
  const Grid grid = Grid::plane(4, 4, 1.0, 1.0, Boundary::periodic);
  const Eigen::ArrayXd h = make_surface_heights(grid, {SurfaceShape::flat, 0.0, 0.0, 0.0});
  EXPECT_EQ(h.size(), 16);
  EXPECT_EQ(h.abs().maxCoeff(), 0.0);
}

TEST(GeometryTest, WavyLineHasTroughHalfAWavelengthFromCentre) {
  // 9 points of 0.25: the centre is x = 0 at i = 4; x = +-1 = lambda / 2 at the ends.
  const Grid grid = Grid::line(9, 0.25, Boundary::periodic);
  const double amplitude = 0.3;
  const Eigen::ArrayXd h = make_surface_heights(grid, {SurfaceShape::wavy, 0.0, 2.0, amplitude});
  EXPECT_NEAR(h[4], 0.0, kExactTolerance);
  EXPECT_NEAR(h[0], -2.0 * amplitude, kExactTolerance);
  EXPECT_NEAR(h[8], -2.0 * amplitude, kExactTolerance);
  EXPECT_NEAR(h[2], -amplitude, kExactTolerance);  // quarter wavelength: cos = 0
}

TEST(GeometryTest, WavyPlaneIsProductOfCosines) {
  const Grid grid = Grid::plane(9, 9, 0.25, 0.25, Boundary::periodic);
  const double amplitude = 0.5;
  const Eigen::ArrayXd h = make_surface_heights(grid, {SurfaceShape::wavy, 0.0, 2.0, amplitude});
  EXPECT_NEAR(at(h, grid, 4, 4), 0.0, kExactTolerance);
  // (x, y) = (lambda/2, 0): cos = -1 and 1, so h = -2A.
  EXPECT_NEAR(at(h, grid, 8, 4), -2.0 * amplitude, kExactTolerance);
  // (x, y) = (lambda/2, lambda/2): the product is +1 again, another peak.
  EXPECT_NEAR(at(h, grid, 8, 8), 0.0, kExactTolerance);
  // (x, y) = (lambda/4, anything): cos(pi/2) = 0, so h = -A.
  EXPECT_NEAR(at(h, grid, 6, 1), -amplitude, kExactTolerance);
}

TEST(GeometryTest, MissingParametersAreNamedInErrors) {
  const Grid grid = Grid::line(8, 1.0, Boundary::free);
  const auto message_for = [&](const SurfaceSpec& spec) -> std::string {
    try {
      make_surface_heights(grid, spec);
    } catch (const InputError& error) {
      return error.what();
    }
    return "no error";
  };
  EXPECT_EQ(message_for({SurfaceShape::sphere, 0.0, 0.0, 0.0}), "sphere needs radius > 0 m (got 0)");
  EXPECT_EQ(message_for({SurfaceShape::cylinder, -2.0, 0.0, 0.0}), "cylinder needs radius > 0 m (got -2)");
  EXPECT_EQ(message_for({SurfaceShape::wavy, 0.0, 0.0, 1.0}), "wavy needs wavelength > 0 m (got 0)");
  EXPECT_EQ(message_for({SurfaceShape::wavy, 0.0, 1.0, 0.0}), "wavy needs amplitude > 0 m (got 0)");
  EXPECT_NE(message_for({SurfaceShape::sphere, std::nan(""), 0.0, 0.0}).find("radius"), std::string::npos);
  EXPECT_EQ(message_for({SurfaceShape::flat, 0.0, 0.0, 0.0}), "no error");
}

TEST(GeometryTest, ParsesShapeNamesAndRejectsOthers) {
  for (SurfaceShape shape : {SurfaceShape::sphere, SurfaceShape::cylinder, SurfaceShape::flat, SurfaceShape::wavy}) {
    EXPECT_EQ(parse_surface_shape(to_string(shape)), shape);
  }
  try {
    parse_surface_shape("cube");
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("'cube'"), std::string::npos) << error.what();
  }
}

TEST(GeometryTest, InitialGapIsZeroAtHighestPoint) {
  const Grid grid = Grid::plane(7, 5, 1e-6, 2e-6, Boundary::free);
  const Eigen::ArrayXd h = make_surface_heights(grid, {SurfaceShape::sphere, 1e-3, 0.0, 0.0});
  const Eigen::ArrayXd raised = h + 5e-9;
  const Eigen::ArrayXd gap = solvers::initial_gap(grid, {raised.data(), grid.size()});
  EXPECT_EQ(gap.minCoeff(), 0.0);
  EXPECT_EQ(at(gap, grid, 3, 2), 0.0);
  // max(h) - h: the gap grows away from the apex exactly as the height falls.
  for (Eigen::Index k = 0; k < gap.size(); ++k) {
    EXPECT_NEAR(gap[k], -h[k], 1e-20) << "at cell " << k;
  }
}

// The rows of a slab (an MPI process's) are the whole surface's rows, bit
// for bit, for every shape, and rows beyond the grid are refused.
TEST(GeometryTest, SurfaceRowsAreTheWholeSurfacesRows) {
  const Grid grid = Grid::plane(9, 7, 0.3, 0.2, Boundary::periodic);
  for (const SurfaceShape shape :
       {SurfaceShape::sphere, SurfaceShape::cylinder, SurfaceShape::flat, SurfaceShape::wavy}) {
    const SurfaceSpec spec{shape, 1.5, 0.7, 0.1};
    const Eigen::ArrayXd whole = make_surface_heights(grid, spec);
    for (const auto& [first, rows] : {std::pair<std::size_t, std::size_t>{0, 3}, {3, 3}, {6, 1}, {7, 0}, {0, 7}}) {
      const Eigen::ArrayXd part = make_surface_rows(grid, spec, first, rows);
      ASSERT_EQ(part.size(), static_cast<Eigen::Index>(rows * 9));
      EXPECT_TRUE((part == whole.segment(static_cast<Eigen::Index>(first * 9), part.size())).all())
          << to_string(shape) << " rows " << first << " + " << rows;
    }
  }
  EXPECT_THROW(make_surface_rows(grid, {SurfaceShape::flat, 0.0, 0.0, 0.0}, 5, 3), InputError);
}

}  // namespace
}  // namespace halfspace::geometry
