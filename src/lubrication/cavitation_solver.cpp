// Projected SOR on the p–theta complementarity problem. With its neighbours
// held, a node's balance is A p + B h theta = R, and the node's own
// complementarity problem has the closed-form solution of Elrod–Adams'
// switch (Ausas, Jai & Buscaglia 2009, J. Tribol. 131, 031702; Giacopini et
// al. 2010): if R >= B h the node is full (theta = 1, p = (R - B h) / A),
// otherwise cavitated (p = 0, theta = R / (B h) in [0, 1), since R >= 0).
// Over-relaxation acts on the pressure of full nodes and is projected onto
// p >= 0. Sweeping along the entrainment makes the cavitated zone's
// transport exact in one sweep. The transient term c h theta - s joins the
// Couette diagonal (B + c) and the right-hand side (+ s) of the same switch. Convergence is measured apart from the
// sweeps, as the mass balance of every node after a sweep.
#include "halfspace/lubrication/cavitation_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "halfspace/error.hpp"

namespace halfspace::lubrication {

void CavitationSolverOptions::validate() const {
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw OptionError("tolerance", format_number(tolerance), "is invalid: allowed range is 0 < tolerance < 1");
  }
  if (max_iterations < 1) {
    throw OptionError("max_iterations", fmt::format("{}", max_iterations), "is invalid: at least 1 sweep");
  }
  if (!(relaxation == 0.0 || (relaxation > 0.0 && relaxation < 2.0))) {
    throw OptionError("relaxation", format_number(relaxation),
                      "is invalid: allowed range is 0 < relaxation < 2 (or 0 for the automatic factor)");
  }
  if (check_every < 1) {
    throw OptionError("check_every", fmt::format("{}", check_every), "is invalid: at least 1 sweep");
  }
}

namespace {

double largest_mass_balance(const ReynoldsStencil& stencil, const Eigen::ArrayXd& pressure,
                            const Eigen::ArrayXd& fluid_fraction) {
  double largest = 0.0;
  for (std::size_t k = 0; k < stencil.size(); ++k) {
    largest = std::max(largest, std::abs(stencil.mass_balance(k, pressure, fluid_fraction)));
  }
  return largest;
}

}  // namespace

double relative_mass_residual(const ReynoldsStencil& stencil, const Eigen::ArrayXd& pressure,
                              const Eigen::ArrayXd& fluid_fraction) {
  return largest_mass_balance(stencil, pressure, fluid_fraction) / stencil.balance_scale(pressure);
}

bool satisfies_complementarity(const Eigen::ArrayXd& pressure, const Eigen::ArrayXd& fluid_fraction,
                               double fraction_tolerance) {
  for (Eigen::Index k = 0; k < pressure.size(); ++k) {
    const double p = pressure[k];
    const double theta = fluid_fraction[k];
    if (!(p >= 0.0 && theta >= 0.0 && theta <= 1.0)) return false;
    if (p > 0.0 && theta < 1.0 - fraction_tolerance) return false;
  }
  return true;
}

namespace {

double automatic_relaxation(const Grid& grid) {
  const double n = static_cast<double>(std::max(grid.nx(), grid.ny()));
  return 2.0 / (1.0 + std::sin(std::numbers::pi / n));
}

// One projected SOR sweep over the unknown nodes, along the entrainment.
void sweep(const ReynoldsStencil& s, double omega, Eigen::ArrayXd& p, Eigen::ArrayXd& theta) {
  const std::size_t nx = s.grid().nx();
  const std::size_t ny = s.grid().ny();
  const bool forward_x = s.conditions().entrainment_velocity[0] >= 0.0;
  const bool forward_y = s.conditions().entrainment_velocity[1] >= 0.0;
  const Eigen::ArrayXd& h = s.film();
  const double b = s.couette_x() + s.couette_y() + s.time_rate();
  for (std::size_t jj = 0; jj < ny; ++jj) {
    const std::size_t j = forward_y ? jj : ny - 1 - jj;
    for (std::size_t ii = 0; ii < nx; ++ii) {
      const std::size_t i = forward_x ? ii : nx - 1 - ii;
      const std::size_t k = j * nx + i;
      if (s.fixed(k)) continue;
      const Neighbours nb = s.neighbours(k);
      double a = 0.0;
      double r = 0.0;
      const auto face = [&](std::size_t other, double conductance) {
        if (other == Neighbours::kNone) return;
        a += conductance;
        r += conductance * p[other];
      };
      face(nb.west, nb.west != Neighbours::kNone ? s.east_conductance(nb.west) : 0.0);
      face(nb.east, s.east_conductance(k));
      face(nb.south, nb.south != Neighbours::kNone ? s.north_conductance(nb.south) : 0.0);
      face(nb.north, s.north_conductance(k));
      const std::size_t up_x = s.upstream_x(nb);
      const std::size_t up_y = s.upstream_y(nb);
      if (up_x != Neighbours::kNone) r += s.couette_x() * h[up_x] * theta[up_x];
      if (up_y != Neighbours::kNone) r += s.couette_y() * h[up_y] * theta[up_y];
      r += s.stored(k);  // the transient term's previous steps (0 when steady)
      const double couette = b * h[k];
      if (r >= couette) {
        const double full = (r - couette) / a;
        p[k] = std::max(0.0, p[k] + omega * (full - p[k]));
        theta[k] = 1.0;
      } else {
        p[k] = 0.0;
        theta[k] = r / couette;
      }
    }
  }
}

}  // namespace

