// Load, boundary flows and friction of a solved film, by the same nodes and
// faces the solver balanced: the flows through the fixed-pressure edges are
// the faces' fluxes, so inflow = outflow is the sum of every control volume's
// balance (telescoping), a check of the solution's mass conservation.
#include "halfspace/lubrication/film_forces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace halfspace::lubrication {
namespace {

// Trapezoidal weight of a node along one axis: half on a fixed-pressure edge.
double edge_weight(std::size_t index, std::size_t count, AxisBoundary boundary) {
  return boundary == AxisBoundary::fixed_pressure && (index == 0 || index + 1 == count) ? 0.5 : 1.0;
}

// dp/dx at node k: central where both neighbours exist, one-sided otherwise.
double gradient(const Eigen::ArrayXd& p, std::size_t k, std::size_t low, std::size_t high, double spacing) {
  if (low != Neighbours::kNone && high != Neighbours::kNone) return (p[high] - p[low]) / (2.0 * spacing);
  if (high != Neighbours::kNone) return (p[high] - p[k]) / spacing;
  if (low != Neighbours::kNone) return (p[k] - p[low]) / spacing;
  return 0.0;
}

}  // namespace

double node_weight(const ReynoldsStencil& stencil, std::size_t k) {
  const Grid& grid = stencil.grid();
  const FlowBoundary& boundary = stencil.conditions().boundary;
  const double weight = edge_weight(k % grid.nx(), grid.nx(), boundary.x);
  return grid.dimension() == 2 ? weight * edge_weight(k / grid.nx(), grid.ny(), boundary.y) : weight;
}

std::array<double, 2> pressure_gradient(const ReynoldsStencil& stencil, const Eigen::ArrayXd& p, std::size_t k) {
  const Grid& grid = stencil.grid();
  const Neighbours nb = stencil.neighbours(k);
  return {gradient(p, k, nb.west, nb.east, grid.dx()),
          grid.dimension() == 2 ? gradient(p, k, nb.south, nb.north, grid.dy()) : 0.0};
}

FilmForces film_forces(const ReynoldsStencil& stencil, const FilmSolution& solution, const FilmRows* rows) {
  const Grid& grid = stencil.grid();
  const FlowConditions& conditions = stencil.conditions();
  const Eigen::ArrayXd& p = solution.pressure;
  const Eigen::ArrayXd& theta = solution.fluid_fraction;
  const Eigen::ArrayXd& h = stencil.film();
  const bool two_d = grid.dimension() == 2;
  // This process's nodes, and which nodes are the whole film's fixed ones
  // (a face joins the boundary flows if it joins a fixed node and an
  // unknown one of the whole film; each face is counted at its west or
  // south node, so every process counts its own).
  const std::size_t first = rows != nullptr ? rows->first_own_node() : 0;
  const std::size_t end = rows != nullptr ? first + rows->own_nodes() : stencil.size();
  const auto fixed = [&](std::size_t k) { return rows != nullptr ? rows->fixed_in_whole(k) : stencil.fixed(k); };
  FilmForces forces;
  double weight_sum = 0.0;
  double cavitated = 0.0;
  double minimum_film = std::numeric_limits<double>::infinity();
  double max_pressure = -std::numeric_limits<double>::infinity();
  for (std::size_t k = first; k < end; ++k) {
    const double weight = node_weight(stencil, k);
    weight_sum += weight;
    forces.load += weight * p[k];
    const Neighbours nb = stencil.neighbours(k);
    const double shear = theta[k] * conditions.viscosity / h[k];
    const std::array<double, 2> dp = pressure_gradient(stencil, p, k);
    forces.friction_force[0] += weight * (shear * conditions.sliding_velocity[0] - 0.5 * h[k] * dp[0]);
    if (two_d) forces.friction_force[1] += weight * (shear * conditions.sliding_velocity[1] - 0.5 * h[k] * dp[1]);
    if (theta[k] < 1.0) cavitated += 1.0;
    minimum_film = std::min(minimum_film, h[k]);
    max_pressure = std::max(max_pressure, p[k]);
    // Flows through faces between a fixed node and an unknown one.
    const auto boundary_face = [&](std::size_t other, double flow_to_other) {
      if (other == Neighbours::kNone || fixed(k) == fixed(other)) return;
      const double into_domain = fixed(k) ? flow_to_other : -flow_to_other;
      forces.inflow += std::max(into_domain, 0.0);
      forces.outflow += std::max(-into_domain, 0.0);
    };
    boundary_face(nb.east, stencil.east_flow(k, p, theta));
    boundary_face(nb.north, stencil.north_flow(k, p, theta));
  }
  std::size_t nodes = stencil.size();
  if (rows != nullptr) {
    std::array<double, 7> sums{
        forces.load, forces.friction_force[0], forces.friction_force[1], weight_sum, forces.inflow, forces.outflow,
        cavitated};
    rows->sum(sums);
    forces.load = sums[0];
    forces.friction_force = {sums[1], sums[2]};
    weight_sum = sums[3];
    forces.inflow = sums[4];
    forces.outflow = sums[5];
    cavitated = sums[6];
    minimum_film = rows->min(minimum_film);
    max_pressure = rows->max(max_pressure);
    nodes = rows->whole_grid().size();
  }
  const double area = grid.cell_area();
  forces.load *= area;
  forces.friction_force[0] *= area;
  forces.friction_force[1] *= area;
  forces.mean_pressure = forces.load / (weight_sum * area);
  const double friction = std::hypot(forces.friction_force[0], forces.friction_force[1]);
  forces.friction_coefficient = forces.load > 0.0 ? friction / forces.load : 0.0;
  forces.minimum_film_thickness = minimum_film;
  forces.max_pressure = max_pressure;
  forces.cavitated_fraction = cavitated / static_cast<double>(nodes);
  return forces;
}

}  // namespace halfspace::lubrication
