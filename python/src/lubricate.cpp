// halfspace.lubricate: the keywords mapped onto the library's lubrication
// problem (LubricationProblemOptions), whose builder make_lubrication_problem
// holds the rules and names a broken one by its keyword (KeywordSpelling).
// The film is solved as `halfspace lubricate` solves it, with the GIL
// released, and handed back as numpy arrays and numbers. With mixed= the
// film may close (mixed_film.hpp, `halfspace lubricate --mixed`); with
// speeds= it is a Stribeck sweep (a list of films, as --speeds).
#include <fmt/format.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/io/mixed_trace_writer.hpp"
#include "halfspace/io/output_file.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/lubrication/elastic_film.hpp"
#include "halfspace/lubrication/film_shear.hpp"
#include "halfspace/lubrication/load_control.hpp"
#include "halfspace/lubrication/lubrication_problem.hpp"
#include "halfspace/lubrication/mixed_film.hpp"
#include "halfspace/lubrication/transient_film.hpp"
#include "halfspace/material.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/threads.hpp"

namespace halfspace::python {
namespace {

using namespace halfspace::lubrication;

// Runs `work`, restating a film option's broken rule found by a solver (the
// separation, the speeds) with its keyword.
template <class Work>
auto with_keywords(Work&& work) {
  try {
    return work();
  } catch (const OptionError& error) {
    throw spelled_film_error(error, KeywordSpelling());
  }
}

// A film's message, with what to try where it did not converge.
std::string with_hint(const std::string& message, bool converged, const LubricationProblem& problem) {
  return converged ? message : fmt::format("{}; {}", message, problem.failure_hint(KeywordSpelling()));
}

// The film's fields and the shear, as the dict _lubricate.py wraps.
void put_fields(nb::dict& out, const Grid& grid, Eigen::ArrayXd pressure, Eigen::ArrayXd film,
                Eigen::ArrayXd fluid_fraction, const FilmShear& shear) {
  const std::vector<std::size_t> shape = io::field_shape(grid);
  out["pressure"] = owning_array(std::move(pressure), shape);
  out["film"] = owning_array(std::move(film), shape);
  out["fluid_fraction"] = owning_array(std::move(fluid_fraction), shape);
  out["shear_x"] = owning_array(Eigen::ArrayXd(shear.shear_x), shape);
  out["shear_y"] = owning_array(Eigen::ArrayXd(shear.shear_y), shape);
  out["friction_force"] = nb::make_tuple(shear.friction_force[0], shear.friction_force[1]);
  out["couette_friction_force"] = nb::make_tuple(shear.couette_force[0], shear.couette_force[1]);
  out["friction_coefficient"] = shear.friction_coefficient;
  out["limited_fraction"] = shear.limited_fraction;
}

// A rigid film's numbers and fields, as the program's summary.
nb::dict rigid_dict(const Grid& grid, const Eigen::ArrayXd& heights, const LubricationProblem& problem,
                    LubricatedFilm film, double seconds) {
  const FlowConditions& conditions = problem.conditions;
  const FilmShear shear = film_shear(grid, conditions, LubricantLaws{}, problem.limits, film.film,
                                     film.solution.pressure, film.solution.fluid_fraction);
  const FilmForces& f = film.forces;
  nb::dict out;
  out["model"] = "rigid";
  out["status"] = std::string(to_string(film.solution.status));
  out["message"] = with_hint(film.solution.message, film.solution.converged(), problem);
  out["converged"] = film.solution.converged();
  out["load"] = f.load;
  out["mean_pressure"] = f.mean_pressure;
  out["separation"] = film.separation;
  Eigen::Index centre = 0;
  heights.maxCoeff(&centre);
  out["central_film_thickness"] = film.film[centre];
  out["minimum_film_thickness"] = f.minimum_film_thickness;
  out["max_pressure"] = film.solution.pressure.maxCoeff();
  out["cavitated_fraction"] = f.cavitated_fraction;
  out["iterations"] = film.solution.iterations;
  out["film_solves"] = film.film_solves;
  out["relative_residual"] = film.solution.relative_residual;
  out["solve_seconds"] = seconds;
  out["inflow"] = f.inflow;
  out["outflow"] = f.outflow;
  out["deformation"] = nb::none();
  out["load_error"] = nb::none();
  put_fields(out, grid, std::move(film.solution.pressure), std::move(film.film),
             std::move(film.solution.fluid_fraction), shear);
  return out;
}

nb::dict solve_rigid(const Grid& grid, const Eigen::ArrayXd& heights, const LubricationProblem& problem) {
  const auto started = std::chrono::steady_clock::now();
  LubricatedFilm film = with_keywords([&] {
    nb::gil_scoped_release release;
    return problem.load_control
               ? lubricate_at_load(grid, heights, problem.conditions, *problem.load_control, problem.cavitation)
               : lubricate_at_separation(grid, heights, problem.conditions, *problem.separation, problem.cavitation);
  });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return rigid_dict(grid, heights, problem, std::move(film), seconds);
}

// The transient rigid film (time_step=): every step's film (the initial
// state first) with its step, time and fluid volume, and how the run ended,
// as `halfspace lubricate --time-step` writes them.
nb::dict solve_transient(const Grid& grid, const Eigen::ArrayXd& heights, const LubricationProblem& problem) {
  std::vector<TransientStep> steps;
  std::vector<double> seconds;
  auto started = std::chrono::steady_clock::now();
  const TransientOutcome outcome = with_keywords([&] {
    nb::gil_scoped_release release;
    return lubricate_transient(grid, heights, problem.conditions, *problem.transient, problem.cavitation,
                               [&](const TransientStep& step) {
                                 const auto now = std::chrono::steady_clock::now();
                                 seconds.push_back(std::chrono::duration<double>(now - started).count());
                                 started = now;
                                 steps.push_back(step);
                               });
  });
  nb::list films;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    nb::dict film = rigid_dict(grid, heights, problem, std::move(steps[k].film), seconds[k]);
    film["step"] = steps[k].step;
    film["time"] = steps[k].time;
    film["fluid_volume"] = steps[k].fluid_volume;
    films.append(film);
  }
  nb::dict out;
  out["films"] = films;
  out["status"] = std::string(to_string(outcome.status));
  out["message"] = outcome.message;
  out["converged"] = outcome.status == FilmStatus::converged;
  out["steps_done"] = outcome.steps_done;
  out["time_step"] = problem.transient->time_step;
  out["time_scheme"] = std::string(to_string(problem.transient->scheme));
  return out;
}

// The numbers an elastic and a mixed film report alike, under the keys of
// the program's summary, in its order.
template <class Film>
void put_elastic_summary(nb::dict& out, const LubricationProblem& problem, const char* model, const Grid& grid,
                         const Film& film, double cavitated_fraction, long long film_solves, const LubricantLaws& laws,
                         double viscosity, CouetteScheme couette_scheme, double e_star) {
  out["model"] = model;
  out["status"] = std::string(to_string(film.status));
  out["message"] = with_hint(film.message, film.converged(), problem);
  out["converged"] = film.converged();
  out["load"] = film.load;
  out["mean_pressure"] = film.load / grid.domain_area();
  out["separation"] = film.offset;
  out["central_film_thickness"] = film.central_film_thickness;
  out["minimum_film_thickness"] = film.minimum_film_thickness;
  out["max_pressure"] = film.max_pressure;
  out["cavitated_fraction"] = cavitated_fraction;
  out["iterations"] = film.iterations;
  out["film_solves"] = film_solves;
  out["relative_residual"] = film.relative_residual;
  out["solve_seconds"] = film.wall_seconds;
  out["inflow"] = nb::none();
  out["outflow"] = nb::none();
  out["load_error"] = film.load_error;
  out["e_star"] = e_star;
  out["piezoviscosity"] = std::string(to_string(laws.piezoviscosity));
  out["roelands_index"] = laws.piezoviscosity == Piezoviscosity::roelands ? laws.roelands_exponent(viscosity) : 0.0;
  out["compressibility"] = std::string(to_string(laws.compressibility));
  out["couette_scheme"] = std::string(to_string(couette_scheme));
}

nb::dict solve_elastic(const Grid& grid, const Eigen::ArrayXd& heights, const LubricationProblem& problem) {
  const FlowConditions& conditions = problem.conditions;
  const LubricantLaws& laws = problem.laws;
  const ElasticFilmOptions& options = problem.elastic;
  const std::optional<LayeredMaterial>& coating = problem.coating;
  const double e_star = problem.e_star;
  const Eigen::ArrayXd gap = heights.maxCoeff() - heights;
  ElasticFilm film = with_keywords([&] {
    nb::gil_scoped_release release;
    FftInfluenceOperator op(grid, coating ? HalfSpace(*coating) : HalfSpace(e_star), problem.fft_planning);
    return solve_elastic_film(op, gap, conditions, laws, options);
  });
  const FilmShear shear =
      film_shear(grid, conditions, laws, problem.limits, film.film, film.pressure, film.fluid_fraction);
  nb::dict out;
  const double cavitated = static_cast<double>((film.fluid_fraction < 1.0).count()) / static_cast<double>(grid.size());
  put_elastic_summary(out, problem, "elastic", grid, film, cavitated, 1, laws, conditions.viscosity,
                      options.couette_scheme, e_star);
  out["deformation"] = owning_array(std::move(film.deformation), io::field_shape(grid));
  put_fields(out, grid, std::move(film.pressure), std::move(film.film), std::move(film.fluid_fraction), shear);
  return out;
}

// A mixed film's numbers and fields, as `halfspace lubricate --mixed` writes
// them (its summary and write_mixed_fields).
nb::dict mixed_dict(const Grid& grid, const LubricationProblem& problem, MixedFilm film, double viscosity,
                    long long film_solves) {
  const MixedFilmOptions& options = problem.mixed;
  const LubricantLaws& laws = problem.laws;
  const double e_star = problem.e_star;
  nb::dict out;
  put_elastic_summary(out, problem, "mixed", grid, film, film.cavitated_fraction, film_solves, laws, viscosity,
                      options.couette_scheme, e_star);
  out["entrainment_speed"] = film.entrainment_speed;
  out["fluid_load"] = film.fluid_load;
  out["contact_load"] = film.contact_load;
  out["contact_load_fraction"] = film.contact_load_fraction;
  out["contact_area"] = film.contact_area;
  out["contact_area_fraction"] = film.contact_area_fraction;
  out["complementarity_error"] = film.complementarity_error;
  out["contact_friction"] = options.friction.contact_friction;
  out["boundary_film"] = options.boundary_film;
  out["fluid_friction_force"] = nb::make_tuple(film.fluid_friction_force[0], film.fluid_friction_force[1]);
  out["contact_friction_force"] = nb::make_tuple(film.contact_friction_force[0], film.contact_friction_force[1]);
  out["friction_force"] = nb::make_tuple(film.fluid_friction_force[0] + film.contact_friction_force[0],
                                         film.fluid_friction_force[1] + film.contact_friction_force[1]);
  out["friction_coefficient"] = film.friction_coefficient;
  // The film's shear fields are the rigid and EHL films' (film_shear.hpp);
  // the mixed film reports its friction as forces only.
  out["shear_x"] = nb::none();
  out["shear_y"] = nb::none();
  out["couette_friction_force"] = nb::none();
  out["limited_fraction"] = nb::none();
  const std::vector<std::size_t> shape = io::field_shape(grid);
  out["fluid_pressure"] = owning_array(std::move(film.fluid_pressure), shape);
  out["contact_pressure"] = owning_array(std::move(film.contact_pressure), shape);
  out["pressure"] = owning_array(std::move(film.pressure), shape);
  out["film"] = owning_array(std::move(film.film), shape);
  out["fluid_fraction"] = owning_array(std::move(film.fluid_fraction), shape);
  out["deformation"] = owning_array(std::move(film.deformation), shape);
  return out;
}

// The mixed film (one dict), or with speeds= the Stribeck sweep (a list of
// dicts, each with its speed and Hersey number), as run_mixed in
// apps/lubricate_command.cpp.
// With `trace` (trace=) every Newton solve's line goes to that CSV file
// (io::MixedTraceWriter, as `--trace`); a write that failed raises
// FileError after the solve.
nb::object solve_mixed(const Grid& grid, const Eigen::ArrayXd& heights, const LubricationProblem& problem,
                       const std::optional<std::string>& trace) {
  const FlowConditions& conditions = problem.conditions;
  const LubricantLaws& laws = problem.laws;
  MixedFilmOptions options = problem.mixed;
  const double e_star = problem.e_star;
  const Eigen::ArrayXd gap = heights.maxCoeff() - heights;
  FftInfluenceOperator op(grid, e_star, problem.fft_planning);
  std::optional<io::MixedTraceWriter> writer;
  if (trace) {
    io::check_output_path(*trace);
    writer.emplace(*trace);
    options.trace = writer->callback();
  }
  const auto check_trace = [&] {
    if (writer && !writer->failure().empty()) throw FileError(writer->failure());
  };
  if (!problem.speeds) {
    MixedFilm film = with_keywords([&] {
      nb::gil_scoped_release release;
      return solve_mixed_film(op, gap, conditions, laws, options);
    });
    check_trace();
    return mixed_dict(grid, problem, std::move(film), conditions.viscosity, 1);
  }
  std::vector<StribeckPoint> points = with_keywords([&] {
    nb::gil_scoped_release release;
    return stribeck_sweep(op, gap, conditions, laws, options, *problem.speeds);
  });
  check_trace();
  nb::list curve;
  for (StribeckPoint& point : points) {
    nb::dict film = mixed_dict(grid, problem, std::move(point.film), conditions.viscosity, 1);
    film["hersey_number"] = point.hersey_number;
    film["entrainment_speed"] = point.entrainment_speed;
    curve.append(film);
  }
  return curve;
}

// The film of the keywords `given` (lubrication_option_names: None for not
// given) on the heights.
nb::object lubricate(const nb::object& heights_object, double dx, double dy, const nb::dict& given,
                     std::optional<int> threads, const std::optional<std::string>& trace) {
  const auto heights = nb::cast<InputArray>(heights_object, false);
  check_array_dimensions(heights, "the surface");
  require_finite_heights(heights, "the surface");
  const Eigen::ArrayXd z = Eigen::Map<const Eigen::ArrayXd>(heights.data(), static_cast<Eigen::Index>(heights.size()));
  const KeywordSpelling keywords;
  const LubricationProblem problem = make_lubrication_problem(
      options_from<LubricationProblemOptions>(given, lubrication_option_names(), "film option"), keywords);
  const Grid grid = array_grid(heights, dx, dy, problem.boundary, "the surface");
  problem.check_grid(grid, keywords);
  if (trace && problem.kind != FilmKind::mixed) {
    throw InputError(fmt::format("trace='{}' traces the mixed film's Newton solves: it needs mixed=True", *trace));
  }
  if (problem.transient) return solve_transient(grid, z, problem);
  if (problem.kind == FilmKind::rigid) return solve_rigid(grid, z, problem);
  // The elastic films' FFT plans take the threads in force (process-wide; a
  // solve(threads=) before may have changed them): the program's unless
  // threads= says otherwise, so that the rounding is the program's too.
  in_context(fmt::format("threads={}", threads.value_or(0)), [&] { set_threads(threads.value_or(default_threads())); });
  if (problem.kind == FilmKind::mixed) return solve_mixed(grid, z, problem, trace);
  return solve_elastic(grid, z, problem);
}

}  // namespace

void bind_lubricate(nb::module_& module) {
  module.def("lubricate", &lubricate, nb::arg("heights"), nb::arg("dx"), nb::arg("dy"), nb::arg("film"),
             nb::arg("threads").none(), nb::arg("trace").none());
}

}  // namespace halfspace::python
