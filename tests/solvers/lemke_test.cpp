// Lemke's method (Siconos) on LCPs with known solutions: by hand, trivial,
// degenerate, random positive definite, with the load equality; and its
// reports: ray termination, pivot limit, bad input.
#include "halfspace/solvers/lemke.hpp"

#include <gtest/gtest.h>

#include <string>

#include "halfspace/error.hpp"
#include "support/lcp_problems.hpp"

namespace halfspace {
namespace {

using solvers::LcpProblem;
using solvers::LcpStatus;
using solvers::solve_lcp_lemke;
using testing::Entry;
using testing::expect_solves;
using testing::known_lcp;
using testing::max_difference;
using testing::random_pattern;
using testing::random_spd_matrix;

// Pivoting is exact up to rounding in O(n) eliminations of O(1) data.
constexpr double kExactTolerance = 1e-12;
// Random problems of size 40 with condition numbers up to ~1e3.
constexpr double kRandomTolerance = 1e-10;

TEST(LemkeTest, SolvesTwoByTwoLcpByHand) {
  // Both in contact: M z = -q gives z = (4/3, 7/3), w = 0.
  LcpProblem problem{(Eigen::MatrixXd(2, 2) << 2, 1, 1, 2).finished(), Eigen::Vector2d(-5, -6), {}, 0.0};
  const auto solution = solve_lcp_lemke(problem);
  expect_solves(problem, solution, kExactTolerance);
  EXPECT_NEAR(solution.z[0], 4.0 / 3.0, kExactTolerance);
  EXPECT_NEAR(solution.z[1], 7.0 / 3.0, kExactTolerance);
  EXPECT_GE(solution.iterations, 2);  // the covering vector enters, then each z
  EXPECT_NEAR(solution.objective, 0.0, kExactTolerance);
}

TEST(LemkeTest, ReturnsZeroWithoutPivotsWhenQIsNonnegative) {
  LcpProblem problem{random_spd_matrix(5, 3), Eigen::VectorXd::LinSpaced(5, 0.0, 2.0), {}, 0.0};
  const auto solution = solve_lcp_lemke(problem);
  expect_solves(problem, solution, kExactTolerance);
  EXPECT_EQ(solution.z, Eigen::VectorXd::Zero(5));
  EXPECT_EQ(solution.iterations, 0);
}

TEST(LemkeTest, SolvesDegenerateLcp) {
  // Ties in the first ratio test (q all equal) and entries with z = w = 0.
  LcpProblem ties{Eigen::MatrixXd::Identity(4, 4) * 2.0, Eigen::VectorXd::Constant(4, -1.0), {}, 0.0};
  const auto tied = solve_lcp_lemke(ties);
  expect_solves(ties, tied, kExactTolerance);
  EXPECT_NEAR(tied.z.minCoeff(), 0.5, kExactTolerance);
  EXPECT_NEAR(tied.z.maxCoeff(), 0.5, kExactTolerance);

  const std::vector<Entry> pattern{Entry::contact, Entry::degenerate, Entry::gap,        Entry::degenerate,
                                   Entry::contact, Entry::contact,    Entry::degenerate, Entry::gap};
  const auto known = known_lcp(random_spd_matrix(8, 11), pattern, 12);
  const auto solution = solve_lcp_lemke(known.problem);
  expect_solves(known.problem, solution, kExactTolerance);
  const auto error = max_difference(solution.z, known.z);
  EXPECT_LE(error.value, kExactTolerance) << "at entry " << error.index;
}

TEST(LemkeTest, SolvesRandomPositiveDefiniteLcps) {
  for (std::uint32_t seed = 1; seed <= 5; ++seed) {
    const auto known = known_lcp(random_spd_matrix(40, seed), random_pattern(40, seed + 100, 0.4, 0.1), seed + 200);
    const auto solution = solve_lcp_lemke(known.problem);
    expect_solves(known.problem, solution, kRandomTolerance);
    const auto error = max_difference(solution.z, known.z);
    EXPECT_LE(error.value, kRandomTolerance) << "seed " << seed << ", entry " << error.index;
  }
}

TEST(LemkeTest, SolvesMixedLcpWithEquality) {
  // The load-control form: w = M z + q - 1 lambda, 1'z = b, lambda free
  // (negative here, as an approach can be under a logarithmic datum).
  const auto known = known_lcp(random_spd_matrix(30, 7), random_pattern(30, 8, 0.5, 0.1), 9, true, -0.4);
  const auto solution = solve_lcp_lemke(known.problem);
  expect_solves(known.problem, solution, kRandomTolerance);
  EXPECT_NEAR(solution.multiplier, known.lambda, kRandomTolerance);
  const auto error = max_difference(solution.z, known.z);
  EXPECT_LE(error.value, kRandomTolerance) << "at entry " << error.index;
}

TEST(LemkeTest, ReportsRayTerminationOnInfeasibleLcp) {
  // M skew-symmetric (positive semidefinite), w2 = -z1 - 1 < 0 for every z >= 0.
  LcpProblem problem{(Eigen::MatrixXd(2, 2) << 0, 1, -1, 0).finished(), Eigen::Vector2d(-1, -1), {}, 0.0};
  const auto solution = solve_lcp_lemke(problem);
  EXPECT_EQ(solution.status, LcpStatus::ray_termination);
  EXPECT_NE(solution.message.find("ray termination"), std::string::npos) << solution.message;
  EXPECT_GT(solution.iterations, 0);
}

TEST(LemkeTest, StopsAtThePivotLimit) {
  const auto known = known_lcp(random_spd_matrix(20, 4), std::vector<Entry>(20, Entry::contact), 5);
  const auto solution = solve_lcp_lemke(known.problem, solvers::LemkeOptions{3});
  EXPECT_EQ(solution.status, LcpStatus::iteration_limit);
  EXPECT_EQ(solution.iterations, 3);
  EXPECT_NE(solution.message.find("3 pivots"), std::string::npos) << solution.message;
}

TEST(LemkeTest, RejectsInconsistentInput) {
  LcpProblem problem{Eigen::MatrixXd::Identity(3, 3), Eigen::VectorXd::Ones(2), {}, 0.0};
  try {
    solve_lcp_lemke(problem);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("3 x 3 but q has 2 entries"), std::string::npos) << error.what();
  }
  EXPECT_THROW(
      solve_lcp_lemke({Eigen::MatrixXd::Identity(2, 2), Eigen::Vector2d(-1, -1), {}, 0.0}, solvers::LemkeOptions{0}),
      InputError);
}

}  // namespace
}  // namespace halfspace
