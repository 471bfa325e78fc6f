// Von Mises and maximum shear against an independent eigen-decomposition.
#include "halfspace/stress/stress_tensor.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

namespace halfspace::stress {
namespace {

TEST(StressTensorTest, MaxShearIsHalfTheExtremePrincipalDifference) {
  // Relative to the tensor's size: the trigonometric eigenvalues lose up to
  // half the digits at exactly repeated roots (SpecialStates), far fewer
  // for random tensors.
  constexpr double kTolerance = 1e-9;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> value(-1e8, 1e8);
  for (int trial = 0; trial < 2000; ++trial) {
    StressTensor s{value(random), value(random), value(random), value(random), value(random), value(random)};
    if (trial % 3 == 0) s.xy = s.xz = 0.0;  // a principal direction along z
    if (trial % 5 == 0) s.yy = s.xx;        // repeated roots are likely
    Eigen::Matrix3d m;
    m << s.xx, s.xy, s.xz, s.xy, s.yy, s.yz, s.xz, s.yz, s.zz;
    const Eigen::Vector3d eig = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m).eigenvalues();
    const double scale = m.norm();
    EXPECT_NEAR(max_shear(s), 0.5 * (eig.maxCoeff() - eig.minCoeff()), kTolerance * scale) << "trial " << trial;
    // Von Mises from the principal stresses.
    const double vm =
        std::sqrt(0.5 * (std::pow(eig[0] - eig[1], 2) + std::pow(eig[1] - eig[2], 2) + std::pow(eig[2] - eig[0], 2)));
    EXPECT_NEAR(von_mises(s), vm, kTolerance * scale) << "trial " << trial;
    EXPECT_NEAR(hydrostatic(s), eig.sum() / 3.0, kTolerance * scale);
  }
}

TEST(StressTensorTest, SpecialStates) {
  // Two equal principal stresses put cos(3 phi) at +-1, where acos turns a
  // rounding error of eps into sqrt(eps) ~ 1e-8 of the shear: ample for a
  // yield criterion, and the price of a closed form with no iteration.
  constexpr double kRepeatedRoot = 1e-8;
  EXPECT_EQ(max_shear({-5.0, -5.0, -5.0, 0.0, 0.0, 0.0}), 0.0);  // hydrostatic
  EXPECT_EQ(von_mises({-5.0, -5.0, -5.0, 0.0, 0.0, 0.0}), 0.0);
  EXPECT_NEAR(max_shear({0.0, 0.0, -2.0, 0.0, 0.0, 0.0}), 1.0, kRepeatedRoot);  // uniaxial
  EXPECT_NEAR(von_mises({0.0, 0.0, -2.0, 0.0, 0.0, 0.0}), 2.0, 1e-15);
  EXPECT_NEAR(max_shear({0.0, 0.0, 0.0, 3.0, 0.0, 0.0}), 3.0, 3.0 * kRepeatedRoot);  // pure shear
  EXPECT_NEAR(von_mises({0.0, 0.0, 0.0, 3.0, 0.0, 0.0}), 3.0 * std::sqrt(3.0), 1e-14);
}

}  // namespace
}  // namespace halfspace::stress
