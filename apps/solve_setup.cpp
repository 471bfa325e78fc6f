// Turns the options as given into a checked SolveSetup. The checks run in the
// order a reader scans the command line (surface, material, load, solver,
// output) and the height map is read last, so cheap mistakes are found first.
#include "solve_setup.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "activity.hpp"
#include "friction_setup.hpp"
#include "grid_options.hpp"
#include "halfspace/elastic_pair.hpp"
#include "halfspace/error.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/io/fft_wisdom_file.hpp"
#include "halfspace/io/height_map_reader.hpp"
#include "halfspace/io/output_file.hpp"
#include "halfspace/io/sweep_writer.hpp"
#include "halfspace/io/xdmf_writer.hpp"
#include "halfspace/memory_estimate.hpp"
#include "halfspace/physical_ranges.hpp"
#include "halfspace/solvers/frictional_solve.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/stress/stress_volume.hpp"
#include "halfspace/stress/stressed_body.hpp"
#include "halfspace/stress/subsurface_stress.hpp"
#include "halfspace/surface/padding.hpp"
#include "halfspace/surface/preparation.hpp"
#include "memory_check.hpp"
#include "processes.hpp"
#include "stress_command.hpp"
#include "value_parsing.hpp"

namespace halfspace::app {
namespace {

namespace fs = std::filesystem;

// Keys paired with whether they were given.
using Presence = std::initializer_list<std::pair<std::string_view, bool>>;

std::vector<std::string> given_names(const SolveOptions& options, Presence keys) {
  std::vector<std::string> names;
  for (const auto& [key, given] : keys) {
    if (given) names.push_back(options.name(key));
  }
  return names;
}

void check_surface_choice(const SolveOptions& options) {
  if (options.height_map && options.geometry) {
    throw InputError(fmt::format("{} and {} cannot be combined: give exactly one surface", options.name("height-map"),
                                 options.name("geometry")));
  }
  if (!options.height_map && !options.geometry) {
    throw InputError("no surface given: pass --height-map FILE or --geometry sphere|cylinder|flat|wavy");
  }
}

// "the solve (pk-multilevel, free boundary, 4194304 cells)", with the steps
// of a sweep.
std::string solve_description(const Grid& grid, const solvers::SolverOptions& solver, std::size_t steps) {
  return fmt::format("the {} ({}, {} boundary, {} cells{})", steps > 1 ? "load sweep" : "solve",
                     solvers::to_string(solver.type), to_string(grid.boundary()), grid.size(),
                     steps > 1 ? fmt::format(", {} steps", steps) : std::string());
}

// The output is checked before solving so that a typo in the path does not
// cost a long solve; the writer itself is atomic, so no partial file appears.
fs::path output_from(const SolveOptions& o) {
  if (!o.output) {
    throw InputError("no output file given: pass --output FILE.h5");
  }
  const fs::path path = *o.output;
  const std::string what = o.describe("output");
  std::error_code error;
  if (path.empty()) {
    throw InputError(fmt::format("{} is invalid: the file name is empty", what));
  }
  if (fs::is_directory(path, error)) {
    throw FileError(fmt::format("{} is invalid: it is a directory, not a file", what));
  }
  const fs::path directory = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  if (!fs::exists(directory, error)) {
    throw FileError(fmt::format("{} is invalid: directory {} does not exist", what, directory.string()));
  }
  if (!fs::is_directory(directory, error)) {
    throw FileError(fmt::format("{} is invalid: {} is not a directory", what, directory.string()));
  }
  if (::access(directory.c_str(), W_OK) != 0) {
    throw FileError(fmt::format("{} is invalid: directory {} is not writable", what, directory.string()));
  }
  return path;
}

// Every file the run writes must be writable (io::check_output_path: a
// regular file or a new name, never a device, FIFO or directory) and none
// may replace one of the run's inputs or another of its outputs: the sweep's
// CSV goes beside the result with the extension .csv, its XDMF sidecar with
// .xdmf (io/xdmf_writer.hpp), and measured FFT plans
// save the wisdom file. Checked before anything is read, solved or written
// (docs/usage.md#output-files).
void check_outputs_against_inputs(const SolveOptions& o, const fs::path& output, bool sweep, FftPlanning planning) {
  struct File {
    std::string what;
    fs::path path;
  };
  std::vector<File> outputs{{o.describe("output"), output}};
  if (sweep) {
    outputs.push_back({fmt::format("the sweep's CSV table {} (the {} name with .csv)",
                                   io::sweep_csv_path(output).string(), o.name("output")),
                       io::sweep_csv_path(output)});
  }
  outputs.push_back({fmt::format("the XDMF sidecar {} (the {} name with .xdmf)", io::xdmf_sidecar_path(output).string(),
                                 o.name("output")),
                     io::xdmf_sidecar_path(output)});
  if (planning != FftPlanning::estimate) {
    if (const std::optional<fs::path> wisdom = io::fft_wisdom_path()) {
      outputs.push_back({fmt::format("the FFTW wisdom file {}", wisdom->string()), *wisdom});
    }
  }
  std::vector<File> inputs;
  if (o.height_map) inputs.push_back({o.describe("height-map"), *o.height_map});
  if (o.config) inputs.push_back({fmt::format("--config {}", *o.config), *o.config});

  // Not the wisdom file: its directory is created on the first save, and a
  // wisdom file that cannot be written is skipped silently at that time.
  for (std::size_t k = 0; k < (sweep ? 3U : 2U); ++k) {
    try {
      io::check_output_path(outputs[k].path);
    } catch (const FileError& error) {
      throw FileError(fmt::format("{} is invalid: {}", outputs[k].what, error.what()));
    }
  }
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    for (const File& input : inputs) {
      if (io::same_file(outputs[k].path, input.path)) {
        throw InputError(
            fmt::format("{} would overwrite the input {}: both are the file '{}'; choose another output name",
                        outputs[k].what, input.what, input.path.string()));
      }
    }
    for (std::size_t m = 0; m < k; ++m) {
      if (io::same_file(outputs[k].path, outputs[m].path)) {
        throw InputError(fmt::format("{} and {} are the same file '{}'; choose another output name", outputs[m].what,
                                     outputs[k].what, outputs[k].path.string()));
      }
    }
  }
}

void reject_given(const SolveOptions& o, Presence keys, std::string_view reason) {
  const std::vector<std::string> given = given_names(o, keys);
  if (!given.empty()) {
    throw InputError(fmt::format("{} {}", given.front(), reason));
  }
}

// The checks that need the grid, run as soon as it is known and before the
// heights are made: the loads' scale on it, and the memory a solve on it
// needs. `request` names where the grid came from.
using GridCheck = std::function<void(const Grid& grid, const std::string& request)>;

Surface builtin_surface(const SolveOptions& o, Boundary boundary, const GridCheck& check_grid,
                        const std::function<RowRange(const Grid&)>& rows_of) {
  reject_given(o,
               {{"dataset", o.dataset.has_value()},
                {"dx", o.dx.has_value()},
                {"dy", o.dy.has_value()},
                {"format", o.format.has_value()},
                {"unit", o.unit.has_value()},
                {"window", o.window.has_value()},
                {"invalid", o.invalid.has_value()},
                {"detrend", o.detrend.has_value()},
                {"pad", o.pad.has_value()}},
               "applies only to --height-map; a built-in geometry takes its spacing from --grid and --size");
  const geometry::SurfaceShape shape =
      in_context(o.name("geometry"), [&] { return geometry::parse_surface_shape(*o.geometry); });
  auto [spec, source] = builtin_shape_from(o, "geometry", shape, o.radius, o.wavelength, o.amplitude);
  Grid grid = grid_for_geometry(o, o.grid, o.size, boundary);
  check_grid(grid, o.describe("grid"));
  // Each process its own rows, from their global coordinates.
  const auto [first_row, rows] = rows_of && grid.dimension() == 2 ? rows_of(grid) : RowRange{0, grid.ny()};
  const Activity activity(
      fmt::format("making the {} surface on the {} grid", o.describe("geometry"), grid.shape_string()));
  Eigen::ArrayXd heights = geometry::make_surface_rows(grid, spec, first_row, rows);
  return {std::move(grid), std::move(heights), std::move(source), {}, first_row, rows};
}

// The spacing along one axis: the option if given, else the file attribute
// (0 when the file has none; the reader rejects negative ones).
std::optional<double> height_map_spacing(const SolveOptions& o, std::string_view key,
                                         const std::optional<double>& option, double attribute) {
  if (option) return require_length(o, key, *option);
  if (attribute > 0.0) return attribute;
  return std::nullopt;
}

// Both spacings are named at once when both are missing, so one retry suffices.
void require_spacings(const std::string& file, const std::vector<std::string_view>& missing) {
  if (missing.empty()) return;
  std::vector<std::string> flags;
  for (std::string_view key : missing) flags.push_back(fmt::format("--{}", key));
  throw FileError(fmt::format("height map {} does not state its spacing {}: pass {} (m)", file,
                              fmt::join(missing, " and "), fmt::join(flags, " and ")));
}

io::ReadOptions read_options_from(const SolveOptions& o) {
  io::ReadOptions read;
  if (o.format) read.format = in_context(o.name("format"), [&] { return io::parse_height_map_format(*o.format); });
  if (o.dataset) read.dataset = *o.dataset;
  if (o.unit) read.unit = in_context(o.name("unit"), [&] { return io::require_length_unit(*o.unit, "unit"); });
  return read;
}

surface::PreparationOptions preparation_from(const SolveOptions& o, Boundary boundary) {
  surface::PreparationOptions prepare;
  if (o.window) prepare.window = in_context(o.name("window"), [&] { return surface::parse_window(*o.window); });
  if (o.invalid) {
    prepare.invalid = in_context(o.name("invalid"), [&] { return surface::parse_invalid_points(*o.invalid); });
  }
  if (o.detrend) prepare.detrend = in_context(o.name("detrend"), [&] { return surface::parse_detrend(*o.detrend); });
  if (o.pad) {
    if (boundary == Boundary::periodic) {
      throw InputError(
          fmt::format("{} cannot be combined with --boundary periodic: padding is for free boundaries "
                      "(a periodic surface repeats without a margin)",
                      o.describe("pad")));
    }
    if (o.mean_pressure) {
      throw InputError(
          fmt::format("{} cannot be combined with {}: the mean pressure would be taken over the padded "
                      "area; give --force instead",
                      o.describe("pad"), o.name("mean-pressure")));
    }
    if (!(*o.pad >= surface::kMinPadFactor && *o.pad <= surface::kMaxPadFactor)) {
      throw InputError(fmt::format("{} is invalid: the factor must be in [{}, {}]", o.describe("pad"),
                                   surface::kMinPadFactor, surface::kMaxPadFactor));
    }
    prepare.pad_factor = *o.pad;
  }
  return prepare;
}

// `slabs`: read this process's rows through it (reads_height_map_in_slabs);
// null: read the whole map.
Surface height_map_surface(const SolveOptions& o, Boundary boundary, const GridCheck& check_grid,
                           const SurfaceSharing* slabs) {
  reject_given(o,
               {{"radius", o.radius.has_value()},
                {"wavelength", o.wavelength.has_value()},
                {"amplitude", o.amplitude.has_value()},
                {"grid", o.grid.has_value()},
                {"size", o.size.has_value()}},
               "cannot be used with --height-map: the grid and its spacing come from the file");
  const std::string& file = *o.height_map;
  const io::ReadOptions read = read_options_from(o);
  const surface::PreparationOptions prepare = preparation_from(o, boundary);
  const Activity reading(fmt::format("reading the height map {}", file));
  HeightMap map;
  std::size_t first_row = 0;
  std::optional<std::size_t> slab_rows;  // set when this process holds only some rows
  if (slabs) {
    io::HeightMapRows part = slabs->read_hdf5_rows(file, io::hdf5_dataset(read));
    map = std::move(part.map);
    first_row = part.first_row;
    if (part.rows != map.ny) slab_rows = part.rows;
  } else {
    map = io::read_height_map(file, read);
  }
  std::string source = map.source.empty() ? file : map.source;

  const std::optional<double> dx = height_map_spacing(o, "dx", o.dx, map.dx);
  std::optional<double> dy;
  if (map.dimension == 1) {
    if (o.dy) throw InputError(fmt::format("{} does not apply to the 1D profile in {}", o.name("dy"), file));
    require_spacings(file, dx ? std::vector<std::string_view>{} : std::vector<std::string_view>{"dx"});
  } else {
    dy = height_map_spacing(o, "dy", o.dy, map.dy);
    std::vector<std::string_view> missing;
    if (!dx) missing.push_back("dx");
    if (!dy) missing.push_back("dy");
    require_spacings(file, missing);
  }
  map.dx = *dx;
  map.dy = dy.value_or(0.0);
  // Spacings from the file's attributes get the range the options have.
  for (const auto& [key, value, given] :
       {std::tuple{"dx", map.dx, o.dx.has_value()}, std::tuple{"dy", map.dy, o.dy.has_value() || map.dimension == 1}}) {
    if (!given) {
      require_in_range(
          fmt::format("the spacing {} = {:g} m of height map {} (override it with --{})", key, value, file, key), value,
          kMinLength, kMaxLength, "m");
    }
  }

  try {
    if (slabs) {
      // prepare_height_map's steps that apply (reads_height_map_in_slabs),
      // with the whole map's sums when the rows are spread out.
      const linalg::Communicator& comm = slab_rows ? *slabs->communicator : linalg::serial_communicator();
      surface::refuse_invalid_points_rows(map, first_row, comm);
      surface::detrend_rows(map, prepare.detrend, first_row, comm);
    } else {
      surface::prepare_height_map(map, prepare);
    }
  } catch (const FileError& error) {
    // Only the refusal of invalid points is a FileError here: say how to proceed.
    throw FileError(fmt::format("{} (pass --invalid fill or --invalid crop)", error.what()));
  }
  Grid grid =
      map.dimension == 1 ? Grid::line(map.nx, map.dx, boundary) : Grid::plane(map.nx, map.ny, map.dx, map.dy, boundary);
  check_grid(grid, fmt::format("height map {} ({} cells{})", file, grid.shape_string(),
                               map.preparation.empty() ? "" : " after preparation"));
  const std::size_t rows = slab_rows.value_or(grid.dimension() == 1 ? 1 : grid.ny());
  return {std::move(grid), std::move(map.heights), std::move(source), std::move(map.preparation), first_row, rows};
}

// Subsurface stresses (--stress-depths, --stress-body, --stress-nu): the
// depths and whose stresses with which Poisson's ratio (the library's rule,
// stress/stressed_body.hpp), or none.
struct StressRequest {
  std::vector<double> depths;
  stress::StressedBodyChoice body;
};

StressRequest stress_request_from(const SolveOptions& o, std::size_t load_steps, const Problem& problem) {
  if (!o.stress_depths) {
    if (o.stress_nu) throw InputError(fmt::format("{} needs --stress-depths", o.describe("stress-nu")));
    if (o.stress_body) throw InputError(fmt::format("{} needs --stress-depths", o.describe("stress-body")));
    return {};
  }
  if (load_steps > 1) {
    throw InputError(fmt::format("{} applies to a single solve, not a load sweep: run `halfspace stress` on a step",
                                 o.describe("stress-depths")));
  }
  const bool range = o.stress_depths->find(':') != std::string::npos;
  StressRequest request;
  const std::string what = o.describe("stress-depths");
  request.depths = range ? parse_depth_range(*o.stress_depths, what) : parse_depth_list(*o.stress_depths, what);
  if (problem.coating && o.stress_nu) {
    // Each body's own Poisson's ratio: --layer-nu and --substrate-nu.
    throw InputError(fmt::format(
        "{} is not used for a coated half-space: the stresses take --layer-nu in the layer and --substrate-nu "
        "below it; drop --stress-nu",
        o.describe("stress-nu")));
  }
  const std::optional<stress::StressedBody> body =
      o.stress_body ? std::optional(stress::parse_stressed_body(*o.stress_body, "--stress-body")) : std::nullopt;
  const std::optional<ElasticPair> bodies =
      problem.coating ? std::optional(ElasticPair::coated(*problem.coating)) : problem.pair;
  request.body = stress::choose_stressed_body(body, o.stress_nu, bodies, "--stress-body", "--stress-nu");
  return request;
}

// The peak while the stresses are computed and written after the solve: the
// heights and the result's fields (5 arrays) kept, the transforms and one
// depth's fields (the depths are computed and written one at a time).
// With friction, the shear tractions' transforms too and, for body 1 (a
// coated body, or --stress-body 1), its tractions (-q, stress::tractions_on).
double stress_peak_memory(const Grid& grid, const StressRequest& stress, bool coated, bool shear) {
  const std::size_t depth_count = stress.depths.size();
  if (depth_count == 0) return 0.0;
  const bool body1 = stress.body.body == stress::StressedBody::body1;
  const double body1_shear = body1 && shear ? 16.0 * static_cast<double>(grid.size()) : 0.0;
  return kProgramBytes + 6.0 * 8.0 * static_cast<double>(grid.size()) + body1_shear +
         stress::stress_memory_estimate(grid, coated, shear);
}

}  // namespace

