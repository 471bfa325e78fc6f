// What a solved film carries and passes: the load, the volume flows through
// the boundary, and the shear (friction) force on a surface.
#pragma once

#include <array>

#include "halfspace/lubrication/film_rows.hpp"
#include "halfspace/lubrication/film_solution.hpp"
#include "halfspace/lubrication/reynolds_stencil.hpp"

namespace halfspace::lubrication {

struct FilmForces {
  // N in 2D, N/m in 1D: the pressure integrated over the domain by the
  // trapezoidal rule (half weights on fixed-pressure edge nodes).
  double load = 0.0;
  double mean_pressure = 0.0;  // Pa: load over the domain's area (length in 1D)
  // Volume flows through the fixed-pressure edges (m^3/s in 2D, m^2/s in
  // 1D): into the domain and out of it, both >= 0. Steady mass conservation:
  // inflow = outflow.
  double inflow = 0.0;
  double outflow = 0.0;
  // The shear force (x, y) of the film on the lower surface (N in 2D, N/m in
  // 1D): tau = theta eta (u_upper - u_lower) / h - (h / 2) grad p, the
  // Couette part carried by the fluid fraction theta of the gap.
  std::array<double, 2> friction_force{0.0, 0.0};
  double friction_coefficient = 0.0;  // |friction force| / load (0 without load)
  double minimum_film_thickness = 0.0;
  double max_pressure = 0.0;        // Pa
  double cavitated_fraction = 0.0;  // share of nodes with theta < 1
};

// The forces of `solution` on `stencil`. With `rows` (film_rows.hpp), the
// stencil and the solution are this process's rows of a film and their
// halo rows: the forces are the whole film's (sums over the processes, in
// another order than the serial one's: equal to rounding). Collective then.
FilmForces film_forces(const ReynoldsStencil& stencil, const FilmSolution& solution, const FilmRows* rows = nullptr);

// What the film's sums (here and film_shear.hpp) take at node k: its
// trapezoidal weight (half on each fixed-pressure edge it lies on), and the
// pressure gradient (central where both neighbours exist, one-sided
// otherwise; y zero on a profile).
double node_weight(const ReynoldsStencil& stencil, std::size_t k);
std::array<double, 2> pressure_gradient(const ReynoldsStencil& stencil, const Eigen::ArrayXd& p, std::size_t k);

}  // namespace halfspace::lubrication
