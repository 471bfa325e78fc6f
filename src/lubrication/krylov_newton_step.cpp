// A Newton step's GMRES solve (krylov_newton_step.hpp).
#include "krylov_newton_step.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace halfspace::lubrication::detail {

void KrylovNewtonStep::resize(Eigen::Index size, int restart) {
  gmres_.resize(size, restart);
  work_.resize(size);
}

KrylovOutcome KrylovNewtonStep::solve(const RestartedGmres::Apply& jacobian, const RestartedGmres::Apply& precondition,
                                      const std::function<bool(std::string&)>& factorise,
                                      const Eigen::VectorXd& residual, int max_iterations, const Rule& rule,
                                      Eigen::VectorXd& step) {
  KrylovOutcome outcome;
  const double b_norm = residual.norm();
  if (b_norm == 0.0) {
    step.setZero(residual.size());
    outcome.converged = true;
    return outcome;
  }
  const LaggedPreconditioner::Run run = lagged_.solve(
      rule.refactorise, max_iterations, [&] { return factorise(outcome.message); },
      [&](int iterations_allowed, bool retry) {
        const bool warm = rule.warm || (retry && rule.retry_warm);
        const int iterations =
            gmres_.solve(jacobian, precondition, residual, rule.tolerance, iterations_allowed, step, warm);
        return std::pair{iterations, step.allFinite()};
      });
  outcome.iterations = run.iterations;
  if (!run.factorised) {
    outcome.relative_residual = std::numeric_limits<double>::infinity();  // no step at all
    return outcome;
  }
  // The residual measured with the operator, not GMRES's estimate.
  jacobian(step, work_);
  work_ += residual;
  outcome.relative_residual = work_.norm() / b_norm;
  outcome.converged = step.allFinite() && outcome.relative_residual <= rule.allowance * rule.tolerance;
  if (!outcome.converged) {
    outcome.message =
        fmt::format(fmt::runtime(rule.failure), outcome.relative_residual, outcome.iterations, rule.tolerance);
  }
  return outcome;
}

}  // namespace halfspace::lubrication::detail