bool reads_height_map_in_slabs(const SolveOptions& o) {
  if (!o.height_map || o.geometry || o.window || o.pad) return false;
  try {
    if (o.invalid && surface::parse_invalid_points(*o.invalid) != surface::InvalidPoints::refuse) return false;
    return io::checked_format(*o.height_map, read_options_from(o)) == io::HeightMapFormat::hdf5;
  } catch (const InputError&) {
    return false;  // the whole reading reports it, as the serial program does
  }
}

SolveSetup make_solve_setup(const SolveOptions& options, const SurfaceSharing& share) {
  check_surface_choice(options);
  const FlagSpelling flags(options);
  Problem problem = make_problem(problem_options(options), flags);
  const std::optional<LayeredMaterial>& coating = problem.coating;
  const std::vector<double>& load_values = problem.load_values;
  const solvers::SolverOptions& solver = problem.solver;
  const Boundary boundary =
      in_context(options.name("boundary"), [&] { return parse_boundary(options.boundary.value_or("free")); });
  fs::path output = output_from(options);
  const std::optional<MemoryLimit> limit = memory_limit(options.max_memory, options.describe("max-memory"));
  const StressRequest stress = stress_request_from(options, load_values.size(), problem);
  // Friction (--friction with a tangential load), checked by make_problem.
  const std::optional<solvers::FrictionOptions> friction = friction_from(options, problem);
  const std::size_t history_steps = friction ? friction->steps() : 0;
  const GridCheck check_grid = [&](const Grid& grid, const std::string& request) {
    problem.check_grid(grid, flags);
    const std::string what = fmt::format("{}: {}", request, solve_description(grid, solver, load_values.size()));
    // A single frictionless solve lends the heights to the initial gap where it can.
    const bool gap_in_heights =
        load_values.size() == 1 && !friction && solvers::initial_gap_in_heights(problem.loading, solver);
    const double estimate = std::max(solve_memory_estimate(grid, solver, load_values.size(), gap_in_heights),
                                     stress_peak_memory(grid, stress, coating.has_value(), friction.has_value())) +
                            (friction ? solvers::friction_memory_estimate(grid, history_steps) : 0.0);
    if (share.check_memory) {
      // A process holding some rows runs the distributed solve (what is not
      // distributed is refused on several processes before it starts); a
      // sweep's steps are kept by rows until all write them (docs/usage.md).
      const std::size_t all_rows = grid.dimension() == 1 ? 1 : grid.ny();
      share.check_memory(
          what, grid,
          [&](std::size_t rows) {
            if (rows >= all_rows) return estimate;
            // Friction's fields and operator are spread over the slabs as the normal solve's are.
            const double friction_share = friction ? solvers::friction_memory_estimate(grid, history_steps) *
                                                         static_cast<double>(rows) / static_cast<double>(all_rows)
                                                   : 0.0;
            // The stresses' transforms and one depth's fields too (computed after the solve).
            const double stress_share = stress_peak_memory(grid, stress, coating.has_value(), friction.has_value()) *
                                        static_cast<double>(rows) / static_cast<double>(all_rows);
            return std::max(slab_solve_memory_estimate(grid, solver, rows, load_values.size()), stress_share) +
                   friction_share;
          },
          limit);
    } else {
      require_memory(what, estimate, limit);
    }
  };
  check_outputs_against_inputs(options, output, load_values.size() > 1 || history_steps > 1, solver.fft_planning);

  Surface surface = [&] {
    if (options.geometry && share.rows) return builtin_surface(options, boundary, check_grid, share.rows);
    if (!options.geometry && share.read_hdf5_rows && reads_height_map_in_slabs(options)) {
      return height_map_surface(options, boundary, check_grid, &share);
    }
    return share.whole([&] {
      return options.geometry ? builtin_surface(options, boundary, check_grid, {})
                              : height_map_surface(options, boundary, check_grid, nullptr);
    });
  }();
  const std::size_t rows = surface.grid.dimension() == 1 ? 1 : surface.grid.ny();
  const bool slab_ok = surface.first_row + surface.rows <= rows &&
                       static_cast<std::size_t>(surface.heights.size()) == surface.rows * surface.grid.nx();
  if (surface.rows == rows ? static_cast<std::size_t>(surface.heights.size()) != surface.grid.size() : !slab_ok) {
    throw InputError(fmt::format("surface {} has {} heights for a {} grid", surface.source, surface.heights.size(),
                                 surface.grid.shape_string()));
  }
  if (surface.rows == rows) {
    problem.check_heights(surface.grid, {surface.heights.data(), static_cast<std::size_t>(surface.heights.size())},
                          flags);
  }
  if (!stress.depths.empty()) {
    in_context(options.describe("stress-depths"), [&] {
      if (coating) stress::require_coated_stress_grid(surface.grid, *coating);
      stress::check_depths(surface.grid, stress.depths);
    });
  }
  // Its rules on the grid are check_grid's (Problem::check_grid).
  const std::size_t first_row = surface.first_row;
  return SolveSetup{std::move(problem),
                    std::move(surface.grid),
                    std::move(surface.heights),
                    first_row,
                    std::move(surface.source),
                    std::move(surface.preparation),
                    std::move(output),
                    options.quiet,
                    options.command_line,
                    options.config_text,
                    options.plot,
                    stress.depths,
                    stress.body,
                    friction};
}

std::string coating_text(const LayeredMaterial& coating) {
  return fmt::format(
      "layer t = {:.6g} m, E1 = {:.6g} Pa, nu1 = {:.6g} on substrate E2 = {:.6g} Pa, nu2 = {:.6g} "
      "(E* above is the layer's)",
      coating.thickness, coating.layer.youngs_modulus, coating.layer.poissons_ratio, coating.substrate.youngs_modulus,
      coating.substrate.poissons_ratio);
}

}  // namespace halfspace::app
