// Cerruti's rectangle coefficients against numerical quadrature of the
// point-load formula (Johnson 1985, sec. 2.2) over the cell, and against
// Love's centre value 8 a ln(1 + sqrt 2) for the isotropic part.
#include "halfspace/kernels/cerruti_rectangle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "halfspace/elastic_pair.hpp"
#include "halfspace/kernels/plane_strain_strip.hpp"
#include "halfspace/kernels/tangential_strip.hpp"

namespace halfspace::kernels {
namespace {

constexpr double kShear = 1.0 / 40e9 + 1.0 / 80e9;         // 1/G1 + 1/G2, 1/Pa
constexpr double kDirectional = 0.3 / 40e9 + 0.25 / 80e9;  // nu1/G1 + nu2/G2

// The point-force displacement summed over both bodies (the header's formula).
TangentialCoefficients point_force(double x, double y) {
  const double rho = std::hypot(x, y);
  const double scale = 1.0 / (2.0 * std::numbers::pi);
  const double isotropic = (kShear - kDirectional) / rho;
  const double r3 = rho * rho * rho;
  return {scale * (isotropic + kDirectional * x * x / r3), scale * (isotropic + kDirectional * y * y / r3),
          scale * kDirectional * x * y / r3};
}

// Composite 5-point Gauss-Legendre quadrature of the point force over the cell
// |x'| <= a, |y'| <= b seen from (x, y) outside it, on m x m sub-cells.
TangentialCoefficients quadrature(double x, double y, double a, double b, int m) {
  static constexpr double kNodes[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                       0.9061798459386640};
  static constexpr double kWeights[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                         0.2369268850561891};
  TangentialCoefficients total;
  const double hx = 2.0 * a / m;
  const double hy = 2.0 * b / m;
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < m; ++j) {
      const double cx = -a + (i + 0.5) * hx;
      const double cy = -b + (j + 0.5) * hy;
      for (int k = 0; k < 5; ++k) {
        for (int l = 0; l < 5; ++l) {
          const double w = kWeights[k] * kWeights[l] * 0.25 * hx * hy;
          const TangentialCoefficients f =
              point_force(x - (cx + 0.5 * hx * kNodes[k]), y - (cy + 0.5 * hy * kNodes[l]));
          total.xx += w * f.xx;
          total.yy += w * f.yy;
          total.xy += w * f.xy;
        }
      }
    }
  }
  return total;
}

TEST(CerrutiRectangle, MatchesQuadratureOfThePointForceOutsideTheCell) {
  const double a = 0.5e-6;
  const double b = 0.8e-6;
  // Near (closed form) and far (Gauss rules) offsets in every quadrant, and
  // on both sides of the switch at two half-diagonals.
  const double h = std::hypot(a, b);
  const double offsets[][2] = {{1.5 * a, 0.3 * b},  {-2.2 * a, 1.4 * b}, {0.4 * a, -3.0 * b}, {-1.9 * h, -0.2 * b},
                               {2.01 * h, 0.1 * b}, {4.0 * a, 4.0 * b},  {-7.0 * h, 2.0 * h}, {30.0 * h, -50.0 * h}};
  for (const auto& offset : offsets) {
    const double x = offset[0];
    const double y = offset[1];
    const TangentialCoefficients closed = cerruti_rectangle_displacement(x, y, a, b, kShear, kDirectional);
    const TangentialCoefficients reference = quadrature(x, y, a, b, 64);
    const double scale = std::abs(reference.xx);
    EXPECT_NEAR(closed.xx, reference.xx, 1e-10 * scale) << x << ", " << y;
    EXPECT_NEAR(closed.yy, reference.yy, 1e-10 * scale) << x << ", " << y;
    EXPECT_NEAR(closed.xy, reference.xy, 1e-10 * scale) << x << ", " << y;
    // The signs of Cerruti's cross term: x y / rho^3.
    EXPECT_EQ(std::signbit(closed.xy), std::signbit(x * y)) << x << ", " << y;
  }
}

TEST(CerrutiRectangle, CentreOfASquareCellIsHalfLovesIntegralInEachDirection) {
  // By symmetry the integrals of x^2/rho^3 and y^2/rho^3 over a square are
  // each half that of 1/rho, 8 a ln(1 + sqrt 2) at the centre.
  const double a = 1e-6;
  const double inverse = 8.0 * a * std::log(1.0 + std::sqrt(2.0));
  const double expected = ((kShear - kDirectional) * inverse + 0.5 * kDirectional * inverse) / (2.0 * std::numbers::pi);
  const TangentialCoefficients centre = cerruti_rectangle_displacement(0.0, 0.0, a, a, kShear, kDirectional);
  EXPECT_NEAR(centre.xx, expected, 1e-14 * expected);
  EXPECT_NEAR(centre.yy, expected, 1e-14 * expected);
  EXPECT_EQ(centre.xy, 0.0);
}

TEST(CerrutiRectangle, IsEvenAndOddBitForBit) {
  const double a = 0.5e-6;
  const double b = 0.3e-6;
  for (const double x : {0.2e-6, 1.1e-6, 9e-6}) {
    for (const double y : {0.1e-6, 0.7e-6, 13e-6}) {
      const TangentialCoefficients c = cerruti_rectangle_displacement(x, y, a, b, kShear, kDirectional);
      const TangentialCoefficients m = cerruti_rectangle_displacement(-x, y, a, b, kShear, kDirectional);
      EXPECT_EQ(c.xx, m.xx);
      EXPECT_EQ(c.yy, m.yy);
      EXPECT_EQ(c.xy, -m.xy);
    }
  }
}

TEST(TangentialStrip, InPlaneIsTheNormalStripWithTheSameEStar) {
  const ElasticPair pair({2e11, 0.3}, {7e10, 0.33});
  const double width = 1e-6;
  for (const double d : {0.0, 0.4e-6, 3e-6, 1e-3}) {
    const TangentialCoefficients t =
        tangential_strip_displacement(d, width, pair.composite_modulus(), pair.shear_compliance());
    EXPECT_DOUBLE_EQ(t.xx, plane_strain_strip_displacement(d, width, pair.composite_modulus()));
    // Antiplane: the compliance 1/G1 + 1/G2 in place of 2/E*.
    EXPECT_NEAR(t.yy, t.xx * pair.shear_compliance() * pair.composite_modulus() / 2.0, 1e-13 * std::abs(t.yy));
    EXPECT_EQ(t.xy, 0.0);
  }
}

}  // namespace
}  // namespace halfspace::kernels
