// The friction of `halfspace solve`: the problem builder (halfspace/problem.hpp)
// holds friction's rules and names the flags; the program adds the one rule
// of its own output (stress depths need a single tangential step).
#pragma once

#include <optional>

#include "halfspace/problem.hpp"
#include "halfspace/solvers/friction_options.hpp"
#include "solve_options.hpp"

namespace halfspace::app {

// The problem's friction, or none without --friction. Throws InputError when
// --stress-depths is combined with a history of several steps (the stresses
// are of one step: `halfspace stress` on a step's result).
std::optional<solvers::FrictionOptions> friction_from(const SolveOptions& options, const Problem& problem);

}  // namespace halfspace::app
