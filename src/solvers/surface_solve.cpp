#include "halfspace/solvers/surface_solve.hpp"

#include <fmt/format.h>

#include <Eigen/Core>
#include <chrono>
#include <limits>
#include <memory>

#include "halfspace/error.hpp"
#include "halfspace/solvers/solver_factory.hpp"

namespace halfspace::solvers {

Eigen::ArrayXd initial_gap(const Grid& grid, std::span<const double> heights, const Layout& layout) {
  const std::size_t cells = layout.rows(grid).count * grid.nx();
  if (heights.size() != cells) {
    throw InputError(fmt::format("the surface has {} heights but the grid has {} cells ({})", heights.size(), cells,
                                 grid.shape_string()));
  }
  const Eigen::Map<const Eigen::ArrayXd> h(heights.data(), static_cast<Eigen::Index>(heights.size()));
  return layout.communicator().max(h.size() > 0 ? h.maxCoeff() : -std::numeric_limits<double>::infinity()) - h;
}

SolveResult solve_surface(const Grid& grid, std::span<const double> heights, const HalfSpace& half_space,
                          const Loading& loading, const SolverOptions& options,
                          std::span<const double> initial_pressure, const Layout& layout) {
  const Eigen::ArrayXd gap = initial_gap(grid, heights, layout);
  // The solver and its operator are freed before returning.
  const std::unique_ptr<ContactSolver> solver = make_solver(grid, half_space, options, layout);
  const auto start = std::chrono::steady_clock::now();
  SolveResult result = solver->solve(std::span<const double>(gap.data(), static_cast<std::size_t>(gap.size())), loading,
                                     initial_pressure);
  if (result.wall_seconds <= 0.0) {
    result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return result;
}

}  // namespace halfspace::solvers
