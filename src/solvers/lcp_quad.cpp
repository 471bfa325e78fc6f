// LCPquad through ALGLIB minqp (DENSE-IPM-QP, Vanderbei's interior-point
// method). ALGLIB minimises (1/2) x'A x + c'x, so the paper's objective
// z'M z + q'z is passed as A = M + M', c = q. The box-constrained LCP of a
// hardness cap is not a complementarity QP of that kind (w <= 0 at the upper
// bound), so it is solved as the energy QP whose optimality conditions it is.
#include "halfspace/solvers/lcp_quad.hpp"

#include <fmt/format.h>
#include <libalglib/optimization.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "halfspace/error.hpp"

namespace halfspace::solvers {
namespace {

std::string completion_meaning(alglib::ae_int_t code) {
  switch (code) {
    case -9:
      return "automatic scaling failed";
    case -5:
      return "inappropriate solver";
    case -4:
      return "unbounded below";
    case -3:
      return "inconsistent constraints";
    case -2:
      return "no primal/dual feasible point found (infeasible or unbounded)";
    case 5:
      return "iteration limit";
    default:
      return "unknown code";
  }
}

// The QP data in ALGLIB's form; unknowns x = (z, lambda) with an equality.
void set_up_qp(const LcpProblem& problem, alglib::minqpstate& state) {
  const Eigen::Index n = problem.size();
  const Eigen::Index unknowns = problem.has_equality() ? n + 1 : n;
  const Eigen::Index rows = problem.has_equality() ? n + 1 : n;
  const double infinity = alglib::fp_posinf;

  alglib::real_2d_array quadratic;
  quadratic.setlength(unknowns, unknowns);
  alglib::real_1d_array linear;
  linear.setlength(unknowns);
  alglib::real_1d_array lower_bound;
  lower_bound.setlength(unknowns);
  alglib::real_1d_array upper_bound;
  upper_bound.setlength(unknowns);
  alglib::real_1d_array scale;
  scale.setlength(unknowns);
  for (Eigen::Index i = 0; i < unknowns; ++i) {
    for (Eigen::Index j = 0; j < unknowns; ++j) {
      quadratic[i][j] = i < n && j < n ? problem.matrix(i, j) + problem.matrix(j, i) : 0.0;
    }
    linear[i] = i < n ? problem.offset[i] : -problem.equality_value;
    lower_bound[i] = i < n ? 0.0 : -infinity;
    upper_bound[i] = infinity;
    scale[i] = 1.0;  // the problem is already O(1) (dense_contact.hpp)
  }

  // M z - a lambda >= -q, one row per unknown, and a'z = b.
  alglib::real_2d_array constraints;
  constraints.setlength(rows, unknowns);
  alglib::real_1d_array row_lower;
  row_lower.setlength(rows);
  alglib::real_1d_array row_upper;
  row_upper.setlength(rows);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) constraints[i][j] = problem.matrix(i, j);
    if (problem.has_equality()) constraints[i][n] = -problem.equality_row[i];
    row_lower[i] = -problem.offset[i];
    row_upper[i] = infinity;
  }
  if (problem.has_equality()) {
    for (Eigen::Index j = 0; j < n; ++j) constraints[n][j] = problem.equality_row[j];
    constraints[n][n] = 0.0;
    row_lower[n] = problem.equality_value;
    row_upper[n] = problem.equality_value;
  }

  alglib::minqpsetquadraticterm(state, quadratic);
  alglib::minqpsetlinearterm(state, linear);
  alglib::minqpsetbc(state, lower_bound, upper_bound);
  alglib::minqpsetlc2dense(state, constraints, row_lower, row_upper);
  alglib::minqpsetscale(state, scale);
}

// The box-constrained LCP with symmetric M as the energy QP
//
//   minimise (1/2) z'M z + q'z  subject to  0 <= z <= u  (and a'z = b),
//
// whose KKT conditions are w = M z + q - a lambda >= 0 at z = 0, = 0
// between the bounds and <= 0 at z = u, with lambda the multiplier of the
// equality (the approach; Kalker's variational principle with a cap).
void set_up_box_qp(const LcpProblem& problem, alglib::minqpstate& state) {
  const Eigen::Index n = problem.size();
  alglib::real_2d_array quadratic;
  quadratic.setlength(n, n);
  alglib::real_1d_array linear;
  linear.setlength(n);
  alglib::real_1d_array lower_bound;
  lower_bound.setlength(n);
  alglib::real_1d_array upper_bound;
  upper_bound.setlength(n);
  alglib::real_1d_array scale;
  scale.setlength(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) quadratic[i][j] = 0.5 * (problem.matrix(i, j) + problem.matrix(j, i));
    linear[i] = problem.offset[i];
    lower_bound[i] = 0.0;
    upper_bound[i] = problem.upper_bound[i];
    scale[i] = 1.0;
  }
  alglib::minqpsetquadraticterm(state, quadratic);
  alglib::minqpsetlinearterm(state, linear);
  alglib::minqpsetbc(state, lower_bound, upper_bound);
  if (problem.has_equality()) {
    alglib::real_2d_array constraints;
    constraints.setlength(1, n);
    alglib::real_1d_array row_bound;
    row_bound.setlength(1);
    for (Eigen::Index j = 0; j < n; ++j) constraints[0][j] = problem.equality_row[j];
    row_bound[0] = problem.equality_value;
    alglib::minqpsetlc2dense(state, constraints, row_bound, row_bound);
  }
  alglib::minqpsetscale(state, scale);
}

