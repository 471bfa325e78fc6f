// The film's shear on its lower surface (film_shear.hpp), node by node with
// the nodes, weights and gradients film_forces uses, so that a Newtonian,
// isoviscous film gives film_forces' friction to rounding.
#include "halfspace/lubrication/film_shear.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <string>

#include "halfspace/error.hpp"
#include "halfspace/lubrication/film_forces.hpp"

namespace halfspace::lubrication {

void ShearLimits::validate() const {
  const auto require = [](double value, const char* name, const char* unit) {
    if (!(std::isfinite(value) && value >= 0.0)) {
      throw OptionError(name, format_number(value) + unit, "is invalid: it must be >= 0 (0: off) and finite");
    }
  };
  require(eyring_stress, "eyring_stress", " Pa");
  require(limiting_shear_stress, "limiting_shear_stress", " Pa");
  require(limiting_shear_slope, "limiting_shear_slope", "");
}

namespace {

// The limited magnitude of a Newtonian Couette stress tau_n >= 0 at pressure p.
double limited_stress(const ShearLimits& limits, double tau_n, double p) {
  double tau = limits.eyring() ? limits.eyring_stress * std::asinh(tau_n / limits.eyring_stress) : tau_n;
  if (limits.capped()) tau = std::min(tau, limits.limiting_shear_stress + limits.limiting_shear_slope * p);
  return tau;
}

}  // namespace

FilmShear film_shear(const Grid& grid, const FlowConditions& conditions, const LubricantLaws& laws,
                     const ShearLimits& limits, const Eigen::ArrayXd& film, const Eigen::ArrayXd& pressure,
                     const Eigen::ArrayXd& fluid_fraction, const Eigen::ArrayXd* contact_pressure,
                     const FilmRows* rows) {
  conditions.validate(grid);
  laws.validate(conditions.viscosity);
  limits.validate();
  const std::size_t n = grid.size();
  if (static_cast<std::size_t>(pressure.size()) != n || static_cast<std::size_t>(fluid_fraction.size()) != n ||
      (contact_pressure && static_cast<std::size_t>(contact_pressure->size()) != n)) {
    throw InputError(fmt::format("film shear: pressure has {} values and fluid fraction {}, the {} grid has {} nodes",
                                 pressure.size(), fluid_fraction.size(), grid.shape_string(), n));
  }
  const ReynoldsStencil stencil(grid, film, conditions);  // checks the film
  const bool two_d = grid.dimension() == 2;
  // This process's nodes (all without rows): the fields cover them alone.
  const std::size_t first = rows != nullptr ? rows->first_own_node() : 0;
  const std::size_t own = rows != nullptr ? rows->own_nodes() : n;
  const double eta0 = conditions.viscosity;
  const std::array<double, 2>& slide = conditions.sliding_velocity;
  const double sliding_speed = std::hypot(slide[0], slide[1]);
  const bool limited = limits.eyring() || limits.capped();
  FilmShear result;
  result.shear_x = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(own));
  result.shear_y = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(own));
  double lowered = 0.0;
  for (std::size_t k = first; k < first + own; ++k) {
    const auto kk = static_cast<Eigen::Index>(k);
    const auto field = static_cast<Eigen::Index>(k - first);
    const double weight = node_weight(stencil, k);
    if (contact_pressure && (*contact_pressure)[kk] > 0.0) continue;
    const double p = std::max(pressure[kk], 0.0);
    const double h = film[kk];
    // theta eta / h: the Couette stress per unit sliding speed.
    double shear = fluid_fraction[kk] * (eta0 * laws.viscosity_ratio(p, eta0)) / h;
    if (limited && sliding_speed > 0.0) {
      const double newtonian = eta0 * laws.viscosity_ratio(p, eta0) * sliding_speed / h;
      const double tau = limited_stress(limits, newtonian, p);
      if (tau < 0.99 * newtonian) lowered += 1.0;
      shear = fluid_fraction[kk] * tau / sliding_speed;
    }
    const std::array<double, 2> dp = pressure_gradient(stencil, pressure, k);
    const double couette_x = shear * slide[0];
    result.shear_x[field] = couette_x - 0.5 * h * dp[0];
    result.friction_force[0] += weight * result.shear_x[field];
    result.couette_force[0] += weight * couette_x;
    if (two_d) {
      const double couette_y = shear * slide[1];
      result.shear_y[field] = couette_y - 0.5 * h * dp[1];
      result.friction_force[1] += weight * result.shear_y[field];
      result.couette_force[1] += weight * couette_y;
    }
    result.load += weight * pressure[kk];
  }
  std::size_t nodes = n;
  if (rows != nullptr) {
    std::array<double, 6> sums{result.friction_force[0],
                               result.friction_force[1],
                               result.couette_force[0],
                               result.couette_force[1],
                               result.load,
                               lowered};
    rows->sum(sums);
    result.friction_force = {sums[0], sums[1]};
    result.couette_force = {sums[2], sums[3]};
    result.load = sums[4];
    lowered = sums[5];
    nodes = rows->whole_grid().size();
  }
  const double area = grid.cell_area();
  for (double* value : {&result.friction_force[0], &result.friction_force[1], &result.couette_force[0],
                        &result.couette_force[1], &result.load}) {
    *value *= area;
  }
  const double friction = std::hypot(result.friction_force[0], result.friction_force[1]);
  result.friction_coefficient = result.load > 0.0 ? friction / result.load : 0.0;
  result.limited_fraction = lowered / static_cast<double>(nodes);
  return result;
}

}  // namespace halfspace::lubrication