FilmSolution solve_cavitating_film(const ReynoldsStencil& stencil, const CavitationSolverOptions& options,
                                   const FilmSolution* start, FilmRows* rows) {
  options.validate();
  const auto n = static_cast<Eigen::Index>(stencil.size());
  FilmSolution solution;
  const bool warm = start != nullptr && start->pressure.size() > 0 && start->fluid_fraction.size() > 0;
  if (warm && (start->pressure.size() != n || start->fluid_fraction.size() != n)) {
    throw InputError(fmt::format("film start has {} pressures and {} fluid fractions, the grid has {} nodes",
                                 start->pressure.size(), start->fluid_fraction.size(), n));
  }
  solution.pressure = warm ? start->pressure : Eigen::ArrayXd::Zero(n);
  solution.fluid_fraction = warm ? start->fluid_fraction : Eigen::ArrayXd::Ones(n);
  const double supply = stencil.conditions().boundary.supply_fluid_fraction;
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!stencil.fixed(static_cast<std::size_t>(k))) continue;
    solution.pressure[k] = stencil.fixed_pressure(static_cast<std::size_t>(k));
    solution.fluid_fraction[k] = supply;
  }
  const Grid& whole = rows != nullptr ? rows->whole_grid() : stencil.grid();
  const double omega = options.relaxation > 0.0 ? options.relaxation : automatic_relaxation(whole);
  if (rows != nullptr) rows->start(solution.pressure, solution.fluid_fraction);
  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    if (rows != nullptr) rows->before_sweep(solution.pressure, solution.fluid_fraction);
    sweep(stencil, omega, solution.pressure, solution.fluid_fraction);
    if (rows != nullptr) rows->after_sweep(solution.pressure, solution.fluid_fraction);
    if (iteration % options.check_every != 0 && iteration != options.max_iterations) continue;
    solution.iterations = iteration;
    if (rows != nullptr) {
      rows->complete(solution.pressure, solution.fluid_fraction);
      solution.relative_residual =
          rows->max(largest_mass_balance(stencil, solution.pressure, solution.fluid_fraction)) /
          rows->max(stencil.balance_scale(solution.pressure));
    } else {
      solution.relative_residual = relative_mass_residual(stencil, solution.pressure, solution.fluid_fraction);
    }
    if (!std::isfinite(solution.relative_residual)) {
      solution.status = FilmStatus::failure;
      solution.message = fmt::format("the film solve diverged after {} sweeps (relaxation {})", iteration, omega);
      return solution;
    }
    const bool complementary = satisfies_complementarity(solution.pressure, solution.fluid_fraction);
    if (solution.relative_residual <= options.tolerance &&
        (rows != nullptr ? rows->all(complementary) : complementary)) {
      solution.status = FilmStatus::converged;
      return solution;
    }
  }
  solution.status = FilmStatus::iteration_limit;
  solution.message =
      fmt::format("the film did not converge in {} sweeps: relative mass residual {:.3g} > tolerance {:.3g}",
                  options.max_iterations, solution.relative_residual, options.tolerance);
  return solution;
}

}  // namespace halfspace::lubrication
