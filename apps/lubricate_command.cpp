// The lubricate command: height map -> film at a separation (or the
// separation carrying a force) -> pressure, film and fluid fraction in an
// HDF5 file; with a material (--E-star or E1, nu1, E2, nu2) the film is
// elastohydrodynamic (elastic_film.hpp) under the force. Flags map onto
// lubrication::FlowConditions, CavitationSolverOptions, LoadControlOptions,
// LubricantLaws and ElasticFilmOptions, whose validate() holds the rules.
#include "lubricate_command.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "exit_codes.hpp"
#include "halfspace/error.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/io/fft_wisdom_file.hpp"
#include "halfspace/io/film_history_writer.hpp"
#include "halfspace/io/friction_history_writer.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/io/height_map_reader.hpp"
#include "halfspace/io/mixed_trace_writer.hpp"
#include "halfspace/io/output_file.hpp"
#include "halfspace/io/result_attributes.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/lubrication/elastic_film.hpp"
#include "halfspace/lubrication/film_shear.hpp"
#include "halfspace/lubrication/load_control.hpp"
#include "halfspace/lubrication/lubrication_problem.hpp"
#include "halfspace/lubrication/mixed_film.hpp"
#include "halfspace/lubrication/transient_film.hpp"
#include "halfspace/material.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/surface/surface_options.hpp"
#include "halfspace/version.hpp"
#include "option_table.hpp"
#include "plot_tool.hpp"
#include "processes.hpp"
#include "surface_option_table.hpp"

