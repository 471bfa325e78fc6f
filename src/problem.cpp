// The rules of a contact problem, checked in the order body, interface law
// and solver, load, friction, threads (the law decides whether loads are
// signed; friction needs the solver and the loads). Numbers are shown with
// six digits (format_number).
#include "halfspace/problem.hpp"

#include <fmt/ranges.h>

#include <Eigen/Core>
#include <algorithm>
#include <climits>
#include <tuple>

#include "halfspace/threads.hpp"
#include "problem_rules.hpp"

namespace halfspace {
namespace {

using P = ProblemOptions;

constexpr std::array kNames{
    ProblemOptionName{"e_star", &P::e_star},
    ProblemOptionName{"E1", &P::e1},
    ProblemOptionName{"nu1", &P::nu1},
    ProblemOptionName{"E2", &P::e2},
    ProblemOptionName{"nu2", &P::nu2},
    ProblemOptionName{"layer_thickness", &P::layer_thickness},
    ProblemOptionName{"layer_E", &P::layer_e},
    ProblemOptionName{"layer_nu", &P::layer_nu},
    ProblemOptionName{"substrate_E", &P::substrate_e},
    ProblemOptionName{"substrate_nu", &P::substrate_nu},
    ProblemOptionName{"hardness", &P::hardness},
    ProblemOptionName{"adhesion", &P::adhesion},
    ProblemOptionName{"work_of_adhesion", &P::work_of_adhesion},
    ProblemOptionName{"adhesion_range", &P::adhesion_range},
    ProblemOptionName{"adhesion_stress", &P::adhesion_stress},
    ProblemOptionName{"adhesion_tol", &P::adhesion_tol},
    ProblemOptionName{"adhesion_precondition", &P::adhesion_precondition},
    ProblemOptionName{"force", &P::force},
    ProblemOptionName{"mean_pressure", &P::mean_pressure},
    ProblemOptionName{"approach", &P::approach},
    ProblemOptionName{"friction", &P::friction},
    ProblemOptionName{"tangential_force", &P::tangential_force},
    ProblemOptionName{"tangential_displacement", &P::tangential_displacement},
    ProblemOptionName{"sliding", &P::sliding},
    ProblemOptionName{"tangential_tol", &P::tangential_tol},
    ProblemOptionName{"tangential_max_iter", &P::tangential_max_iter},
    ProblemOptionName{"tangential_release_period", &P::tangential_release_period},
    ProblemOptionName{"tangential_active_set", &P::tangential_active_set},
    ProblemOptionName{"tangential_coarse_start", &P::tangential_coarse_start},
    ProblemOptionName{"coupling", &P::coupling},
    ProblemOptionName{"normal_load_steps", &P::normal_load_steps},
    ProblemOptionName{"solver", &P::solver},
    ProblemOptionName{"tol", &P::tol},
    ProblemOptionName{"max_iter", &P::max_iter},
    ProblemOptionName{"fft_planning", &P::fft_planning},
    ProblemOptionName{"precision", &P::precision},
    ProblemOptionName{"deflation_block", &P::deflation_block},
    ProblemOptionName{"active_set", &P::active_set},
    ProblemOptionName{"threads", &P::threads},
};

}  // namespace

namespace detail {

InputError spelled(const OptionError& error, const OptionSpelling& spelling) {
  return InputError(fmt::format("{} {}", spelling.describe(error.option(), error.value()), error.rule()));
}

std::string_view problem_name(std::string_view member) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 8> kMembers{{
      {"tolerance", "tol"},
      {"max_iterations", "max_iter"},
      {"type", "solver"},
      {"adhesion.work", "work_of_adhesion"},
      {"adhesion.range", "adhesion_range"},
      {"adhesion.tolerance", "adhesion_tol"},
      {"hardness", "hardness"},
      {"precision", "precision"},
  }};
  if (member.starts_with("deflation")) return "deflation_block";
  if (member.starts_with("active_set") || member == "multilevel.active_set") return "active_set";
  for (const auto& [known, name] : kMembers) {
    if (known == member) return name;
  }
  return "solver";
}

std::string text(const std::vector<double>& values) {
  std::vector<std::string> parts;
  for (const double value : values) parts.push_back(format_number(value));
  return fmt::format("{}", fmt::join(parts, ","));
}
std::string text(const std::vector<std::array<double, 2>>& steps) {
  std::vector<std::string> parts;
  for (const auto& [x, y] : steps) parts.push_back(format_number(x) + "," + format_number(y));
  return fmt::format("{}", fmt::join(parts, ";"));
}

std::optional<std::string> Rules::value(std::string_view option) const {
  const auto found = std::ranges::find(kNames, option, &ProblemOptionName::name);
  return std::visit(
      [&](auto member) -> std::optional<std::string> {
        const auto& field = o_.*member;
        if (!field) return std::nullopt;
        return text(*field);
      },
      found->field);
}

// The load mode and every value of the load (one for a single solve, more
// for a sweep).
std::pair<Loading, std::vector<double>> Rules::loads() const {
  const std::vector<std::string> present = given({{"force", o_.force.has_value()},
                                                  {"mean_pressure", o_.mean_pressure.has_value()},
                                                  {"approach", o_.approach.has_value()}});
  if (present.empty()) {
    throw InputError(
        fmt::format("no load given: pass one of {}, {}, {}", name("force"), name("mean_pressure"), name("approach")));
  }
  if (present.size() > 1) {
    throw InputError(fmt::format("{} cannot be combined: give exactly one of {}, {}, {}", fmt::join(present, " and "),
                                 name("force"), name("mean_pressure"), name("approach")));
  }
  const auto [option, mode, unit, values] =
      o_.force           ? std::tuple{"force", ControlMode::force, "N in 2D, N/m in 1D", *o_.force}
      : o_.mean_pressure ? std::tuple{"mean_pressure", ControlMode::mean_pressure, "Pa", *o_.mean_pressure}
                         : std::tuple{"approach", ControlMode::approach, "m", *o_.approach};
  if (values.empty()) throw OptionError(option, "", "is invalid: give at least one value");
  // With adhesion any finite value is a load: the approach of surfaces
  // apart (negative), or a pull (a negative force).
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (o_.adhesion) {
      if (!std::isfinite(values[k])) {
        throw OptionError(option, text(values), fmt::format("is invalid: every value must be finite ({})", unit));
      }
    } else if (values.size() == 1) {
      positive(option, values[k], unit);
    } else if (!(std::isfinite(values[k]) && values[k] > 0.0)) {
      throw OptionError(option, text(values),
                        fmt::format("is invalid: every value must be positive ({}); value {} is {}", unit, k + 1,
                                    format_number(values[k])));
    }
  }
  return {Loading{mode, values.front()}, values};
}

