// A rigid sphere pressed into a steel half-space with friction (the coupled
// problem of Spence 1975; Johnson 1985, sec. 5.6), against the number of load
// increments and the grid: does the stick zone converge, and to what?
//
//   pressed_sphere CELLS,... INCREMENTS,... MU,...
//   pressed_sphere 32,48 4,8,16,32 0.3
//
// Spence's solution is self-similar: under a growing load the stick radius c
// keeps the ratio c/a, a function of beta/mu alone. A discrete history
// approaches it as the increments shrink; each increment's new contact ring
// enters without the shear it would have gathered under a continuous load.
// The rows print c/a = sqrt(stick cells / contact cells), slip/a = the
// nearest slipping cell's distance from the centre over a (the inner edge of
// the slip annulus: cells held just below mu p in the last increment count
// as stick, so the first is the better measure of Spence's c), the peak
// pressure and the approach against the frictionless solve, and the
// alternations. PRESSED_SPHERE_MAP=1 prints each solve's map: '.' no
// contact, '#' slip, a digit 10 |q|/(mu p) of a stick cell.
#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "../number_list.hpp"
#include "halfspace/elastic_pair.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/solvers/frictional_solve.hpp"
#include "support/analytic_solutions.hpp"
#include "support/grid_fields.hpp"
#include "support/pk_solvers.hpp"

namespace {

using namespace halfspace;

constexpr double kRadius = 0.01;  // m
constexpr double kForce = 10.0;   // N

struct Pressed {
  double stick_over_contact = 0.0;  // c/a of a circular stick zone
  double inner_slip = 0.0;          // the nearest slipping cell's distance from the centre over a
  double peak = 0.0;
  double approach = 0.0;
  int alternations = 0;
  double seconds = 0.0;
};

Pressed press(std::size_t cells, int increments, double mu, bool coupling) {
  const ElasticPair pair = ElasticPair::on_rigid(ElasticBody{2.1e11, 0.3});
  const double a = halfspace::testing::hertz_point(kForce, kRadius, pair.composite_modulus()).radius;
  const double h = 2.4 * a / static_cast<double>(cells);
  const Grid grid = Grid::plane(cells, cells, h, h, Boundary::free);
  const Eigen::ArrayXd heights =
      halfspace::testing::field_from(grid, [](double x, double y) { return -(x * x + y * y) / (2 * kRadius); });
  solvers::FrictionOptions friction;
  friction.tangential.friction_coefficient = mu;
  friction.history = {TangentialLoading::force(0.0)};
  friction.coupling = coupling;
  friction.normal_load_steps = increments;
  const auto started = std::chrono::steady_clock::now();
  const FrictionalSolveResult r = solvers::solve_frictional_surface(
      grid, {heights.data(), grid.size()}, pair, Loading::force(kForce),
      halfspace::testing::test_options(solvers::SolverType::pk_fourier, 1e-12), friction);
  Pressed out;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (!r.converged()) {
    fmt::print("# {} cells, {} increments, mu {}: not converged: {}\n", cells, increments, mu, r.failure());
    return out;
  }
  const SolveResult& normal = coupling ? r.step_normals.back() : r.normal;
  const TangentialResult& last = r.steps.back();
  out.stick_over_contact = std::sqrt(last.stick_fraction);
  double contact_cells = 0.0;
  double nearest_slip = 1e300;
  for (std::size_t j = 0; j < cells; ++j) {
    for (std::size_t i = 0; i < cells; ++i) {
      const auto k = static_cast<Eigen::Index>(j * cells + i);
      if (!(normal.pressure[k] > 0.0)) continue;
      contact_cells += 1.0;
      if (last.stick[k] == 0.0) {
        nearest_slip = std::min(
            nearest_slip, std::hypot(halfspace::testing::centred_x(grid, i), halfspace::testing::centred_y(grid, j)));
      }
    }
  }
  if (std::getenv("PRESSED_SPHERE_MAP") != nullptr) {
    for (std::size_t j = 0; j < cells; ++j) {
      std::string row;
      for (std::size_t i = 0; i < cells; ++i) {
        const auto k = static_cast<Eigen::Index>(j * cells + i);
        const double ratio = std::hypot(last.state.shear_x[k], last.state.shear_y[k]) / (mu * normal.pressure[k]);
        row += !(normal.pressure[k] > 0.0) ? '.'
               : last.stick[k] != 0.0      ? char('0' + std::min(9, int(10 * ratio)))
                                           : '#';
      }
      fmt::print("{}\n", row);
    }
  }
  out.inner_slip = nearest_slip / std::sqrt(contact_cells * h * h / M_PI);
  out.peak = normal.pressure.maxCoeff();
  out.approach = normal.approach;
  for (const TangentialResult& t : r.loading_steps) out.alternations += t.coupling_alternations;
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<double> grids = bench::number_list(argc > 1 ? argv[1] : "32");
  const std::vector<double> increments = bench::number_list(argc > 2 ? argv[2] : "4,8");
  const std::vector<double> mus = bench::number_list(argc > 3 ? argv[3] : "0.3");
  fmt::print("# rigid sphere R = 10 mm, 10 N into steel (nu 0.3, beta 0.286), free grid over 2.4 a\n");
  fmt::print("{:>6} {:>6} {:>10} {:>8} {:>8} {:>10} {:>10} {:>6} {:>8}\n", "mu", "cells", "increments", "c/a", "slip/a",
             "peak %", "approach %", "alts", "seconds");
  for (const double cells : grids) {
    const auto n = static_cast<std::size_t>(cells);
    const Pressed plain = press(n, 1, 0.3, false);
    for (const double mu : mus) {
      for (const double steps : increments) {
        const Pressed p = press(n, static_cast<int>(steps), mu, true);
        fmt::print("{:6.2f} {:6d} {:10d} {:8.4f} {:8.4f} {:+10.3f} {:+10.4f} {:6d} {:8.2f}\n", mu, n,
                   static_cast<int>(steps), p.stick_over_contact, p.inner_slip, 100.0 * (p.peak / plain.peak - 1.0),
                   100.0 * (p.approach / plain.approach - 1.0), p.alternations, p.seconds);
      }
    }
  }
  return 0;
}
