// The rules of a frictional solve's options (friction_options.hpp), each
// broken one a SolverOptionError naming the option so that a front end can
// restate it with its own flag or keyword.
#include "halfspace/solvers/friction_options.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "halfspace/operators/tangential_operator.hpp"
#include "halfspace/solvers/adhesion_law.hpp"

namespace halfspace::solvers {
namespace {

std::string number(double value) {
  return fmt::format("{}", value);
}

std::string loading_text(const TangentialLoading& loading) {
  return fmt::format("{},{}", loading.x, loading.y);
}

std::string_view load_unit(const TangentialLoading& loading, const Grid* grid) {
  if (loading.control == TangentialControl::displacement) return "m";
  return grid != nullptr && grid->dimension() == 1 ? "N/m" : "N";
}

}  // namespace

TangentialOptions FrictionOptions::tangential_options(const std::size_t& current) const {
  TangentialOptions options = tangential;
  if (progress) {
    options.progress = [this, &current](int iteration, double residual) {
      return progress(current, iteration, residual);
    };
  }
  return options;
}

void FrictionOptions::validate() const {
  tangential.validate();
  const double friction_coefficient = tangential.friction_coefficient;
  if (sliding_direction && !history.empty()) {
    throw SolverOptionError("sliding", fmt::format("{},{}", (*sliding_direction)[0], (*sliding_direction)[1]),
                            "cannot be combined with a tangential load: gross sliding is its own step (mu P along "
                            "the direction)");
  }
  if (!sliding_direction && history.empty()) {
    throw SolverOptionError("friction", number(friction_coefficient),
                            "needs a tangential load (a force or a tangential displacement) or a sliding direction");
  }
  for (std::size_t k = 0; k < history.size(); ++k) {
    const TangentialLoading& step = history[k];
    if (!(std::isfinite(step.x) && std::isfinite(step.y))) {
      throw SolverOptionError("tangential_load", loading_text(step),
                              fmt::format("is invalid: step {} is not finite", k + 1));
    }
  }
  if (sliding_direction) {
    const auto [x, y] = *sliding_direction;
    if (!(std::isfinite(x) && std::isfinite(y) && std::hypot(x, y) > 0.0)) {
      throw SolverOptionError("sliding", fmt::format("{},{}", x, y),
                              "is invalid: the direction must be finite and not zero");
    }
    if (!(friction_coefficient > 0.0)) {
      throw SolverOptionError("friction", number(friction_coefficient),
                              "is invalid for sliding: without friction (mu = 0) there is no sliding force");
    }
  }
  if (normal_load_steps < 1) {
    throw SolverOptionError("normal_load_steps", fmt::format("{}", normal_load_steps),
                            "is invalid: must be at least 1");
  }
  coupled_step.validate();
}

void FrictionOptions::validate(const SolverOptions& normal) const {
  validate();
  if (normal.adhesion) {
    throw SolverOptionError("adhesion", std::string(to_string(normal.adhesion->law.type)),
                            "cannot be combined with friction: Coulomb's bound mu p needs a compressive pressure, "
                            "and the cohesive law's tensile tractions are not yet coupled with the shear");
  }
}

void FrictionOptions::validate(const Grid& grid, const SolverOptions& normal, const Loading& loading) const {
  validate(normal);
  if (grid.dimension() == 1) {
    for (const TangentialLoading& step : history) {
      if (step.y != 0.0) {
        throw SolverOptionError("tangential_load", loading_text(step),
                                "is invalid on a 1D grid: the y component must be zero (a line contact is loaded "
                                "along x)");
      }
    }
    if (sliding_direction && (*sliding_direction)[1] != 0.0) {
      throw SolverOptionError("sliding", fmt::format("{},{}", (*sliding_direction)[0], (*sliding_direction)[1]),
                              "is invalid on a 1D grid: the direction must be along x (y = 0)");
    }
  }
  if (loading.load_controlled()) {
    // The force the normal solve will carry; beyond mu P no partial slip exists.
    const double limit = tangential.friction_coefficient * loading.target_force(grid.domain_area());
    for (std::size_t k = 0; k < history.size(); ++k) {
      const TangentialLoading& step = history[k];
      if (step.control != TangentialControl::force) continue;
      const double force = std::hypot(step.x, step.y);
      if (force > limit * (1.0 + 1e-9)) {
        throw SolverOptionError(
            "tangential_load", loading_text(step),
            fmt::format("is invalid: step {} asks for |Q| = {:g} {} beyond mu P = {:g} {}, where the contact slides "
                        "(use a tangential displacement, or sliding)",
                        k + 1, force, load_unit(step, &grid), limit, load_unit(step, &grid)));
      }
    }
  }
}

void FrictionOptions::check_body(const Grid& grid, const ElasticPair& pair) {
  if (const std::string refusal = operators::coated_free_grid_refusal(grid, pair); !refusal.empty()) {
    throw SolverOptionError("coating", "given", fmt::format("cannot be combined with friction here: {}", refusal));
  }
}

void FrictionOptions::refuse_composite_modulus_only() {
  throw SolverOptionError("pair", "E* only",
                          "does not fix the tangential compliance: friction needs each body's E and nu (E1, nu1, E2, "
                          "nu2; a rigid body 2 is E2 = inf)");
}

}  // namespace halfspace::solvers