// The cohesive law made from its parameters: the work and the range or,
// for Maugis-Dugdale, the stress sigma0 = w / h0.
std::optional<solvers::SolverOptions::Adhesion> Rules::adhesion() const {
  if (!o_.adhesion) {
    const std::vector<std::string> present = given({{"work_of_adhesion", o_.work_of_adhesion.has_value()},
                                                    {"adhesion_range", o_.adhesion_range.has_value()},
                                                    {"adhesion_stress", o_.adhesion_stress.has_value()},
                                                    {"adhesion_tol", o_.adhesion_tol.has_value()},
                                                    {"adhesion_precondition", o_.adhesion_precondition.has_value()}});
    if (!present.empty())
      throw InputError(fmt::format("{} needs {} md|exponential", present.front(), name("adhesion")));
    return std::nullopt;
  }
  const std::string adhesion = s_.describe("adhesion", *o_.adhesion);
  const AdhesionLawType type =
      in_context(name("adhesion"), [&] { return solvers::parse_adhesion_law_type(*o_.adhesion); });
  if (o_.solver) {
    throw InputError(fmt::format("{} cannot be combined with {}: adhesion has its own solver (adhesive-pcg)",
                                 s_.describe("solver", *o_.solver), adhesion));
  }
  const bool md = type == AdhesionLawType::maugis_dugdale;
  if (!o_.work_of_adhesion) throw InputError(fmt::format("{} needs {} W (J/m^2)", adhesion, name("work_of_adhesion")));
  if (o_.adhesion_stress && !md) {
    throw InputError(fmt::format("{} applies only to {} md; give {} RHO (m) for {}",
                                 describe("adhesion_stress", *o_.adhesion_stress), name("adhesion"),
                                 name("adhesion_range"), adhesion));
  }
  if (o_.adhesion_stress && o_.adhesion_range) {
    throw InputError(fmt::format("{} and {} cannot be combined: give the range h0 or the stress sigma0 = w / h0",
                                 describe("adhesion_range", *o_.adhesion_range),
                                 describe("adhesion_stress", *o_.adhesion_stress)));
  }
  if (!o_.adhesion_stress && !o_.adhesion_range) {
    throw InputError(fmt::format("{} needs {} {} (m){}", adhesion, name("adhesion_range"), md ? "H0" : "RHO",
                                 md ? fmt::format(" or {} SIGMA0 (Pa)", name("adhesion_stress")) : std::string()));
  }
  const double w = *o_.work_of_adhesion;
  solvers::SolverOptions::Adhesion made;
  made.law = o_.adhesion_stress ? AdhesionLaw::maugis_dugdale_from_stress(w, *o_.adhesion_stress)
                                : AdhesionLaw{type, w, *o_.adhesion_range};
  // Given or derived (w / sigma0, w / range), the stress and the range stay
  // in the ranges of their kinds.
  law_ranges(made.law);
  if (o_.adhesion_tol) made.tolerance = *o_.adhesion_tol;
  if (o_.adhesion_precondition) made.precondition = on_off("adhesion_precondition", *o_.adhesion_precondition);
  return made;
}

