// A contact problem as a front end states it, and the one place its rules
// live: the elastic body (E*, both bodies' E and nu, or a coated half-space),
// the interface law (a hardness cap; a cohesive law made from its
// parameters), the loads (one, or a sweep; signed with adhesion), friction
// (Coulomb's coefficient and the tangential loads), the solver's settings
// and the threads. The program maps its flags onto
// ProblemOptions and Python its keywords; make_problem checks them and every
// message names the option as the front end spells it (OptionSpelling).
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "halfspace/elastic_pair.hpp"
#include "halfspace/error.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/solvers/friction_options.hpp"
#include "halfspace/solvers/loading.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace {

// How a front end writes an option in messages. `option` is the problem's
// name of it (problem_option_names: "e_star", "work_of_adhesion", "tol").
// The defaults are the library's: the name itself, and "name=value".
class OptionSpelling {
 public:
  virtual ~OptionSpelling() = default;
  // The option by itself: "--work-of-adhesion", "work_of_adhesion".
  // Inline, as the whole class: front ends (and the config fuzzer, which
  // links no library) derive from it without the builder's object file.
  virtual std::string name(std::string_view option) const { return std::string(option); }
  // The option with its value; `value` as the library shows it, which a
  // front end may replace by what the user wrote: "--force 1,-2", "force=-1".
  virtual std::string describe(std::string_view option, std::string_view value) const {
    return std::string(option) + "=" + std::string(value);
  }
};

// Runs `function`; an InputError (not a FileError) it throws is thrown again
// with `context` in front: the option it came from as a front end spells
// it ("--window", "boundary"), with its value or not.
template <class Function>
auto in_context(const std::string& context, Function&& function) {
  try {
    return function();
  } catch (const FileError&) {
    throw;
  } catch (const InputError& error) {
    throw InputError(context + ": " + error.what());
  }
}

// The elastic body as a front end gives it, in a contact problem and in a
// lubricated film alike: e_star; or E1, nu1, E2 (inf: a rigid body 2), nu2;
// or a coated half-space (all five layer_ and substrate_ constants) against
// a rigid surface. Pa, m; unset means not given.
struct BodyOptions {
  std::optional<double> e_star;
  std::optional<double> e1;
  std::optional<double> nu1;
  std::optional<double> e2;
  std::optional<double> nu2;
  std::optional<double> layer_thickness;
  std::optional<double> layer_e;
  std::optional<double> layer_nu;
  std::optional<double> substrate_e;
  std::optional<double> substrate_nu;
};

// The elastic body BodyOptions give.
struct ProblemBody {
  double e_star = 0.0;                     // Pa; a coating's is the layer's E1 / (1 - nu1^2)
  std::optional<LayeredMaterial> coating;  // a coated half-space, else homogeneous
  // Both bodies, when E1, nu1, E2, nu2 were given; the coated body against
  // the rigid surface (ElasticPair::coated) with a coating.
  std::optional<ElasticPair> pair;
};

// The one rule of the elastic body, for every problem: none when no
// constant was given. Throws InputError naming the options as `spelling`
// writes them: a coating with a material, an incomplete coating or pair,
// e_star with E1..nu2, a value outside its range (moduli and lengths in the
// ranges of physical_ranges.hpp, nu in (-1, 0.5]).
std::optional<ProblemBody> make_body(const BodyOptions& options, const OptionSpelling& spelling = {});

