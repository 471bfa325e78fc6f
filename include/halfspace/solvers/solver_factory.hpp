// Chooses a contact solver by name and builds it with the operator it needs,
// so front ends (the CLI, sweeps) handle every solver the same way.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/solvers/contact_solver.hpp"

namespace halfspace::solvers {

inline constexpr std::size_t kDefaultDeflationBlock = 32;

struct SolverSettings {
  std::string name =
      "pk-multilevel";       // one of solver_names(); the default was chosen by measurement (docs/performance.md)
  double tolerance = 1e-10;  // the solver's own relative stopping tolerance
  int max_iterations = 10000;
  FftPlanning fft_planning = FftPlanning::estimate;  // FFT-based solvers only
  // Block size of the coarse-grid correction (BlockDeflation) of pk-fourier
  // and of pk-multilevel's finest grid: B (refused where it does not apply),
  // 0 for none, or unset: kDefaultDeflationBlock for pk-multilevel on
  // periodic 2D grids it divides into at least 3 blocks per axis (chosen by
  // measurement, docs/performance.md), none otherwise.
  std::optional<std::size_t> deflation_block;
  std::function<void(int, double)> progress;  // (iteration, residual), may be empty
};

// The names make_solver accepts, in the order --help lists them.
std::vector<std::string> solver_names();

// A solver for contacts on `grid` with composite modulus e_star (Pa), owning
// its influence operator. Uses the threads in force (set_threads) for FFT
// plans. Throws InputError naming the solver if the name is unknown or the
// settings are invalid for it.
std::unique_ptr<ContactSolver> make_solver(const Grid& grid, double e_star, const SolverSettings& settings);

}  // namespace halfspace::solvers
