// Private: the rules of a contact problem's options (problem.cpp), shared
// with the friction rules (problem_friction.cpp), the elastic body's
// (problem_body.cpp) and, for the checks of single options, the lubricated
// film's (lubrication/lubrication_problem.cpp).
#pragma once

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "halfspace/elastic_pair.hpp"
#include "halfspace/error.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/physical_ranges.hpp"
#include "halfspace/problem.hpp"
#include "halfspace/solvers/adhesion_law.hpp"
#include "halfspace/solvers/friction_options.hpp"

namespace halfspace::detail {

// The option of ProblemOptions that sets each SolverOptions member a
// SolverOptionError names.
std::string_view problem_name(std::string_view member);

// The text of a given value as the library shows it: "1,-2" for a list,
// "1,0;2,0" for steps (x, y).
inline std::string text(double value) {
  return format_number(value);
}
inline std::string text(long long value) {
  return fmt::format("{}", value);
}
inline std::string text(const std::string& value) {
  return value;
}
std::string text(const std::vector<double>& values);
std::string text(const std::vector<std::array<double, 2>>& steps);

// The option of ProblemOptions that sets each FrictionOptions member a
// SolverOptionError names; a tangential load is the force or displacement
// steps `friction` holds.
std::string_view friction_name(std::string_view member, const solvers::FrictionOptions& friction);

// Options paired with whether they were given.
using Presence = std::vector<std::pair<std::string_view, bool>>;

// One option's broken rule as the front end writes it: "--tol 2 is invalid: ...".
InputError spelled(const OptionError& error, const OptionSpelling& spelling);

// Runs `function`; an OptionError it throws is thrown again spelled.
template <class Function>
auto spelled_errors(const OptionSpelling& spelling, Function&& function) {
  try {
    return function();
  } catch (const OptionError& error) {
    throw spelled(error, spelling);
  }
}

// The checks of single options, written with the front end's spelling; each
// throws OptionError naming the option, its value and its allowed range.
class Checks {
 public:
  explicit Checks(const OptionSpelling& spelling) : s_(spelling) {}

  std::string name(std::string_view option) const { return s_.name(option); }
  std::string describe(std::string_view option, double value) const {
    return s_.describe(option, format_number(value));
  }
  // The names of the options among `options` that were given (or not).
  std::vector<std::string> given(const Presence& options, bool present = true) const {
    std::vector<std::string> out;
    for (const auto& [option, is_given] : options) {
      if (is_given == present) out.push_back(name(option));
    }
    return out;
  }
  // The names of all of `options`.
  std::vector<std::string> names(std::initializer_list<std::string_view> options) const {
    std::vector<std::string> all;
    for (const std::string_view option : options) all.push_back(name(option));
    return all;
  }
  std::vector<std::string> names(const Presence& options) const {
    std::vector<std::string> all;
    for (const auto& [option, _] : options) all.push_back(name(option));
    return all;
  }
  // "on" or "off" as true or false.
  static bool on_off(std::string_view option, const std::string& value) {
    if (value != "on" && value != "off") {
      throw OptionError(std::string(option), value, "is invalid: allowed values are on and off");
    }
    return value == "on";
  }
  double positive(std::string_view option, double value, std::string_view unit) const {
    if (!(std::isfinite(value) && value > 0.0)) {
      throw OptionError(std::string(option), format_number(value),
                        fmt::format("is invalid: must be positive ({})", unit));
    }
    return value;
  }
  double length(std::string_view option, double value) const {
    positive(option, value, "m");
    return require_in_range(describe(option, value), value, kMinLength, kMaxLength, "m");
  }
  double modulus(std::string_view option, double value) const {
    positive(option, value, "Pa");
    return require_in_range(describe(option, value), value, kMinModulus, kMaxModulus, "Pa");
  }
  double poisson(std::string_view option, double nu) const {
    if (!(nu > -1.0 && nu <= 0.5)) {
      throw OptionError(std::string(option), format_number(nu), "is invalid: allowed range is (-1, 0.5]");
    }
    return nu;
  }

 protected:
  const OptionSpelling& s_;
};

// The rules of one problem's options, written with the front end's spelling.
class Rules : public Checks {
 public:
  Rules(const ProblemOptions& options, const OptionSpelling& spelling) : Checks(spelling), o_(options) {}

  // The text of the option's value if it was given, else none.
  std::optional<std::string> value(std::string_view option) const;
  // Options paired with whether they were given.
  Presence presence(std::initializer_list<std::string_view> options) const {
    Presence pairs;
    for (const std::string_view option : options) pairs.emplace_back(option, value(option).has_value());
    return pairs;
  }

  // Runs `function`; an OptionError it throws (a SolverOptions rule) is
  // named by the option of the problem that set it.
  template <class Function>
  auto restated(Function&& function) const {
    try {
      return function();
    } catch (const OptionError& error) {
      const std::string_view option = problem_name(error.option());
      throw OptionError(std::string(option), error.value(), error.rule());
    }
  }

  // The law's given and derived quantities in the ranges of their kinds: a
  // derived one obeys the range of the option it replaces (a stress w / range
  // of 1e306 Pa ended "converged" with a force of -inf, issue 32).
  void law_ranges(const AdhesionLaw& law) const {
    if (!(std::isfinite(law.work) && law.work > 0.0)) {
      throw OptionError("work_of_adhesion", format_number(law.work) + " J/m^2",
                        "is invalid: must be positive and finite");
    }
    const std::string work = fmt::format("the work of adhesion {} J/m^2", format_number(law.work));
    const auto outside = [](double value, double low, double high) { return !(value >= low && value <= high); };
    if (o_.adhesion_stress) {  // sigma0 given; the range h0 = w / sigma0 derived
      const double sigma0 = law.work / law.range;
      const std::string given = s_.describe("adhesion_stress", format_number(sigma0) + " Pa");
      require_in_range(given, sigma0, kMinMeanPressure, kMaxMeanPressure, "Pa");
      if (outside(law.range, kMinLength, kMaxLength)) {
        throw InputError(
            fmt::format("{} is invalid with {}: the range h0 = work / stress = {} m it gives must lie in "
                        "[{:g}, {:g}] m, the range of lengths",
                        given, work, format_number(law.range), kMinLength, kMaxLength));
      }
    } else {
      const std::string given = s_.describe("adhesion_range", format_number(law.range) + " m");
      require_in_range(given, law.range, kMinLength, kMaxLength, "m");
      if (outside(law.stress(), kMinMeanPressure, kMaxMeanPressure)) {
        throw InputError(
            fmt::format("{} is invalid with {}: the adhesive stress work / range = {} Pa it gives must "
                        "lie in [{:g}, {:g}] Pa, the range of stresses",
                        given, work, format_number(law.stress()), kMinMeanPressure, kMaxMeanPressure));
      }
    }
    law.validate();
  }

  std::pair<Loading, std::vector<double>> loads() const;
  std::optional<solvers::SolverOptions::Adhesion> adhesion() const;
  solvers::SolverOptions solver() const;
  std::optional<solvers::FrictionOptions> friction(const solvers::SolverOptions& normal, std::size_t loads) const;
  int threads() const;

 private:
  const ProblemOptions& o_;
};

}  // namespace halfspace::detail