// Everything a contact problem is, as given: unset means not given, so that
// make_problem can tell a default from a choice and name what is missing.
// The elastic body (BodyOptions) is required.
struct ProblemOptions : BodyOptions {
  // The interface law: a hardness cap p <= H (Pa); a cohesive law ("md" or
  // "exponential") of work w (J/m^2) and range (m) or, for md, stress (Pa).
  std::optional<double> hardness;
  std::optional<std::string> adhesion;
  std::optional<double> work_of_adhesion;
  std::optional<double> adhesion_range;
  std::optional<double> adhesion_stress;
  std::optional<double> adhesion_tol;
  std::optional<std::string> adhesion_precondition;  // "on" or "off"
  // The load: exactly one; more than one value is a sweep, solved in order.
  std::optional<std::vector<double>> force;          // N in 2D, N/m in 1D
  std::optional<std::vector<double>> mean_pressure;  // Pa
  std::optional<std::vector<double>> approach;       // m
  // Friction (solvers/friction_options.hpp): Coulomb's coefficient mu and
  // exactly one tangential load: steps (x, y) of force (N, N/m in 1D) or of
  // tangential displacement (m), more than one a history applied in order,
  // or a sliding direction (x, y). The tangential solver's tolerance,
  // iteration limit, release period, active-set updates and coarse start; dissimilar bodies: coupling "on" or "off" and
  // the normal load's increments.
  std::optional<double> friction;
  std::optional<std::vector<std::array<double, 2>>> tangential_force;
  std::optional<std::vector<std::array<double, 2>>> tangential_displacement;
  std::optional<std::vector<double>> sliding;  // (x, y)
  std::optional<double> tangential_tol;
  std::optional<long long> tangential_max_iter;
  std::optional<long long> tangential_release_period;  // TangentialOptions::release_period
  std::optional<long long> tangential_active_set;      // TangentialOptions::active_set_updates
  std::optional<std::string> tangential_coarse_start;  // "on", "off" or "automatic" (TangentialOptions::coarse_start)
  std::optional<std::string> coupling;
  std::optional<long long> normal_load_steps;
  // The solver (solver_options.hpp) and the threads.
  std::optional<std::string> solver;
  std::optional<double> tol;
  std::optional<long long> max_iter;
  std::optional<std::string> fft_planning;
  std::optional<std::string> precision;      // double or mixed (SolverOptions::precision)
  std::optional<long long> deflation_block;  // 0: off
  std::optional<std::string> active_set;     // on, off or automatic (pk-multilevel's active-set phase)
  std::optional<long long> threads;
};

// The problem's name of each option of ProblemOptions and where it is held:
// Python's keyword; the program's flag is the name with '-' for '_'.
using ProblemOptionField =
    std::variant<std::optional<double> ProblemOptions::*, std::optional<long long> ProblemOptions::*,
                 std::optional<std::string> ProblemOptions::*, std::optional<std::vector<double>> ProblemOptions::*,
                 std::optional<std::vector<std::array<double, 2>>> ProblemOptions::*>;
struct ProblemOptionName {
  std::string_view name;
  ProblemOptionField field;
};
std::span<const ProblemOptionName> problem_option_names();

// A checked problem. The grid and the heights come later (a front end reads
// or builds them), so the rules that need them are methods.
struct Problem : ProblemBody {
  Loading loading;                  // the first load; its mode is every load's
  std::vector<double> load_values;  // every load, in loading.mode's unit
  solvers::SolverOptions solver;
  // With friction: one normal load, both bodies given or a coating (pair).
  std::optional<solvers::FrictionOptions> friction;
  int threads = 1;

  bool sweep() const { return load_values.size() > 1; }
  // The rules that need the grid: each load's scale (the mean pressure it
  // makes within the range of pressures; signed loads by size), the hardness
  // cap against each load, the solver's (SolverOptions::validate(grid),
  // with the coating's) and friction's (FrictionOptions::validate(grid,
  // normal, loading): a force step beyond mu P, y components on a 1D grid;
  // FrictionOptions::check_body: a coating on a periodic grid).
  // Throws InputError naming the option.
  void check_grid(const Grid& grid, const OptionSpelling& spelling = {}) const;
  // The rule that needs the surface's preparation: a map padded for a free
  // grid (`pad_factor` > 1) takes no mean-pressure load, which would be
  // taken over the padded area too. Throws InputError naming both options.
  void check_padding(double pad_factor, const OptionSpelling& spelling = {}) const;
  // Displacement control on a periodic grid: each approach below the mean
  // initial gap of `heights` (check_periodic_approach), named as an option.
  void check_heights(const Grid& grid, std::span<const double> heights, const OptionSpelling& spelling = {}) const;
};

// Applies the defaults and checks every option and their combinations that
// need no grid. Throws InputError (OptionError for one option's value) with
// a message naming the option as `spelling` writes it, its value and the
// rule it broke.
Problem make_problem(const ProblemOptions& options, const OptionSpelling& spelling = {});

}  // namespace halfspace
