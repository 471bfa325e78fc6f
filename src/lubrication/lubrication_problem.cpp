// The rules of a lubricated film, checked in the order control, flow, body,
// film kind, shear, lubricant and solver (the body decides the film; the
// film which options it takes). Numbers are shown with six digits
// (format_number).
#include "halfspace/lubrication/lubrication_problem.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <climits>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "../problem_rules.hpp"

namespace halfspace::lubrication {
namespace {

// The Newton steps an elastic or mixed film may be given: the range
// `halfspace lubricate` has always held (Python now shares it).
constexpr long long kMaxNewtonSteps = 100000;
// The time steps of a transient film: each is at least one film solve.
constexpr long long kMaxTimeSteps = 10'000'000;

using O = LubricationProblemOptions;

constexpr std::array kNames{
    LubricationOptionName{"viscosity", &O::viscosity},
    LubricationOptionName{"entrainment_velocity", &O::entrainment_velocity},
    LubricationOptionName{"sliding_velocity", &O::sliding_velocity},
    LubricationOptionName{"separation", &O::separation},
    LubricationOptionName{"force", &O::force},
    LubricationOptionName{"inlet_pressure", &O::inlet_pressure},
    LubricationOptionName{"outlet_pressure", &O::outlet_pressure},
    LubricationOptionName{"side_pressure", &O::side_pressure},
    LubricationOptionName{"periodic_x", &O::periodic_x},
    LubricationOptionName{"periodic_y", &O::periodic_y},
    LubricationOptionName{"supply_fluid_fraction", &O::supply_fluid_fraction},
    LubricationOptionName{"tolerance", &O::tolerance},
    LubricationOptionName{"max_iterations", &O::max_iterations},
    LubricationOptionName{"e_star", &O::e_star},
    LubricationOptionName{"E1", &O::e1},
    LubricationOptionName{"nu1", &O::nu1},
    LubricationOptionName{"E2", &O::e2},
    LubricationOptionName{"nu2", &O::nu2},
    LubricationOptionName{"layer_thickness", &O::layer_thickness},
    LubricationOptionName{"layer_E", &O::layer_e},
    LubricationOptionName{"layer_nu", &O::layer_nu},
    LubricationOptionName{"substrate_E", &O::substrate_e},
    LubricationOptionName{"substrate_nu", &O::substrate_nu},
    LubricationOptionName{"boundary", &O::boundary},
    LubricationOptionName{"pressure_viscosity", &O::pressure_viscosity},
    LubricationOptionName{"piezoviscosity", &O::piezoviscosity},
    LubricationOptionName{"roelands_index", &O::roelands_index},
    LubricationOptionName{"compressibility", &O::compressibility},
    LubricationOptionName{"couette_scheme", &O::couette_scheme},
    LubricationOptionName{"film_preconditioner", &O::film_preconditioner},
    LubricationOptionName{"fft_planning", &O::fft_planning},
    LubricationOptionName{"eyring_stress", &O::eyring_stress},
    LubricationOptionName{"limiting_shear_stress", &O::limiting_shear_stress},
    LubricationOptionName{"limiting_shear_slope", &O::limiting_shear_slope},
    LubricationOptionName{"mixed", &O::mixed},
    LubricationOptionName{"offset", &O::offset},
    LubricationOptionName{"contact_friction", &O::contact_friction},
    LubricationOptionName{"boundary_film", &O::boundary_film},
    LubricationOptionName{"speeds", &O::speeds},
    LubricationOptionName{"time_step", &O::time_step},
    LubricationOptionName{"steps", &O::steps},
    LubricationOptionName{"time_scheme", &O::time_scheme},
    LubricationOptionName{"approach_velocity", &O::approach_velocity},
    LubricationOptionName{"separation_history", &O::separation_history},
};

class Rules : public halfspace::detail::Checks {
 public:
  Rules(const LubricationProblemOptions& options, const OptionSpelling& spelling) : Checks(spelling), o_(options) {}

  // A library parse of a named option's text, its error prefixed by the
  // option and its value.
  template <class Parse>
  auto parsed(std::string_view option, const std::string& value, Parse&& parse) const {
    return in_context(s_.describe(option, "'" + value + "'"), [&] { return parse(value); });
  }

