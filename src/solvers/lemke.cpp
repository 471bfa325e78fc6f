// Lemke's method through Siconos Numerics. Siconos's driver is called with
// its result filter off: it would turn a solution whose error exceeds its own
// absolute tolerance (1e-6) into a failure, whereas we measure the result
// ourselves, relative to the problem's scale.
//
// Ray termination is detected here, not taken from Siconos's return code:
// Siconos 4.4 (Debian 12) reports success when the ratio test finds no
// blocking row (fixed in later releases). On a ray the covering variable z0
// is still basic, so the w Siconos reads off its tableau exceeds M z + q by
// z0 in every row; at a true solution the two agree to rounding.
#include "halfspace/solvers/lemke.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <limits>
#include <memory>

#include "halfspace/error.hpp"

// Siconos Numerics (C API).
#include "LCP_Solvers.h"
#include "LinearComplementarityProblem.h"
#include "NonSmoothDrivers.h"
#include "NumericsMatrix.h"
#include "SolverOptions.h"
#include "lcp_cst.h"

namespace halfspace::solvers {
namespace {

// A returned point counts as a solution when it meets the LCP to this
// fraction of the problem's scale: far above the rounding of a pivoting
// sequence, far below any real violation.
constexpr double kAcceptance = 1e-9;

struct MatrixDeleter {
  void operator()(NumericsMatrix* m) const { NM_free(m); }
};
struct OptionsDeleter {
  void operator()(SolverOptions* o) const { solver_options_delete(o); }
};

// The plain LCP Siconos solves: the problem itself, or with an equality the
// (n + 2) LCP in (z, lambda+, lambda-) described in the header.
struct PlainLcp {
  Eigen::MatrixXd matrix;
  Eigen::VectorXd offset;
};

PlainLcp plain_lcp(const LcpProblem& problem) {
  if (!problem.has_equality()) return {problem.matrix, problem.offset};
  const Eigen::Index n = problem.size();
  const Eigen::VectorXd& a = problem.equality_row;
  PlainLcp plain{Eigen::MatrixXd::Zero(n + 2, n + 2), Eigen::VectorXd(n + 2)};
  plain.matrix.topLeftCorner(n, n) = problem.matrix;
  plain.matrix.col(n).head(n) = -a;
  plain.matrix.col(n + 1).head(n) = a;
  plain.matrix.row(n).head(n) = a.transpose();
  plain.matrix.row(n + 1).head(n) = -a.transpose();
  plain.offset.head(n) = problem.offset;
  plain.offset[n] = -problem.equality_value;
  plain.offset[n + 1] = problem.equality_value;
  return plain;
}

}  // namespace

void LemkeOptions::validate() const {
  if (max_pivots < 1) {
    throw InputError(fmt::format("max_pivots = {} is invalid: must be at least 1", max_pivots));
  }
}

LcpSolution solve_lcp_lemke(const LcpProblem& problem, const LemkeOptions& options) {
  problem.validate();
  options.validate();
  if (problem.has_upper_bound()) {
    throw InputError(
        "Lemke's method solves the plain LCP and takes no upper bound on z (a hardness cap): use LCPquad "
        "(solve_lcp_quad, solver 'lcpquad') for the box-constrained LCP");
  }
  const auto start = std::chrono::steady_clock::now();
  PlainLcp plain = plain_lcp(problem);
  const auto size = static_cast<int>(plain.offset.size());

  // Siconos stores dense matrices column-major, as Eigen does.
  std::unique_ptr<NumericsMatrix, MatrixDeleter> matrix(NM_create(NM_DENSE, size, size));
  std::memcpy(matrix->matrix0, plain.matrix.data(), sizeof(double) * static_cast<std::size_t>(size) * size);
  LinearComplementarityProblem lcp{size, matrix.get(), plain.offset.data()};
  std::unique_ptr<SolverOptions, OptionsDeleter> siconos(solver_options_create(SICONOS_LCP_LEMKE));
  // Siconos counts the pivots after the first (which brings in z0).
  const int loop_limit = options.max_pivots - 1;
  siconos->iparam[SICONOS_IPARAM_MAX_ITER] = loop_limit;
  siconos->iparam[SICONOS_IPARAM_ITER_DONE] = 0;  // the driver's shortcuts leave it unset
  siconos->filterOn = false;

  Eigen::VectorXd z = Eigen::VectorXd::Zero(size);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(size);
  const int info = linearComplementarity_driver(&lcp, z.data(), w.data(), siconos.get());
  const int loops = siconos->iparam[SICONOS_IPARAM_ITER_DONE];
  const bool trivial = plain.offset.minCoeff() >= 0.0 || size == 1;  // solved without pivoting

  // The scale of the problem's entries, for telling rounding from a real gap.
  const Eigen::VectorXd recomputed = plain.matrix * z + plain.offset;
  const double scale = std::max({plain.offset.cwiseAbs().maxCoeff(), (plain.matrix * z).cwiseAbs().maxCoeff(),
                                 std::numeric_limits<double>::min()});
  const double covering = trivial ? 0.0 : (w - recomputed).maxCoeff();
  const LcpViolation violation = lcp_violation({plain.matrix, plain.offset, {}, 0.0}, z, 0.0);
  const double worst = std::max({violation.negative_z, violation.negative_w, violation.complementarity});

  LcpSolution solution;
  const Eigen::Index n = problem.size();
  solution.z = z.head(n);
  solution.multiplier = problem.has_equality() ? z[n] - z[n + 1] : 0.0;
  solution.w = lcp_slack(problem, solution.z, solution.multiplier);
  solution.objective = solution.z.dot(solution.w);
  if (info == 1 && loops >= loop_limit) {
    solution.status = LcpStatus::iteration_limit;
    solution.iterations = loops + 1;
    solution.message = fmt::format("Lemke: no solution after {} pivots (the limit)", solution.iterations);
  } else if (info == 1 || covering > kAcceptance * scale) {
    // The last loop ended at the ray, without a pivot.
    solution.status = LcpStatus::ray_termination;
    solution.iterations = loops;
    solution.message = fmt::format(
        "Lemke: ray termination after {} pivots (covering variable z0 = {:.3g} still basic): the LCP has no "
        "solution, or its matrix is not copositive-plus",
        loops, covering);
  } else if (info != 0 || worst > kAcceptance * scale) {
    solution.status = LcpStatus::failure;
    solution.iterations = trivial ? 0 : loops + 1;
    solution.message =
        fmt::format("Lemke: Siconos returned code {} with a point that violates the LCP by {:.3g}", info, worst);
  } else {
    solution.status = LcpStatus::solved;
    solution.iterations = trivial ? 0 : loops + 1;
  }
  solution.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return solution;
}

}  // namespace halfspace::solvers