// The equality's multiplier lambda of a box-QP solution z: w_i = 0 between
// the bounds gives lambda = v_i / a_i with v = M z + q; the mean over the
// cells clearly between them (an interior point approaches the bounds to
// its tolerance only). Without such cells, the middle of the interval the
// bounds allow: v_i / a_i >= lambda where z = 0, <= lambda where z = u.
double box_multiplier(const LcpProblem& problem, const Eigen::VectorXd& z) {
  if (!problem.has_equality()) return 0.0;
  const Eigen::VectorXd v = problem.matrix * z + problem.offset;
  constexpr double kInterior = 1e-6;  // relative distance from a bound of a cell between them
  double sum = 0.0;
  double count = 0.0;
  double below = -std::numeric_limits<double>::infinity();
  double above = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    const double a = problem.equality_row[i];
    if (a == 0.0) continue;
    const double u = problem.upper_bound[i];
    const double value = v[i] / a;
    if (z[i] > kInterior * u && u - z[i] > kInterior * u) {
      sum += value;
      count += 1.0;
    } else if (z[i] > 0.5 * u) {
      below = std::max(below, value);
    } else {
      above = std::min(above, value);
    }
  }
  if (count > 0.0) return sum / count;
  if (std::isfinite(below) && std::isfinite(above)) return 0.5 * (below + above);
  return std::isfinite(below) ? below : above;
}

}  // namespace

void LcpQuadOptions::validate() const {
  if (!(tolerance >= 0.0 && tolerance < 1.0)) {
    throw InputError(
        fmt::format("LCPquad tolerance = {} is invalid: allowed range is [0, 1) (0: ALGLIB's choice)", tolerance));
  }
}

LcpSolution solve_lcp_quad(const LcpProblem& problem, const LcpQuadOptions& options) {
  problem.validate();
  options.validate();
  const auto start = std::chrono::steady_clock::now();
  const Eigen::Index n = problem.size();
  LcpSolution solution;
  solution.z = Eigen::VectorXd::Zero(n);
  try {
    alglib::minqpstate state;
    const bool box = problem.has_upper_bound();
    alglib::minqpcreate(problem.has_equality() && !box ? n + 1 : n, state);
    if (box) {
      set_up_box_qp(problem, state);
    } else {
      set_up_qp(problem, state);
    }
    alglib::minqpsetalgodenseipm(state, options.tolerance);
    alglib::minqpoptimize(state);
    alglib::real_1d_array x;
    alglib::minqpreport report;
    alglib::minqpresults(state, x, report);

    for (Eigen::Index i = 0; i < n; ++i) solution.z[i] = x[i];
    if (box) {
      solution.multiplier = box_multiplier(problem, solution.z);
    } else {
      solution.multiplier = problem.has_equality() ? x[n] : 0.0;
    }
    solution.iterations = static_cast<int>(report.inneriterationscount);
    const alglib::ae_int_t code = report.terminationtype;
    if ((code >= 1 && code <= 4) || code == 7) {
      // 7: "stopping conditions too stringent, no further improvement": the
      // point is as good as the method gets; the caller measures it.
      solution.status = LcpStatus::solved;
    } else {
      solution.status = code == 5 ? LcpStatus::iteration_limit : LcpStatus::failure;
      solution.message = fmt::format(
          "LCPquad: ALGLIB minqp (dense IPM) stopped with completion code {} ({}) after "
          "{} iterations",
          static_cast<long>(code), completion_meaning(code), solution.iterations);
    }
  } catch (const alglib::ap_error& error) {
    // E.g. a failed Cholesky factorisation when M + M' is indefinite.
    solution.status = LcpStatus::failure;
    solution.message = fmt::format("LCPquad: ALGLIB minqp failed: {}", error.msg);
  }
  solution.w = lcp_slack(problem, solution.z, solution.multiplier);
  // z'w, or with a cap the complementarity left at both bounds.
  solution.objective = problem.has_upper_bound()
                           ? (solution.z.array() * solution.w.array().max(0.0)).sum() +
                                 ((problem.upper_bound - solution.z).array() * (-solution.w.array()).max(0.0)).sum()
                           : solution.z.dot(solution.w);
  solution.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return solution;
}

}  // namespace halfspace::solvers
