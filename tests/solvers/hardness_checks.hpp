// Checks every solve with a hardness cap must pass: 0 <= p <= H, a closed
// gap below the cap, no interpenetration out of contact, and a gap that is
// not open at the cap (the rigid surface penetrates the elastic one there),
// each to within a stated gap tolerance; and the force the load asked for.
#pragma once

#include <gtest/gtest.h>

#include <cmath>

#include "halfspace/solvers/solve_result.hpp"

namespace halfspace::testing {

// gap_tolerance (m): the largest |gap| below the cap, interpenetration out
// of contact and open gap at the cap allowed.
inline void expect_capped_contact_conditions(const SolveResult& result, double hardness, double gap_tolerance) {
  double worst[3] = {0.0, 0.0, 0.0};
  Eigen::Index where[3] = {-1, -1, -1};
  auto note = [&](int kind, double value, Eigen::Index i) {
    if (value > worst[kind]) {
      worst[kind] = value;
      where[kind] = i;
    }
  };
  for (Eigen::Index i = 0; i < result.pressure.size(); ++i) {
    const double p = result.pressure[i];
    const double g = result.gap[i];
    ASSERT_GE(p, 0.0) << "negative pressure at cell " << i;
    ASSERT_LE(p, hardness) << "pressure above the hardness at cell " << i;
    if (p == 0.0) note(0, -g, i);
    if (p > 0.0 && p < hardness) note(1, std::abs(g), i);
    if (p == hardness) note(2, g, i);
  }
  EXPECT_LE(worst[0], gap_tolerance) << "interpenetration out of contact at cell " << where[0];
  EXPECT_LE(worst[1], gap_tolerance) << "open gap below the cap at cell " << where[1];
  EXPECT_LE(worst[2], gap_tolerance) << "open gap at the cap at cell " << where[2];
}

// Cells at the cap.
inline double plastic_cells(const SolveResult& result, double hardness) {
  return static_cast<double>((result.pressure >= hardness).count());
}

}  // namespace halfspace::testing
