// A Stribeck curve: the mixed film over entrainment speeds at one load, each
// solve warm-started from the last (mixed_film.hpp).
#include <fmt/format.h>

#include <cmath>

#include "halfspace/error.hpp"
#include "halfspace/lubrication/mixed_film.hpp"

namespace halfspace::lubrication {

std::vector<StribeckPoint> stribeck_sweep(InfluenceOperator& op, const Eigen::ArrayXd& gap,
                                          const FlowConditions& conditions, const LubricantLaws& laws,
                                          const MixedFilmOptions& options, const std::vector<double>& speeds) {
  options.validate();
  if (!options.load_controlled()) throw InputError("a Stribeck sweep is load controlled: give the mixed film a load");
  const std::array<double, 2>& u = conditions.entrainment_velocity;
  const double speed = std::hypot(u[0], u[1]);
  if (!(speed > 0.0)) throw InputError("a Stribeck sweep needs a nonzero entrainment velocity (its direction)");
  if (speeds.empty()) throw InputError("a Stribeck sweep needs at least one speed");
  for (const double s : speeds) {
    if (!(std::isfinite(s) && s > 0.0)) {
      throw OptionError("speeds", format_number(s) + " m/s", "is invalid: speeds must be positive and finite");
    }
  }
  const Grid& grid = op.grid();
  // The load per unit width across the entrainment.
  const double width = grid.dimension() == 1              ? 1.0
                       : std::abs(u[0]) >= std::abs(u[1]) ? static_cast<double>(grid.ny()) * grid.dy()
                                                          : static_cast<double>(grid.nx()) * grid.dx();
  std::vector<StribeckPoint> points;
  points.reserve(speeds.size());
  for (const double s : speeds) {
    FlowConditions scaled = conditions;
    const double factor = s / speed;
    for (int axis = 0; axis < 2; ++axis) {
      scaled.entrainment_velocity[axis] = u[axis] * factor;
      scaled.sliding_velocity[axis] = conditions.sliding_velocity[axis] * factor;
    }
    StribeckPoint point;
    point.entrainment_speed = s;
    point.hersey_number = conditions.viscosity * s / (options.load / width);
    const MixedFilm* previous = !points.empty() && points.back().film.converged() ? &points.back().film : nullptr;
    point.film = solve_mixed_film(op, gap, scaled, laws, options, previous);
    points.push_back(std::move(point));
  }
  return points;
}

}  // namespace halfspace::lubrication
