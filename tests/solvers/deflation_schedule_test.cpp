// The policy of when the coarse-grid correction joins a solve: only after
// settled steps, only if they were slow, never once declined, and not while
// a step clips many cells.
#include "halfspace/solvers/deflation_schedule.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace halfspace::solvers {
namespace {

constexpr double kSearched = 10000.0;
constexpr double kSettled = 0.5 * DeflationSchedule::kDeflateBelowClipped * kSearched;
constexpr double kMoving = 2.0 * DeflationSchedule::kDeflateBelowClipped * kSearched;

// Residuals falling by `rate` per step from 1.
std::vector<double> falling(double rate, int steps) {
  std::vector<double> residuals{1.0};
  for (int k = 0; k < steps; ++k) residuals.push_back(residuals.back() * rate);
  return residuals;
}

TEST(DeflationScheduleTest, JoinsAfterSlowSettledStepsOnly) {
  DeflationSchedule schedule;
  const std::vector<double> slow = falling(0.8, 3);
  EXPECT_FALSE(schedule.wants({slow.data(), 1}));  // no step yet
  schedule.observe_step(false, kSettled, kSearched);
  EXPECT_FALSE(schedule.wants({slow.data(), 2}));  // one settled step: no rate yet
  schedule.observe_step(false, kSettled, kSearched);
  EXPECT_TRUE(schedule.wants({slow.data(), 3}));
  EXPECT_EQ(schedule.fast_rate(), 0.0);
}

TEST(DeflationScheduleTest, StaysOutOfAFastSolveAndReportsItsRate) {
  DeflationSchedule schedule;
  const std::vector<double> fast = falling(0.3, 4);
  schedule.observe_step(false, kSettled, kSearched);
  schedule.observe_step(false, kSettled, kSearched);
  EXPECT_FALSE(schedule.wants({fast.data(), 3}));
  EXPECT_NEAR(schedule.fast_rate(), 0.3, 1e-12);
  schedule.begin_solve();
  EXPECT_EQ(schedule.fast_rate(), 0.0);
}

TEST(DeflationScheduleTest, WaitsWhileStepsClipAndLeavesWhenOneDoes) {
  DeflationSchedule schedule;
  const std::vector<double> slow = falling(0.8, 6);
  schedule.observe_step(false, kMoving, kSearched);
  schedule.observe_step(false, kSettled, kSearched);
  EXPECT_FALSE(schedule.wants({slow.data(), 3}));  // one settled step since the clipping
  schedule.observe_step(false, kSettled, kSearched);
  EXPECT_TRUE(schedule.wants({slow.data(), 4}));
  schedule.observe_step(true, kMoving, kSearched);
  EXPECT_FALSE(schedule.wants({slow.data(), 5}));  // the last step clipped too much
  schedule.observe_step(false, kSettled, kSearched);
  EXPECT_TRUE(schedule.wants({slow.data(), 6}));  // the rate was measured once: it pays
}

TEST(DeflationScheduleTest, NeverJoinsOnceDeclined) {
  DeflationSchedule schedule;
  const std::vector<double> slow = falling(0.8, 3);
  schedule.observe_step(false, kSettled, kSearched);
  schedule.observe_step(false, kSettled, kSearched);
  schedule.decline();
  EXPECT_FALSE(schedule.wants({slow.data(), 3}));
  EXPECT_TRUE(schedule.declined());
}

}  // namespace
}  // namespace halfspace::solvers
