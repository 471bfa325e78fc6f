// Validation and the violation measure of dense LCPs.
#include "halfspace/solvers/lcp.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "halfspace/error.hpp"

namespace halfspace::solvers {

void LcpProblem::validate() const {
  const Eigen::Index n = size();
  if (n < 1) throw InputError("LCP: the vector q is empty; the problem needs at least one unknown");
  if (matrix.rows() != n || matrix.cols() != n) {
    throw InputError(fmt::format("LCP: the matrix M is {} x {} but q has {} entries; M must be {} x {}", matrix.rows(),
                                 matrix.cols(), n, n, n));
  }
  if (has_equality() && equality_row.size() != n) {
    throw InputError(fmt::format("LCP: the equality row a has {} entries but q has {}", equality_row.size(), n));
  }
  if (!matrix.allFinite()) throw InputError("LCP: the matrix M holds a non-finite entry");
  if (!offset.allFinite()) throw InputError("LCP: the vector q holds a non-finite entry");
  if (has_equality() && !(equality_row.allFinite() && std::isfinite(equality_value))) {
    throw InputError("LCP: the equality a' z = b holds a non-finite value");
  }
  if (has_upper_bound()) {
    if (upper_bound.size() != n) {
      throw InputError(fmt::format("LCP: the upper bound u has {} entries but q has {}", upper_bound.size(), n));
    }
    if (!(upper_bound.allFinite() && (upper_bound.array() > 0.0).all())) {
      throw InputError("LCP: the upper bound u must be finite and positive");
    }
  }
}

std::string_view to_string(LcpStatus status) {
  switch (status) {
    case LcpStatus::solved:
      return "solved";
    case LcpStatus::ray_termination:
      return "ray_termination";
    case LcpStatus::iteration_limit:
      return "iteration_limit";
    case LcpStatus::failure:
      return "failure";
  }
  return "unknown";
}

Eigen::VectorXd lcp_slack(const LcpProblem& problem, const Eigen::VectorXd& z, double lambda) {
  Eigen::VectorXd w = problem.matrix * z + problem.offset;
  if (problem.has_equality()) w -= lambda * problem.equality_row;
  return w;
}

LcpViolation lcp_violation(const LcpProblem& problem, const Eigen::VectorXd& z, double lambda) {
  const Eigen::VectorXd w = lcp_slack(problem, z, lambda);
  LcpViolation violation;
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    violation.negative_z = std::max(violation.negative_z, -z[i]);
    violation.negative_w = std::max(violation.negative_w, -w[i]);
    if (z[i] > 0.0 && w[i] > 0.0) violation.complementarity = std::max(violation.complementarity, std::min(z[i], w[i]));
  }
  if (problem.has_equality()) violation.equality = std::abs(problem.equality_row.dot(z) - problem.equality_value);
  return violation;
}

}  // namespace halfspace::solvers
