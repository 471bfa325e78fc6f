// The inexact Newton forcing term (src/lubrication/newton_forcing.hpp)
// against Eisenstat & Walker's (1996) choice 2 and its safeguards, written
// out by hand for each branch.
#include "lubrication/newton_forcing.hpp"

#include <gtest/gtest.h>

namespace halfspace::lubrication::detail {
namespace {

constexpr double kLargest = 1e-2;
constexpr double kTolerance = 1e-10;

TEST(NewtonForcingTest, FirstStepTakesTheLargest) {
  EXPECT_EQ(newton_forcing(3.0, 0.0, 0.5, kLargest, kTolerance), kLargest);
  EXPECT_EQ(newton_forcing(3.0, 0.0, 0.5, 0.9, kTolerance), 0.9);
}

TEST(NewtonForcingTest, FollowsTheSquaredResidualRatio) {
  // gamma (||F_k|| / ||F_{k-1}||)^2 with gamma = 0.9.
  EXPECT_DOUBLE_EQ(newton_forcing(1e-3, 1e-1, kLargest, kLargest, kTolerance), 0.9 * 1e-4);
  EXPECT_DOUBLE_EQ(newton_forcing(0.5, 1.0, 0.01, 0.9, kTolerance), 0.9 * 0.25);
  // A residual that falls slowly: the largest.
  EXPECT_EQ(newton_forcing(0.99, 1.0, kLargest, kLargest, kTolerance), kLargest);
}

TEST(NewtonForcingTest, OneFastStepDoesNotMakeTheNextSolveTight) {
  // Previous 0.5: gamma 0.5^2 = 0.225 > 0.1 is kept; previous 0.3: 0.081 is not.
  EXPECT_DOUBLE_EQ(newton_forcing(1e-3, 1e-1, 0.5, 0.9, kTolerance), 0.9 * 0.25);
  EXPECT_DOUBLE_EQ(newton_forcing(1e-3, 1e-1, 0.3, 0.9, kTolerance), 0.9 * 1e-4);
}

TEST(NewtonForcingTest, NoTighterThanTheStoppingTestNeeds) {
  // Half the tolerance over ||F_k||: 0.5e-10 / 1e-7 = 5e-4 above 0.9 (1e-7 / 1e-4)^2.
  EXPECT_DOUBLE_EQ(newton_forcing(1e-7, 1e-4, 1e-3, kLargest, kTolerance), 0.5 * kTolerance / 1e-7);
  // and never above the largest.
  EXPECT_EQ(newton_forcing(1e-12, 1e-4, 1e-3, kLargest, kTolerance), kLargest);
  EXPECT_DOUBLE_EQ(newton_forcing(0.0, 1e-4, 1e-3, kLargest, kTolerance), 0.0);
}

}  // namespace
}  // namespace halfspace::lubrication::detail
