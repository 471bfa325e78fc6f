// `halfspace solve --friction`: the normal solve, the tangential steps under
// its pressure, and the result file (a single step) or the history file and
// its CSV (several steps), docs/usage.md#friction.
#pragma once

#include "solve_place.hpp"
#include "solve_setup.hpp"

namespace halfspace::app {

// Runs the frictional solve of `setup` (setup.friction and setup.pair set)
// at `place` and returns the exit code: kExitOk, kExitNotConverged (the
// result is still written, with the steps solved) or kExitPlotFailed.
int run_frictional_solve(const SolveSetup& setup, const SolvePlace& place);

}  // namespace halfspace::app
