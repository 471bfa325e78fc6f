// The lubricate command: height map -> film at a separation (or the
// separation carrying a force) -> pressure, film and fluid fraction in an
// HDF5 file. Flags map onto lubrication::FlowConditions,
// CavitationSolverOptions and LoadControlOptions, whose validate() holds the
// rules.
#include "lubricate_command.hpp"

#include <fmt/format.h>

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "exit_codes.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/io/height_map_reader.hpp"
#include "halfspace/io/output_file.hpp"
#include "halfspace/lubrication/load_control.hpp"
#include "halfspace/version.hpp"
#include "option_table.hpp"

namespace halfspace::app {
namespace {

struct LubricateOptions : GivenOptions {
  std::optional<std::string> height_map;
  std::optional<double> viscosity;
  std::optional<std::vector<double>> entrainment_velocity;
  std::optional<std::vector<double>> sliding_velocity;
  std::optional<double> separation;
  std::optional<double> force;
  std::optional<double> inlet_pressure;
  std::optional<double> outlet_pressure;
  std::optional<double> side_pressure;
  bool periodic_y = false;
  std::optional<double> tolerance;
  std::optional<std::string> output;
  bool quiet = false;
};

using LubricateOption = OptionSpec<LubricateOptions>;
using Kind = OptionKind;
constexpr std::string_view kFilm = "Film";
constexpr std::string_view kOutput = "Output";

const std::array kOptions{
    LubricateOption{"height-map", &LubricateOptions::height_map, Kind::path, kFilm, "FILE",
                    "the rigid surface's heights (any format solve reads; spacing from the file) (required)"},
    LubricateOption{"viscosity", &LubricateOptions::viscosity, Kind::number, kFilm, "PA_S",
                    "lubricant viscosity (Pa s) (required)"},
    LubricateOption{"entrainment-velocity", &LubricateOptions::entrainment_velocity, Kind::numbers, kFilm, "UX[,UY]",
                    "mean of the two surfaces' velocities (m/s) (required)"},
    LubricateOption{"sliding-velocity", &LubricateOptions::sliding_velocity, Kind::numbers, kFilm, "UX[,UY]",
                    "upper minus lower surface velocity (m/s), for the friction force [0]"},
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
    LubricateOption{"periodic-y", &LubricateOptions::periodic_y, Kind::flag, kFilm, "",
                    "the film repeats along y instead of having fixed side pressures"},
    LubricateOption{"tolerance", &LubricateOptions::tolerance, Kind::number, kFilm, "TOL",
                    "relative mass residual at convergence [1e-11]"},
    LubricateOption{"output", &LubricateOptions::output, Kind::path, kOutput, "FILE.h5", "result file (required)"},
    LubricateOption{"quiet", &LubricateOptions::quiet, Kind::flag, kOutput, "", "print nothing on success"},
};

std::array<double, 2> velocity(const std::optional<std::vector<double>>& given, std::string_view flag) {
  if (!given) return {0.0, 0.0};
  if (given->empty() || given->size() > 2) {
    throw InputError(fmt::format("--{} has {} values: give UX or UX,UY (m/s)", flag, given->size()));
  }
  return {(*given)[0], given->size() == 2 ? (*given)[1] : 0.0};
}

int run_lubricate(const LubricateOptions& o) {
  if (!o.height_map) throw InputError("no surface given: pass --height-map FILE");
  if (!o.viscosity) throw InputError("no viscosity given: pass --viscosity PA_S");
  if (!o.entrainment_velocity) throw InputError("no entrainment velocity given: pass --entrainment-velocity UX[,UY]");
  if (o.separation.has_value() == o.force.has_value()) {
    throw InputError("give exactly one of --separation M and --force N");
  }
  if (!o.output) throw InputError("no output file given: pass --output FILE.h5");
  io::check_output_path(*o.output);

  lubrication::FlowConditions conditions;
  conditions.viscosity = *o.viscosity;
  conditions.entrainment_velocity = velocity(o.entrainment_velocity, "entrainment-velocity");
  conditions.sliding_velocity = velocity(o.sliding_velocity, "sliding-velocity");
  conditions.boundary.x_low_pressure = o.inlet_pressure.value_or(0.0);
  conditions.boundary.x_high_pressure = o.outlet_pressure.value_or(0.0);
  conditions.boundary.y_low_pressure = o.side_pressure.value_or(0.0);
  conditions.boundary.y_high_pressure = o.side_pressure.value_or(0.0);
  if (o.periodic_y) conditions.boundary.y = lubrication::AxisBoundary::periodic;
  lubrication::CavitationSolverOptions solver;
  if (o.tolerance) solver.tolerance = *o.tolerance;

  const HeightMap map = io::read_height_map(*o.height_map);
  if (!map.all_valid()) {
    throw InputError(fmt::format("{} has invalid points: a film needs every height", *o.height_map));
  }
  if (!(map.dx > 0.0) || (map.dimension == 2 && !(map.dy > 0.0))) {
    throw InputError(fmt::format("{} does not give its spacing: a film needs dx (and dy) in metres", *o.height_map));
  }
  const Grid grid = map.dimension == 1 ? Grid::line(map.nx, map.dx, Boundary::free)
                                       : Grid::plane(map.nx, map.ny, map.dx, map.dy, Boundary::free);
  conditions.validate(grid);
  const lubrication::LubricatedFilm film =
      o.force ? lubrication::lubricate_at_load(grid, map.heights, conditions, {.load = *o.force}, solver)
              : lubrication::lubricate_at_separation(grid, map.heights, conditions, *o.separation, solver);

  const lubrication::FilmForces& f = film.forces;
  std::vector<std::size_t> shape =
      map.dimension == 1 ? std::vector<std::size_t>{map.nx} : std::vector<std::size_t>{map.ny, map.nx};
  io::write_hdf5_file(*o.output, [&](const io::Hdf5Node& root) {
    root.write_dataset("pressure", shape, std::span<const double>(film.solution.pressure.data(), grid.size()), "Pa");
    root.write_dataset("film_thickness", shape, std::span<const double>(film.film.data(), grid.size()), "m");
    root.write_dataset("fluid_fraction", shape,
                       std::span<const double>(film.solution.fluid_fraction.data(), grid.size()), "");
    root.write_double_attribute("load", f.load);
    root.write_double_attribute("mean_pressure", f.mean_pressure);
    root.write_double_attribute("separation", film.separation);
    root.write_double_attribute("minimum_film_thickness", f.minimum_film_thickness);
    root.write_double_attribute("inflow", f.inflow);
    root.write_double_attribute("outflow", f.outflow);
    root.write_double_attribute("friction_force_x", f.friction_force[0]);
    root.write_double_attribute("friction_force_y", f.friction_force[1]);
    root.write_double_attribute("friction_coefficient", f.friction_coefficient);
    root.write_double_attribute("cavitated_fraction", f.cavitated_fraction);
    root.write_double_attribute("viscosity", conditions.viscosity);
    root.write_double_attribute("dx", grid.dx());
    root.write_double_attribute("dy", grid.dy());
    root.write_int64_attribute("iterations", film.solution.iterations);
    root.write_double_attribute("relative_residual", film.solution.relative_residual);
    root.write_string_attribute("status", lubrication::to_string(film.solution.status));
    root.write_string_attribute("source", map.source);
    root.write_string_attribute("command_line", o.command_line);
    root.write_string_attribute("halfspace_version", fmt::format("{} ({})", kVersion, kGitHash));
  });
  if (!film.solution.converged()) {
    fmt::print(stderr, "warning: {}; the result is written to {}\n", film.solution.message, *o.output);
    return kExitNotConverged;
  }
  if (!o.quiet) {
    fmt::print("halfspace {} ({}) lubricate\n", kVersion, kGitHash);
    fmt::print("  {:<15} {}\n", "surface", *o.height_map);
    fmt::print("  {:<15} {:.6g} m ({} film solves)\n", "separation", film.separation, film.film_solves);
    fmt::print("  {:<15} {:.6g} ({} sweeps)\n", "load", f.load, film.solution.iterations);
    fmt::print("  {:<15} in {:.6g}, out {:.6g}\n", "flow", f.inflow, f.outflow);
    fmt::print("  {:<15} {:.3g}\n", "cavitated", f.cavitated_fraction);
    fmt::print("  {:<15} {:.6g}\n", "friction coeff", f.friction_coefficient);
    fmt::print("  {:<15} {}\n", "output", *o.output);
  }
  return kExitOk;
}

}  // namespace

Command add_lubricate_command(CLI::App& program) {
  CLI::App* lubricate = program.add_subcommand(
      "lubricate", "Solve the rigid Reynolds film with mass-conserving cavitation between a height map and a flat");
  lubricate->footer("See docs/usage.md#lubricated-films and docs/theory.md.");
  add_config_option(*lubricate, "viscosity = 0.1");
  add_options(*lubricate, std::span<const LubricateOption>(kOptions));
  return {lubricate, [lubricate](const std::vector<std::string>& argv) {
            LubricateOptions options;
            const std::vector<BoundOption> bound = bind_options(std::span<const LubricateOption>(kOptions), options);
            read_command_line(*lubricate, argv, bound, options);
            merge_config_file(bound, {}, "lubricate", options);
            return run_lubricate(options);
          }};
}

}  // namespace halfspace::app
