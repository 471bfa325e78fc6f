// The friction of a mixed film (mixed_film.hpp): the film's shear
// (film_shear: Couette with its limits, and Poiseuille) on cells without
// contact, the film as the Reynolds equation sees it (reynolds_film),
// and Coulomb's mu p_c along the sliding velocity on contact cells (no
// sliding: no asperity friction).
#include <array>
#include <cmath>

#include "halfspace/lubrication/film_shear.hpp"
#include "halfspace/lubrication/mixed_film.hpp"

namespace halfspace::lubrication {

void add_mixed_friction(const Grid& grid, const FlowConditions& conditions, const LubricantLaws& laws,
                        const MixedFrictionOptions& friction, double boundary_film, MixedFilm& film,
                        const FilmRows* rows) {
  FilmShear fluid;
  std::array<double, 1> contact_sum{(film.contact_pressure.max(0.0)).sum()};
  if (rows == nullptr) {
    const Eigen::ArrayXd seen_film = reynolds_film(film.film, boundary_film);
    fluid = film_shear(grid, conditions, laws, friction.shear, seen_film, film.fluid_pressure, film.fluid_fraction,
                       &film.contact_pressure);
  } else {
    // The pressure gradient reaches the neighbours' rows: the fields on the
    // stencil.
    const auto stencil = [&](const Eigen::ArrayXd& field) {
      return rows->stencil_field({field.data(), static_cast<std::size_t>(field.size())});
    };
    const Eigen::ArrayXd seen_film = reynolds_film(stencil(film.film), boundary_film);
    const Eigen::ArrayXd contact = stencil(film.contact_pressure);
    fluid = film_shear(rows->stencil_grid(), rows->stencil_conditions(), laws, friction.shear, seen_film,
                       stencil(film.fluid_pressure), stencil(film.fluid_fraction), &contact, rows);
    rows->sum(contact_sum);
  }
  const std::array<double, 2>& sliding = conditions.sliding_velocity;
  const double sliding_speed = std::hypot(sliding[0], sliding[1]);
  const double contact_load = contact_sum[0] * grid.cell_area();
  for (int axis = 0; axis < 2; ++axis) {
    film.fluid_friction_force[axis] = fluid.friction_force[axis];
    film.contact_friction_force[axis] =
        sliding_speed > 0.0 ? friction.contact_friction * contact_load * sliding[axis] / sliding_speed : 0.0;
  }
  const double total = std::hypot(film.fluid_friction_force[0] + film.contact_friction_force[0],
                                  film.fluid_friction_force[1] + film.contact_friction_force[1]);
  film.friction_coefficient = film.load > 0.0 ? total / film.load : 0.0;
}

}  // namespace halfspace::lubrication
