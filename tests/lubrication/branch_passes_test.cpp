// The cavitation switch's branches in a Newton step (reynolds_linearisation.hpp):
// the branch passes choose the side of the nodes on the switch s = 0 from
// the step, and where they end before the branches agree with it, the trial
// path keeps the nodes whose step goes to the side they were not solved on
// at s = 0 (detail::stays_on_switch).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/lubrication/flow_conditions.hpp"
#include "halfspace/lubrication/reynolds_stencil.hpp"
#include "lubrication/reynolds_linearisation.hpp"

namespace halfspace::lubrication {
namespace {

TEST(BranchPassesTest, OnlyANodeOnTheSwitchSteppingToTheOtherBranchStays) {
  // On the switch: solved cavitated, the step raises s (a pressure): stays.
  EXPECT_TRUE(detail::stays_on_switch(0.0, 0.3, false));
  // Solved full, the step lowers s (a fraction below 1): stays.
  EXPECT_TRUE(detail::stays_on_switch(0.0, -0.3, true));
  // The step goes where it was solved: it moves.
  EXPECT_FALSE(detail::stays_on_switch(0.0, 0.3, true));
  EXPECT_FALSE(detail::stays_on_switch(0.0, -0.3, false));
  EXPECT_FALSE(detail::stays_on_switch(0.0, 0.0, false));
  // Off the switch a node's branch is its side's (the bent path stops it
  // where it crosses; that rule is the caller's).
  EXPECT_FALSE(detail::stays_on_switch(1e-12, 0.3, false));
  EXPECT_FALSE(detail::stays_on_switch(-1e-12, -0.3, true));
}

TEST(BranchPassesTest, PassesThatEndFlipTheBranchesAfterTheLastSolve) {
  // Two nodes on the switch: node 1's step always goes against its branch
  // (it flips at every pass), node 2's with it. The passes end at their
  // limit with branches set from the last step, not those it was solved
  // on, which is why the trial path reads the solve's own branches.
  const Grid grid = Grid::line(4, 1e-6, Boundary::free);
  FlowConditions conditions;
  conditions.entrainment_velocity = {1.0, 0.0};
  conditions.viscosity = 1.0;  // nodes 0 and 3 hold the imposed pressures
  const ReynoldsStencil topology(grid, Eigen::ArrayXd::Ones(4), conditions);
  const Eigen::ArrayXd s = Eigen::ArrayXd::Zero(4);
  Eigen::VectorXd step = Eigen::VectorXd::Zero(4);
  std::vector<char> branches(4, 1);
  std::vector<std::vector<char>> solved_on;
  const auto solve = [&] {
    solved_on.push_back(branches);
    step[1] = branches[1] != 0 ? -1.0 : 1.0;
    step[2] = branches[2] != 0 ? 1.0 : -1.0;
    return true;
  };
  ASSERT_TRUE(detail::branch_consistent_step_with(solve, topology, s, step, branches));
  ASSERT_EQ(static_cast<int>(solved_on.size()), detail::kBranchPasses);
  const std::vector<char>& last = solved_on.back();
  for (const int j : {1, 2}) {
    const auto jj = static_cast<std::size_t>(j);
    EXPECT_EQ(branches[jj] != 0, step[j] > 0.0) << j;  // flipped to the last step's side
  }
  EXPECT_NE(branches[1], last[1]);
  EXPECT_TRUE(detail::stays_on_switch(s[1], step[1], last[1] != 0));
  EXPECT_FALSE(detail::stays_on_switch(s[2], step[2], last[2] != 0));
}

}  // namespace
}  // namespace halfspace::lubrication
