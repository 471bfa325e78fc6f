// `halfspace solve --friction`: the normal solve, the tangential steps under
// its pressure, and the result file (a single step) or the history file and
// its CSV (several steps), docs/usage.md#friction.
#pragma once

#include <functional>
#include <span>

#include "halfspace/analysis/contact_statistics.hpp"
#include "halfspace/io/result_metadata.hpp"
#include "halfspace/solvers/layout.hpp"
#include "halfspace/solvers/solve_result.hpp"
#include "halfspace/solvers/tangential_loading.hpp"
#include "halfspace/solvers/tangential_result.hpp"
#include "solve_setup.hpp"

namespace halfspace::app {

// Where a frictional solve runs and how its statistics and files are made:
// the whole grid on this process (run_frictional_solve(setup)), or this
// process's slab of rows (apps/mpi), every hook then collective.
struct FrictionPlace {
  const solvers::Layout& layout;
  std::span<const double> heights;               // the cells `layout` holds here
  bool first = true;                             // the first (or only) process: it prints and plots
  std::function<io::ResultMetadata()> metadata;  // provenance and surface statistics
  std::function<analysis::ContactStatistics(const SolveResult& normal)> contact_statistics;
  std::function<void(const SolveResult& normal, const io::ResultMetadata& metadata)> write_result;
  std::function<void(const SolveResult& normal, std::span<const TangentialResult> steps,
                     std::span<const TangentialLoading> loads, const io::ResultMetadata& metadata)>
      write_history;
  // Runs a step everywhere, every process learning of a failure on any;
  // the first process's value on every process (one process: the step, the
  // value).
  std::function<void(const std::function<void()>& step)> agree = [](const std::function<void()>& step) { step(); };
  std::function<int(int value)> first_value = [](int value) { return value; };
};

// Runs the frictional solve of `setup` (setup.friction and setup.pair set)
// and returns the exit code: kExitOk, kExitNotConverged (the result is
// still written, with the steps solved) or kExitPlotFailed.
int run_frictional_solve(const SolveSetup& setup);
// The same at `place`.
int run_frictional_solve(const SolveSetup& setup, const FrictionPlace& place);

}  // namespace halfspace::app
