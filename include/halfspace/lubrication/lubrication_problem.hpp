// A lubricated film as a front end states it, and the one place its rules
// live (issue 28): the body (none: a rigid film; E*, both bodies' E and nu,
// or a coated half-space: an elastic film, EHL), whether the film may close
// (mixed), the load or separation, the flow, the lubricant's laws, the
// solvers' settings, the shear limits and the mixed film's extras. The
// program maps its flags onto LubricationProblemOptions and Python its
// keywords; make_lubrication_problem checks them and every message names
// the option as the front end spells it (OptionSpelling, problem.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/lubrication/cavitation_solver.hpp"
#include "halfspace/lubrication/elastic_film.hpp"
#include "halfspace/lubrication/film_shear.hpp"
#include "halfspace/lubrication/flow_conditions.hpp"
#include "halfspace/lubrication/load_control.hpp"
#include "halfspace/lubrication/lubricant.hpp"
#include "halfspace/lubrication/mixed_film.hpp"
#include "halfspace/lubrication/transient_film.hpp"
#include "halfspace/problem.hpp"

namespace halfspace::lubrication {

// Everything a film is, as given; unset means not given. Each member's
// name is the option's name in messages ("e_star", "layer_E",
// "tolerance"), which the front end's OptionSpelling respells.
// The body (BodyOptions, make_body): none makes a rigid film.
struct LubricationProblemOptions : BodyOptions {
  bool mixed = false;  // the elastic film may close (mixed_film.hpp)
  // Exactly one: the rigid film's minimum film (separation, m), the load
  // (force; N, N/m on a profile) or the mixed film's offset h0 (m).
  std::optional<double> separation, force, offset;
  // The flow (FlowConditions): Pa s; (x) or (x, y) m/s; Pa.
  std::optional<double> viscosity;
  std::optional<std::vector<double>> entrainment_velocity, sliding_velocity;
  std::optional<double> inlet_pressure, outlet_pressure, side_pressure;
  bool periodic_x = false, periodic_y = false;
  std::optional<double> supply_fluid_fraction;
  // The elastic half-space's boundary ("free" or "periodic"), elastic only.
  std::optional<std::string> boundary;
  // The lubricant (LubricantLaws) and the Couette scheme, elastic only.
  std::optional<double> pressure_viscosity;
  std::optional<std::string> piezoviscosity;
  std::optional<double> roelands_index;
  std::optional<std::string> compressibility;
  std::optional<std::string> couette_scheme;
  // The EHL film's GMRES preconditioner ("multigrid" or "sparse-lu"), elastic only.
  std::optional<std::string> film_preconditioner;
  // FFTW's effort planning the influence operator's transforms ("estimate",
  // "measure" or "patient"), elastic only.
  std::optional<std::string> fft_planning;
  // The solver of the film in force.
  std::optional<double> tolerance;
  std::optional<long long> max_iterations;
  // The shear (ShearLimits).
  std::optional<double> eyring_stress, limiting_shear_stress, limiting_shear_slope;
  // The mixed film: Coulomb's coefficient on contact cells, the thinnest
  // film the Reynolds equation sees, and a Stribeck sweep's speeds (m/s).
  std::optional<double> contact_friction, boundary_film;
  std::optional<std::vector<double>> speeds;
  // The transient rigid film (transient_film.hpp): the time step (s), the
  // steps, the scheme ("bdf2" or "backward-euler"), and what moves the
  // separation from `separation` at t = 0: an approach velocity (m/s), the
  // separations at the ends of the steps (m), or `force`.
  std::optional<double> time_step;
  std::optional<long long> steps;
  std::optional<std::string> time_scheme;
  std::optional<double> approach_velocity;
  std::optional<std::vector<double>> separation_history;
};

// The name of each option of LubricationProblemOptions and where it is
// held (Python's keyword; the program's flag is the name with '-' for '_'),
// as problem_option_names.
using LubricationOptionField =
    std::variant<bool LubricationProblemOptions::*, std::optional<double> LubricationProblemOptions::*,
                 std::optional<long long> LubricationProblemOptions::*,
                 std::optional<std::string> LubricationProblemOptions::*,
                 std::optional<std::vector<double>> LubricationProblemOptions::*>;
struct LubricationOptionName {
  std::string_view name;
  LubricationOptionField field;
};
std::span<const LubricationOptionName> lubrication_option_names();

enum class FilmKind { rigid, elastic, mixed };

// A checked film. The grid comes later (a front end reads or builds it), so
// the rules that need it are a method.
struct LubricationProblem {
  FilmKind kind = FilmKind::rigid;
  double e_star = 0.0;                     // Pa, elastic and mixed; a coating's is its layer's E1 / (1 - nu1^2)
  std::optional<LayeredMaterial> coating;  // the elastic film's coated half-space
  Boundary boundary = Boundary::free;      // the elastic half-space's
  FlowConditions conditions;               // checked on the grid by check_grid
  LubricantLaws laws;                      // none for the rigid film
  // The influence operator's FFT plans (elastic and mixed): estimated
  // unless told. Measured plans did not shorten the films' solves (the EHL
  // point contact at 1024^2, the mixed film at 512^2; docs/performance.md),
  // whose time is in the Newton and GMRES iterations, not the transforms.
  FftPlanning fft_planning = FftPlanning::estimate;
  ShearLimits limits;
  // The rigid film's solver and its control: the separation, or the load.
  CavitationSolverOptions cavitation;
  std::optional<double> separation;
  std::optional<LoadControlOptions> load_control;
  ElasticFilmOptions elastic;                 // FilmKind::elastic
  MixedFilmOptions mixed;                     // FilmKind::mixed (load 0: offset control)
  std::optional<std::vector<double>> speeds;  // the mixed film's Stribeck sweep
  // The rigid film stepped in time (the separation above is its initial
  // one; its load control, if any, is transient->load).
  std::optional<TransientFilmOptions> transient;

  // The grid's rules: the flow's (FlowConditions::validate(grid)) and the
  // mixed film's (require_mixed_film_fits, for `nodes` of the grid's nodes:
  // 0 all of them, on slabs of rows a process's share); `surface` names the
  // heights in messages.
  // Throws InputError naming the option.
  void check_grid(const Grid& grid, const OptionSpelling& spelling = {}, std::string_view surface = "the surface",
                  std::size_t nodes = 0) const;

  // What to try where the film did not converge, naming the options that
  // help as `spelling` writes them: "to try: ...". The elastic and mixed
  // films converge more easily at a higher speed or a lighter load, and the
  // mixed film from a faster one (a Stribeck sweep's speeds, each film from
  // the last); every film with more iterations or a looser tolerance.
  std::string failure_hint(const OptionSpelling& spelling = {}) const;
};

// Applies the defaults and checks every option and their combinations that
// need no grid. Throws InputError with a message naming the option as
// `spelling` writes it, its value and the rule it broke.
LubricationProblem make_lubrication_problem(const LubricationProblemOptions& options,
                                            const OptionSpelling& spelling = {});

// A lubrication option's broken rule (OptionError from the film's options
// or its solvers: "entrainment_velocity.y", "boundary.x_low_pressure",
// "load") as the front end writes it: "--inlet-pressure -5 Pa is invalid ...".
InputError spelled_film_error(const OptionError& error, const OptionSpelling& spelling);

}  // namespace halfspace::lubrication
