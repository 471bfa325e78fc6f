// Dense LCPs with known solutions for the Lemke and LCPquad tests: a solution
// (z*, w*, lambda*) is chosen first and q (and b) built from it, so that the
// solvers are checked against data they never produced; and a checker of the
// complementarity conditions that prints the worst entry.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "halfspace/solvers/lcp.hpp"

namespace halfspace::testing {

// Random n x n symmetric positive definite matrix A A'/n + shift I, with
// entries O(1), from a fixed seed.
inline Eigen::MatrixXd random_spd_matrix(Eigen::Index n, std::uint32_t seed, double shift = 0.1) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd a(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    for (Eigen::Index i = 0; i < n; ++i) a(i, j) = uniform(generator);
  }
  Eigen::MatrixXd m = a * a.transpose() / static_cast<double>(n);
  m.diagonal().array() += shift;
  return m;
}

// How each entry of the chosen solution is made.
enum class Entry { contact, gap, degenerate };  // z > 0 = w; w > 0 = z; z = w = 0

struct KnownLcp {
  solvers::LcpProblem problem;
  Eigen::VectorXd z;  // the solution
  Eigen::VectorXd w;
  double lambda = 0.0;
};

// The LCP whose solution has the given pattern: z_i, w_i in [0.5, 2] where
// positive, q = w - M z (+ a lambda, with a = 1 and b = 1'z when `equality`).
// For a positive definite M the solution is unique.
inline KnownLcp known_lcp(const Eigen::MatrixXd& m, const std::vector<Entry>& pattern, std::uint32_t seed,
                          bool equality = false, double lambda = 0.7) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> magnitude(0.5, 2.0);
  const auto n = static_cast<Eigen::Index>(pattern.size());
  KnownLcp known;
  known.z = Eigen::VectorXd::Zero(n);
  known.w = Eigen::VectorXd::Zero(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (pattern[static_cast<std::size_t>(i)] == Entry::contact) known.z[i] = magnitude(generator);
    if (pattern[static_cast<std::size_t>(i)] == Entry::gap) known.w[i] = magnitude(generator);
  }
  known.problem.matrix = m;
  known.problem.offset = known.w - m * known.z;
  if (equality) {
    known.lambda = lambda;
    known.problem.equality_row = Eigen::VectorXd::Ones(n);
    known.problem.equality_value = known.z.sum();
    known.problem.offset += known.lambda * known.problem.equality_row;
  }
  return known;
}

// A random pattern with roughly the given shares of contact and degenerate entries.
inline std::vector<Entry> random_pattern(std::size_t n, std::uint32_t seed, double contact_share,
                                         double degenerate_share = 0.0) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Entry> pattern(n);
  for (Entry& entry : pattern) {
    const double u = uniform(generator);
    entry =
        u < contact_share ? Entry::contact : (u < contact_share + degenerate_share ? Entry::degenerate : Entry::gap);
  }
  return pattern;
}

// Checks z >= -tol, w >= -tol, min(z, w) <= tol entry by entry and the
// equality to tol, with w recomputed from z and lambda; prints the worst.
inline void expect_solves(const solvers::LcpProblem& problem, const solvers::LcpSolution& solution, double tol) {
  ASSERT_TRUE(solution.solved()) << to_string(solution.status) << ": " << solution.message;
  const Eigen::VectorXd w = solvers::lcp_slack(problem, solution.z, solution.multiplier);
  double worst = 0.0;
  Eigen::Index where = -1;
  for (Eigen::Index i = 0; i < w.size(); ++i) {
    const double violation = std::max({-solution.z[i], -w[i], std::min(std::abs(solution.z[i]), std::abs(w[i]))});
    if (violation > worst) {
      worst = violation;
      where = i;
    }
  }
  EXPECT_LE(worst, tol) << "worst violation at entry " << where << ": z = " << solution.z[where]
                        << ", w = " << w[where];
  if (problem.has_equality()) {
    EXPECT_NEAR(problem.equality_row.dot(solution.z), problem.equality_value, tol) << "equality a'z = b";
  }
}

// Largest |a_i - b_i|, printed with its index on failure by the caller.
struct MaxDifference {
  double value = 0.0;
  Eigen::Index index = -1;
};
inline MaxDifference max_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  MaxDifference d;
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    if (std::abs(a[i] - b[i]) > d.value) {
      d.value = std::abs(a[i] - b[i]);
      d.index = i;
    }
  }
  return d;
}

}  // namespace halfspace::testing