  void control() const;
  std::optional<TransientFilmOptions> transient() const;
  FilmKind kind(bool elastic, bool coated) const;
  FlowConditions conditions() const;
  LubricantLaws laws() const;
  int max_iterations(bool newton) const;

 private:
  const LubricationProblemOptions& o_;
};

// Exactly one of the separation (rigid), the force and the offset (mixed);
// the mixed film's options only with it.
void Rules::control() const {
  const int controls = o_.separation.has_value() + o_.force.has_value() + o_.offset.has_value();
  if (o_.time_step && !o_.mixed) {
    // Its driver (the force among them) is checked by transient().
    if (!o_.separation) {
      throw InputError(fmt::format("a transient film ({}) starts at a separation: pass {}", name("time_step"),
                                   s_.describe("separation", "M")));
    }
  } else if (controls != 1) {
    throw InputError(
        o_.mixed
            ? fmt::format("give exactly one of {} and {}", s_.describe("force", "N"), s_.describe("offset", "M"))
            : fmt::format("give exactly one of {} and {}", s_.describe("separation", "M"), s_.describe("force", "N")));
  }
  if (!o_.mixed && (o_.offset || o_.contact_friction || o_.boundary_film || o_.speeds)) {
    throw InputError(fmt::format("{} belong to the mixed film: add {}",
                                 fmt::join(names({"offset", "contact_friction", "boundary_film", "speeds"}), ", "),
                                 name("mixed")));
  }
}

// The transient rigid film: the time step and one driver of the separation
// (the approach velocity, the history or the force), the steps unless the
// history counts them.
std::optional<TransientFilmOptions> Rules::transient() const {
  const std::vector<std::string> present = given({{"steps", o_.steps.has_value()},
                                                  {"time_scheme", o_.time_scheme.has_value()},
                                                  {"approach_velocity", o_.approach_velocity.has_value()},
                                                  {"separation_history", o_.separation_history.has_value()}});
  if (!o_.time_step) {
    if (!present.empty()) {
      throw InputError(fmt::format("{} belong to a transient film: add {}", fmt::join(present, ", "),
                                   s_.describe("time_step", "DT")));
    }
    return std::nullopt;
  }
  const int drivers = o_.approach_velocity.has_value() + o_.separation_history.has_value() + o_.force.has_value();
  if (drivers != 1) {
    throw InputError(fmt::format("a transient film takes exactly one of {}, {} and {}",
                                 s_.describe("approach_velocity", "V"), s_.describe("separation_history", "S1,S2,..."),
                                 s_.describe("force", "N")));
  }
  TransientFilmOptions t;
  t.time_step = *o_.time_step;
  t.initial_separation = *o_.separation;
  if (o_.time_scheme) t.scheme = parsed("time_scheme", *o_.time_scheme, parse_time_scheme);
  t.approach_velocity = o_.approach_velocity;
  t.separation_history = o_.separation_history;
  if (o_.separation_history) {
    const auto count = static_cast<long long>(o_.separation_history->size());
    if (o_.steps && *o_.steps != count) {
      throw InputError(fmt::format("{} has {} separations but {}: give one separation a step (or drop {})",
                                   name("separation_history"), count,
                                   s_.describe("steps", fmt::format("{}", *o_.steps)), name("steps")));
    }
    t.steps = static_cast<int>(std::min<long long>(count, INT_MAX));
  } else {
    if (!o_.steps) throw InputError(fmt::format("a transient film needs {}", s_.describe("steps", "N")));
    if (*o_.steps < 1 || *o_.steps > kMaxTimeSteps) {
      throw OptionError("steps", fmt::format("{}", *o_.steps),
                        fmt::format("is invalid: allowed range is 1 to {}", kMaxTimeSteps));
    }
    t.steps = static_cast<int>(*o_.steps);
  }
  if (o_.force) t.load = LoadControlOptions{.load = *o_.force};
  t.validate();
  return t;
}

// The film the body makes, and the options only an elastic film takes.
FilmKind Rules::kind(bool elastic, bool coated) const {
  const std::string bodies =
      fmt::format("{} (or {})", name("e_star"), fmt::join(names({"E1", "nu1", "E2", "nu2"}), ", "));
  if (o_.time_step && (elastic || o_.mixed)) {
    throw InputError(
        fmt::format("{} steps a rigid film only: the elastic and mixed films are steady (drop {}, "
                    "or {} and the body's moduli)",
                    name("time_step"), name("time_step"), name("mixed")));
  }
  if (o_.mixed) {
    if (!elastic) throw InputError(fmt::format("{} needs an elastic body: give {}", name("mixed"), bodies));
    if (coated) {
      throw InputError(fmt::format(
          "{} takes a homogeneous body: a coating is not supported by the mixed film yet "
          "(drop {})",
          name("mixed"),
          fmt::join(names({"layer_thickness", "layer_E", "layer_nu", "substrate_E", "substrate_nu"}), ", ")));
    }
  }
  if (!elastic) {
    const std::vector<std::string> present = given({{"pressure_viscosity", o_.pressure_viscosity.has_value()},
                                                    {"piezoviscosity", o_.piezoviscosity.has_value()},
                                                    {"roelands_index", o_.roelands_index.has_value()},
                                                    {"compressibility", o_.compressibility.has_value()},
                                                    {"couette_scheme", o_.couette_scheme.has_value()},
                                                    {"film_preconditioner", o_.film_preconditioner.has_value()},
                                                    {"fft_planning", o_.fft_planning.has_value()},
                                                    {"boundary", o_.boundary.has_value()}});
    if (!present.empty()) {
      throw InputError(fmt::format(
          "{} need an elastic film: give {} (or {}, or a coated body, {})", fmt::join(present, ", "), name("e_star"),
          fmt::join(names({"E1", "nu1", "E2", "nu2"}), ", "),
          fmt::join(names({"layer_thickness", "layer_E", "layer_nu", "substrate_E", "substrate_nu"}), ", ")));
    }
    return FilmKind::rigid;
  }
  if (o_.mixed) {
    if (o_.film_preconditioner) {
      throw InputError(
          fmt::format("{} applies to the EHL film without {}: the mixed film's preconditioner is "
                      "its sparse LU with the contact rows",
                      s_.describe("film_preconditioner", *o_.film_preconditioner), name("mixed")));
    }
    if (o_.separation) {
      throw InputError(fmt::format("{} is the rigid film's: the mixed film takes {} or {}", name("separation"),
                                   s_.describe("force", "N"), s_.describe("offset", "M")));
    }
    if (o_.speeds && !o_.force) {
      throw InputError(
          fmt::format("a Stribeck sweep ({}) is load controlled: pass {}", name("speeds"), s_.describe("force", "N")));
    }
    return FilmKind::mixed;
  }
  if (!o_.force) {
    throw InputError(fmt::format("an elastic film (EHL) is load controlled: pass {}, not {}", s_.describe("force", "N"),
                                 name("separation")));
  }
  return FilmKind::elastic;
}

FlowConditions Rules::conditions() const {
  if (!o_.viscosity) throw InputError(fmt::format("no viscosity given: pass {}", s_.describe("viscosity", "PA_S")));
  if (!o_.entrainment_velocity) {
    throw InputError(
        fmt::format("no entrainment velocity given: pass {}", s_.describe("entrainment_velocity", "UX[,UY]")));
  }
  const auto velocity = [&](std::string_view option, const std::optional<std::vector<double>>& given) {
    if (!given) return std::array<double, 2>{0.0, 0.0};
    if (given->empty() || given->size() > 2) {
      throw InputError(fmt::format("{} has {} values: give UX or UX,UY (m/s)", name(option), given->size()));
    }
    return std::array<double, 2>{(*given)[0], given->size() == 2 ? (*given)[1] : 0.0};
  };
  FlowConditions conditions;
  conditions.viscosity = *o_.viscosity;
  conditions.entrainment_velocity = velocity("entrainment_velocity", o_.entrainment_velocity);
  conditions.sliding_velocity = velocity("sliding_velocity", o_.sliding_velocity);
  FlowBoundary& boundary = conditions.boundary;
  boundary.x = o_.periodic_x ? AxisBoundary::periodic : AxisBoundary::fixed_pressure;
  boundary.y = o_.periodic_y ? AxisBoundary::periodic : AxisBoundary::fixed_pressure;
  boundary.x_low_pressure = o_.inlet_pressure.value_or(0.0);
  boundary.x_high_pressure = o_.outlet_pressure.value_or(0.0);
  boundary.y_low_pressure = o_.side_pressure.value_or(0.0);
  boundary.y_high_pressure = o_.side_pressure.value_or(0.0);
  boundary.supply_fluid_fraction = o_.supply_fluid_fraction.value_or(1.0);
  return conditions;
}

// Barus when alpha is given without a law; Dowson-Higginson unless told.
LubricantLaws Rules::laws() const {
  LubricantLaws laws;
  laws.pressure_viscosity = o_.pressure_viscosity.value_or(0.0);
  laws.roelands_index = o_.roelands_index.value_or(0.0);
  laws.piezoviscosity = o_.piezoviscosity ? parsed("piezoviscosity", *o_.piezoviscosity, parse_piezoviscosity)
                        : laws.pressure_viscosity > 0.0 ? Piezoviscosity::barus
                                                        : Piezoviscosity::none;
  laws.compressibility = o_.compressibility ? parsed("compressibility", *o_.compressibility, parse_compressibility)
                                            : Compressibility::dowson_higginson;
  return laws;
}

// The film solver's limit: sweeps of the rigid film (beyond int, no limit:
// validate() sees the nearest int), Newton steps of the others.
int Rules::max_iterations(bool newton) const {
  const long long given = *o_.max_iterations;
  if (newton && (given < 1 || given > kMaxNewtonSteps)) {
    throw OptionError("max_iterations", fmt::format("{}", given),
                      fmt::format("is invalid: allowed range is 1 to {}", kMaxNewtonSteps));
  }
  return static_cast<int>(std::clamp<long long>(given, INT_MIN, INT_MAX));
}

// The option of LubricationProblemOptions that sets each member a film's
// OptionError names, and the component of a velocity.
std::pair<std::string_view, std::string_view> problem_name(std::string_view member) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 7> kMembers{{
      {"initial_separation", "separation"},
      {"boundary.x_low_pressure", "inlet_pressure"},
      {"boundary.x_high_pressure", "outlet_pressure"},
      {"boundary.y_low_pressure", "side_pressure"},
      {"boundary.y_high_pressure", "side_pressure"},
      {"boundary.supply_fluid_fraction", "supply_fluid_fraction"},
      {"load", "force"},
  }};
  for (const std::string_view velocity : {"entrainment_velocity", "sliding_velocity"}) {
    if (!member.starts_with(velocity)) continue;
    return {velocity, member.ends_with(".x") ? " (x component)" : member.ends_with(".y") ? " (y component)" : ""};
  }
  for (const auto& [known, option] : kMembers) {
    if (known == member) return {option, ""};
  }
  return {member, ""};  // viscosity, separation, tolerance, max_iterations, offset, speeds, ...
}

}  // namespace

