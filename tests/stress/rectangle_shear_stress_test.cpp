// The closed-form shear coefficients of a cell against an independent
// evaluation: Cerruti's point-force stresses (Johnson 1985, eq. 3.87) and the
// tangential and antiplane line forces integrated numerically over the cell.
#include "halfspace/stress/rectangle_shear_stress.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>

#include "support/cerruti_point_force.hpp"
#include "support/gauss_legendre.hpp"

namespace halfspace::stress {
namespace {

using halfspace::testing::cerruti_point_force_stress;
using halfspace::testing::gauss_legendre;
using halfspace::testing::QuadratureRule;

// The composite Gauss rule resolves the smooth integrand (the points are at
// least 0.2 half-widths deep) to about 1e-12 of the largest component.
constexpr double kQuadratureTolerance = 1e-10;

// Cerruti's force along `direction` (x, or y by exchanging the axes).
StressTensor point_force_stress(Traction direction, double x, double y, double z, double nu) {
  if (direction == Traction::shear_x) return cerruti_point_force_stress(x, y, z, nu);
  StressTensor s = cerruti_point_force_stress(y, x, z, nu);
  std::swap(s.xx, s.yy);
  std::swap(s.xz, s.yz);
  return s;
}

StressTensor integrated_point_forces(Traction direction, double x, double y, double z, double a, double b, double nu) {
  const QuadratureRule rule = gauss_legendre(10);
  constexpr int kPanels = 24;
  StressTensor sum;
  const double hx = a / kPanels;
  const double hy = b / kPanels;
  for (int pi = 0; pi < kPanels; ++pi) {
    for (int pj = 0; pj < kPanels; ++pj) {
      const double cx = -a + (2.0 * pi + 1.0) * hx;
      const double cy = -b + (2.0 * pj + 1.0) * hy;
      for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
        for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
          const double w = rule.weights[i] * rule.weights[j] * hx * hy;
          const StressTensor t =
              point_force_stress(direction, x - (cx + hx * rule.nodes[i]), y - (cy + hy * rule.nodes[j]), z, nu);
          sum.xx += w * t.xx;
          sum.yy += w * t.yy;
          sum.zz += w * t.zz;
          sum.xy += w * t.xy;
          sum.xz += w * t.xz;
          sum.yz += w * t.yz;
        }
      }
    }
  }
  return sum;
}

void expect_close(const StressTensor& actual, const StressTensor& expected, double tolerance) {
  EXPECT_NEAR(actual.xx, expected.xx, tolerance) << "sigma_xx";
  EXPECT_NEAR(actual.yy, expected.yy, tolerance) << "sigma_yy";
  EXPECT_NEAR(actual.zz, expected.zz, tolerance) << "sigma_zz";
  EXPECT_NEAR(actual.xy, expected.xy, tolerance) << "sigma_xy";
  EXPECT_NEAR(actual.xz, expected.xz, tolerance) << "sigma_xz";
  EXPECT_NEAR(actual.yz, expected.yz, tolerance) << "sigma_yz";
}

TEST(RectangleShearStressTest, MatchesIntegratedCerrutiPointForces) {
  const double a = 0.5e-6;
  const double b = 0.8e-6;
  struct Point {
    double x, y, z;
  };
  // Inside, on an edge, below a corner, outside and far away; shallow and deep.
  const Point points[] = {{0.1e-6, -0.2e-6, 0.1e-6}, {0.5e-6, 0.3e-6, 0.2e-6},  {-0.5e-6, 0.8e-6, 0.15e-6},
                          {1.3e-6, -0.4e-6, 0.5e-6}, {-3.0e-6, 2.0e-6, 1.0e-6}, {0.0, 0.0, 2.0e-6},
                          {0.2e-6, 1.1e-6, 0.3e-6},  {-0.7e-6, -1.2e-6, 0.2e-6}};
  for (const Traction direction : {Traction::shear_x, Traction::shear_y}) {
    for (const double nu : {0.3, 0.0, 0.5, -0.4}) {
      for (const Point& p : points) {
        SCOPED_TRACE(::testing::Message() << (direction == Traction::shear_x ? "shear x" : "shear y") << ", nu = " << nu
                                          << " at (" << p.x << ", " << p.y << ", " << p.z << ")");
        expect_close(rectangle_shear_stress(direction, p.x, p.y, p.z, a, b, nu),
                     integrated_point_forces(direction, p.x, p.y, p.z, a, b, nu), kQuadratureTolerance);
      }
    }
  }
}

