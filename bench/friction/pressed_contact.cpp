// A rigid sphere or cylinder pressed into an elastic half-space with
// friction (the coupled problem of Spence 1975; Johnson 1985, sec. 5.6),
// against the number of load increments and the grid: does the stick zone
// converge, and to Spence's c/a?
//
//   pressed_contact sphere|cylinder CELLS,... INCREMENTS,... MU,... [NU,...]
//   pressed_contact sphere 64,128 8,16 0.1,0.3
//   pressed_contact cylinder 200,400 16,32 0.2857 0.3,0.4,0.45
//
// NU is the elastic body's Poisson ratio (0.3 unless given; beta =
// (1 - 2 nu)/(2 (1 - nu)) against the rigid indenter). Spence's solution is
// self-similar: under a growing load the stick zone keeps the ratio c/a, a
// function of |beta|/mu alone when the shear's effect on the pressure is
// neglected (support/spence_stick_zone.hpp). A discrete history approaches
// the continuous one as the increments shrink; each increment's new contact
// enters without the shear it would have gathered under a continuous load.
// The rows print c/a = (stick cells / contact cells)^(1/dimension), slip/a
// = the inner edge of the slip zone over a (sphere: the nearest slipping
// cell's distance from the centre, a = sqrt(contact area/pi); cylinder: half
// a cell inside the nearest slipping cell, a = half the contact width; cells
// held just below mu p in the last increment count as stick, so slip/a is
// the better measure of Spence's c), Spence's c/a, the peak pressure and the
// approach against the frictionless solve, and the alternations.
// PRESSED_CONTACT_MAP=1 prints each solve's map: '.' no contact, '#' slip,
// a digit 10 |q|/(mu p) of a stick cell.
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
#include "support/spence_stick_zone.hpp"

