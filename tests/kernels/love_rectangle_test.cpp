// Love's rectangle coefficient against independent numerical integration of
// 1/(pi E* r) over the cell, the closed-form centre value, and its far field.
#include "halfspace/kernels/love_rectangle.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "support/gauss_legendre.hpp"

namespace halfspace {
namespace {

using kernels::love_rectangle_displacement;

constexpr double kEStar = 2.0e11;  // Pa
constexpr double kPi = std::numbers::pi;
// Closed-form values evaluated two ways: a few ulps of rounding.
constexpr double kRoundingTolerance = 1e-14;
// Against the quadrature references below (themselves good to a few eps):
// the closed form loses up to ~30 eps to cancellation within 2 half-diagonals.
constexpr double kQuadratureTolerance = 1e-14;
// Far-field multipole truncated after the quadrupole: error (a/R)^4 ~ 1e-16 at
// R = 1e4 a, so the test checks the far-field branch to near rounding.
constexpr double kMultipoleTolerance = 1e-14;

// The 16-point Gauss-Legendre rule on [-1, 1], computed once.
const testing::QuadratureRule& gauss() {
  static const testing::QuadratureRule rule = testing::gauss_legendre(16);
  return rule;
}

template <class F>
double gauss_panel(double lo, double hi, F&& f) {
  const double mid = 0.5 * (lo + hi);
  const double half = 0.5 * (hi - lo);
  double sum = 0.0;
  for (std::size_t k = 0; k < 16; ++k) sum += gauss().weights[k] * f(mid + half * gauss().nodes[k]);
  return half * sum;
}

// int_0^1 dv / sqrt(c^2 + v^2) on panels graded geometrically towards the
// near-singularity at v = +-i c (each panel's Gauss rule then converges fast).
double graded_inverse_hypot(double c) {
  auto f = [c](double v) { return 1.0 / std::hypot(c, v); };
  double total = 0.0;
  double lo = 0.0;
  double hi = std::min(c, 0.5);
  while (lo < 1.0) {
    total += gauss_panel(lo, hi, f);
    lo = hi;
    hi = std::min(1.0, 2.0 * hi);
  }
  return total;
}

// int_0^A int_0^B dx dy / r for A, B >= 0, the singularity at the corner (0,0)
// removed by Duffy's map of each half-triangle: x = A u, y = B u v gives
// A B int_0^1 dv / sqrt(A^2 + B^2 v^2), and likewise with A and B swapped.
double corner_integral(double a, double b) {
  if (a == 0.0 || b == 0.0) return 0.0;
  return a * graded_inverse_hypot(a / b) + b * graded_inverse_hypot(b / a);
}

// Reference by numerical integration for points in or near the cell: the cell
// seen from (x, y) split at the point into four corner rectangles (signed when
// the point is outside), each integrated by corner_integral. The signed sum
// cancels like the closed form, so it is used only within 1.25 half-widths.
double corner_reference(double x, double y, double a, double b) {
  auto oriented = [](double s, double t) {
    return std::copysign(1.0, s) * std::copysign(1.0, t) * corner_integral(std::abs(s), std::abs(t));
  };
  const double s1 = -a - x;
  const double s2 = a - x;
  const double t1 = -b - y;
  const double t2 = b - y;
  const double integral = oriented(s2, t2) - oriented(s1, t2) - oriented(s2, t1) + oriented(s1, t1);
  return integral / (kPi * kEStar);
}

// Plain tensor-product Gauss integration of 1/r over the cell on square-ish
// panels of side at most min(a, b) / `refinement`: accurate for points outside
// the cell by at least two panel sides, where 1/r is smooth on every panel.
double tensor_reference(double x, double y, double a, double b, int refinement) {
  const double side = std::min(a, b) / refinement;
  const int px = static_cast<int>(std::ceil(2.0 * a / side - 1e-9));
  const int py = static_cast<int>(std::ceil(2.0 * b / side - 1e-9));
  double total = 0.0;
  for (int i = 0; i < px; ++i) {
    const double x0 = -a + 2.0 * a * i / px;
    const double x1 = -a + 2.0 * a * (i + 1) / px;
    total += gauss_panel(x0, x1, [&](double xs) {
      double column = 0.0;
      for (int j = 0; j < py; ++j) {
        const double y0 = -b + 2.0 * b * j / py;
        const double y1 = -b + 2.0 * b * (j + 1) / py;
        column += gauss_panel(y0, y1, [&](double ys) { return 1.0 / std::hypot(x - xs, y - ys); });
      }
      return column;
    });
  }
  return total / (kPi * kEStar);
}

// Points at least a/4 or b/4 outside the cell: the tensor rule on panels of
// side min(a, b)/8, so the point is two panel sides or more from every panel;
// closer in (within 1.25 half-widths, where the corner sum cancels little):
// the corner rule.
double reference_displacement(double x, double y, double a, double b) {
  constexpr double kNear = 1.25;
  constexpr int kRefinement = 8;
  if (std::abs(x) >= kNear * a || std::abs(y) >= kNear * b) return tensor_reference(x, y, a, b, kRefinement);
  return corner_reference(x, y, a, b);
}

struct Point {
  double x;
  double y;
};

// Checks the kernel at `points` (in units of the half-widths) against `reference`
// and reports the largest relative error and where.
template <class Reference>
void expect_matches(double a, double b, const std::vector<Point>& points, double tolerance, Reference&& reference) {
  double worst = 0.0;
  Point worst_point{0.0, 0.0};
  for (const Point& p : points) {
    const double x = p.x * a;
    const double y = p.y * b;
    const double value = love_rectangle_displacement(x, y, a, b, kEStar);
    const double expected = reference(x, y);
    ASSERT_TRUE(std::isfinite(value)) << "at (" << p.x << " a, " << p.y << " b)";
    const double error = std::abs(value - expected) / std::abs(expected);
    if (error > worst) {
      worst = error;
      worst_point = p;
    }
  }
  std::printf("Love a=%g b=%g: largest relative error %.2e at (%g a, %g b)\n", a, b, worst, worst_point.x,
              worst_point.y);
  EXPECT_LE(worst, tolerance) << "at (" << worst_point.x << " a, " << worst_point.y << " b)";
}

// Inside, on edges and corners, just off them, and a few cells away.
const std::vector<Point> kNearPoints{{0.3, 0.0},   {0.3, 0.7},         {-0.9, 0.2},
                                     {1.0, 0.0},   {1.0, 1.0},         {-1.0, 0.5},
                                     {0.4, -1.0},  {1.0 + 1e-12, 0.3}, {1.0 - 1e-12, 1.0 + 1e-12},
                                     {1.5, 0.2},   {2.0, 2.0},         {3.0, -1.0},
                                     {-4.0, 0.0},  {0.0, 5.0},         {7.3, 2.1},
                                     {11.0, -9.0}, {1e-300, 1e-300}};

TEST(LoveRectangleTest, CentreOfSquareMatchesClosedForm) {
  const double a = 0.5e-6;
  const double expected = 8.0 * a * std::log(1.0 + std::sqrt(2.0)) / (kPi * kEStar);
  const double value = love_rectangle_displacement(0.0, 0.0, a, a, kEStar);
  EXPECT_NEAR(value, expected, kRoundingTolerance * expected);
}

TEST(LoveRectangleTest, CentreOfRectangleMatchesClosedForm) {
  // Centre of a 2a x 2b cell: (4/(pi E*)) [a asinh(b/a) + b asinh(a/b)].
  const double a = 0.5e-6;
  const double b = 1.3e-6;
  const double expected = 4.0 * (a * std::asinh(b / a) + b * std::asinh(a / b)) / (kPi * kEStar);
  const double value = love_rectangle_displacement(0.0, 0.0, a, b, kEStar);
  EXPECT_NEAR(value, expected, kRoundingTolerance * expected);
}

TEST(LoveRectangleTest, MatchesNumericalIntegrationSquare) {
  const double a = 0.5e-6;
  expect_matches(a, a, kNearPoints, kQuadratureTolerance,
                 [&](double x, double y) { return reference_displacement(x, y, a, a); });
}

TEST(LoveRectangleTest, MatchesNumericalIntegrationDxNotDy) {
  for (const double ratio : {0.3, 2.5, 10.0}) {
    const double a = 0.5e-6;
    const double b = ratio * a;
    expect_matches(a, b, kNearPoints, kQuadratureTolerance,
                   [&](double x, double y) { return reference_displacement(x, y, a, b); });
  }
}

TEST(LoveRectangleTest, QuadratureBranchesMatchNumericalIntegration) {
  // Points on both sides of the switches to Gauss quadrature (2, 6 and 64
  // half-diagonals), in several directions; all are outside the cell by more
  // than two panel widths of the refined tensor reference.
  constexpr int kRefinement = 4;
  for (const double ratio : {1.0, 0.4, 3.0}) {
    const double a = 0.5e-6;
    const double b = ratio * a;
    const double half_diagonal = std::hypot(a, b);
    std::vector<Point> points;
    for (const double distance : {1.9, 2.0, 2.1, 5.9, 6.0, 6.1, 20.0, 63.9, 64.0, 64.1, 500.0}) {
      for (const double angle : {0.0, 0.4, 0.785, 1.3, 1.5707963267948966}) {
        const double r = distance * half_diagonal;
        points.push_back({r * std::cos(angle) / a, r * std::sin(angle) / b});
      }
    }
    expect_matches(a, b, points, kQuadratureTolerance,
                   [&](double x, double y) { return tensor_reference(x, y, a, b, kRefinement); });
  }
}

TEST(LoveRectangleTest, FarFieldTendsToPointLoadWithQuadrupole) {
  // int 1/|X - s| dA = A/R + (1/2)[Ixx (3x^2 - R^2) + Iyy (3y^2 - R^2)]/R^5 + O((a/R)^4)
  // with Ixx = A a^2/3, Iyy = A b^2/3 (the dipole vanishes by symmetry).
  const double a = 0.5e-6;
  const double b = 0.8e-6;
  const double area = 4.0 * a * b;
  for (const double angle : {0.0, 0.7, 1.5707963267948966}) {
    const double r = 1e4 * a;
    const double x = r * std::cos(angle);
    const double y = r * std::sin(angle);
    const double quadrupole =
        0.5 * (area * a * a / 3.0 * (3.0 * x * x - r * r) + area * b * b / 3.0 * (3.0 * y * y - r * r)) /
        std::pow(r, 5);
    const double expected = (area / r + quadrupole) / (kPi * kEStar);
    const double value = love_rectangle_displacement(x, y, a, b, kEStar);
    EXPECT_NEAR(value, expected, kMultipoleTolerance * expected) << "angle " << angle;
  }
}

TEST(LoveRectangleTest, EvenInBothCoordinates) {
  const double a = 0.5e-6;
  const double b = 0.7e-6;
  for (const Point& p : kNearPoints) {
    const double value = love_rectangle_displacement(p.x * a, p.y * b, a, b, kEStar);
    EXPECT_EQ(value, love_rectangle_displacement(-p.x * a, p.y * b, a, b, kEStar));
    EXPECT_EQ(value, love_rectangle_displacement(p.x * a, -p.y * b, a, b, kEStar));
  }
}

TEST(LoveRectangleTest, ContinuousAcrossEdgesAndCorners) {
  // The displacement is continuous (its gradient has a log singularity at the
  // edges): values just either side of an edge or corner differ by O(delta ln delta).
  const double a = 0.5e-6;
  const double b = 0.5e-6;
  const double delta = 1e-9;
  const double scale = love_rectangle_displacement(0.0, 0.0, a, b, kEStar);
  for (const Point& p : std::vector<Point>{{1.0, 0.0}, {1.0, 1.0}, {0.3, 1.0}, {-1.0, -1.0}}) {
    const double on = love_rectangle_displacement(p.x * a, p.y * b, a, b, kEStar);
    ASSERT_TRUE(std::isfinite(on));
    for (const double sign : {-1.0, 1.0}) {
      const double off =
          love_rectangle_displacement(p.x * a * (1.0 + sign * delta), p.y * b * (1.0 + sign * delta), a, b, kEStar);
      EXPECT_NEAR(off, on, 100.0 * delta * scale) << "at (" << p.x << " a, " << p.y << " b)";
    }
  }
}

}  // namespace
}  // namespace halfspace