TEST(RectangleShearStressTest, LargeRectangleGivesUniformShear) {
  // Below the centre of a sheared area much wider than the depth:
  // sigma_xz = -q and nothing else (the in-plane stresses are odd in x and
  // vanish there).
  constexpr double kTolerance = 1e-6;  // O(z / a) of the finite rectangle
  const StressTensor s = rectangle_shear_stress(Traction::shear_x, 0.0, 0.0, 1e-9, 1.0, 1.0, 0.3);
  EXPECT_NEAR(s.xz, -1.0, kTolerance);
  EXPECT_NEAR(s.yz, 0.0, kTolerance);
  EXPECT_NEAR(s.zz, 0.0, kTolerance);
  EXPECT_NEAR(s.xx, 0.0, kTolerance);
  EXPECT_NEAR(s.yy, 0.0, kTolerance);
  EXPECT_NEAR(s.xy, 0.0, kTolerance);
  const StressTensor t = rectangle_shear_stress(Traction::shear_y, 0.0, 0.0, 1e-9, 1.0, 1.0, 0.3);
  EXPECT_NEAR(t.yz, -1.0, kTolerance);
  EXPECT_NEAR(t.xz, 0.0, kTolerance);
}

TEST(RectangleShearStressTest, ParitiesOfTheComponents) {
  // A shear along x: xx, yy, zz and yz odd in x, xy and xz even in x; xy and
  // yz odd in y.
  constexpr double kRounding = 1e-14;
  const double nu = 0.25;
  const StressTensor s = rectangle_shear_stress(Traction::shear_x, 0.7, 0.4, 0.3, 0.5, 0.5, nu);
  const StressTensor mx = rectangle_shear_stress(Traction::shear_x, -0.7, 0.4, 0.3, 0.5, 0.5, nu);
  const StressTensor my = rectangle_shear_stress(Traction::shear_x, 0.7, -0.4, 0.3, 0.5, 0.5, nu);
  EXPECT_NEAR(mx.xx, -s.xx, kRounding);
  EXPECT_NEAR(mx.yy, -s.yy, kRounding);
  EXPECT_NEAR(mx.zz, -s.zz, kRounding);
  EXPECT_NEAR(mx.xy, s.xy, kRounding);
  EXPECT_NEAR(mx.xz, s.xz, kRounding);
  EXPECT_NEAR(mx.yz, -s.yz, kRounding);
  EXPECT_NEAR(my.xx, s.xx, kRounding);
  EXPECT_NEAR(my.xy, -s.xy, kRounding);
  EXPECT_NEAR(my.yz, -s.yz, kRounding);
  EXPECT_NEAR(my.xz, s.xz, kRounding);
  // Ahead of a forward shear the material is compressed, behind it stretched.
  EXPECT_LT(s.xx, 0.0);
  EXPECT_GT(mx.xx, 0.0);
}

TEST(StripShearStressTest, MatchesIntegratedLineForces) {
  const double a = 1.5e-6;
  const QuadratureRule rule = gauss_legendre(12);
  constexpr int kPanels = 64;
  for (const double nu : {0.3, 0.5}) {
    for (const double x : {0.0, 0.4e-6, 1.5e-6, -2.7e-6, 10e-6}) {
      for (const double z : {0.3e-6, 1.0e-6, 5.0e-6}) {
        StressTensor along_x;
        StressTensor along_y;
        for (int panel = 0; panel < kPanels; ++panel) {
          const double h = a / kPanels;
          const double centre = -a + (2.0 * panel + 1.0) * h;
          for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
            const double s = x - (centre + h * rule.nodes[i]);
            const double r2 = s * s + z * z;
            // The tangential line force (Johnson 1985, eq. 2.19) and the
            // antiplane one (u_y = -(F / (pi G)) ln r).
            const double w = rule.weights[i] * h * 2.0 / (std::numbers::pi * r2 * r2);
            along_x.xx -= w * s * s * s;
            along_x.zz -= w * s * z * z;
            along_x.xz -= w * s * s * z;
            const double v = rule.weights[i] * h / (std::numbers::pi * r2);
            along_y.yz -= v * z;
            along_y.xy -= v * s;
          }
        }
        along_x.yy = nu * (along_x.xx + along_x.zz);
        SCOPED_TRACE(::testing::Message() << "nu = " << nu << " x = " << x << " z = " << z);
        expect_close(strip_shear_stress(Traction::shear_x, x, z, a, nu), along_x, kQuadratureTolerance);
        expect_close(strip_shear_stress(Traction::shear_y, x, z, a, nu), along_y, kQuadratureTolerance);
      }
    }
  }
}

}  // namespace
}  // namespace halfspace::stress
