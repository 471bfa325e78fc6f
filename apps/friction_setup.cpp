// --friction and its tangential loads onto FrictionOptions (friction_setup.hpp).
#include "friction_setup.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <climits>
#include <string>

#include "halfspace/error.hpp"
#include "value_parsing.hpp"

namespace halfspace::app {
namespace {

// One step "X" or "X,Y" of a tangential load.
std::pair<double, double> parse_step(std::string_view text, std::string_view what) {
  const std::size_t comma = text.find(',');
  if (comma == std::string_view::npos) return {parse_number(text, what), 0.0};
  if (text.find(',', comma + 1) != std::string_view::npos) {
    throw InputError(fmt::format(
        "{} is invalid: step '{}' has more than two components; a step is X or X,Y, and the steps of a history are "
        "separated by ';' (e.g. '0;0.5;1' along x, quoted for the shell)",
        what, text));
  }
  return {parse_number(text.substr(0, comma), what), parse_number(text.substr(comma + 1), what)};
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

// The key of the option a FrictionOptions rule came from.
std::string_view tangential_key(const SolveOptions& o) {
  return o.tangential_displacement ? "tangential-displacement" : "tangential-force";
}

template <class Function>
void with_friction_flags(const SolveOptions& o, Function&& function) {
  try {
    function();
  } catch (const solvers::SolverOptionError& error) {
    const std::string& option = error.option();
    if (option == "tangential_load")
      throw InputError(fmt::format("{} {}", o.describe(tangential_key(o)), error.rule()));
    if (option == "sliding") throw InputError(fmt::format("{} {}", o.describe("sliding"), error.rule()));
    if (option == "tolerance") throw InputError(fmt::format("{} {}", o.describe("tangential-tol"), error.rule()));
    if (option == "max_iterations") {
      throw InputError(fmt::format("{} {}", o.describe("tangential-max-iter"), error.rule()));
    }
    if (option == "normal_load_steps") {
      throw InputError(fmt::format("{} {}", o.describe("normal-load-steps"), error.rule()));
    }
    if (option == "adhesion") {
      throw InputError(fmt::format("{} {} ({})", o.describe("adhesion"), error.rule(), o.describe("friction")));
    }
    if (option == "pair") {
      const std::string material = o.e_star ? o.describe("E-star")
                                            : fmt::format("{}, {}, {}, {}", o.describe("E1"), o.describe("nu1"),
                                                          o.describe("E2"), o.describe("nu2"));
      throw InputError(fmt::format("{} with {}: {} {}", o.describe("friction"), material, error.value(), error.rule()));
    }
    if (option == "coating") {
      throw InputError(fmt::format("the coated half-space (--layer-*, --substrate-*) {} ({})", error.rule(),
                                   o.describe("friction")));
    }
    throw InputError(fmt::format("{} {}", o.describe("friction"), error.rule()));
  }
}

}  // namespace

std::vector<solvers::TangentialLoading> parse_tangential_steps(std::string_view text,
                                                               solvers::TangentialControl control,
                                                               std::string_view what) {
  std::vector<solvers::TangentialLoading> steps;
  const auto add = [&](double x, double y) {
    if (static_cast<long long>(steps.size()) >= kMaxListValues) {
      throw InputError(fmt::format("{} is invalid: more than {} steps", what, kMaxListValues));
    }
    steps.push_back({control, x, y});
  };
  for (std::string_view part : split(text, ';')) {
    if (part.empty())
      throw InputError(fmt::format("{} is invalid: an empty step (two ';' in a row, or at an end)", what));
    const std::vector<std::string_view> range = split(part, ':');
    if (range.size() == 1) {
      const auto [x, y] = parse_step(part, what);
      add(x, y);
      continue;
    }
    if (range.size() != 3) {
      throw InputError(fmt::format("{} is invalid: '{}' is not a range START:STOP:COUNT", what, part));
    }
    const auto [x0, y0] = parse_step(range[0], what);
    const auto [x1, y1] = parse_step(range[1], what);
    const long long count = parse_integer(range[2], what);
    if (count < 2 || count > kMaxListValues) {
      throw InputError(
          fmt::format("{} is invalid: the COUNT of range '{}' must be 2 to {}", what, part, kMaxListValues));
    }
    for (long long k = 0; k < count; ++k) {
      const double t = static_cast<double>(k) / static_cast<double>(count - 1);
      // The ends exactly, the steps between evenly spaced.
      add(k + 1 == count ? x1 : x0 + t * (x1 - x0), k + 1 == count ? y1 : y0 + t * (y1 - y0));
    }
  }
  return steps;
}

std::optional<solvers::FrictionOptions> friction_from(const SolveOptions& o, bool coated,
                                                      std::size_t normal_load_steps) {
  const std::vector<std::string_view> tangential = [&] {
    std::vector<std::string_view> keys;
    for (const auto& [key, given] :
         {std::pair{"tangential-force", o.tangential_force.has_value()},
          std::pair{"tangential-displacement", o.tangential_displacement.has_value()},
          std::pair{"sliding", o.sliding.has_value()}, std::pair{"tangential-tol", o.tangential_tol.has_value()},
          std::pair{"tangential-max-iter", o.tangential_max_iter.has_value()}, std::pair{"no-coupling", o.no_coupling},
          std::pair{"normal-load-steps", o.normal_load_steps.has_value()}}) {
      if (given) keys.emplace_back(key);
    }
    return keys;
  }();
  if (!o.friction) {
    if (!tangential.empty()) {
      throw InputError(
          fmt::format("{} needs --friction MU (the Coulomb friction coefficient)", o.describe(tangential.front())));
    }
    return std::nullopt;
  }
  const int loads = (o.tangential_force ? 1 : 0) + (o.tangential_displacement ? 1 : 0) + (o.sliding ? 1 : 0);
  if (loads == 0) {
    throw InputError(
        fmt::format("{} needs a tangential load: --tangential-force QX[,QY], --tangential-displacement "
                    "DX[,DY] or --sliding X,Y",
                    o.describe("friction")));
  }
  if (loads > 1) {
    std::vector<std::string> given;
    for (std::string_view key : {"tangential-force", "tangential-displacement", "sliding"}) {
      if (o.given(key)) given.push_back(o.describe(key));
    }
    throw InputError(
        fmt::format("{} cannot be combined: give one of --tangential-force, --tangential-displacement, "
                    "--sliding",
                    fmt::join(given, " and ")));
  }
  if (normal_load_steps > 1) {
    throw InputError(
        fmt::format("{} takes one normal load, not a load sweep: give a single --force, --mean-pressure "
                    "or --approach",
                    o.describe("friction")));
  }
  solvers::FrictionOptions friction;
  friction.friction_coefficient = *o.friction;
  if (o.tangential_force) {
    friction.history =
        parse_tangential_steps(*o.tangential_force, solvers::TangentialControl::force, o.describe("tangential-force"));
  } else if (o.tangential_displacement) {
    friction.history = parse_tangential_steps(*o.tangential_displacement, solvers::TangentialControl::displacement,
                                              o.describe("tangential-displacement"));
  } else {
    const std::vector<std::string_view> parts = split(*o.sliding, ',');
    if (parts.size() != 2) {
      throw InputError(fmt::format("{} is invalid: expected a direction X,Y", o.describe("sliding")));
    }
    friction.sliding_direction = {parse_number(parts[0], o.describe("sliding")),
                                  parse_number(parts[1], o.describe("sliding"))};
  }
  if (o.stress_depths && friction.steps() > 1) {
    throw InputError(
        fmt::format("{} applies to a single tangential step, not a history of {}: run `halfspace "
                    "stress` on a result of one step",
                    o.describe("stress-depths"), friction.steps()));
  }
  if (o.tangential_tol) friction.tolerance = *o.tangential_tol;
  // Beyond int, a limit is no limit: validate() sees the nearest int.
  if (o.tangential_max_iter) {
    friction.max_iterations = static_cast<int>(std::clamp<long long>(*o.tangential_max_iter, INT_MIN, INT_MAX));
  }
  friction.coupling = !o.no_coupling;
  if (o.normal_load_steps) {
    friction.normal_load_steps = static_cast<int>(std::clamp<long long>(*o.normal_load_steps, INT_MIN, INT_MAX));
  }
  with_friction_flags(o, [&] {
    friction.validate();
    if (coated) solvers::FrictionOptions::refuse_coating();
    if (o.e_star) solvers::FrictionOptions::refuse_composite_modulus_only();
  });
  return friction;
}

void check_friction(const SolveOptions& o, const solvers::FrictionOptions& friction, const Grid& grid,
                    const ElasticPair& pair, const solvers::SolverOptions& normal, const Loading& loading) {
  with_friction_flags(o, [&] { friction.validate(grid, pair, normal, loading); });
}

}  // namespace halfspace::app
