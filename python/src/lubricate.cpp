// halfspace.lubricate: the keywords mapped onto the library's lubrication
// options (FlowConditions, CavitationSolverOptions, LoadControlOptions,
// LubricantLaws, ElasticFilmOptions, ShearLimits), whose validate() holds
// the rules; a broken rule (OptionError) is restated with the keyword it
// came from. The film is solved as `halfspace lubricate` solves it, with the
// GIL released, and handed back as numpy arrays and numbers. With mixed=
// the film may close (mixed_film.hpp, `halfspace lubricate --mixed`); with
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
#include "halfspace/layered_material.hpp"
#include "halfspace/lubrication/elastic_film.hpp"
#include "halfspace/lubrication/film_shear.hpp"
#include "halfspace/lubrication/load_control.hpp"
#include "halfspace/lubrication/mixed_film.hpp"
#include "halfspace/material.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/threads.hpp"

namespace halfspace::python {
namespace {

using namespace halfspace::lubrication;

// The keyword of halfspace.lubricate that sets each library option.
std::string keyword_for(const std::string& option) {
  if (option.starts_with("entrainment_velocity")) return "entrainment_velocity";
  if (option.starts_with("sliding_velocity")) return "sliding_velocity";
  if (option == "boundary.x_low_pressure") return "inlet_pressure";
  if (option == "boundary.x_high_pressure") return "outlet_pressure";
  if (option == "boundary.y_low_pressure" || option == "boundary.y_high_pressure") return "side_pressure";
  if (option == "boundary.supply_fluid_fraction") return "supply_fluid_fraction";
  if (option == "tolerance") return "tol";
  if (option == "max_iterations") return "max_iter";
  if (option == "load") return "force";
  return option;  // viscosity, separation, offset, boundary_film, contact_friction, speeds, pressure_viscosity, ...
}

// Runs `work`, restating an OptionError as "keyword=value rule".
template <class Work>
auto with_keywords(Work&& work) {
  try {
    return work();
  } catch (const OptionError& error) {
    const std::string& option = error.option();
    const std::string component = option.ends_with(".x")   ? " (x component)"
                                  : option.ends_with(".y") ? " (y component)"
                                                           : "";
    throw InputError(fmt::format("{}={}{} {}", keyword_for(option), error.value(), component, error.rule()));
  }
}

// What the keywords give, as _lubricate.py passes them (None: not given).
struct Keywords {
  double viscosity = 0.0;
  std::vector<double> entrainment_velocity, sliding_velocity;
  std::optional<double> separation, force;
  double inlet_pressure = 0.0, outlet_pressure = 0.0, side_pressure = 0.0;
  bool periodic_x = false, periodic_y = false;
  double supply_fluid_fraction = 1.0;
  std::optional<double> tol;
  std::optional<int> max_iter;
  // Elastic film (EHL): E* or a coated half-space.
  std::optional<double> e_star;
  std::optional<std::vector<double>> coating;
  std::string boundary = "free";
  std::optional<double> pressure_viscosity;
  std::optional<std::string> piezoviscosity;
  std::optional<double> roelands_index;
  std::optional<std::string> compressibility;
  std::optional<std::string> couette_scheme;
  ShearLimits limits;
  // Mixed film: the film may close; offset (separation control) instead of
  // force; a Stribeck sweep over speeds.
  bool mixed = false;
  std::optional<double> offset, contact_friction, boundary_film;
  std::optional<std::vector<double>> speeds;
  std::optional<int> threads;  // None: default_threads(), as the program
};

std::array<double, 2> velocity(const std::vector<double>& given, const char* keyword) {
  if (given.empty() || given.size() > 2) {
    throw InputError(fmt::format("{} has {} values: give UX or (UX, UY) in m/s", keyword, given.size()));
  }
  return {given[0], given.size() == 2 ? given[1] : 0.0};
}

// The keyword's name prefixed to a parse error ("piezoviscosity='x': ...").
template <class Parse>
auto named(const char* keyword, const std::string& value, Parse&& parse) {
  try {
    return parse(value);
  } catch (const InputError& error) {
    throw InputError(fmt::format("{}='{}': {}", keyword, value, error.what()));
  }
}

LubricantLaws lubricant_laws(const Keywords& k) {
  LubricantLaws laws;
  laws.pressure_viscosity = k.pressure_viscosity.value_or(0.0);
  laws.roelands_index = k.roelands_index.value_or(0.0);
  laws.piezoviscosity = k.piezoviscosity ? named("piezoviscosity", *k.piezoviscosity, parse_piezoviscosity)
                        : laws.pressure_viscosity > 0.0 ? Piezoviscosity::barus
                                                        : Piezoviscosity::none;
  laws.compressibility =
      named("compressibility", k.compressibility.value_or("dowson-higginson"), parse_compressibility);
  return laws;
}

std::vector<std::size_t> shape_of(const Grid& grid) {
  return grid.dimension() == 1 ? std::vector<std::size_t>{grid.nx()} : std::vector<std::size_t>{grid.ny(), grid.nx()};
}

// The film's fields and the shear, as the dict _lubricate.py wraps.
void put_fields(nb::dict& out, const Grid& grid, Eigen::ArrayXd pressure, Eigen::ArrayXd film,
                Eigen::ArrayXd fluid_fraction, const FilmShear& shear) {
  const std::vector<std::size_t> shape = shape_of(grid);
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

nb::dict solve_rigid(const Grid& grid, const Eigen::ArrayXd& heights, const FlowConditions& conditions,
                     const Keywords& k) {
  CavitationSolverOptions solver;
  if (k.tol) solver.tolerance = *k.tol;
  if (k.max_iter) solver.max_iterations = *k.max_iter;
  LoadControlOptions load;
  if (k.force) load.load = *k.force;
  with_keywords([&] {
    solver.validate();
    if (k.force) load.validate();
    k.limits.validate();
  });
  const auto started = std::chrono::steady_clock::now();
  LubricatedFilm film = with_keywords([&] {
    nb::gil_scoped_release release;
    return k.force ? lubricate_at_load(grid, heights, conditions, load, solver)
                   : lubricate_at_separation(grid, heights, conditions, *k.separation, solver);
  });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const FilmShear shear = film_shear(grid, conditions, LubricantLaws{}, k.limits, film.film, film.solution.pressure,
                                     film.solution.fluid_fraction);
  const FilmForces& f = film.forces;
  nb::dict out;
  out["model"] = "rigid";
  out["status"] = std::string(to_string(film.solution.status));
  out["message"] = film.solution.message;
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

// The numbers an elastic and a mixed film report alike, under the keys of
// the program's summary, in its order.
template <class Film>
void put_elastic_summary(nb::dict& out, const char* model, const Grid& grid, const Film& film,
                         double cavitated_fraction, long long film_solves, const LubricantLaws& laws, double viscosity,
                         CouetteScheme couette_scheme, double e_star) {
  out["model"] = model;
  out["status"] = std::string(to_string(film.status));
  out["message"] = film.message;
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

nb::dict solve_elastic(const Grid& grid, const Eigen::ArrayXd& heights, const FlowConditions& conditions,
                       const Keywords& k, const std::optional<LayeredMaterial>& coating, double e_star) {
  if (!k.force) throw InputError("an elastic film (EHL) is load controlled: pass force=, not separation=");
  const LubricantLaws laws = lubricant_laws(k);
  ElasticFilmOptions options;
  options.load = *k.force;
  if (k.tol) options.tolerance = *k.tol;
  if (k.max_iter) options.max_iterations = *k.max_iter;
  if (k.couette_scheme) options.couette_scheme = named("couette_scheme", *k.couette_scheme, parse_couette_scheme);
  with_keywords([&] {
    laws.validate(conditions.viscosity);
    options.validate();
    k.limits.validate();
  });
  const Eigen::ArrayXd gap = heights.maxCoeff() - heights;
  ElasticFilm film = with_keywords([&] {
    nb::gil_scoped_release release;
    if (coating) {
      FftInfluenceOperator op(grid, *coating);
      return solve_elastic_film(op, gap, conditions, laws, options);
    }
    FftInfluenceOperator op(grid, e_star);
    return solve_elastic_film(op, gap, conditions, laws, options);
  });
  const FilmShear shear = film_shear(grid, conditions, laws, k.limits, film.film, film.pressure, film.fluid_fraction);
  nb::dict out;
  const double cavitated = static_cast<double>((film.fluid_fraction < 1.0).count()) / static_cast<double>(grid.size());
  put_elastic_summary(out, "elastic", grid, film, cavitated, 1, laws, conditions.viscosity, options.couette_scheme,
                      e_star);
  out["deformation"] = owning_array(std::move(film.deformation), shape_of(grid));
  put_fields(out, grid, std::move(film.pressure), std::move(film.film), std::move(film.fluid_fraction), shear);
  return out;
}

// A mixed film's numbers and fields, as `halfspace lubricate --mixed` writes
// them (its summary and write_mixed_fields).
nb::dict mixed_dict(const Grid& grid, MixedFilm film, const MixedFilmOptions& options, const LubricantLaws& laws,
                    double viscosity, double e_star, long long film_solves) {
  nb::dict out;
  put_elastic_summary(out, "mixed", grid, film, film.cavitated_fraction, film_solves, laws, viscosity,
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
  const std::vector<std::size_t> shape = shape_of(grid);
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
nb::object solve_mixed(const Grid& grid, const Eigen::ArrayXd& heights, const FlowConditions& conditions,
                       const Keywords& k, double e_star) {
  if (k.separation) {
    throw InputError("separation= is the rigid film's: the mixed film takes force= (N/m) or offset= (m)");
  }
  if (k.speeds && !k.force) throw InputError("a Stribeck sweep (speeds=) is load controlled: pass force=");
  const LubricantLaws laws = lubricant_laws(k);
  MixedFilmOptions options;
  options.load = k.force.value_or(0.0);
  options.offset = k.offset.value_or(0.0);
  if (k.boundary_film) options.boundary_film = *k.boundary_film;
  if (k.tol) options.tolerance = *k.tol;
  if (k.max_iter) options.max_iterations = *k.max_iter;
  if (k.couette_scheme) options.couette_scheme = named("couette_scheme", *k.couette_scheme, parse_couette_scheme);
  if (k.contact_friction) options.friction.contact_friction = *k.contact_friction;
  options.friction.shear = k.limits;
  with_keywords([&] {
    laws.validate(conditions.viscosity);
    options.validate();
  });
  if (grid.size() > kMaxMixedFilmNodes) {
    throw InputError(
        fmt::format("the surface has {} points: the mixed film's dense Newton path allows at most {} (coarsen it)",
                    grid.size(), kMaxMixedFilmNodes));
  }
  const Eigen::ArrayXd gap = heights.maxCoeff() - heights;
  FftInfluenceOperator op(grid, e_star);
  if (!k.speeds) {
    MixedFilm film = with_keywords([&] {
      nb::gil_scoped_release release;
      return solve_mixed_film(op, gap, conditions, laws, options);
    });
    return mixed_dict(grid, std::move(film), options, laws, conditions.viscosity, e_star, 1);
  }
  std::vector<StribeckPoint> points = with_keywords([&] {
    nb::gil_scoped_release release;
    return stribeck_sweep(op, gap, conditions, laws, options, *k.speeds);
  });
  nb::list curve;
  for (StribeckPoint& point : points) {
    nb::dict film = mixed_dict(grid, std::move(point.film), options, laws, conditions.viscosity, e_star, 1);
    film["hersey_number"] = point.hersey_number;
    film["entrainment_speed"] = point.entrainment_speed;
    curve.append(film);
  }
  return curve;
}

nb::object lubricate(const nb::object& heights_object, double dx, double dy, const Keywords& k) {
  const auto heights = nb::cast<InputArray>(heights_object, false);
  if (heights.ndim() != 1 && heights.ndim() != 2) {
    throw InputError(fmt::format("the surface must be a 1D or 2D array, got {} dimensions", heights.ndim()));
  }
  const Eigen::ArrayXd z = Eigen::Map<const Eigen::ArrayXd>(heights.data(), static_cast<Eigen::Index>(heights.size()));
  if (!z.allFinite()) {
    throw InputError(
        "the surface has non-finite heights: a film needs every height (HeightMap.prepare(invalid='fill'))");
  }
  if (k.separation.has_value() + k.force.has_value() + k.offset.has_value() != 1) {
    throw InputError(k.mixed ? "give exactly one of force= and offset=" : "give exactly one of separation= and force=");
  }
  if (!k.mixed && (k.offset || k.contact_friction || k.boundary_film || k.speeds)) {
    throw InputError("offset, contact_friction, boundary_film and speeds belong to the mixed film: add mixed=True");
  }
  const bool elastic = k.e_star.has_value() || k.coating.has_value();
  if (k.mixed && !elastic) throw InputError("mixed=True needs an elastic body: give e_star (or E1, nu1, E2, nu2)");
  if (k.mixed && k.coating) {
    throw InputError("mixed=True takes a homogeneous body: a coating is not supported by the mixed film yet");
  }
  if (!elastic && (k.pressure_viscosity || k.piezoviscosity || k.roelands_index || k.compressibility ||
                   k.couette_scheme || k.boundary != "free")) {
    throw InputError(
        "pressure_viscosity, piezoviscosity, roelands_index, compressibility, couette_scheme and boundary need an "
        "elastic film: give e_star (or E1, nu1, E2, nu2, or coating)");
  }
  Boundary boundary = Boundary::free;
  try {
    boundary = parse_boundary(k.boundary);
  } catch (const InputError& error) {
    throw InputError(fmt::format("boundary: {}", error.what()));
  }
  const Grid grid = heights.ndim() == 1 ? Grid::line(heights.shape(0), dx, boundary)
                                        : Grid::plane(heights.shape(1), heights.shape(0), dx, dy, boundary);
  FlowConditions conditions;
  conditions.viscosity = k.viscosity;
  conditions.entrainment_velocity = velocity(k.entrainment_velocity, "entrainment_velocity");
  conditions.sliding_velocity =
      k.sliding_velocity.empty() ? std::array<double, 2>{0.0, 0.0} : velocity(k.sliding_velocity, "sliding_velocity");
  conditions.boundary.x = k.periodic_x ? AxisBoundary::periodic : AxisBoundary::fixed_pressure;
  conditions.boundary.y = k.periodic_y ? AxisBoundary::periodic : AxisBoundary::fixed_pressure;
  conditions.boundary.x_low_pressure = k.inlet_pressure;
  conditions.boundary.x_high_pressure = k.outlet_pressure;
  conditions.boundary.y_low_pressure = k.side_pressure;
  conditions.boundary.y_high_pressure = k.side_pressure;
  conditions.boundary.supply_fluid_fraction = k.supply_fluid_fraction;
  with_keywords([&] { conditions.validate(grid); });
  if (!elastic) return solve_rigid(grid, z, conditions, k);
  // The elastic films' FFT plans take the threads in force (process-wide; a
  // solve(threads=) before may have changed them): the program's unless
  // threads= says otherwise, so that the rounding is the program's too.
  try {
    set_threads(k.threads.value_or(default_threads()));
  } catch (const InputError& error) {
    throw InputError(fmt::format("threads={}: {}", k.threads.value_or(0), error.what()));
  }
  if (k.mixed) return solve_mixed(grid, z, conditions, k, checked_composite_modulus(*k.e_star));

  std::optional<LayeredMaterial> coating;
  double e_star = 0.0;
  if (k.coating) {
    const std::vector<double>& v = *k.coating;
    if (v.size() != 5) {
      throw InputError("coating needs five values: thickness, layer_E, layer_nu, substrate_E, substrate_nu");
    }
    coating = LayeredMaterial{v[0], {v[1], v[2]}, {v[3], v[4]}};
    try {
      validated(*coating);
    } catch (const InputError& error) {
      throw InputError(fmt::format("coating: {}", error.what()));
    }
    e_star = plane_strain_modulus(coating->layer);
  } else {
    e_star = checked_composite_modulus(*k.e_star);
  }
  return solve_elastic(grid, z, conditions, k, coating, e_star);
}

}  // namespace

void bind_lubricate(nb::module_& module) {
  module.def(
      "lubricate",
      [](const nb::object& heights, double dx, double dy, double viscosity, const std::vector<double>& entrainment,
         const std::vector<double>& sliding, std::optional<double> separation, std::optional<double> force,
         double inlet_pressure, double outlet_pressure, double side_pressure, bool periodic_x, bool periodic_y,
         double supply_fluid_fraction, std::optional<double> tol, std::optional<int> max_iter,
         std::optional<double> e_star, std::optional<std::vector<double>> coating, const std::string& boundary,
         std::optional<double> pressure_viscosity, std::optional<std::string> piezoviscosity,
         std::optional<double> roelands_index, std::optional<std::string> compressibility,
         std::optional<std::string> couette_scheme, double eyring_stress, double limiting_shear_stress,
         double limiting_shear_slope, bool mixed, std::optional<double> offset, std::optional<double> contact_friction,
         std::optional<double> boundary_film, std::optional<std::vector<double>> speeds, std::optional<int> threads) {
        Keywords k;
        k.viscosity = viscosity;
        k.entrainment_velocity = entrainment;
        k.sliding_velocity = sliding;
        k.separation = separation;
        k.force = force;
        k.inlet_pressure = inlet_pressure;
        k.outlet_pressure = outlet_pressure;
        k.side_pressure = side_pressure;
        k.periodic_x = periodic_x;
        k.periodic_y = periodic_y;
        k.supply_fluid_fraction = supply_fluid_fraction;
        k.tol = tol;
        k.max_iter = max_iter;
        k.e_star = e_star;
        k.coating = std::move(coating);
        k.boundary = boundary;
        k.pressure_viscosity = pressure_viscosity;
        k.piezoviscosity = std::move(piezoviscosity);
        k.roelands_index = roelands_index;
        k.compressibility = std::move(compressibility);
        k.couette_scheme = std::move(couette_scheme);
        k.limits = {eyring_stress, limiting_shear_stress, limiting_shear_slope};
        k.mixed = mixed;
        k.offset = offset;
        k.contact_friction = contact_friction;
        k.boundary_film = boundary_film;
        k.speeds = std::move(speeds);
        k.threads = threads;
        return lubricate(heights, dx, dy, k);
      },
      nb::arg("heights"), nb::arg("dx"), nb::arg("dy"), nb::arg("viscosity"), nb::arg("entrainment_velocity"),
      nb::arg("sliding_velocity"), nb::arg("separation").none(), nb::arg("force").none(), nb::arg("inlet_pressure"),
      nb::arg("outlet_pressure"), nb::arg("side_pressure"), nb::arg("periodic_x"), nb::arg("periodic_y"),
      nb::arg("supply_fluid_fraction"), nb::arg("tol").none(), nb::arg("max_iter").none(), nb::arg("e_star").none(),
      nb::arg("coating").none(), nb::arg("boundary"), nb::arg("pressure_viscosity").none(),
      nb::arg("piezoviscosity").none(), nb::arg("roelands_index").none(), nb::arg("compressibility").none(),
      nb::arg("couette_scheme").none(), nb::arg("eyring_stress"), nb::arg("limiting_shear_stress"),
      nb::arg("limiting_shear_slope"), nb::arg("mixed"), nb::arg("offset").none(), nb::arg("contact_friction").none(),
      nb::arg("boundary_film").none(), nb::arg("speeds").none(), nb::arg("threads").none());
}

}  // namespace halfspace::python
