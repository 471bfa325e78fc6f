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
// The default correction starts at this many cells (2048^2): below, its
// costs (two more products per iteration, the kernel product, building A,
// the coarse solves) outweigh the iterations it saves (256^2-512^2: 15-55 %
// more time, 1024^2: 2 % less to 23 % more; 2048^2 up: 15-38 % less,
// docs/development-log.md).
inline constexpr std::size_t kDefaultDeflationFromCells = std::size_t{1} << 22;

struct SolverSettings {
  std::string name =
      "pk-multilevel";       // one of solver_names(); the default was chosen by measurement (docs/performance.md)
  double tolerance = 1e-10;  // the solver's own relative stopping tolerance
  int max_iterations = 10000;
  FftPlanning fft_planning = FftPlanning::estimate;  // FFT-based solvers only
  // Block size of the coarse-grid correction (BlockDeflation) of pk-fourier
  // and of pk-multilevel's finest grid: B (refused where it does not apply),
  // 0 for none, or unset: default_deflation() for pk-multilevel, none
  // otherwise.
  std::optional<std::size_t> deflation_block;
  std::function<void(int, double)> progress;  // (iteration, residual), may be empty
};

// Whether pk-multilevel's finest grid gets the coarse correction when the
// block is not set: 2D grids, periodic or free, of at least
// kDefaultDeflationFromCells cells that kDefaultDeflationBlock divides into
// at least 3 blocks per axis (chosen by measurement, docs/development-log.md).
bool default_deflation(const Grid& grid);

// The names make_solver accepts, in the order --help lists them.
std::vector<std::string> solver_names();

// A solver for contacts on `grid` with composite modulus e_star (Pa), owning
// its influence operator. Uses the threads in force (set_threads) for FFT
// plans. Throws InputError naming the solver if the name is unknown or the
// settings are invalid for it.
std::unique_ptr<ContactSolver> make_solver(const Grid& grid, double e_star, const SolverSettings& settings);

}  // namespace halfspace::solvers
