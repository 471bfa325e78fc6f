#include "halfspace/solvers/surface_solve.hpp"

#include <fmt/format.h>

#include <Eigen/Core>
#include <chrono>
#include <memory>

#include "halfspace/error.hpp"
#include "halfspace/solvers/solver_factory.hpp"

namespace halfspace::solvers {
namespace {

// The solve with the solver `make` builds, freed before returning.
template <typename MakeSolver>
SolveResult solve_with(const Grid& grid, std::span<const double> heights, MakeSolver make, const Loading& loading,
                       std::span<const double> initial_pressure) {
  const Eigen::ArrayXd gap = initial_gap(grid, heights);
  const std::unique_ptr<ContactSolver> solver = make();
  const auto start = std::chrono::steady_clock::now();
  SolveResult result = solver->solve(std::span<const double>(gap.data(), static_cast<std::size_t>(gap.size())), loading,
                                     initial_pressure);
  if (result.wall_seconds <= 0.0) {
    result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return result;
}

}  // namespace

Eigen::ArrayXd initial_gap(const Grid& grid, std::span<const double> heights) {
  if (heights.size() != grid.size()) {
    throw InputError(fmt::format("the surface has {} heights but the grid has {} cells ({})", heights.size(),
                                 grid.size(), grid.shape_string()));
  }
  const Eigen::Map<const Eigen::ArrayXd> h(heights.data(), static_cast<Eigen::Index>(heights.size()));
  return h.maxCoeff() - h;
}

SolveResult solve_surface(const Grid& grid, std::span<const double> heights, double e_star, const Loading& loading,
                          const SolverOptions& options, std::span<const double> initial_pressure) {
  return solve_with(
      grid, heights, [&] { return make_solver(grid, e_star, options); }, loading, initial_pressure);
}

SolveResult solve_surface(const Grid& grid, std::span<const double> heights, const LayeredMaterial& coating,
                          const Loading& loading, const SolverOptions& options,
                          std::span<const double> initial_pressure) {
  return solve_with(
      grid, heights, [&] { return make_solver(grid, coating, options); }, loading, initial_pressure);
}

}  // namespace halfspace::solvers
