// The program's own rule on friction (friction_setup.hpp).
#include "friction_setup.hpp"

#include <fmt/format.h>

#include "halfspace/error.hpp"

namespace halfspace::app {

std::optional<solvers::FrictionOptions> friction_from(const SolveOptions& o, const Problem& problem) {
  if (o.stress_depths && problem.friction && problem.friction->steps() > 1) {
    throw InputError(
        fmt::format("{} applies to a single tangential step, not a history of {}: run `halfspace "
                    "stress` on a result of one step",
                    o.describe("stress-depths"), problem.friction->steps()));
  }
  return problem.friction;
}

}  // namespace halfspace::app
