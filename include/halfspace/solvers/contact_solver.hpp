// Interface of every normal-contact solver (Polonsky-Keer on the FFT operator,
// and the dense Lemke and QP solvers), so front ends can choose one by name.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string_view>

#include "halfspace/grid.hpp"
#include "halfspace/solvers/interface_law.hpp"
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
  // Throws InputError for invalid loading or sizes, and for a load the
  // interface law cannot carry (InterfaceLaw::check_load, checked here once
  // for every solver); returns non-convergence as a status.
  SolveResult solve(std::span<const double> initial_gap, const Loading& loading,
                    std::span<const double> initial_pressure = {}) {
    check_load(loading);
    return do_solve(initial_gap, loading, initial_pressure);
  }

  // solve() warm-started from `start`, which the solver may take over as the
  // storage of its result's pressure, so that a start made only for this
  // solve (a coarse-grid solution) holds no memory of its own meanwhile.
  SolveResult solve_from(std::span<const double> initial_gap, const Loading& loading, Eigen::ArrayXd&& start) {
    check_load(loading);
    return do_solve_from(initial_gap, loading, std::move(start));
  }

 protected:
  // A solver that delegates to another (which checks the load).
  ContactSolver() = default;
  // A solver of the problem on `grid` under `law`, the one object every
  // solver takes unchanged and checks here once: its values when the solver
  // is made (InterfaceLaw::validate), each load when solve() is called.
  ContactSolver(const Grid& grid, const InterfaceLaw& law) : grid_(grid), law_((law.validate(), law)) {}

  const InterfaceLaw& interface_law() const { return law_; }

  virtual SolveResult do_solve(std::span<const double> initial_gap, const Loading& loading,
                               std::span<const double> initial_pressure) = 0;
  // The default copies `start`.
  virtual SolveResult do_solve_from(std::span<const double> initial_gap, const Loading& loading,
                                    Eigen::ArrayXd&& start) {
    return do_solve(initial_gap, loading, {start.data(), static_cast<std::size_t>(start.size())});
  }

 private:
  void check_load(const Loading& loading) const {
    if (grid_) law_.check_load(*grid_, loading);
  }

  std::optional<Grid> grid_;  // unset in solvers that delegate
  InterfaceLaw law_;
};

}  // namespace halfspace::solvers

// The library, its writers and front ends name these without the folder's
// namespace.
namespace halfspace {
using solvers::ContactSolver;
}  // namespace halfspace
