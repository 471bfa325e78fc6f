// Names of solver outcomes.
#include "halfspace/solvers/solve_result.hpp"

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

}  // namespace halfspace::solvers