InputError spelled_film_error(const OptionError& error, const OptionSpelling& spelling) {
  const auto [option, component] = problem_name(error.option());
  return InputError(fmt::format("{}{} {}", spelling.describe(option, error.value()), component, error.rule()));
}

LubricationProblem make_lubrication_problem(const LubricationProblemOptions& options, const OptionSpelling& spelling) {
  const Rules rules(options, spelling);
  const LubricationProblemOptions& o = options;
  try {
    LubricationProblem problem;
    rules.control();
    problem.conditions = rules.conditions();
    const std::optional<ProblemBody> body = make_body(o, spelling);  // none: a rigid film
    if (body) {
      problem.e_star = body->e_star;
      problem.coating = body->coating;
    }
    problem.kind = rules.kind(body.has_value(), problem.coating.has_value());
    problem.transient = rules.transient();
    problem.limits = {o.eyring_stress.value_or(0.0), o.limiting_shear_stress.value_or(0.0),
                      o.limiting_shear_slope.value_or(0.0)};
    problem.limits.validate();
    if (problem.kind == FilmKind::rigid) {
      if (o.tolerance) problem.cavitation.tolerance = *o.tolerance;
      if (o.max_iterations) problem.cavitation.max_iterations = rules.max_iterations(false);
      problem.cavitation.validate();
      problem.separation = o.separation;
      if (o.force && !problem.transient) {
        problem.load_control = LoadControlOptions{.load = *o.force};
        problem.load_control->validate();
      }
      return problem;
    }
    if (o.boundary) problem.boundary = in_context(rules.name("boundary"), [&] { return parse_boundary(*o.boundary); });
    problem.laws = rules.laws();
    if (o.fft_planning) problem.fft_planning = rules.parsed("fft_planning", *o.fft_planning, parse_fft_planning);
    const std::optional<CouetteScheme> scheme =
        o.couette_scheme ? std::optional(rules.parsed("couette_scheme", *o.couette_scheme, parse_couette_scheme))
                         : std::nullopt;
    if (problem.kind == FilmKind::elastic) {
      ElasticFilmOptions& elastic = problem.elastic;
      elastic.load = *o.force;
      if (o.tolerance) elastic.tolerance = *o.tolerance;
      if (o.max_iterations) elastic.max_iterations = rules.max_iterations(true);
      if (scheme) elastic.couette_scheme = *scheme;
      if (o.film_preconditioner) {
        elastic.preconditioner =
            rules.parsed("film_preconditioner", *o.film_preconditioner, parse_krylov_preconditioner);
      }
      elastic.validate();
      return problem;
    }
    MixedFilmOptions& mixed = problem.mixed;
    mixed.load = o.force.value_or(0.0);
    mixed.offset = o.offset.value_or(0.0);
    if (o.boundary_film) mixed.boundary_film = *o.boundary_film;
    if (o.tolerance) mixed.tolerance = *o.tolerance;
    if (o.max_iterations) mixed.max_iterations = rules.max_iterations(true);
    if (scheme) mixed.couette_scheme = *scheme;
    if (o.contact_friction) mixed.friction.contact_friction = *o.contact_friction;
    mixed.friction.shear = problem.limits;
    mixed.validate();
    problem.speeds = o.speeds;
    return problem;
  } catch (const OptionError& error) {
    throw spelled_film_error(error, spelling);
  }
}

