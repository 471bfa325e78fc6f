// Names of the film solvers' outcomes.
#include "halfspace/lubrication/film_solution.hpp"

namespace halfspace::lubrication {

std::string_view to_string(FilmStatus status) {
  switch (status) {
    case FilmStatus::converged:
      return "converged";
    case FilmStatus::iteration_limit:
      return "iteration limit";
    case FilmStatus::failure:
      return "failure";
  }
  return "unknown";
}

}  // namespace halfspace::lubrication