namespace halfspace::app {
namespace {

// The surface's options (SurfaceOptions, which make_surface_choice checks),
// the film's (LubricationProblemOptions, which make_lubrication_problem
// checks) and the program's own: the files and how to report.
struct LubricateOptions : GivenOptions, SurfaceOptions, lubrication::LubricationProblemOptions {
  std::optional<std::string> roughness;
  std::optional<std::string> stribeck;
  std::optional<std::string> trace;
  std::optional<std::string> output;
  bool plot = false;
  bool quiet = false;
};

using LubricateOption = OptionSpec<LubricateOptions>;
using Kind = OptionKind;
constexpr std::string_view kFilm = "Film";
constexpr std::string_view kElastic = "Elastic film (EHL)";
constexpr std::string_view kMixed = "Mixed lubrication";
constexpr std::string_view kTransient = "Transient film (rigid)";
constexpr std::string_view kOutput = "Output";

// The rows of lubricate's own options, after the surface's.
const std::array kOwnOptions{
    LubricateOption{"viscosity", &LubricateOptions::viscosity, Kind::number, kFilm, "PA_S",
                    "lubricant viscosity (Pa s) (required)"},
    LubricateOption{"entrainment-velocity", &LubricateOptions::entrainment_velocity, Kind::numbers, kFilm, "UX[,UY]",
                    "mean of the two surfaces' velocities (m/s) (required)"},
    LubricateOption{"sliding-velocity", &LubricateOptions::sliding_velocity, Kind::numbers, kFilm, "UX[,UY]",
                    "upper minus lower surface velocity (m/s), for the friction force [0]"},
    LubricateOption{"eyring-stress", &LubricateOptions::eyring_stress, Kind::number, kFilm, "PA",
                    "Eyring stress tau0 (Pa): the film's Couette shear is tau0 asinh(tau / tau0) [Newtonian]"},
    LubricateOption{"limiting-shear-stress", &LubricateOptions::limiting_shear_stress, Kind::number, kFilm, "PA",
                    "limiting shear stress tau_L0 (Pa): the Couette shear is at most tau_L0 + gamma p [none]"},
    LubricateOption{"limiting-shear-slope", &LubricateOptions::limiting_shear_slope, Kind::number, kFilm, "GAMMA",
                    "the limiting shear stress' growth with pressure gamma [0]"},
    LubricateOption{"separation", &LubricateOptions::separation, Kind::number, kFilm, "M",
                    "minimum film thickness (m); or --force"},
    LubricateOption{"force", &LubricateOptions::force, Kind::number, kFilm, "N",
                    "load the film carries (N; N/m on a profile): the separation is found"},
    LubricateOption{"inlet-pressure", &LubricateOptions::inlet_pressure, Kind::number, kFilm, "PA",
                    "pressure at x = 0 (Pa) [0]"},
    LubricateOption{"outlet-pressure", &LubricateOptions::outlet_pressure, Kind::number, kFilm, "PA",
                    "pressure at the last x (Pa) [0]"},
    LubricateOption{"side-pressure", &LubricateOptions::side_pressure, Kind::number, kFilm, "PA",
                    "pressure at y = 0 and the last y of a map (Pa) [0]"},
    LubricateOption{"periodic-x", &LubricateOptions::periodic_x, Kind::flag, kFilm, "",
                    "the film repeats along x instead of having inlet and outlet pressures (a map; needs fixed "
                    "sides)"},
    LubricateOption{"periodic-y", &LubricateOptions::periodic_y, Kind::flag, kFilm, "",
                    "the film repeats along y instead of having fixed side pressures"},
    LubricateOption{"supply-fluid-fraction", &LubricateOptions::supply_fluid_fraction, Kind::number, kFilm, "THETA",
                    "fluid fraction of the lubricant at the fixed-pressure edges, 0 to 1 (below 1: a starved "
                    "supply) [1]"},
    LubricateOption{"tolerance", &LubricateOptions::tolerance, Kind::number, kFilm, "TOL",
                    "relative mass residual at convergence [1e-11; 1e-8 for an elastic film]"},
    LubricateOption{"E-star", &LubricateOptions::e_star, Kind::number, kElastic, "PA",
                    "composite modulus E* (Pa): the film is elastic (EHL) and needs --force; or E1, nu1, E2, nu2"},
    LubricateOption{"E1", &LubricateOptions::e1, Kind::number, kElastic, "PA", "Young's modulus of body 1 (Pa)"},
    LubricateOption{"nu1", &LubricateOptions::nu1, Kind::number, kElastic, "NU", "Poisson's ratio of body 1"},
    LubricateOption{"E2", &LubricateOptions::e2, Kind::number, kElastic, "PA", "Young's modulus of body 2 (Pa)"},
    LubricateOption{"nu2", &LubricateOptions::nu2, Kind::number, kElastic, "NU", "Poisson's ratio of body 2"},
    LubricateOption{"layer-thickness", &LubricateOptions::layer_thickness, Kind::number, kElastic, "M",
                    "a coated elastic body: the layer's thickness (m), with --layer-E, --layer-nu, --substrate-E, "
                    "--substrate-nu instead of --E-star (the other surface rigid)"},
    LubricateOption{"layer-E", &LubricateOptions::layer_e, Kind::number, kElastic, "PA", "the layer's Young's modulus"},
    LubricateOption{"layer-nu", &LubricateOptions::layer_nu, Kind::number, kElastic, "NU",
                    "the layer's Poisson's ratio"},
    LubricateOption{"substrate-E", &LubricateOptions::substrate_e, Kind::number, kElastic, "PA",
                    "the substrate's Young's modulus"},
    LubricateOption{"substrate-nu", &LubricateOptions::substrate_nu, Kind::number, kElastic, "NU",
                    "the substrate's Poisson's ratio"},
    LubricateOption{"boundary", &LubricateOptions::boundary, Kind::text, kElastic, "TYPE",
                    "elastic half-space periodic or free [free]"},
    LubricateOption{"pressure-viscosity", &LubricateOptions::pressure_viscosity, Kind::number, kElastic, "ALPHA",
                    "pressure-viscosity coefficient alpha (1/Pa) [0]"},
    LubricateOption{"piezoviscosity", &LubricateOptions::piezoviscosity, Kind::text, kElastic, "LAW",
                    "none, barus or roelands [barus with --pressure-viscosity, else none]"},
    LubricateOption{"roelands-index", &LubricateOptions::roelands_index, Kind::number, kElastic, "Z",
                    "Roelands' z [from alpha: alpha 1.96e8 / (ln eta0 + 9.67)]"},
    LubricateOption{"compressibility", &LubricateOptions::compressibility, Kind::text, kElastic, "LAW",
                    "none or dowson-higginson [dowson-higginson]"},
    LubricateOption{"couette-scheme", &LubricateOptions::couette_scheme, Kind::text, kElastic, "SCHEME",
                    "first-order or second-order upwinding of the wedge flux [first-order]"},
    LubricateOption{"film-preconditioner", &LubricateOptions::film_preconditioner, Kind::text, kElastic, "NAME",
                    "the EHL film's GMRES preconditioner: multigrid or sparse-lu (exact, for cross-checks) "
                    "[multigrid]"},
    LubricateOption{"fft-planning", &LubricateOptions::fft_planning, Kind::text, kElastic, "MODE",
                    "FFTW planning effort for the elastic film's transforms: estimate, measure or patient [estimate]"},
    LubricateOption{"max-iterations", &LubricateOptions::max_iterations, Kind::integer, kFilm, "N",
                    "Newton steps of an elastic film, 1 to 100000 [100; 200 mixed]; sweeps of a rigid one [2e6]"},
    LubricateOption{"mixed", &LubricateOptions::mixed, Kind::flag, kMixed, "",
                    "the elastic film may close: asperities in contact carry a contact pressure (needs --E-star)"},
    LubricateOption{"roughness", &LubricateOptions::roughness, Kind::path, kMixed, "FILE",
                    "heights added to the surface's (same points and spacing): a rough profile on the contact"},
    LubricateOption{"offset", &LubricateOptions::offset, Kind::number, kMixed, "M",
                    "separation control of the mixed film: h0 of h = h0 + gap + K p (m), instead of --force"},
    LubricateOption{"contact-friction", &LubricateOptions::contact_friction, Kind::number, kMixed, "MU",
                    "Coulomb coefficient on contact cells [0.1]"},
    LubricateOption{"boundary-film", &LubricateOptions::boundary_film, Kind::number, kMixed, "M",
                    "the thinnest film the Reynolds equation sees, on contact cells (m) [1e-9]"},
    LubricateOption{"speeds", &LubricateOptions::speeds, Kind::numbers, kMixed, "U1,U2,...",
                    "Stribeck sweep: entrainment speeds (m/s), sliding scaled alike; needs --stribeck"},
    LubricateOption{"stribeck", &LubricateOptions::stribeck, Kind::path, kMixed, "FILE.csv",
                    "the Stribeck curve of --speeds as CSV"},
    LubricateOption{"trace", &LubricateOptions::trace, Kind::path, kMixed, "FILE.csv",
                    "one line per Newton solve of the mixed film as it ends (grid, speed, steps, GMRES iterations, "
                    "seconds), written as the run goes: where a long run is and where its time went"},
    LubricateOption{"time-step", &LubricateOptions::time_step, Kind::number, kTransient, "DT",
                    "step the rigid film in time (s): the squeeze term d(h theta)/dt from --separation at t = 0, "
                    "moved by --approach-velocity, --separation-history or --force; writes /steps and a CSV "
                    "history beside --output"},
    LubricateOption{"steps", &LubricateOptions::steps, Kind::integer, kTransient, "N",
                    "time steps, 1 to 10000000 [the length of --separation-history]"},
    LubricateOption{"time-scheme", &LubricateOptions::time_scheme, Kind::text, kTransient, "SCHEME",
                    "bdf2 or backward-euler [bdf2]"},
    LubricateOption{"approach-velocity", &LubricateOptions::approach_velocity, Kind::number, kTransient, "V",
                    "the separation falls at V (m/s; negative: the surfaces part)"},
    LubricateOption{"separation-history", &LubricateOptions::separation_history, Kind::numbers, kTransient, "S1,S2,...",
                    "the separation at the end of each step (m)"},
    LubricateOption{"output", &LubricateOptions::output, Kind::path, kOutput, "FILE.h5", "result file (required)"},
    LubricateOption{"plot", &LubricateOptions::plot, Kind::flag, kOutput, "",
                    "draw PNG figures next to the output with scripts/halfspace_plot.py (pressure and film along the "
                    "centre line, maps of a 2D film; the Stribeck curve of --stribeck)"},
    LubricateOption{"quiet", &LubricateOptions::quiet, Kind::flag, kOutput, "", "print nothing on success"},
};
const std::array kOptions = joined(surface_option_table<LubricateOptions>(), kOwnOptions);

// The program's spelling of the film's and the surface's options, with the
// values (and units) the library shows.
GivenSpelling flags(const LubricateOptions& options) {
  return {options, std::span<const LubricateOption>(kOptions), true};
}

// The film's shear on the lower surface (film_shear.hpp): its friction in
// the summary, its fields and the limits in the file.
void add_shear(lubrication::FilmSummary& summary, const lubrication::FilmShear& shear) {
  summary.friction_force_x = shear.friction_force[0];
  summary.friction_force_y = shear.friction_force[1];
  summary.friction_coefficient = shear.friction_coefficient;
}

// The shear's fields are the rows held at `place`.
void write_shear(const io::Hdf5Node& root, const std::vector<std::size_t>& shape, const lubrication::FilmShear& shear,
                 const lubrication::ShearLimits& limits, const FilmPlace& place = FilmPlace{}) {
  root.write_dataset_rows("shear_x", shape, place.first_row,
                          std::span<const double>(shear.shear_x.data(), shear.shear_x.size()), "Pa");
  root.write_dataset_rows("shear_y", shape, place.first_row,
                          std::span<const double>(shear.shear_y.data(), shear.shear_y.size()), "Pa");
  root.write_double_attribute("couette_friction_force_x", shear.couette_force[0]);
  root.write_double_attribute("couette_friction_force_y", shear.couette_force[1]);
  root.write_double_attribute("eyring_stress", limits.eyring_stress);
  root.write_double_attribute("limiting_shear_stress", limits.limiting_shear_stress);
  root.write_double_attribute("limiting_shear_slope", limits.limiting_shear_slope);
  root.write_double_attribute("limited_fraction", shear.limited_fraction);
}

// Runs `function`; a film option's broken rule found by a solver (the
// separation, the speeds) is named by its flag.
template <class Function>
int with_lubricate_flags(const LubricateOptions& o, Function&& function) {
  try {
    return function();
  } catch (const OptionError& error) {
    throw lubrication::spelled_film_error(error, flags(o));
  }
}

// The fields that a film file holds at most (the mixed film's): pressure,
// film, fluid fraction, fluid and contact pressure, deformation, shear x and y.
constexpr int kMostFilmFields = 8;

// The film's fields (the rows `place` holds), its summary, the grid, `more`
// and where it came from, on a film file's root (the single film's, or a
// transient run's last step).
void write_film_root(const io::Hdf5Node& root, const LubricateOptions& o, const HeightMap& map, const Grid& grid,
                     const FilmPlace& place, const lubrication::FilmSummary& summary, const Eigen::ArrayXd& pressure,
                     const Eigen::ArrayXd& film, const Eigen::ArrayXd& fluid_fraction,
                     const std::function<void(const io::Hdf5Node&)>& more) {
  const std::vector<std::size_t> shape = io::field_shape(grid);
  const auto field = [&](std::string_view name, const Eigen::ArrayXd& values, std::string_view unit) {
    root.write_dataset_rows(name, shape, place.first_row,
                            std::span<const double>(values.data(), static_cast<std::size_t>(values.size())), unit);
  };
  field("pressure", pressure, "Pa");
  field("film", film, "m");
  field("fluid_fraction", fluid_fraction, "");
  io::write_film_attributes(root, summary);
  io::write_grid_attributes(root, grid);
  more(root);
  root.write_string_attribute("source", map.source);
  if (!map.preparation.empty())
    root.write_string_attribute("preparation", fmt::format("{}", fmt::join(map.preparation, "\n")));
  root.write_string_attribute("command_line", o.command_line);
  root.write_string_attribute("halfspace_version", fmt::format("{} ({})", kVersion, kGitHash));
}

// The film file, written where `place` says; the fields hold the rows held
// there.
void write_film_file(const LubricateOptions& o, const HeightMap& map, const Grid& grid, const FilmPlace& place,
                     const lubrication::FilmSummary& summary, const Eigen::ArrayXd& pressure,
                     const Eigen::ArrayXd& film, const Eigen::ArrayXd& fluid_fraction,
                     const std::function<void(const io::Hdf5Node&)>& more) {
  const std::uint64_t bound =
      kMostFilmFields * io::hdf5_dataset_bound(io::field_shape(grid), io::Compression::deflate) +
      io::kHdf5SmallItemsBound;
  place.write_file(*o.output, bound, [&](const io::Hdf5Node& root) {
    write_film_root(root, o, map, grid, place, summary, pressure, film, fluid_fraction, more);
  });
}

// What an elastic and a mixed film report alike: the summary (the film's
// own cavitated fraction and film solves given), and the body's and the
// lubricant's attributes.
template <class Film>
lubrication::FilmSummary elastic_summary(std::string_view model, const Film& film, const Grid& grid, double viscosity,
                                         double cavitated_fraction, long long film_solves) {
  lubrication::FilmSummary summary;
  summary.model = model;
  summary.status = std::string(lubrication::to_string(film.status));
  summary.message = film.message;
  summary.load = film.load;
  summary.mean_pressure = film.load / grid.domain_area();
  summary.separation = film.offset;
  summary.central_film_thickness = film.central_film_thickness;
  summary.minimum_film_thickness = film.minimum_film_thickness;
  summary.max_pressure = film.max_pressure;
  summary.cavitated_fraction = cavitated_fraction;
  summary.viscosity = viscosity;
  summary.iterations = film.iterations;
  summary.film_solves = film_solves;
  summary.relative_residual = film.relative_residual;
  summary.solve_seconds = film.wall_seconds;
  return summary;
}

void write_elastic_attributes(const io::Hdf5Node& root, double e_star, const lubrication::LubricantLaws& laws,
                              double viscosity, lubrication::CouetteScheme scheme, double load_error) {
  root.write_double_attribute("E_star", e_star);
  root.write_string_attribute("piezoviscosity", lubrication::to_string(laws.piezoviscosity));
  root.write_double_attribute("pressure_viscosity", laws.pressure_viscosity);
  root.write_double_attribute("roelands_index", laws.piezoviscosity == lubrication::Piezoviscosity::roelands
                                                    ? laws.roelands_exponent(viscosity)
                                                    : 0.0);
  root.write_string_attribute("compressibility", lubrication::to_string(laws.compressibility));
  root.write_string_attribute("couette_scheme", lubrication::to_string(scheme));
  root.write_double_attribute("load_error", load_error);
}

// The summary printed by the first (or only) process, `prints`.
// A film that did not converge: the warning and what to try
// (LubricationProblem::failure_hint).
int report(const LubricateOptions& o, const HeightMap& map, const lubrication::FilmSummary& summary, bool converged,
           const lubrication::LubricationProblem& problem, bool prints = true) {
  if (!converged) {
    if (prints) {
      fmt::print(stderr, "warning: {}; the result is written to {}\n  {}\n", summary.message, *o.output,
                 problem.failure_hint(flags(o)));
    }
    return kExitNotConverged;
  }
  if (o.quiet || !prints) return kExitOk;
  fmt::print("halfspace {} ({}) lubricate\n", kVersion, kGitHash);
  fmt::print("  {:<15} {}\n", "surface", map.source);
  fmt::print("  {:<15} {}\n", "film", summary.model);
  fmt::print("  {:<15} {:.6g} ({} {})\n", "load", summary.load, summary.iterations,
             summary.model == "rigid" ? "sweeps" : "Newton steps");
  fmt::print("  {:<15} central {:.6g} m, minimum {:.6g} m\n", "film", summary.central_film_thickness,
             summary.minimum_film_thickness);
  fmt::print("  {:<15} {:.6g} Pa\n", "max pressure", summary.max_pressure);
  if (summary.inflow) fmt::print("  {:<15} in {:.6g}, out {:.6g}\n", "flow", *summary.inflow, *summary.outflow);
  fmt::print("  {:<15} {:.3g}\n", "cavitated", summary.cavitated_fraction);
  if (summary.friction_coefficient) fmt::print("  {:<15} {:.6g}\n", "friction coeff", *summary.friction_coefficient);
  fmt::print("  {:<15} {:.3g} s\n", "solve time", summary.solve_seconds);
  fmt::print("  {:<15} {}\n", "output", *o.output);
  return kExitOk;
}

// The EHL film on the whole map, or on the rows `place` holds (the film's
// solver on an operator of slab transforms; the same code).
int run_elastic(const LubricateOptions& o, const HeightMap& map, const Grid& grid, const FilmPlace& place,
                const lubrication::LubricationProblem& problem) {
  const lubrication::FlowConditions& conditions = problem.conditions;
  const lubrication::LubricantLaws& laws = problem.laws;
  const lubrication::ElasticFilmOptions& options = problem.elastic;
  const lubrication::ShearLimits& limits = problem.limits;
  const std::optional<LayeredMaterial>& coating = problem.coating;
  const double e_star = problem.e_star;
  // The rows' halo for the shear and the reductions over the processes.
  const std::unique_ptr<lubrication::FilmRows> rows = place.film_rows(grid, conditions);
  const double highest = rows ? rows->max(map.heights.maxCoeff()) : map.heights.maxCoeff();
  const Eigen::ArrayXd gap = highest - map.heights;
  const HalfSpace body = coating ? HalfSpace(*coating) : HalfSpace(e_star);
  const std::shared_ptr<operators::SpectralTransforms> transforms = place.transforms(grid, problem.fft_planning);
  FftInfluenceOperator op = transforms ? FftInfluenceOperator(grid, body, transforms)
                                       : FftInfluenceOperator(grid, body, problem.fft_planning);
  const lubrication::ElasticFilm film = lubrication::solve_elastic_film(op, gap, conditions, laws, options);
  const auto stencil = [&](const Eigen::ArrayXd& field) {
    return rows ? rows->stencil_field({field.data(), static_cast<std::size_t>(field.size())}) : field;
  };
  const lubrication::FilmShear shear = lubrication::film_shear(
      rows ? rows->stencil_grid() : grid, rows ? rows->stencil_conditions() : conditions, laws, limits,
      stencil(film.film), stencil(film.pressure), stencil(film.fluid_fraction), nullptr, rows.get());

  double cavitated = static_cast<double>((film.fluid_fraction < 1.0).count());
  if (rows) rows->sum({&cavitated, 1});
  lubrication::FilmSummary summary =
      elastic_summary("elastic", film, grid, conditions.viscosity, cavitated / static_cast<double>(grid.size()), 1);
  // One time in the file: every process writes the same attributes.
  if (rows) summary.solve_seconds = rows->max(summary.solve_seconds);
  add_shear(summary, shear);
  write_film_file(
      o, map, grid, place, summary, film.pressure, film.film, film.fluid_fraction, [&](const io::Hdf5Node& root) {
        root.write_dataset_rows(
            "deformation", io::field_shape(grid), place.first_row,
            std::span<const double>(film.deformation.data(), static_cast<std::size_t>(film.deformation.size())), "m");
        write_elastic_attributes(root, e_star, laws, conditions.viscosity, options.couette_scheme, film.load_error);
        if (coating) io::write_coating_attributes(root, *coating);
        write_shear(root, io::field_shape(grid), shear, limits, place);
      });
  return report(o, map, summary, film.converged(), problem, place.first);
}

// The film's fields (the rows `place` holds) and the mixed film's own
// attributes, beyond the summary's.
void write_mixed_fields(const io::Hdf5Node& root, const std::vector<std::size_t>& shape, const FilmPlace& place,
                        const lubrication::MixedFilm& film, const lubrication::MixedFilmOptions& options, double e_star,
                        const lubrication::LubricantLaws& laws, double viscosity) {
  const auto field = [&](std::string_view name, const Eigen::ArrayXd& values, std::string_view unit) {
    root.write_dataset_rows(name, shape, place.first_row,
                            std::span<const double>(values.data(), static_cast<std::size_t>(values.size())), unit);
  };
  field("fluid_pressure", film.fluid_pressure, "Pa");
  field("contact_pressure", film.contact_pressure, "Pa");
  field("deformation", film.deformation, "m");
  write_elastic_attributes(root, e_star, laws, viscosity, options.couette_scheme, film.load_error);
  root.write_double_attribute("fluid_load", film.fluid_load);
  root.write_double_attribute("contact_load", film.contact_load);
  root.write_double_attribute("contact_load_fraction", film.contact_load_fraction);
  root.write_double_attribute("contact_area", film.contact_area);
  root.write_double_attribute("contact_area_fraction", film.contact_area_fraction);
  root.write_double_attribute("fluid_friction_force_x", film.fluid_friction_force[0]);
  root.write_double_attribute("fluid_friction_force_y", film.fluid_friction_force[1]);
  root.write_double_attribute("contact_friction_force_x", film.contact_friction_force[0]);
  root.write_double_attribute("contact_friction_force_y", film.contact_friction_force[1]);
  root.write_double_attribute("contact_friction", options.friction.contact_friction);
  root.write_double_attribute("eyring_stress", options.friction.shear.eyring_stress);
  root.write_double_attribute("limiting_shear_stress", options.friction.shear.limiting_shear_stress);
  root.write_double_attribute("limiting_shear_slope", options.friction.shear.limiting_shear_slope);
  root.write_double_attribute("boundary_film", options.boundary_film);
  root.write_double_attribute("complementarity_error", film.complementarity_error);
}

void write_stribeck_csv(const std::string& path, const std::vector<lubrication::StribeckPoint>& points) {
  std::ofstream out(path, std::ios::trunc);
  if (!out) throw InputError(fmt::format("cannot write the Stribeck curve to {}", path));
  out << "entrainment_speed,hersey_number,friction_coefficient,fluid_friction,contact_friction,"
         "contact_load_fraction,contact_area_fraction,central_film_thickness,minimum_film_thickness,status,"
         "newton_steps\n";
  for (const lubrication::StribeckPoint& point : points) {
    const lubrication::MixedFilm& f = point.film;
    out << fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{},{}\n",
                       point.entrainment_speed, point.hersey_number, f.friction_coefficient,
                       std::hypot(f.fluid_friction_force[0], f.fluid_friction_force[1]),
                       std::hypot(f.contact_friction_force[0], f.contact_friction_force[1]), f.contact_load_fraction,
                       f.contact_area_fraction, f.central_film_thickness, f.minimum_film_thickness,
                       lubrication::to_string(f.status), f.iterations);
  }
  if (!out) throw InputError(fmt::format("writing the Stribeck curve to {} failed", path));
}

// The mixed film on the whole map, or on the rows `place` holds (the
// film's solver on an operator of slab transforms; the same code), or a
// Stribeck sweep, whole or with its speeds shared out.
int run_mixed(const LubricateOptions& o, const HeightMap& map, const Grid& grid, const FilmPlace& place,
              const lubrication::LubricationProblem& problem) {
  const lubrication::FlowConditions& conditions = problem.conditions;
  const lubrication::LubricantLaws& laws = problem.laws;
  lubrication::MixedFilmOptions options = problem.mixed;
  const double e_star = problem.e_star;
  if (o.stribeck) io::check_output_path(*o.stribeck);
  // --trace: the first process writes the solves' lines (on slabs every
  // process takes the same solves); opening it may fail there alone.
  std::optional<io::MixedTraceWriter> trace;
  if (o.trace) {
    const auto open = [&] {
      if (place.first) trace.emplace(*o.trace);
    };
    if (place.whole) {
      open();
    } else {
      agree_everywhere(open);
    }
    if (trace) options.trace = trace->callback();
  }
  // On slabs the reductions over the processes.
  const std::unique_ptr<lubrication::FilmRows> rows = place.film_rows(grid, conditions);
  const double highest = rows ? rows->max(map.heights.maxCoeff()) : map.heights.maxCoeff();
  const Eigen::ArrayXd gap = highest - map.heights;
  const std::shared_ptr<operators::SpectralTransforms> transforms = place.transforms(grid, problem.fft_planning);
  FftInfluenceOperator op = transforms ? FftInfluenceOperator(grid, e_star, transforms)
                                       : FftInfluenceOperator(grid, e_star, problem.fft_planning);
  lubrication::FlowConditions used = conditions;
  lubrication::MixedFilm film;
  bool all_converged = true;
  std::string first_failure;
  // With the speeds shared out, what may fail on one process alone (the
  // memory of a whole film, writing the files) ends every process alike,
  // before any waits for another; otherwise this process runs alone.
  const auto agreed = [&](const std::function<void()>& step) {
    if (place.sweep_processes) {
      agree_everywhere(step);
    } else {
      step();
    }
  };
  if (problem.speeds) {
    if (place.sweep_processes) {
      agree_everywhere([&] { lubrication::require_mixed_film_fits(grid, options, "the mixed film"); });
    }
    std::vector<lubrication::StribeckPoint> points =
        place.sweep_processes
            ? lubrication::stribeck_sweep(op, gap, conditions, laws, options, *problem.speeds, *place.sweep_processes)
            : lubrication::stribeck_sweep(op, gap, conditions, laws, options, *problem.speeds);
    agreed([&] {
      if (place.first) write_stribeck_csv(*o.stribeck, points);
    });
    for (const lubrication::StribeckPoint& point : points) {
      if (!point.film.converged() && all_converged) {
        all_converged = false;
        first_failure = fmt::format("at {} m/s: {}", point.entrainment_speed, point.film.message);
      }
    }
    const double speed = std::hypot(conditions.entrainment_velocity[0], conditions.entrainment_velocity[1]);
    for (int axis = 0; axis < 2; ++axis) {
      used.entrainment_velocity[axis] *= points.back().entrainment_speed / speed;
      used.sliding_velocity[axis] *= points.back().entrainment_speed / speed;
    }
    film = std::move(points.back().film);
  } else {
    film = lubrication::solve_mixed_film(op, gap, conditions, laws, options);
    all_converged = film.converged();
    first_failure = film.message;
  }

  lubrication::FilmSummary summary =
      elastic_summary("mixed", film, grid, conditions.viscosity, film.cavitated_fraction,
                      problem.speeds ? static_cast<long long>(problem.speeds->size()) : 1);
  summary.message = all_converged ? std::string() : first_failure;
  summary.friction_force_x = film.fluid_friction_force[0] + film.contact_friction_force[0];
  summary.friction_force_y = film.fluid_friction_force[1] + film.contact_friction_force[1];
  summary.friction_coefficient = film.friction_coefficient;
  // One time in the file: every process writes the same attributes.
  if (rows) summary.solve_seconds = rows->max(summary.solve_seconds);
  const auto write = [&](const FilmPlace& at) {
    write_film_file(o, map, grid, at, summary, film.pressure, film.film, film.fluid_fraction,
                    [&](const io::Hdf5Node& root) {
                      write_mixed_fields(root, io::field_shape(grid), at, film, options, e_star, laws, used.viscosity);
                      root.write_double_attribute(
                          "entrainment_speed", std::hypot(used.entrainment_velocity[0], used.entrainment_velocity[1]));
                    });
  };
  if (!place.whole) {
    // On slabs every process writes its rows (the parallel writer).
    write(place);
  } else {
    // With the speeds shared out, the first process holds the last film
    // whole (stribeck_sweep) and writes it.
    agreed([&] {
      if (place.first) write(FilmPlace{});
    });
  }
  const int code = report(o, map, summary, all_converged, problem, place.first);
  if (trace && !trace->failure().empty()) {
    fmt::print(stderr, "error: {}; the film is written to {}\n", trace->failure(), *o.output);
    return kExitInputError;
  }
  if (code == kExitOk && !o.quiet && place.first) {
    fmt::print("  {:<15} {:.4g} of the load, area {:.4g} of the cells\n", "contact", film.contact_load_fraction,
               film.contact_area_fraction);
    if (o.stribeck) fmt::print("  {:<15} {} ({} speeds)\n", "stribeck", *o.stribeck, problem.speeds->size());
  }
  return code;
}

// The summary of a rigid film (its own solve's status and counts; a
// transient run replaces them with the whole run's).
lubrication::FilmSummary rigid_summary(const lubrication::LubricatedFilm& film,
                                       const lubrication::FlowConditions& conditions,
                                       std::chrono::steady_clock::time_point started) {
  const lubrication::FilmForces& f = film.forces;
  lubrication::FilmSummary summary;
  summary.model = "rigid";
  summary.status = std::string(lubrication::to_string(film.solution.status));
  summary.message = film.solution.message;
  summary.load = f.load;
  summary.mean_pressure = f.mean_pressure;
  summary.separation = film.separation;
  // At the surface's highest point, where the film is the separation.
  summary.central_film_thickness = film.separation;
  summary.minimum_film_thickness = f.minimum_film_thickness;
  summary.max_pressure = f.max_pressure;
  summary.cavitated_fraction = f.cavitated_fraction;
  summary.viscosity = conditions.viscosity;
  summary.iterations = film.solution.iterations;
  summary.film_solves = film.film_solves;
  summary.relative_residual = film.solution.relative_residual;
  summary.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  summary.inflow = f.inflow;
  summary.outflow = f.outflow;
  return summary;
}

// The rigid film stepped in time: each step's fields under /steps, the
// last step as the file's single film, the history as CSV beside it.
int run_transient(const LubricateOptions& o, const HeightMap& map, const Grid& grid,
                  const lubrication::LubricationProblem& problem) {
  const lubrication::FlowConditions& conditions = problem.conditions;
  const lubrication::TransientFilmOptions& transient = *problem.transient;
  const auto started = std::chrono::steady_clock::now();
  lubrication::TransientOutcome outcome;
  lubrication::TransientStep last;
  long long sweeps = 0, solves = 0;
  io::write_film_history(
      *o.output, grid, static_cast<std::size_t>(transient.steps),
      [&](const io::FilmStepSink& sink) {
        outcome = lubrication::lubricate_transient(grid, map.heights, conditions, transient, problem.cavitation,
                                                   [&](const lubrication::TransientStep& step) {
                                                     sink(step);
                                                     sweeps += step.film.solution.iterations;
                                                     solves += step.film.film_solves;
                                                     last = step;
                                                   });
      },
      [&](const io::Hdf5Node& root) {
        const lubrication::LubricatedFilm& film = last.film;
        lubrication::FilmSummary summary = rigid_summary(film, conditions, started);
        summary.status = std::string(lubrication::to_string(outcome.status));
        summary.message = outcome.message;
        summary.iterations = sweeps;
        summary.film_solves = solves;
        const lubrication::FilmShear shear = lubrication::film_shear(
            grid, conditions, {}, problem.limits, film.film, film.solution.pressure, film.solution.fluid_fraction);
        add_shear(summary, shear);
        write_film_root(root, o, map, grid, FilmPlace{}, summary, film.solution.pressure, film.film,
                        film.solution.fluid_fraction, [&](const io::Hdf5Node& node) {
                          write_shear(node, io::field_shape(grid), shear, problem.limits);
                          node.write_double_attribute("time_step", transient.time_step);
                          node.write_int64_attribute("time_steps", transient.steps);
                          node.write_string_attribute("time_scheme", lubrication::to_string(transient.scheme));
                          node.write_double_attribute("time", last.time);
                        });
      });
  const bool converged = outcome.status == lubrication::FilmStatus::converged;
  if (!converged) {
    fmt::print(stderr, "warning: {}; the steps solved are written to {}\n", outcome.message, *o.output);
    return kExitNotConverged;
  }
  if (o.quiet) return kExitOk;
  fmt::print("halfspace {} ({}) lubricate\n", kVersion, kGitHash);
  fmt::print("  {:<15} {}\n", "surface", map.source);
  fmt::print("  {:<15} rigid, {} steps of {:.6g} s ({})\n", "film", transient.steps, transient.time_step,
             lubrication::to_string(transient.scheme));
  fmt::print("  {:<15} t {:.6g} s: separation {:.6g} m, load {:.6g}\n", "last step", last.time, last.film.separation,
             last.film.forces.load);
  fmt::print("  {:<15} {} film solves, {} sweeps\n", "work", solves, sweeps);
  fmt::print("  {:<15} {} and {}\n", "output", *o.output, io::history_csv_path(*o.output).string());
  return kExitOk;
}

// --roughness: a second profile's heights added point by point.
void add_roughness(const std::string& path, HeightMap& map) {
  const HeightMap rough = io::read_height_map(path);
  if (rough.nx != map.nx || rough.ny != map.ny || rough.dimension != map.dimension) {
    throw InputError(fmt::format("--roughness {} has {} x {} points, the height map {} x {}: they must be equal", path,
                                 rough.nx, rough.ny, map.nx, map.ny));
  }
  if (!rough.all_valid()) throw InputError(fmt::format("--roughness {} has invalid points", path));
  if (rough.dx > 0.0 && std::abs(rough.dx - map.dx) > 1e-9 * map.dx) {
    throw InputError(fmt::format("--roughness {} has spacing {} m, the height map {} m: they must be equal", path,
                                 rough.dx, map.dx));
  }
  map.heights += rough.heights;
}

// The surface against the flat (a height map, prepared as solve prepares
// one, or a built-in shape on its grid, centred on the domain as solve's),
// with --roughness added: what the first process reads.
HeightMap read_film_map(const LubricateOptions& o, const SurfaceChoice& choice) {
  HeightMap map;
  if (const auto* file = std::get_if<HeightMapFile>(&choice)) {
    map = read_height_map_file(*file, flags(o));
  } else {
    const auto& [shape, grid] = std::get<BuiltinSurface>(choice);
    map.dimension = grid.dimension();
    map.nx = grid.nx();
    map.ny = grid.ny();
    map.dx = grid.dx();
    map.dy = grid.dimension() == 2 ? grid.dy() : 0.0;
    map.heights = geometry::make_surface_heights(grid, shape.spec);
    map.source = shape.source;
  }
  if (o.roughness) add_roughness(*o.roughness, map);
  return map;
}

// The rigid film at a separation or a load, on the whole map or on the rows
// `place` holds (the same code: the rows' solver gives the serial iterates).
int run_rigid(const LubricateOptions& o, const HeightMap& map, const Grid& grid, const FilmPlace& place,
              const lubrication::LubricationProblem& problem) {
  const lubrication::FlowConditions& conditions = problem.conditions;
  const lubrication::ShearLimits& limits = problem.limits;
  const auto started = std::chrono::steady_clock::now();
  const std::unique_ptr<lubrication::FilmRows> rows = place.film_rows(grid, conditions);
  const lubrication::LubricatedFilm film =
      problem.load_control ? lubrication::lubricate_at_load(grid, map.heights, conditions, *problem.load_control,
                                                            problem.cavitation, rows.get())
                           : lubrication::lubricate_at_separation(grid, map.heights, conditions, *problem.separation,
                                                                  problem.cavitation, rows.get());
  lubrication::FilmSummary summary = rigid_summary(film, conditions, started);
  // One time in the file: every process writes the same attributes.
  if (rows) summary.solve_seconds = rows->max(summary.solve_seconds);
  const lubrication::FilmShear shear = lubrication::film_shear(
      rows ? rows->stencil_grid() : grid, rows ? rows->stencil_conditions() : conditions, {}, limits, film.film,
      film.solution.pressure, film.solution.fluid_fraction, nullptr, rows.get());
  add_shear(summary, shear);
  // The rows held here of a field on the solver's nodes (halo rows dropped).
  const auto own = [&](const Eigen::ArrayXd& field) -> Eigen::ArrayXd {
    if (!rows) return field;
    return field.segment(static_cast<Eigen::Index>(rows->first_own_node()),
                         static_cast<Eigen::Index>(rows->own_nodes()));
  };
  write_film_file(o, map, grid, place, summary, own(film.solution.pressure), own(film.film),
                  own(film.solution.fluid_fraction),
                  [&](const io::Hdf5Node& root) { write_shear(root, io::field_shape(grid), shear, limits, place); });
  return report(o, map, summary, film.solution.converged(), problem, place.first);
}

// --trace: a mixed film's, a file of its own, and on one process where a
// Stribeck sweep's speeds are shared out (each process would trace its own).
void check_trace_path(const LubricateOptions& o, const lubrication::LubricationProblem& problem) {
  if (problem.kind != lubrication::FilmKind::mixed) {
    throw InputError(fmt::format("--trace {} traces the mixed film's Newton solves: it needs --mixed", *o.trace));
  }
  if (problem.speeds && process_count() > 1) {
    throw InputError(fmt::format(
        "--trace {} with a Stribeck sweep on several processes: each process solves its own speeds; trace the "
        "sweep on one process",
        *o.trace));
  }
  io::check_output_path(*o.trace);
  for (const std::optional<std::string>& other : {o.output, o.stribeck}) {
    if (other && io::same_file(*o.trace, *other)) {
      throw InputError(
          fmt::format("--trace {} is the same file as {}: give the trace a file of its own", *o.trace, *other));
    }
  }
}

// No output may replace an input or another output (docs/usage.md#output-files):
// the result (a film's file has no XDMF sidecar), a transient film's history
// CSV, the Stribeck curve, the trace and, with measured plans, the FFTW
// wisdom file saved at exit; against the height map and the roughness.
// Checked before anything is read or solved.
void check_outputs_against_inputs(const LubricateOptions& o, const lubrication::LubricationProblem& problem) {
  const std::filesystem::path output = *o.output;
  std::vector<io::RunFile> outputs{{o.describe("output"), output}};
  if (problem.transient) {
    outputs.push_back({fmt::format("the history CSV {} (the {} name with .csv)", io::history_csv_path(output).string(),
                                   o.name("output")),
                       io::history_csv_path(output)});
  }
  if (o.stribeck) outputs.push_back({o.describe("stribeck"), *o.stribeck});
  if (o.trace) outputs.push_back({o.describe("trace"), *o.trace});
  if (problem.fft_planning != FftPlanning::estimate) {  // a rigid film has no transforms: always estimate
    if (const std::optional<std::filesystem::path> wisdom = io::fft_wisdom_path()) {
      outputs.push_back({fmt::format("the FFTW wisdom file {}", wisdom->string()), *wisdom});
    }
  }
  std::vector<io::RunFile> inputs;
  if (o.height_map) inputs.push_back({o.describe("height-map"), *o.height_map});
  if (o.roughness) inputs.push_back({o.describe("roughness"), *o.roughness});
  io::check_outputs_apart(outputs, inputs);
}

int solve_film(const LubricateOptions& o) {
  const GivenSpelling spelling = flags(o);
  const lubrication::LubricationProblem problem = lubrication::make_lubrication_problem(o, spelling);
  const SurfaceChoice surface = make_surface_choice(o, problem.boundary, spelling);
  if (o.speeds.has_value() != o.stribeck.has_value()) {
    throw InputError("--speeds and --stribeck go together: the sweep's speeds and its CSV file");
  }
  if (!o.output) throw InputError("no output file given: pass --output FILE.h5");
  io::check_output_path(*o.output);
  if (o.stribeck) io::check_output_path(*o.stribeck);
  if (o.trace) check_trace_path(o, problem);
  check_outputs_against_inputs(o, problem);

  // On several processes the steady rigid, EHL and mixed films' solvers
  // run on slabs of rows (mpi/slab_film_rows.hpp; lubrication/elastic_film.hpp
  // and mixed_film.hpp on a distributed operator), a mixed film's Stribeck
  // sweep shares out its speeds, and the first process solves the others.
  const bool on_rows =
      (problem.kind == lubrication::FilmKind::rigid || problem.kind == lubrication::FilmKind::elastic ||
       (problem.kind == lubrication::FilmKind::mixed && !problem.speeds)) &&
      !problem.transient;
  const FilmSpread spread = on_rows ? FilmSpread::row_slabs
                            : problem.kind == lubrication::FilmKind::mixed && problem.speeds
                                ? FilmSpread::sweep_speeds
                                : FilmSpread::first_process;
  return run_film_everywhere(
      [&] { return read_film_map(o, surface); },
      [&](HeightMap& map, const FilmPlace& place) {
        const Grid grid = map.dimension == 1 ? Grid::line(map.nx, map.dx, problem.boundary)
                                             : Grid::plane(map.nx, map.ny, map.dx, map.dy, problem.boundary);
        if (place.whole) {
          problem.check_grid(grid, spelling, map.source);
        } else {
          // Each process checks its share of the memory, agreed.
          agree_everywhere(
              [&] { problem.check_grid(grid, spelling, map.source, static_cast<std::size_t>(map.heights.size())); });
        }
        if (problem.kind == lubrication::FilmKind::mixed) {
          return run_mixed(o, map, grid, place, problem);
        }
        if (problem.kind == lubrication::FilmKind::elastic) {
          return run_elastic(o, map, grid, place, problem);
        }
        if (problem.transient) return run_transient(o, map, grid, problem);
        return run_rigid(o, map, grid, place, problem);
      },
      spread);
}

// --plot: the tool is found (and its packages checked) before the solve; the
// figures are drawn from the files written, also for a film that did not
// converge (as solve --plot does).
int run_lubricate(const LubricateOptions& o) {
  if (o.plot && process_count() > 1) {
    throw InputError(
        "--plot is not available with more than one process: draw the figures afterwards with "
        "`halfspace_plot.py film FILE` (scripts/), or run without mpirun");
  }
  const std::optional<PlotTool> plot =
      o.plot ? std::optional<PlotTool>(find_plot_tool({"--plot", "drop --plot", {}})) : std::nullopt;
  const int code = solve_film(o);
  if (!plot || (code != kExitOk && code != kExitNotConverged)) return code;
  std::vector<std::pair<std::string_view, std::string>> figures{{"film", *o.output}};
  if (o.stribeck) figures.emplace_back("stribeck", *o.stribeck);
  bool plotted = true;
  for (const auto& [subcommand, file] : figures) {
    const std::string failure = run_plot_tool(*plot, subcommand, file, o.quiet);
    if (!failure.empty()) {
      fmt::print(stderr, "error: --plot: {}; the result is written to {}\n", failure, file);
      plotted = false;
    }
  }
  return plotted || code != kExitOk ? code : kExitPlotFailed;
}

}  // namespace

Command add_lubricate_command(CLI::App& program) {
  CLI::App* lubricate = program.add_subcommand(
      "lubricate",
      "Solve the Reynolds film with mass-conserving cavitation between a height map and a flat, rigid or elastic "
      "(EHL, with --E-star)");
  lubricate->footer("See docs/usage.md#lubricated-films and docs/theory.md.");
  return {lubricate, table_command(*lubricate, std::span<const LubricateOption>(kOptions), "viscosity = 0.1",
                                   [](const LubricateOptions& options) {
                                     return with_lubricate_flags(options, [&] { return run_lubricate(options); });
                                   })};
}

}  // namespace halfspace::app
