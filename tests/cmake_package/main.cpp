// A consumer of the installed halfspace package: a rigid sphere on an elastic
// half-space (free 2D grid, force control) solved by Polonsky-Keer, checked
// against Hertz (Johnson 1985, Contact Mechanics, sec. 4.2). Exits 1 when a
// quantity is off by more than the tolerance, so the package test fails.
#include <cmath>
#include <cstdio>
#include <exception>
#include <numbers>
#include <string_view>

#include "halfspace/halfspace.hpp"

namespace {

constexpr double kEStar = 1.1e11;       // Pa, steel on steel
constexpr double kSphereRadius = 0.01;  // m
constexpr double kForce = 10.0;         // N
constexpr std::size_t kCells = 64;      // per side; the contact radius is ~21 cells
// Discretisation error of a ~21-cell contact radius: the bound the validation
// tests (tests/solvers/polonsky_keer_hertz_test.cpp) use at this resolution.
constexpr double kRelativeTolerance = 0.01;
// Load control keeps the total force to rounding.
constexpr double kForceTolerance = 1e-10;

bool within(const char* what, double value, double expected, double tolerance) {
  const double error = std::abs(value - expected) / std::abs(expected);
  std::printf("%-14s %.6e  Hertz %.6e  relative error %.2e (allowed %.0e)\n", what, value, expected, error, tolerance);
  return error <= tolerance;
}

}  // namespace

int main() {
  try {
    // Hertz point contact: radius a, peak pressure p0, approach delta.
    const double a = std::cbrt(3.0 * kForce * kSphereRadius / (4.0 * kEStar));
    const double p0 = 3.0 * kForce / (2.0 * std::numbers::pi * a * a);
    const double delta = a * a / kSphereRadius;

    const double side = 3.0 * a;
    const double dx = side / static_cast<double>(kCells);
    const halfspace::Grid grid = halfspace::Grid::plane(kCells, kCells, dx, dx, halfspace::Boundary::free);
    // The sphere's heights (peaks positive): the solve starts from max(h) - h.
    Eigen::ArrayXd heights(static_cast<Eigen::Index>(grid.size()));
    for (std::size_t j = 0; j < kCells; ++j) {
      for (std::size_t i = 0; i < kCells; ++i) {
        const double x = (static_cast<double>(i) + 0.5) * dx - 0.5 * side;
        const double y = (static_cast<double>(j) + 0.5) * dx - 0.5 * side;
        heights[static_cast<Eigen::Index>(j * kCells + i)] = -(x * x + y * y) / (2.0 * kSphereRadius);
      }
    }

    halfspace::solvers::SolverOptions options;
    options.type = halfspace::solvers::SolverType::pk;
    const halfspace::SolveResult result = halfspace::solvers::solve_surface(grid, {heights.data(), grid.size()}, kEStar,
                                                                            halfspace::Loading::force(kForce), options);
    const std::string_view status = halfspace::to_string(result.status);
    std::printf("%s: %.*s after %d iterations\n", result.solver.c_str(), static_cast<int>(status.size()), status.data(),
                result.iterations);
    if (!result.converged()) {
      std::printf("not converged: %s\n", result.message.c_str());
      return 1;
    }

    const double contact_area = static_cast<double>((result.pressure > 0.0).count()) * grid.cell_area();
    const double radius = std::sqrt(contact_area / std::numbers::pi);
    bool ok = within("total force", result.total_force, kForce, kForceTolerance);
    ok = within("peak pressure", result.max_pressure, p0, kRelativeTolerance) && ok;
    ok = within("approach", result.approach, delta, kRelativeTolerance) && ok;
    // The contact radius is known to within a cell.
    ok = within("contact radius", radius, a, dx / a) && ok;
    std::printf("%s\n", ok ? "agrees with Hertz" : "DISAGREES with Hertz");
    return ok ? 0 : 1;
  } catch (const std::exception& error) {
    std::printf("error: %s\n", error.what());
    return 1;
  }
}
