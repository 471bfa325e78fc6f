// LCPquad (the paper's QP through ALGLIB's dense IPM) on LCPs with known
// solutions, against Lemke and the complementarity conditions, and its
// reports on problems it cannot solve.
#include "halfspace/solvers/lcp_quad.hpp"

#include <gtest/gtest.h>

#include <string>

#include "halfspace/error.hpp"
#include "halfspace/solvers/lemke.hpp"
#include "support/lcp_problems.hpp"

namespace halfspace {
namespace {

using solvers::LcpProblem;
using solvers::LcpStatus;
using solvers::solve_lcp_lemke;
using solvers::solve_lcp_quad;
using testing::Entry;
using testing::expect_solves;
using testing::known_lcp;
using testing::max_difference;
using testing::random_pattern;
using testing::random_spd_matrix;

// With strict complementarity (z_i + w_i > 0) the interior-point iterate
// meets the conditions to about its stopping tolerance (1e-12) times the
// conditioning of the O(1) data (measured: below 1e-12).
constexpr double kInteriorPointTolerance = 1e-10;
// Without it (z_i = w_i = 0) interior-point iterates converge only like the
// square root of the barrier parameter (measured: 2e-7 at tolerance 1e-12).
constexpr double kDegenerateTolerance = 1e-6;

TEST(LcpQuadTest, SolvesTwoByTwoLcpByHand) {
  LcpProblem problem{(Eigen::MatrixXd(2, 2) << 2, 1, 1, 2).finished(), Eigen::Vector2d(-5, -6), {}, 0.0};
  const auto solution = solve_lcp_quad(problem);
  expect_solves(problem, solution, kInteriorPointTolerance);
  EXPECT_NEAR(solution.z[0], 4.0 / 3.0, kInteriorPointTolerance);
  EXPECT_NEAR(solution.z[1], 7.0 / 3.0, kInteriorPointTolerance);
  EXPECT_NEAR(solution.objective, 0.0, kInteriorPointTolerance);
  EXPECT_GT(solution.iterations, 0);
}

TEST(LcpQuadTest, SolvesDegenerateLcp) {
  const std::vector<Entry> pattern{Entry::degenerate, Entry::contact, Entry::gap,       Entry::degenerate,
                                   Entry::contact,    Entry::gap,     Entry::degenerate};
  const auto known = known_lcp(random_spd_matrix(7, 21), pattern, 22);
  const auto solution = solve_lcp_quad(known.problem);
  expect_solves(known.problem, solution, kDegenerateTolerance);
  const auto error = max_difference(solution.z, known.z);
  EXPECT_LE(error.value, kDegenerateTolerance) << "at entry " << error.index;

  for (std::uint32_t seed = 1; seed <= 2; ++seed) {
    const auto random =
        known_lcp(random_spd_matrix(40, seed + 60), random_pattern(40, seed + 70, 0.4, 0.1), seed + 80, seed == 2);
    const auto quad = solve_lcp_quad(random.problem);
    expect_solves(random.problem, quad, kDegenerateTolerance);
    const auto to_known = max_difference(quad.z, random.z);
    EXPECT_LE(to_known.value, kDegenerateTolerance) << "seed " << seed << ", entry " << to_known.index;
  }
}

TEST(LcpQuadTest, AgreesWithLemkeOnRandomPositiveDefiniteLcps) {
  for (std::uint32_t seed = 1; seed <= 4; ++seed) {
    const bool equality = seed % 2 == 0;
    const auto known =
        known_lcp(random_spd_matrix(40, seed + 30), random_pattern(40, seed + 40, 0.4), seed + 50, equality);
    const auto quad = solve_lcp_quad(known.problem);
    const auto lemke = solve_lcp_lemke(known.problem);
    expect_solves(known.problem, quad, kInteriorPointTolerance);
    expect_solves(known.problem, lemke, kInteriorPointTolerance);
    const auto to_lemke = max_difference(quad.z, lemke.z);
    EXPECT_LE(to_lemke.value, kInteriorPointTolerance) << "seed " << seed << ", entry " << to_lemke.index;
    const auto to_known = max_difference(quad.z, known.z);
    EXPECT_LE(to_known.value, kInteriorPointTolerance) << "seed " << seed << ", entry " << to_known.index;
    if (equality) {
      EXPECT_NEAR(quad.multiplier, known.lambda, kInteriorPointTolerance);
    }
    // The paper's objective z'(Mz + q) vanishes at the solution.
    EXPECT_NEAR(quad.objective, 0.0, kInteriorPointTolerance) << "seed " << seed;
  }
}

TEST(LcpQuadTest, ReportsInfeasibleLcpAsFailure) {
  // M skew-symmetric (semidefinite, so the QP is convex) and no z >= 0 has
  // w2 = -z1 - 1 >= 0: the QP's constraints are inconsistent.
  LcpProblem problem{(Eigen::MatrixXd(2, 2) << 0, 1, -1, 0).finished(), Eigen::Vector2d(-1, -1), {}, 0.0};
  const auto solution = solve_lcp_quad(problem);
  EXPECT_FALSE(solution.solved());
  EXPECT_NE(solution.message.find("LCPquad"), std::string::npos) << solution.message;
}

TEST(LcpQuadTest, RejectsInvalidOptions) {
  LcpProblem problem{Eigen::MatrixXd::Identity(2, 2), Eigen::Vector2d(-1, -1), {}, 0.0};
  try {
    solve_lcp_quad(problem, solvers::LcpQuadOptions{-1.0});
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("LCPquad tolerance = -1"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace halfspace
