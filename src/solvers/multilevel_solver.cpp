#include "halfspace/solvers/multilevel_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <utility>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/solvers/grid_transfer.hpp"

namespace halfspace::solvers {
namespace {

// A level's solve from the prolonged start, which becomes the level's
// pressure array (no second copy during the solve), or cold without one.
SolveResult solve_level(ContactSolver& level, std::span<const double> gap, const Loading& loading,
                        Eigen::ArrayXd start) {
  if (start.size() == 0) return level.solve(gap, loading);
  return level.solve_from(gap, loading, std::move(start));
}

}  // namespace

bool MultilevelSolver::warm_start_is_close(std::span<const double> pressure, const Loading& loading) const {
  if (!loading.load_controlled()) return true;
  const double target = loading.target_force(grid_.domain_area());
  const double force = grid_.cell_area() * linalg::sum(transfer_->communicator(grid_), pressure.size(),
                                                       [&](std::size_t i) { return std::max(pressure[i], 0.0); });
  if (!(force > 0.0)) return false;
  const double ratio = target > force ? target / force : force / target;
  return ratio <= options_.warm_start_max_load_ratio;
}

MultilevelSolver::MultilevelSolver(const Grid& grid, double fine_tolerance, LevelSolverFactory make_level,
                                   MultilevelOptions options, std::unique_ptr<LevelTransfer> transfer)
    : grid_(grid),
      fine_tolerance_(fine_tolerance),
      make_level_(std::move(make_level)),
      options_(options),
      transfer_(transfer ? std::move(transfer) : std::make_unique<LevelTransfer>()) {
  options_.validate();
  fine_ = make_level_(grid_, fine_tolerance_, true);
  // Build each coarse level once and drop it: its FFT plans (measured ones
  // stay in FFTW's wisdom) are then made here rather than inside the timed
  // solve, and the levels take no memory between solves.
  for (std::optional<Grid> level = coarser_grid(grid_, options_.min_cells_per_axis); level;
       level = coarser_grid(*level, options_.min_cells_per_axis)) {
    make_level_(*level, coarse_tolerance(), false);
  }
}

double MultilevelSolver::coarse_tolerance() const {
  return std::max(options_.coarse_tolerance, fine_tolerance_);
}

Eigen::ArrayXd MultilevelSolver::coarse_start(const Grid& grid, std::span<const double> gap, const Loading& loading,
                                              CoarseStart& record) {
  const std::optional<Grid> coarse = coarser_grid(grid, options_.min_cells_per_axis);
  if (!coarse) return {};
  const std::size_t coarse_size = transfer_->local_size(*coarse);
  Eigen::ArrayXd coarse_gap(static_cast<Eigen::Index>(coarse_size));
  transfer_->restrict_to_coarse(grid, gap, {coarse_gap.data(), coarse_size});
  Eigen::ArrayXd start = coarse_start(*coarse, {coarse_gap.data(), coarse_size}, loading, record);

  // The same load on the same domain: force, mean pressure and approach all
  // carry over unchanged.
  SolveResult coarse_result;
  try {
    coarse_result = solve_level(*make_level_(*coarse, coarse_tolerance(), false), {coarse_gap.data(), coarse_size},
                                loading, std::move(start));
  } catch (const InputError&) {
    // The input was checked on the fine grid; a coarse grid can only differ
    // by rounding (e.g. an approach a hair below the mean gap, which the
    // averaged gap no longer exceeds). Go without a start; the fine solve
    // reports a real problem itself.
    return {};
  }
  const double weight = static_cast<double>(coarse->size()) / static_cast<double>(grid_.size());
  ++record.levels;
  record.iterations += coarse_result.iterations;
  record.operator_work += weight * coarse_result.operator_applications;
  record.preconditioner_work += weight * coarse_result.preconditioner_applications;
  // Only a start: a coarse solve short of its tolerance still helps, one
  // that broke down does not (a distributed level agrees on it).
  if (transfer_->communicator(*coarse).max(coarse_result.pressure.allFinite() ? 0.0 : 1.0) > 0.0) return {};
  const std::size_t fine_size = transfer_->local_size(grid);
  Eigen::ArrayXd fine_start(static_cast<Eigen::Index>(fine_size));
  transfer_->prolong_to_fine(grid, {coarse_result.pressure.data(), coarse_size}, {fine_start.data(), fine_size});
  return fine_start;
}

SolveResult MultilevelSolver::do_solve(std::span<const double> initial_gap, const Loading& loading,
                                       std::span<const double> initial_pressure) {
  const auto start_time = std::chrono::steady_clock::now();
  // Given if given on any process (one without cells of a distributed grid
  // holds none), so that the processes decide alike.
  const std::size_t local_size = transfer_->local_size(grid_);
  bool warm = transfer_->communicator(grid_).max(initial_pressure.empty() ? 0.0 : 1.0) > 0.0;
  if (warm && initial_pressure.size() == local_size && !warm_start_is_close(initial_pressure, loading)) warm = false;
  if (warm) {
    SolveResult result = fine_->solve(initial_gap, loading, initial_pressure);
    result.solver = std::string(name());
    return result;
  }
  check_field_size("initial gap", initial_gap.size(), grid_, local_size);
  loading.validate();
  CoarseStart coarse;
  SolveResult result = solve_level(*fine_, initial_gap, loading, coarse_start(grid_, initial_gap, loading, coarse));
  result.solver = std::string(name());
  result.coarse = coarse;
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return result;
}

}  // namespace halfspace::solvers
