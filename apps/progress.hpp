// The progress line of long solves and sweeps on stderr: step, iteration,
// residual, elapsed and estimated remaining time, redrawn in place.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

#include "halfspace/solvers/solve_result.hpp"

namespace halfspace::app {

class Progress {
 public:
  // Shows anything only if `enabled` (not --quiet) and stderr is a terminal,
  // so logs and pipes stay clean. `steps` is 1 for a single solve;
  // `tolerance` is the solver's, used to estimate how far a step has come.
  Progress(bool enabled, std::size_t steps, double tolerance);
  ~Progress();  // clears the line
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  bool active() const { return active_; }

  // A step begins; `load` describes it, e.g. "mean pressure 2e+05 Pa".
  void start_step(std::size_t step, std::string load);
  // One solver iteration (the SolverOptions::progress callback). Redraws at
  // most every kInterval, and not before kInterval has passed, so quick
  // solves print nothing.
  void iteration(int iteration, double residual);
  // Removes the line (before the summary is printed).
  void clear();

  // A callback for SolverOptions::progress that feeds iteration() and never
  // stops the solve; empty when inactive, so the solver does not even call it.
  solvers::ProgressCallback callback();

 private:
  using Clock = std::chrono::steady_clock;
  void draw(int iteration, double residual);

  bool active_ = false;
  std::size_t steps_ = 1;
  double tolerance_ = 1e-10;
  std::size_t step_ = 0;
  std::string load_;
  double first_residual_ = 0.0;  // of the current step
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_draw_ = Clock::now();
  double interval_ = 0.5;  // s
  bool drawn_ = false;
};

// "4.2 s", "3m07s", "2h05m".
std::string format_duration(double seconds);

}  // namespace halfspace::app
