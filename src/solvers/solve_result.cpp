// Names of solver outcomes, and when an iteration ends.
#include "halfspace/solvers/solve_result.hpp"

#include <fmt/format.h>

#include <cmath>

namespace halfspace::solvers {

std::string_view to_string(SolveStatus status) {
  switch (status) {
    case SolveStatus::converged:
      return "converged";
    case SolveStatus::iteration_limit:
      return "iteration_limit";
    case SolveStatus::breakdown:
      return "breakdown";
  }
  return "unknown";
}

std::optional<SolveStatus> stopping_status(double residual, double tolerance, int iteration, int max_iterations,
                                           std::string* message) {
  if (residual <= tolerance) return SolveStatus::converged;
  if (!std::isfinite(residual)) {
    *message = fmt::format("residual became non-finite at iteration {}", iteration);
    return SolveStatus::breakdown;
  }
  if (iteration == max_iterations) {
    *message = fmt::format("no convergence after {} iterations: residual {:.3e} > tolerance {:.3e}", iteration,
                           residual, tolerance);
    return SolveStatus::iteration_limit;
  }
  return std::nullopt;
}

}  // namespace halfspace::solvers
