// The plane-strain strip coefficient against its diagonal value, numerical
// integration of the line-load kernel over the strip, and the far field.
#include "halfspace/kernels/plane_strain_strip.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace halfspace {
namespace {

using kernels::plane_strain_strip_displacement;

constexpr double kEStar = 2.0e11;  // Pa
constexpr double kPi = std::numbers::pi;
constexpr double kWidth = 1e-5;  // m; datum 1 m, so ln|d| < 0 on the grid
// Closed forms evaluated two ways: a few ulps of rounding.
constexpr double kRoundingTolerance = 1e-14;
// Against graded Gauss quadrature of ln|t| (reference good to a few eps).
constexpr double kQuadratureTolerance = 1e-14;

// Line-load displacement -(2/(pi E*)) ln|t| per unit force per length.
double line_load(double t) {
  return -2.0 / (kPi * kEStar) * std::log(std::abs(t));
}

// int_lo^hi ln t dt for 0 <= lo < hi by 16-point Gauss-Legendre on panels
// graded geometrically towards lo, [lo + w 2^-(k+1), lo + w 2^-k] with
// w = hi - lo: each panel is at least its own width from the singularity at
// t = 0 (Bernstein ellipse parameter >= 5.8, so the rule's error is below
// 5.8^-32). The grading stops once the remaining piece [lo, lo + w 2^-k] is
// no wider than lo/4 (one panel then suffices), or for lo = 0 after 100
// halvings: the dropped [0, w 2^-100] contributes ~ w 2^-100 * 70, far below
// rounding.
double graded_log_integral(double lo, double hi) {
  constexpr std::array<double, 8> nodes{0.989400934991649932596, 0.944575023073232576078, 0.86563120238783174388,
                                        0.755404408355003033895, 0.617876244402643748447, 0.458016777657227386342,
                                        0.28160355077925891323,  0.0950125098376374401853};
  constexpr std::array<double, 8> weights{0.0271524594117540948518, 0.0622535239386478928628, 0.0951585116824927848099,
                                          0.124628971255533872052,  0.149595988816576732082,  0.169156519395002538189,
                                          0.182603415044923588867,  0.189450610455068496285};
  auto panel = [&](double a, double b) {
    const double mid = 0.5 * (a + b);
    const double half = 0.5 * (b - a);
    double sum = 0.0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      sum += weights[i] * (std::log(mid + half * nodes[i]) + std::log(mid - half * nodes[i]));
    }
    return half * sum;
  };
  double total = 0.0;
  double width = hi - lo;
  for (int k = 0; k < 100 && width > 0.25 * lo; ++k) {
    total += panel(lo + 0.5 * width, lo + width);
    width *= 0.5;
  }
  if (lo > 0.0) total += panel(lo, lo + width);
  return total;
}

// Displacement at d under unit pressure on a strip of half-width h: the line
// load integrated over distances t in [d - h, d + h], split at t = 0 if the
// strip contains it (both halves then add, without cancellation).
double reference_displacement(double d, double width) {
  const double h = 0.5 * width;
  const double lo = d - h;
  const double hi = d + h;
  const double integral =
      lo >= 0.0 ? graded_log_integral(lo, hi) : graded_log_integral(0.0, -lo) + graded_log_integral(0.0, hi);
  return -2.0 / (kPi * kEStar) * integral;
}

TEST(PlaneStrainStripTest, DiagonalValue) {
  const double expected = -2.0 / (kPi * kEStar) * kWidth * (std::log(kWidth / 2.0) - 1.0);
  EXPECT_NEAR(plane_strain_strip_displacement(0.0, kWidth, kEStar), expected, kRoundingTolerance * expected);
}

TEST(PlaneStrainStripTest, MatchesNumericalIntegration) {
  double worst = 0.0;
  double worst_offset = 0.0;
  for (const double cells : {0.0, 0.2, 0.5, 0.5 + 1e-12, 0.8, 1.0, 1.0 - 1e-13, 1.0 + 1e-13, 1.5, 3.0, 10.0}) {
    const double d = cells * kWidth;
    const double value = plane_strain_strip_displacement(d, kWidth, kEStar);
    ASSERT_TRUE(std::isfinite(value)) << "at d = " << cells << " dx";
    const double expected = reference_displacement(d, kWidth);
    const double error = std::abs(value - expected) / std::abs(expected);
    if (error > worst) {
      worst = error;
      worst_offset = cells;
    }
  }
  std::printf("Strip: largest relative error %.2e at d = %g dx\n", worst, worst_offset);
  EXPECT_LE(worst, kQuadratureTolerance) << "at d = " << worst_offset << " dx";
}

TEST(PlaneStrainStripTest, FarFieldTendsToLineLoad) {
  // K(d) = line load * dx + (2/(pi E*)) (dx/6) (h/d)^2 + O((h/d)^4): checks
  // both the limit and the far-field form's accuracy (no cancellation).
  for (const double cells : {30.0, 1e3, 1e6}) {
    const double d = cells * kWidth;
    const double z = 0.5 * kWidth / d;
    const double expected = line_load(d) * kWidth + 2.0 / (kPi * kEStar) * kWidth / 6.0 * z * z;
    const double value = plane_strain_strip_displacement(d, kWidth, kEStar);
    EXPECT_NEAR(value, expected,
                kRoundingTolerance * std::abs(expected) + 2.0 / (kPi * kEStar) * kWidth * z * z * z * z)
        << "at d = " << cells << " dx";
  }
}

TEST(PlaneStrainStripTest, ContinuousAtBranchSwitch) {
  // The closed form switches to its far-field rewriting at d = 2 dx/2 = dx.
  const double below = plane_strain_strip_displacement(kWidth * (1.0 - 1e-15), kWidth, kEStar);
  const double above = plane_strain_strip_displacement(kWidth * (1.0 + 1e-15), kWidth, kEStar);
  EXPECT_NEAR(below, above, kRoundingTolerance * std::abs(above));
}

TEST(PlaneStrainStripTest, EvenAndFiniteAtEdges) {
  for (const double cells : {0.5, 1.0, 2.5, 17.0}) {
    const double value = plane_strain_strip_displacement(cells * kWidth, kWidth, kEStar);
    EXPECT_TRUE(std::isfinite(value));
    EXPECT_EQ(value, plane_strain_strip_displacement(-cells * kWidth, kWidth, kEStar));
  }
}

}  // namespace
}  // namespace halfspace
