// The friction of a mixed film (mixed_film.hpp): the film's shear on cells
// without contact and Coulomb's law on contact cells, as the rigid film's
// film_forces takes the shear on the lower surface,
//
//   tau = theta eta(p_f) (u_upper - u_lower) / h_R - (h_R / 2) grad p_f,
//
// the Couette part capped at the limiting shear stress tau_L = tau_0 +
// gamma p_f when one is given (Bair & Winer 1979: the piezoviscous
// Newtonian shear at GPa pressures exceeds anything a lubricant carries),
// and mu p_c along the sliding velocity on contact cells (no sliding: no
// asperity friction).
#include <algorithm>
#include <cmath>

#include "halfspace/lubrication/mixed_film.hpp"
#include "halfspace/lubrication/reynolds_stencil.hpp"

namespace halfspace::lubrication {

namespace {

// dp/dx at node k: central where both neighbours exist, one-sided otherwise.
double gradient(const Eigen::ArrayXd& p, std::size_t k, std::size_t low, std::size_t high, double spacing) {
  if (low != Neighbours::kNone && high != Neighbours::kNone) return (p[high] - p[low]) / (2.0 * spacing);
  if (high != Neighbours::kNone) return (p[high] - p[k]) / spacing;
  if (low != Neighbours::kNone) return (p[k] - p[low]) / spacing;
  return 0.0;
}

}  // namespace

void add_mixed_friction(const Grid& grid, const FlowConditions& conditions, const LubricantLaws& laws,
                        const MixedFrictionOptions& friction, double boundary_film, MixedFilm& film) {
  const std::size_t n = grid.size();
  const ReynoldsStencil topology(grid, Eigen::ArrayXd::Ones(static_cast<Eigen::Index>(n)), conditions);
  const std::array<double, 2>& sliding = conditions.sliding_velocity;
  const double sliding_speed = std::hypot(sliding[0], sliding[1]);
  const bool capped = friction.limiting_shear_stress > 0.0 || friction.limiting_shear_slope > 0.0;
  const bool two_d = grid.dimension() == 2;
  std::array<double, 2> fluid{0.0, 0.0}, contact{0.0, 0.0};
  for (std::size_t k = 0; k < n; ++k) {
    const auto kk = static_cast<Eigen::Index>(k);
    const double pc = film.contact_pressure[kk];
    if (pc > 0.0) {
      if (sliding_speed > 0.0) {
        contact[0] += friction.contact_friction * pc * sliding[0] / sliding_speed;
        contact[1] += friction.contact_friction * pc * sliding[1] / sliding_speed;
      }
      continue;
    }
    const double pf = film.fluid_pressure[kk];
    const double h = std::max(film.film[kk], boundary_film);
    const double eta = conditions.viscosity * laws.viscosity_ratio(std::max(pf, 0.0), conditions.viscosity);
    double scale = film.fluid_fraction[kk] * eta / h;
    if (capped && sliding_speed > 0.0) {
      const double limit = friction.limiting_shear_stress + friction.limiting_shear_slope * std::max(pf, 0.0);
      scale = std::min(scale, limit / sliding_speed);
    }
    const Neighbours nb = topology.neighbours(k);
    fluid[0] += scale * sliding[0] - 0.5 * h * gradient(film.fluid_pressure, k, nb.west, nb.east, grid.dx());
    if (two_d) {
      fluid[1] += scale * sliding[1] - 0.5 * h * gradient(film.fluid_pressure, k, nb.south, nb.north, grid.dy());
    }
  }
  const double area = grid.cell_area();
  for (int axis = 0; axis < 2; ++axis) {
    film.fluid_friction_force[axis] = fluid[axis] * area;
    film.contact_friction_force[axis] = contact[axis] * area;
  }
  const double total = std::hypot(film.fluid_friction_force[0] + film.contact_friction_force[0],
                                  film.fluid_friction_force[1] + film.contact_friction_force[1]);
  film.friction_coefficient = film.load > 0.0 ? total / film.load : 0.0;
}

}  // namespace halfspace::lubrication
