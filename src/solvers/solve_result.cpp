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
    case SolveStatus::stopped:
      return "stopped";
  }
  return "unknown";
}

std::optional<SolveStatus> parse_solve_status(std::string_view name) {
  for (const SolveStatus status :
       {SolveStatus::converged, SolveStatus::iteration_limit, SolveStatus::breakdown, SolveStatus::stopped}) {
    if (to_string(status) == name) return status;
  }
  return std::nullopt;
}

bool stop_requested(const ProgressCallback& progress, int iteration, double residual) {
  return progress && progress(iteration, residual) == IterationDecision::stop;
}

std::optional<SolveStatus> stopping_status(double residual, double tolerance, int iteration, int max_iterations,
                                           std::string* message, bool stop) {
  if (stop) {
    *message = fmt::format("stopped by the caller at iteration {} (residual {:.3e})", iteration, residual);
    return SolveStatus::stopped;
  }
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
