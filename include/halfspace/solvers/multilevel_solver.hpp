// Polonsky-Keer started from coarse-grid solutions (nested iteration).
// Polonsky-Keer moves the edge of a contact spot by about a cell per
// iteration, so on a large domain, whose contact spots span many cells, the
// iterations grow with the domain. Solving the same contact on grids of 2, 4,
// 8, ... times the spacing first (gap averaged over blocks, same load) and
// starting each finer grid from the coarser pressure leaves the fine grid
// only the last cells of every edge. Each coarser level has a quarter of the
// cells (half in 1D), so all of them together cost about a third of the fine
// work per iteration.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <span>
#include <string_view>

#include "halfspace/grid.hpp"
#include "halfspace/solvers/contact_solver.hpp"
#include "halfspace/solvers/level_transfer.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::solvers {

class MultilevelSolver final : public ContactSolver {
 public:
  // Builds the solver of one level: its grid, its tolerance, and whether it
  // is the fine level (whose solver reports progress).
  using LevelSolverFactory =
      std::function<std::unique_ptr<ContactSolver>(const Grid& grid, double tolerance, bool fine)>;

  // The fine level's solver is built here, with `fine_tolerance`; coarse ones
  // only during solve(), each freed before the next finer level starts (they
  // are also built once here, so that their FFT planning happens now).
  // `transfer` says where the levels' fields live (null: whole, here); the
  // level solvers take and return fields as it holds them.
  MultilevelSolver(const Grid& grid, double fine_tolerance, LevelSolverFactory make_level,
                   MultilevelOptions options = {}, std::unique_ptr<LevelTransfer> transfer = nullptr);

  std::string_view name() const override { return "multilevel-polonsky-keer"; }

  // With an initial pressure (e.g. the previous step of a sweep) the coarse
  // levels are skipped: the warm start is already a good start, unless under
  // load control its force is off the target by more than
  // warm_start_max_load_ratio, in which case it is set aside.
 protected:
  SolveResult do_solve(std::span<const double> initial_gap, const Loading& loading,
                       std::span<const double> initial_pressure) override;

 private:
  // Whether a warm start is close enough to the load to beat the coarse grids.
  bool warm_start_is_close(std::span<const double> pressure, const Loading& loading) const;
  // Pressure on `grid` prolonged from the solution on the next coarser grid
  // (itself started from the one below), or empty if there is no coarser
  // grid. Adds the coarse work to `record`.
  Eigen::ArrayXd coarse_start(const Grid& grid, std::span<const double> gap, const Loading& loading,
                              CoarseStart& record);
  // The coarse solves' tolerance: options_.coarse_tolerance, but never
  // tighter than the fine one.
  double coarse_tolerance() const;

  Grid grid_;
  double fine_tolerance_;
  LevelSolverFactory make_level_;
  MultilevelOptions options_;
  std::unique_ptr<LevelTransfer> transfer_;
  std::unique_ptr<ContactSolver> fine_;
};

}  // namespace halfspace::solvers
