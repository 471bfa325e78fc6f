// The closed-form cell coefficients against an independent evaluation: the
// point-load (Boussinesq, Johnson 1985 eq. 3.21) and line-load (Flamant,
// Johnson eq. 2.15) stresses integrated numerically over the cell.
#include "halfspace/stress/rectangle_stress.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "support/gauss_legendre.hpp"

namespace halfspace::stress {
namespace {

// The composite Gauss rule resolves the smooth integrand (the points are at
// least 0.2 half-widths deep) to about 1e-12 of the largest component.
constexpr double kQuadratureTolerance = 1e-10;

using Rule = halfspace::testing::QuadratureRule;
using halfspace::testing::gauss_legendre;

// Boussinesq's unit point load at the origin, Johnson (1985) eq. 3.21, in
// cylindrical components rotated to x, y.
StressTensor point_load_stress(double x, double y, double z, double nu) {
  const double r2 = x * x + y * y;
  const double r = std::sqrt(r2);
  const double rho = std::sqrt(r2 + z * z);
  const double rho5 = rho * rho * rho * rho * rho;
  const double scale = 1.0 / (2.0 * std::numbers::pi);
  const double near = 1.0 / (rho * (rho + z));  // (1/r^2)(1 - z/rho), finite at r = 0
  const double sigma_r = scale * ((1.0 - 2.0 * nu) * near - 3.0 * z * r2 / rho5);
  const double sigma_theta = -scale * (1.0 - 2.0 * nu) * (near - z / (rho * rho * rho));
  const double tau_rz = -3.0 * scale * r * z * z / rho5;
  const double c = r > 0.0 ? x / r : 1.0;
  const double s = r > 0.0 ? y / r : 0.0;
  StressTensor t;
  t.xx = sigma_r * c * c + sigma_theta * s * s;
  t.yy = sigma_r * s * s + sigma_theta * c * c;
  t.xy = (sigma_r - sigma_theta) * s * c;
  t.zz = -3.0 * scale * z * z * z / rho5;
  t.xz = tau_rz * c;
  t.yz = tau_rz * s;
  return t;
}

// int over |x'| <= a, |y'| <= b of the point-load stress at (x - x', y - y', z).
StressTensor integrated_point_loads(double x, double y, double z, double a, double b, double nu) {
  const Rule rule = gauss_legendre(10);
  constexpr int kPanels = 24;
  StressTensor sum;
  for (int pi = 0; pi < kPanels; ++pi) {
    for (int pj = 0; pj < kPanels; ++pj) {
      const double cx = -a + (2.0 * pi + 1.0) * a / kPanels;
      const double cy = -b + (2.0 * pj + 1.0) * b / kPanels;
      const double hx = a / kPanels;
      const double hy = b / kPanels;
      for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
        for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
          const double w = rule.weights[i] * rule.weights[j] * hx * hy;
          const StressTensor t = point_load_stress(x - (cx + hx * rule.nodes[i]), y - (cy + hy * rule.nodes[j]), z, nu);
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

TEST(RectangleStressTest, MatchesIntegratedBoussinesqPointLoads) {
  const double a = 0.5e-6;
  const double b = 0.8e-6;
  struct Point {
    double x, y, z;
  };
  // Inside, on an edge, below a corner, outside and far away; shallow and deep.
  const Point points[] = {{0.1e-6, -0.2e-6, 0.1e-6}, {0.5e-6, 0.3e-6, 0.2e-6},  {-0.5e-6, 0.8e-6, 0.15e-6},
                          {1.3e-6, -0.4e-6, 0.5e-6}, {-3.0e-6, 2.0e-6, 1.0e-6}, {0.0, 0.0, 2.0e-6},
                          {0.2e-6, 1.1e-6, 0.3e-6}};
  for (const double nu : {0.3, 0.0, 0.5, -0.4}) {
    for (const Point& p : points) {
      SCOPED_TRACE(::testing::Message() << "nu = " << nu << " at (" << p.x << ", " << p.y << ", " << p.z << ")");
      expect_close(rectangle_stress(p.x, p.y, p.z, a, b, nu), integrated_point_loads(p.x, p.y, p.z, a, b, nu),
                   kQuadratureTolerance);
    }
  }
}

TEST(RectangleStressTest, LargeRectangleGivesTheUniformPressureField) {
  // Far inside a loaded area much wider than the depth: szz = -1 and, at the
  // surface limit of a square, sxx = syy = -(1 + 2 nu) / 2 (the isotropic
  // average of the Fourier mean-mode limits), no shear.
  constexpr double kTolerance = 1e-6;  // O(z / a) of the finite rectangle
  const double nu = 0.3;
  const StressTensor s = rectangle_stress(0.0, 0.0, 1e-9, 1.0, 1.0, nu);
  EXPECT_NEAR(s.zz, -1.0, kTolerance);
  EXPECT_NEAR(s.xx, -(1.0 + 2.0 * nu) / 2.0, kTolerance);
  EXPECT_NEAR(s.yy, -(1.0 + 2.0 * nu) / 2.0, kTolerance);
  EXPECT_NEAR(s.xy, 0.0, kTolerance);
  EXPECT_NEAR(s.xz, 0.0, kTolerance);
  EXPECT_NEAR(s.yz, 0.0, kTolerance);
}

TEST(RectangleStressTest, ParitiesOfTheComponents) {
  const double nu = 0.25;
  const StressTensor s = rectangle_stress(0.7, 0.4, 0.3, 0.5, 0.5, nu);
  const StressTensor m = rectangle_stress(-0.7, -0.4, 0.3, 0.5, 0.5, nu);
  constexpr double kRounding = 1e-14;
  EXPECT_NEAR(m.xx, s.xx, kRounding);
  EXPECT_NEAR(m.zz, s.zz, kRounding);
  EXPECT_NEAR(m.xy, s.xy, kRounding);  // odd in both: even under the joint flip
  EXPECT_NEAR(m.xz, -s.xz, kRounding);
  EXPECT_NEAR(m.yz, -s.yz, kRounding);
  EXPECT_LT(s.xz, 0.0);  // the shear points away from the load, as Flamant's
}

TEST(StripStressTest, MatchesIntegratedFlamantLineLoads) {
  const double a = 1.5e-6;
  const Rule rule = gauss_legendre(12);
  constexpr int kPanels = 64;
  for (const double nu : {0.3, 0.5}) {
    for (const double x : {0.0, 0.4e-6, 1.5e-6, -2.7e-6, 10e-6}) {
      for (const double z : {0.3e-6, 1.0e-6, 5.0e-6}) {
        StressTensor expected;
        for (int panel = 0; panel < kPanels; ++panel) {
          const double h = a / kPanels;
          const double centre = -a + (2.0 * panel + 1.0) * h;
          for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
            const double s = x - (centre + h * rule.nodes[i]);
            const double r2 = s * s + z * z;
            const double w = rule.weights[i] * h * 2.0 / (std::numbers::pi * r2 * r2);
            expected.xx -= w * s * s * z;
            expected.zz -= w * z * z * z;
            expected.xz -= w * s * z * z;
          }
        }
        expected.yy = nu * (expected.xx + expected.zz);
        SCOPED_TRACE(::testing::Message() << "nu = " << nu << " x = " << x << " z = " << z);
        expect_close(strip_stress(x, z, a, nu), expected, kQuadratureTolerance);
      }
    }
  }
}

}  // namespace
}  // namespace halfspace::stress
