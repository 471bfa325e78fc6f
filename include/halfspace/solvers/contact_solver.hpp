// Interface of every normal-contact solver (Polonsky-Keer on the FFT operator,
// and the dense Lemke and QP solvers), so front ends can choose one by name.
#pragma once

#include <Eigen/Core>
#include <span>
#include <string_view>

#include "halfspace/solvers/loading.hpp"
#include "halfspace/solvers/solve_result.hpp"

namespace halfspace::solvers {

class ContactSolver {
 public:
  virtual ~ContactSolver() = default;

  virtual std::string_view name() const = 0;

  // Solves the contact problem
  //   gap = initial_gap + K p - approach,  p >= 0,  gap >= 0,  p * gap = 0,
  // under `loading`. `initial_gap` (m, one entry per cell) is the separation
  // of the undeformed surfaces at zero approach; its minimum is normally 0.
  // `initial_pressure` (Pa), if not empty, warm-starts the iteration.
  // Throws InputError for invalid loading or sizes; returns non-convergence
  // as a status.
  virtual SolveResult solve(std::span<const double> initial_gap, const Loading& loading,
                            std::span<const double> initial_pressure = {}) = 0;

  // solve() warm-started from `start`, which the solver may take over as the
  // storage of its result's pressure, so that a start made only for this
  // solve (a coarse-grid solution) holds no memory of its own meanwhile. The
  // default copies it.
  virtual SolveResult solve_from(std::span<const double> initial_gap, const Loading& loading, Eigen::ArrayXd&& start) {
    return solve(initial_gap, loading, {start.data(), static_cast<std::size_t>(start.size())});
  }
};

}  // namespace halfspace::solvers

// The library, its writers and front ends name these without the folder's
// namespace.
namespace halfspace {
using solvers::ContactSolver;
}  // namespace halfspace