solvers::SolverOptions Rules::solver() const {
  solvers::SolverOptions solver;
  solver.adhesion = adhesion();
  restated([&] {
    if (o_.solver) solver.type = solvers::parse_solver_type(*o_.solver);
    if (o_.tol) solver.tolerance = *o_.tol;
    if (o_.precision) solver.precision = solvers::parse_precision(*o_.precision);
    // Beyond int, a limit is no limit: validate() sees the nearest int.
    if (o_.max_iter) solver.max_iterations = static_cast<int>(std::clamp<long long>(*o_.max_iter, INT_MIN, INT_MAX));
    if (o_.deflation_block) {
      const long long block = *o_.deflation_block;
      if (block < 0) {
        throw OptionError("deflation_block", fmt::format("{}", block), "is invalid: give 0 (off) or a block size");
      }
      solver.deflation.mode = block == 0 ? solvers::DeflationOptions::Mode::off : solvers::DeflationOptions::Mode::on;
      if (block != 0) solver.deflation.block = static_cast<std::size_t>(block);
    }
    // The law made from its option is checked as the option here, so that
    // the front end names it before any file is read; every solver checks
    // the law it is given (ContactSolver) for the library's other callers.
    if (o_.hardness) {
      solver.interface_law.hardness = *o_.hardness;
      solver.interface_law.validate();
    }
    if (o_.active_set) solver.multilevel.active_set = solvers::parse_active_set(*o_.active_set);
    solver.validate();
  });
  if (o_.fft_planning) {
    solver.fft_planning = in_context(name("fft_planning"), [&] { return parse_fft_planning(*o_.fft_planning); });
  }
  return solver;
}

int Rules::threads() const {
  if (!o_.threads) return default_threads();
  if (*o_.threads < 1 || *o_.threads > max_threads()) {
    throw OptionError("threads", fmt::format("{}", *o_.threads),
                      fmt::format("is invalid: allowed range is 1 to {} threads ({} x the {} hardware threads)",
                                  max_threads(), kThreadsPerHardwareThread, hardware_threads()));
  }
  return static_cast<int>(*o_.threads);
}

}  // namespace detail

namespace {

using detail::friction_name;
using detail::problem_name;
using detail::Rules;
using detail::spelled;
using detail::text;

// The option a load of `mode` is given by.
std::string_view load_option(ControlMode mode) {
  return mode == ControlMode::force ? "force" : mode == ControlMode::approach ? "approach" : "mean_pressure";
}

}  // namespace

std::span<const ProblemOptionName> problem_option_names() {
  return kNames;
}

Problem make_problem(const ProblemOptions& options, const OptionSpelling& spelling) {
  const Rules rules(options, spelling);
  return detail::spelled_errors(spelling, [&] {
    std::optional<ProblemBody> body = make_body(options, spelling);
    if (!body) {
      throw InputError(fmt::format("no material given: pass {}, or {}, {}, {} and {}", rules.name("e_star"),
                                   rules.name("E1"), rules.name("nu1"), rules.name("E2"), rules.name("nu2")));
    }
    Problem problem;
    static_cast<ProblemBody&>(problem) = std::move(*body);
    problem.solver = rules.solver();  // the interface law first: adhesion makes loads signed
    std::tie(problem.loading, problem.load_values) = rules.loads();
    problem.friction = rules.friction(problem.solver, problem.load_values.size());
    problem.threads = rules.threads();
    return problem;
  });
}

