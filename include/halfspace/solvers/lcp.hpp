// A dense linear complementarity problem (LCP), optionally with one linear
// equality and its free multiplier (the mixed LCP of load control), and the
// outcome of solving it: the common language of the Lemke and LCPquad solvers.
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>

namespace halfspace::solvers {

// Find z >= 0 and a free scalar lambda such that
//
//   w = M z + q - a lambda >= 0,   z' w = 0,   a' z = b.
//
// Without an equality (a empty) lambda is 0 and this is the plain LCP
// w = M z + q. In a contact problem z is the pressure, w the gap, a' z = b
// the load and lambda the approach.
struct LcpProblem {
  Eigen::MatrixXd matrix;        // M, n x n
  Eigen::VectorXd offset;        // q, n entries
  Eigen::VectorXd equality_row;  // a, n entries, or empty for no equality
  double equality_value = 0.0;   // b
  // u, n entries, or empty for none: the box-constrained LCP 0 <= z <= u,
  // w >= 0 where z = 0, w = 0 where 0 < z < u, w <= 0 where z = u (a
  // hardness cap). Lemke's method does not take it.
  Eigen::VectorXd upper_bound = Eigen::VectorXd();

  Eigen::Index size() const { return offset.size(); }
  bool has_equality() const { return equality_row.size() > 0; }
  bool has_upper_bound() const { return upper_bound.size() > 0; }
  // Throws InputError naming the part unless n >= 1, M is n x n, a and u
  // are empty or have n entries, every entry is finite and u > 0.
  void validate() const;
};

enum class LcpStatus {
  solved,           // the method ended at a solution
  ray_termination,  // Lemke: secondary ray; no solution exists or M is outside the class Lemke can process
  iteration_limit,  // stopped at the pivot or iteration limit
  failure,          // the method reported another failure (message says which)
};

std::string_view to_string(LcpStatus status);

struct LcpSolution {
  LcpStatus status = LcpStatus::failure;
  std::string message;      // the method's own report; empty when solved
  Eigen::VectorXd z;        // n entries
  Eigen::VectorXd w;        // M z + q - a lambda, recomputed from z and lambda
  double multiplier = 0.0;  // lambda (0 without an equality)
  int iterations = 0;       // Lemke: pivots; LCPquad: interior-point iterations
  double objective = 0.0;   // z' w: zero at a solution (LCPquad's objective)
  double seconds = 0.0;     // wall-clock time of the method itself

  bool solved() const { return status == LcpStatus::solved; }
};

// How far (z, lambda) is from solving the problem, each part as a largest
// absolute value over the entries, in the units of z and w:
struct LcpViolation {
  double negative_z = 0.0;       // max(-z_i, 0)
  double negative_w = 0.0;       // max(-w_i, 0)
  double complementarity = 0.0;  // |min(z_i, w_i)| over entries with z_i, w_i > 0
  double equality = 0.0;         // |a' z - b|
};

// Recomputes w = M z + q - a lambda from `z` and `lambda` and measures it.
LcpViolation lcp_violation(const LcpProblem& problem, const Eigen::VectorXd& z, double lambda);

// w = M z + q - a lambda.
Eigen::VectorXd lcp_slack(const LcpProblem& problem, const Eigen::VectorXd& z, double lambda);

}  // namespace halfspace::solvers