std::string LubricationProblem::failure_hint(const OptionSpelling& spelling) const {
  const auto name = [&](std::string_view option) { return spelling.name(option); };
  const auto solver = [&](int max_iterations, double tolerance) {
    return fmt::format("more {} (now {}) or a looser {} (now {:g})", name("max_iterations"), max_iterations,
                       name("tolerance"), tolerance);
  };
  if (kind == FilmKind::rigid) {
    return "to try: " + solver(cavitation.max_iterations, cavitation.tolerance);
  }
  if (kind == FilmKind::elastic) {
    return fmt::format(
        "to try: a faster {} or a smaller {} first (a thicker film converges more easily), {}, or {} sparse-lu "
        "(exact, on small grids)",
        name("entrainment_velocity"), name("force"), solver(elastic.max_iterations, elastic.tolerance),
        name("film_preconditioner"));
  }
  if (!mixed.load_controlled()) {
    return fmt::format("to try: a larger {} (a thicker film), a faster {}, {}", name("offset"),
                       name("entrainment_velocity"), solver(mixed.max_iterations, mixed.tolerance));
  }
  return fmt::format(
      "to try: {} from a faster speed down to this one (each film starts from the last; finer steps where one "
      "fails), a smaller {}, {}",
      name("speeds"), name("force"), solver(mixed.max_iterations, mixed.tolerance));
}