void Problem::check_grid(const Grid& grid, const OptionSpelling& spelling) const {
  const std::string_view option = load_option(loading.mode);
  const std::vector<double>& values = load_values;
  const std::string given = spelling.describe(option, text(values));
  const auto which = [&](std::size_t k) {
    return values.size() == 1 ? std::string() : fmt::format(" (value {}: {})", k + 1, format_number(values[k]));
  };
  const bool area = grid.dimension() == 2;
  for (std::size_t k = 0; k < values.size(); ++k) {
    // The mean pressure each load makes on `grid`, within the range of
    // pressures: a force of 1e300 N on a 1 mm^2 domain, or a mean pressure
    // of 1e-300 Pa, would overflow or underflow inside the solve.
    if (solver.adhesion) {
      // Adhesive loads are signed: only their size is checked.
      const bool approach = loading.mode == ControlMode::approach;
      const double size = std::abs(loading.mode == ControlMode::force ? values[k] / grid.domain_area() : values[k]);
      require_in_range(given + which(k), size, 0.0, approach ? kMaxLength : kMaxMeanPressure,
                       approach ? "m (in size)" : "Pa (in size)");
    } else if (loading.mode == ControlMode::force) {
      const double pressure = values[k] / grid.domain_area();
      require_in_range(fmt::format("{}{} on the {} grid of {} {:g} {}: the mean pressure force / {} = {:g} Pa", given,
                                   which(k), grid.shape_string(), area ? "area" : "length", grid.domain_area(),
                                   area ? "m^2" : "m", area ? "area" : "length", pressure),
                       pressure, kMinMeanPressure, kMaxMeanPressure, "Pa");
    } else if (loading.mode == ControlMode::mean_pressure) {
      require_in_range(given + which(k), values[k], kMinMeanPressure, kMaxMeanPressure, "Pa");
    } else {
      require_in_range(given + which(k), values[k], kMinLength, kMaxLength, "m");
    }
    // Hardness cap: no load above H times the domain area.
    in_context(given + which(k), [&] { solver.interface_law.check_load(grid, Loading{loading.mode, values[k]}); });
  }
  if (friction) {
    try {
      if (pair) solvers::FrictionOptions::check_body(grid, *pair);
    } catch (const solvers::SolverOptionError& error) {
      std::vector<std::string> layers;
      for (const std::string_view option : {"layer_thickness", "layer_E", "layer_nu", "substrate_E", "substrate_nu"})
        layers.push_back(spelling.name(option));
      throw InputError(fmt::format("the coated half-space ({}) {} ({})", fmt::join(layers, ", "), error.rule(),
                                   spelling.describe("friction", text(friction->tangential.friction_coefficient))));
    }
    try {
      friction->validate(grid, solver, loading);
    } catch (const solvers::SolverOptionError& error) {
      throw spelled(OptionError(std::string(friction_name(error.option(), *friction)), error.value(), error.rule()),
                    spelling);
    }
  }
  try {
    if (coating) {
      solver.validate(grid, *coating);
    } else {
      solver.validate(grid);
    }
  } catch (const OptionError& error) {
    throw spelled(OptionError(std::string(problem_name(error.option())), error.value(), error.rule()), spelling);
  }
}

void Problem::check_padding(double pad_factor, const OptionSpelling& spelling) const {
  if (pad_factor > 1.0 && loading.mode == ControlMode::mean_pressure) {
    throw InputError(fmt::format(
        "{} cannot be combined with {}: the mean pressure would be taken over the padded area; give {} instead",
        spelling.describe("pad", format_number(pad_factor)), spelling.name("mean_pressure"), spelling.name("force")));
  }
}

void Problem::check_heights(const Grid& grid, std::span<const double> heights, const OptionSpelling& spelling) const {
  if (loading.mode != ControlMode::approach || !grid.periodic() || heights.empty()) return;
  const Eigen::Map<const Eigen::ArrayXd> h(heights.data(), static_cast<Eigen::Index>(heights.size()));
  const double mean_gap = h.maxCoeff() - h.mean();
  for (std::size_t k = 0; k < load_values.size(); ++k) {
    try {
      solvers::check_periodic_approach(load_values[k], mean_gap);
    } catch (const OptionError& error) {
      const std::string which = load_values.size() == 1
                                    ? std::string()
                                    : fmt::format(" (value {}: {} m)", k + 1, format_number(load_values[k]));
      throw InputError(fmt::format("{}{} {}", spelling.describe("approach", text(load_values)), which, error.rule()));
    }
  }
}

}  // namespace halfspace
