#include "halfspace/solvers/surface_solve.hpp"

#include <fmt/format.h>

#include <Eigen/Core>
#include <chrono>
#include <limits>
#include <memory>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/solvers/solver_factory.hpp"

namespace halfspace::solvers {
namespace {

void check_heights(const Grid& grid, std::size_t heights, const Layout& layout) {
  const std::size_t cells = layout.rows(grid).count * grid.nx();
  if (heights != cells) {
    throw InputError(
        fmt::format("the surface has {} heights but the grid has {} cells ({})", heights, cells, grid.shape_string()));
  }
}

// max(h) over every process.
double highest(std::span<const double> heights, const Layout& layout) {
  const Eigen::Map<const Eigen::ArrayXd> h(heights.data(), static_cast<Eigen::Index>(heights.size()));
  return layout.communicator().max(h.size() > 0 ? h.maxCoeff() : -std::numeric_limits<double>::infinity());
}

// h = -h, exactly.
void negate(std::span<double> heights) {
  linalg::for_each_index(heights.size(), [&](std::size_t i) { heights[i] = -heights[i]; });
}

// The solve on `gap`, the initial gap less `offset` (m): the approach the
// solver finds is `offset` short of the one measured from the highest point.
SolveResult solve_gap(const Grid& grid, std::span<const double> gap, double offset, const HalfSpace& half_space,
                      const Loading& loading, const SolverOptions& options, std::span<const double> initial_pressure,
                      const Layout& layout) {
  // The solver and its operator are freed before returning.
  const std::unique_ptr<ContactSolver> solver = make_solver(grid, half_space, options, layout);
  const auto start = std::chrono::steady_clock::now();
  SolveResult result = solver->solve(gap, loading, initial_pressure);
  if (result.wall_seconds <= 0.0) {
    result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  result.approach += offset;
  return result;
}

}  // namespace

Eigen::ArrayXd initial_gap(const Grid& grid, std::span<const double> heights, const Layout& layout) {
  check_heights(grid, heights.size(), layout);
  const Eigen::Map<const Eigen::ArrayXd> h(heights.data(), static_cast<Eigen::Index>(heights.size()));
  return highest(heights, layout) - h;
}

bool initial_gap_in_heights(const Loading& loading, const SolverOptions& options) {
  const bool polonsky_keer = options.type == SolverType::pk || options.type == SolverType::pk_fourier ||
                             options.type == SolverType::pk_multilevel;
  return polonsky_keer && !options.adhesion && loading.load_controlled();
}

SolveResult solve_surface(const Grid& grid, std::span<const double> heights, const HalfSpace& half_space,
                          const Loading& loading, const SolverOptions& options,
                          std::span<const double> initial_pressure, const Layout& layout) {
  if (initial_gap_in_heights(loading, options)) {
    // The same solve as the borrowing one's, on a copy.
    check_heights(grid, heights.size(), layout);
    Eigen::ArrayXd copy = Eigen::Map<const Eigen::ArrayXd>(heights.data(), static_cast<Eigen::Index>(heights.size()));
    return solve_surface_in_place(grid, {copy.data(), heights.size()}, half_space, loading, options, initial_pressure,
                                  layout);
  }
  const Eigen::ArrayXd gap = initial_gap(grid, heights, layout);
  return solve_gap(grid, {gap.data(), static_cast<std::size_t>(gap.size())}, 0.0, half_space, loading, options,
                   initial_pressure, layout);
}

SolveResult solve_surface_in_place(const Grid& grid, std::span<double> heights, const HalfSpace& half_space,
                                   const Loading& loading, const SolverOptions& options,
                                   std::span<const double> initial_pressure, const Layout& layout) {
  if (!initial_gap_in_heights(loading, options)) {
    return solve_surface(grid, std::span<const double>(heights), half_space, loading, options, initial_pressure,
                         layout);
  }
  check_heights(grid, heights.size(), layout);
  const double top = highest(heights, layout);
  // -h = (max(h) - h) - max(h): the initial gap less the constant max(h).
  negate(heights);
  struct GiveBack {
    std::span<double> heights;
    ~GiveBack() { negate(heights); }
  } give_back{heights};
  return solve_gap(grid, heights, top, half_space, loading, options, initial_pressure, layout);
}

}  // namespace halfspace::solvers
