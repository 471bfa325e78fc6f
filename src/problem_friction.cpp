// The friction rules of a contact problem (Rules::friction, problem_rules.hpp):
// mu, one tangential load, one normal load, each body's constants, then
// FrictionOptions::validate, named by the problem's options.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <climits>

#include "problem_rules.hpp"

namespace halfspace::detail {

std::string_view friction_name(std::string_view member, const solvers::FrictionOptions& friction) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 6> kMembers{{
      {"sliding", "sliding"},
      {"tolerance", "tangential_tol"},
      {"max_iterations", "tangential_max_iter"},
      {"release_period", "tangential_release_period"},
      {"active_set_updates", "tangential_active_set"},
      {"normal_load_steps", "normal_load_steps"},
  }};
  if (member == "tangential_load") {
    const bool displacement =
        !friction.history.empty() && friction.history.front().control == solvers::TangentialControl::displacement;
    return displacement ? "tangential_displacement" : "tangential_force";
  }
  for (const auto& [known, name] : kMembers) {
    if (known == member) return name;
  }
  return "friction";
}

// Friction: the tangential loads and the settings need mu; exactly one
// tangential load; one normal load; each body's constants; then
// FrictionOptions::validate(normal), named by the problem's options.
std::optional<solvers::FrictionOptions> Rules::friction(const solvers::SolverOptions& normal, std::size_t loads) const {
  const Presence tangential = presence({"tangential_force", "tangential_displacement", "sliding"});
  const Presence settings =
      presence({"tangential_tol", "tangential_max_iter", "tangential_release_period", "tangential_active_set",
                "tangential_coarse_start", "coupling", "normal_load_steps"});
  const std::string mu = o_.friction ? describe("friction", *o_.friction) : std::string();
  if (!o_.friction) {
    for (const Presence& options : {tangential, settings}) {
      const auto first = std::ranges::find(options, true, &Presence::value_type::second);
      if (first == options.end()) continue;
      throw InputError(fmt::format("{} needs {} (the Coulomb friction coefficient)",
                                   s_.describe(first->first, *value(first->first)), s_.describe("friction", "MU")));
    }
    return std::nullopt;
  }
  std::vector<std::string> loads_given;
  for (const auto& [option, is_given] : tangential) {
    if (is_given) loads_given.push_back(s_.describe(option, *value(option)));
  }
  if (loads_given.empty()) {
    throw InputError(fmt::format("{} needs a tangential load: {} QX[,QY], {} DX[,DY] or {} X,Y", mu,
                                 name("tangential_force"), name("tangential_displacement"), name("sliding")));
  }
  if (loads_given.size() > 1) {
    throw InputError(fmt::format("{} cannot be combined: give one of {}, {}, {}", fmt::join(loads_given, " and "),
                                 name("tangential_force"), name("tangential_displacement"), name("sliding")));
  }
  if (loads > 1) {
    throw InputError(fmt::format("{} takes one normal load, not a load sweep: give a single {}, {} or {}", mu,
                                 name("force"), name("mean_pressure"), name("approach")));
  }
  // What the friction slice does not support, refused before the options
  // are read (a coating's rule needs the grid: Problem::check_grid).
  try {
    if (o_.e_star) solvers::FrictionOptions::refuse_composite_modulus_only();
  } catch (const solvers::SolverOptionError& error) {
    throw InputError(fmt::format("{} with {}: {} {}", mu, describe("e_star", *o_.e_star), error.value(), error.rule()));
  }
  solvers::FrictionOptions friction;
  friction.tangential.friction_coefficient = *o_.friction;
  const auto steps = [&](std::string_view option, const std::vector<std::array<double, 2>>& given,
                         solvers::TangentialControl control) {
    if (given.empty()) throw OptionError(std::string(option), "", "is invalid: give at least one step");
    for (const auto& [x, y] : given) friction.history.push_back({control, x, y});
  };
  if (o_.tangential_force) steps("tangential_force", *o_.tangential_force, solvers::TangentialControl::force);
  if (o_.tangential_displacement) {
    steps("tangential_displacement", *o_.tangential_displacement, solvers::TangentialControl::displacement);
  }
  if (o_.sliding) {
    if (o_.sliding->size() != 2)
      throw OptionError("sliding", text(*o_.sliding), "is invalid: expected a direction X,Y");
    friction.sliding_direction = {(*o_.sliding)[0], (*o_.sliding)[1]};
  }
  if (o_.tangential_tol) friction.tangential.tolerance = *o_.tangential_tol;
  // Beyond int, a limit is no limit: validate() sees the nearest int.
  const auto clamped = [](long long value) { return static_cast<int>(std::clamp<long long>(value, INT_MIN, INT_MAX)); };
  if (o_.tangential_max_iter) friction.tangential.max_iterations = clamped(*o_.tangential_max_iter);
  if (o_.tangential_release_period) friction.tangential.release_period = clamped(*o_.tangential_release_period);
  if (o_.tangential_active_set) friction.tangential.active_set_updates = clamped(*o_.tangential_active_set);
  if (o_.normal_load_steps) friction.normal_load_steps = clamped(*o_.normal_load_steps);
  if (o_.tangential_coarse_start) {
    const std::string& value = *o_.tangential_coarse_start;
    if (value == "automatic") {
      friction.tangential.coarse_start = solvers::TangentialCoarseStart::automatic;
    } else if (value == "on" || value == "off") {
      friction.tangential.coarse_start =
          value == "on" ? solvers::TangentialCoarseStart::on : solvers::TangentialCoarseStart::off;
    } else {
      throw OptionError("tangential_coarse_start", value, "is invalid: allowed values are on, off and automatic");
    }
  }
  if (o_.coupling) friction.coupling = on_off("coupling", *o_.coupling);
  try {
    friction.validate(normal);
  } catch (const solvers::SolverOptionError& error) {
    if (error.option() == "adhesion") {
      throw InputError(fmt::format("{} {} ({})", s_.describe("adhesion", *o_.adhesion), error.rule(), mu));
    }
    throw OptionError(std::string(friction_name(error.option(), friction)), error.value(), error.rule());
  }
  return friction;
}

}  // namespace halfspace::detail