namespace {

using namespace halfspace;

constexpr double kRadius = 0.01;          // m
constexpr double kForce = 10.0;           // N (sphere)
constexpr double kLineForce = 2e5;        // N/m (cylinder)
constexpr double kYoungModulus = 2.1e11;  // Pa

struct Pressed {
  double stick_over_contact = 0.0;  // c/a from the stick fraction
  double inner_slip = 0.0;          // the inner edge of the slip zone over a
  double peak = 0.0;
  double approach = 0.0;
  int alternations = 0;
  double seconds = 0.0;
  bool converged = false;
};

Pressed press(bool sphere, std::size_t cells, int increments, double mu, double nu, bool coupling) {
  const ElasticPair pair = ElasticPair::on_rigid(ElasticBody{kYoungModulus, nu});
  const double a = sphere ? halfspace::testing::hertz_point(kForce, kRadius, pair.composite_modulus()).radius
                          : halfspace::testing::hertz_line(kLineForce, kRadius, pair.composite_modulus()).half_width;
  const double h = 2.4 * a / static_cast<double>(cells);
  const Grid grid = sphere ? Grid::plane(cells, cells, h, h, Boundary::free) : Grid::line(cells, h, Boundary::free);
  const Eigen::ArrayXd heights =
      halfspace::testing::field_from(grid, [](double x, double y) { return -(x * x + y * y) / (2 * kRadius); });
  solvers::FrictionOptions friction;
  friction.tangential.friction_coefficient = mu;
  friction.history = {TangentialLoading::force(0.0)};
  friction.coupling = coupling;
  friction.normal_load_steps = increments;
  if (!sphere) friction.tangential.max_iterations = 200000;  // plane strain converges slowly
  const auto started = std::chrono::steady_clock::now();
  const FrictionalSolveResult r = solvers::solve_frictional_surface(
      grid, {heights.data(), grid.size()}, pair, Loading::force(sphere ? kForce : kLineForce),
      halfspace::testing::test_options(solvers::SolverType::pk_fourier, 1e-12), friction);
  Pressed out;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (!r.converged()) {
    fmt::print("# {} cells, {} increments, mu {}: not converged: {}\n", cells, increments, mu, r.failure());
    return out;
  }
  out.converged = true;
  const SolveResult& normal = coupling ? r.step_normals.back() : r.normal;
  const TangentialResult& last = r.steps.back();
  out.stick_over_contact = sphere ? std::sqrt(last.stick_fraction) : last.stick_fraction;
  double contact_cells = 0.0;
  double nearest_slip = 1e300;
  for (std::size_t k = 0; k < grid.size(); ++k) {
    const auto e = static_cast<Eigen::Index>(k);
    if (!(normal.pressure[e] > 0.0)) continue;
    contact_cells += 1.0;
    if (last.stick[e] == 0.0) {
      const std::size_t i = k % grid.nx();
      const std::size_t j = k / grid.nx();
      nearest_slip = std::min(nearest_slip, sphere ? std::hypot(halfspace::testing::centred_x(grid, i),
                                                                halfspace::testing::centred_y(grid, j))
                                                   : std::abs(halfspace::testing::centred_x(grid, i)) - 0.5 * h);
    }
  }
  if (std::getenv("PRESSED_CONTACT_MAP") != nullptr) {
    for (std::size_t j = 0; j < grid.ny(); ++j) {
      std::string row;
      for (std::size_t i = 0; i < cells; ++i) {
        const auto k = static_cast<Eigen::Index>(j * grid.nx() + i);
        const double ratio = std::hypot(last.state.shear_x[k], last.state.shear_y[k]) / (mu * normal.pressure[k]);
        row += !(normal.pressure[k] > 0.0) ? '.'
               : last.stick[k] != 0.0      ? char('0' + std::min(9, int(10 * ratio)))
                                           : '#';
      }
      fmt::print("{}\n", row);
    }
  }
  const double measured_a = sphere ? std::sqrt(contact_cells * h * h / M_PI) : 0.5 * contact_cells * h;
  out.inner_slip = std::min(nearest_slip, measured_a) / measured_a;
  out.peak = normal.pressure.maxCoeff();
  out.approach = normal.approach;
  for (const TangentialResult& t : r.loading_steps) out.alternations += t.coupling_alternations;
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string shape = argc > 1 ? argv[1] : "sphere";
  if (shape != "sphere" && shape != "cylinder") {
    fmt::print(stderr, "pressed_contact: the shape must be sphere or cylinder, not '{}'\n", shape);
    return 2;
  }
  const bool sphere = shape == "sphere";
  const std::vector<double> grids = bench::number_list(argc > 2 ? argv[2] : (sphere ? "32" : "200"));
  const std::vector<double> increments = bench::number_list(argc > 3 ? argv[3] : "4,8");
  const std::vector<double> mus = bench::number_list(argc > 4 ? argv[4] : "0.3");
  const std::vector<double> nus = bench::number_list(argc > 5 ? argv[5] : "0.3");
  fmt::print("# rigid {} R = 10 mm, {} into an elastic body (E 210 GPa), free grid over 2.4 a\n", shape,
             sphere ? "10 N" : "2e5 N/m");
  fmt::print("{:>5} {:>6} {:>6} {:>6} {:>10} {:>7} {:>7} {:>7} {:>8} {:>9} {:>10} {:>6} {:>8}\n", "nu", "beta", "mu",
             "cells", "increments", "c/a", "slip/a", "Spence", "differ", "peak %", "approach %", "alts", "seconds");
  for (const double nu : nus) {
    const double beta = ElasticPair::on_rigid(ElasticBody{kYoungModulus, nu}).dundurs_beta();
    for (const double cells : grids) {
      const auto n = static_cast<std::size_t>(cells);
      const Pressed plain = press(sphere, n, 1, 0.3, nu, false);
      for (const double mu : mus) {
        const double spence = sphere ? halfspace::testing::spence_axisymmetric_stick_ratio(std::abs(beta) / mu)
                                     : halfspace::testing::spence_plane_stick_ratio(std::abs(beta) / mu);
        for (const double steps : increments) {
          const Pressed p = press(sphere, n, static_cast<int>(steps), mu, nu, true);
          if (!p.converged) continue;
          fmt::print(
              "{:5.3f} {:6.4f} {:6.4f} {:6d} {:10d} {:7.4f} {:7.4f} {:7.4f} {:+8.4f} {:+9.3f} {:+10.4f} {:6d} "
              "{:8.2f}\n",
              nu, beta, mu, n, static_cast<int>(steps), p.stick_over_contact, p.inner_slip, spence,
              p.inner_slip - spence, 100.0 * (p.peak / plain.peak - 1.0), 100.0 * (p.approach / plain.approach - 1.0),
              p.alternations, p.seconds);
        }
      }
    }
  }
  return 0;
}