void LubricationProblem::check_grid(const Grid& grid, const OptionSpelling& spelling, std::string_view surface,
                                    std::size_t nodes) const {
  // A film periodic along every axis has no pressure level and no supply:
  // named here by the options that made it so (FlowConditions::validate
  // cannot name them).
  const FlowBoundary& flow = conditions.boundary;
  const bool y_periodic = grid.dimension() == 1 || flow.y == AxisBoundary::periodic;
  if (flow.x == AxisBoundary::periodic && y_periodic) {
    throw InputError(fmt::format(
        "{}: the film is periodic along every axis: fix the pressures along one axis (a film periodic in every "
        "direction has no pressure level and no supply)",
        grid.dimension() == 1 ? fmt::format("{} on a 1D grid", spelling.name("periodic_x"))
                              : fmt::format("{} with {}", spelling.name("periodic_x"), spelling.name("periodic_y"))));
  }
  try {
    conditions.validate(grid);
    if (kind != FilmKind::rigid) laws.validate(conditions.viscosity);
  } catch (const OptionError& error) {
    throw spelled_film_error(error, spelling);
  }
  if (kind == FilmKind::mixed) require_mixed_film_fits(grid, mixed, surface, nodes);
}

std::span<const LubricationOptionName> lubrication_option_names() {
  return kNames;
}

}  // namespace halfspace::lubrication
