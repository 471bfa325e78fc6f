// Checks every solve result must pass: p >= 0 everywhere, no interpenetration,
// and a closed gap on the contact set, to within a stated gap tolerance.
#pragma once

#include <gtest/gtest.h>

#include <cmath>

#include "halfspace/solvers/solve_result.hpp"

namespace halfspace::testing {

// gap_tolerance (m): the largest |gap| allowed on the contact set and the
// largest interpenetration allowed off it.
inline void expect_contact_conditions(const SolveResult& result, double gap_tolerance) {
  Eigen::Index worst_contact = -1;
  double worst_contact_gap = 0.0;
  Eigen::Index worst_overlap = -1;
  double worst_overlap_gap = 0.0;
  for (Eigen::Index i = 0; i < result.pressure.size(); ++i) {
    ASSERT_GE(result.pressure[i], 0.0) << "negative pressure at cell " << i;
    const double g = result.gap[i];
    if (result.pressure[i] > 0.0 && std::abs(g) > worst_contact_gap) {
      worst_contact_gap = std::abs(g);
      worst_contact = i;
    }
    if (-g > worst_overlap_gap) {
      worst_overlap_gap = -g;
      worst_overlap = i;
    }
  }
  EXPECT_LE(worst_contact_gap, gap_tolerance) << "open gap on the contact set at cell " << worst_contact;
  EXPECT_LE(worst_overlap_gap, gap_tolerance) << "interpenetration at cell " << worst_overlap;
}

}  // namespace halfspace::testing
