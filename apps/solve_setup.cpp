// Turns the options as given into a checked SolveSetup. The checks run in the
// order a reader scans the command line (surface, material, load, solver,
// output) and the height map is read last, so cheap mistakes are found first.
#include "solve_setup.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <utility>
#include <variant>
#include <vector>

#include "activity.hpp"
#include "friction_setup.hpp"
#include "halfspace/elastic_pair.hpp"
#include "halfspace/error.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/io/fft_wisdom_file.hpp"
#include "halfspace/io/height_map_reader.hpp"
#include "halfspace/io/output_file.hpp"
#include "halfspace/io/sweep_writer.hpp"
#include "halfspace/io/xdmf_writer.hpp"
#include "halfspace/memory_estimate.hpp"
#include "halfspace/solvers/frictional_solve.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/stress/stress_volume.hpp"
#include "halfspace/stress/stressed_body.hpp"
#include "halfspace/stress/subsurface_stress.hpp"
#include "halfspace/surface/preparation.hpp"
#include "memory_check.hpp"
#include "processes.hpp"
#include "stress_command.hpp"
#include "value_parsing.hpp"

namespace halfspace::app {
namespace {

namespace fs = std::filesystem;

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
  std::vector<io::RunFile> outputs{{o.describe("output"), output}};
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
  std::vector<io::RunFile> inputs;
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
  io::check_outputs_apart(outputs, inputs);
}

// The checks that need the grid, run as soon as it is known and before the
// heights are made: the loads' scale on it, and the memory a solve on it
// needs. `request` names where the grid came from.
using GridCheck = std::function<void(const Grid& grid, const std::string& request)>;

Surface builtin_surface(const SolveOptions& o, const BuiltinSurface& builtin, const GridCheck& check_grid,
                        const std::function<RowRange(const Grid&)>& rows_of) {
  const Grid& grid = builtin.grid;
  check_grid(grid, o.describe("grid"));
  // Each process its own rows, from their global coordinates.
  const auto [first_row, rows] = rows_of && grid.dimension() == 2 ? rows_of(grid) : RowRange{0, grid.ny()};
  const Activity activity(
      fmt::format("making the {} surface on the {} grid", o.describe("geometry"), grid.shape_string()));
  Eigen::ArrayXd heights = geometry::make_surface_rows(grid, builtin.shape.spec, first_row, rows);
  return {grid, std::move(heights), builtin.shape.source, {}, first_row, rows};
}

// `slabs`: read this process's rows through it (reads_height_map_in_slabs);
// null: read the whole map.
Surface height_map_surface(const HeightMapFile& file, Boundary boundary, const OptionSpelling& flags,
                           const GridCheck& check_grid, const SurfaceSharing* slabs) {
  const Activity reading(fmt::format("reading the height map {}", file.path));
  HeightMap map;
  std::size_t first_row = 0;
  std::optional<std::size_t> slab_rows;  // set when this process holds only some rows
  if (slabs) {
    io::HeightMapRows part = slabs->read_hdf5_rows(file.path, io::hdf5_dataset(file.read));
    map = std::move(part.map);
    first_row = part.first_row;
    if (part.rows != map.ny) slab_rows = part.rows;
    set_spacing(map, file, flags);
    // prepare_height_map's steps that apply (reads_height_map_in_slabs),
    // with the whole map's sums when the rows are spread out.
    const linalg::Communicator& comm = slab_rows ? *slabs->communicator : linalg::serial_communicator();
    try {
      surface::refuse_invalid_points_rows(map, first_row, comm);
    } catch (const FileError& error) {
      throw with_invalid_points_hint(error, flags);
    }
    surface::detrend_rows(map, file.prepare.detrend, first_row, comm);
  } else {
    map = read_height_map_file(file, flags);
  }
  std::string source = map.source.empty() ? file.path : map.source;
  Grid grid =
      map.dimension == 1 ? Grid::line(map.nx, map.dx, boundary) : Grid::plane(map.nx, map.ny, map.dx, map.dy, boundary);
  check_grid(grid, fmt::format("height map {} ({} cells{})", file.path, grid.shape_string(),
                               map.preparation.empty() ? "" : " after preparation"));
  const std::size_t rows = slab_rows.value_or(grid.dimension() == 1 ? 1 : grid.ny());
  return {std::move(grid), std::move(map.heights), std::move(source), std::move(map.preparation), first_row, rows};
}

// Subsurface stresses (--stress-depths, --stress-body, --stress-nu): the
// depths and whose stresses with which Poisson's ratio (the library's rule,
// stress/stressed_body.hpp), or none. Which of these flags need which is
// the program's own: Python asks for stresses by a call of their own.
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
  const std::optional<stress::StressedBody> body =
      o.stress_body ? std::optional(stress::parse_stressed_body(*o.stress_body, "--stress-body")) : std::nullopt;
  // problem.pair is the coated body's (ElasticPair::coated) with a coating.
  request.body = stress::choose_stressed_body(body, o.stress_nu, problem.pair, "--stress-body", "--stress-nu");
  return request;
}

}  // namespace

bool reads_height_map_in_slabs(const HeightMapFile& file) {
  if (file.prepare.window || file.prepare.resample || file.prepare.pad_factor > 1.0) return false;
  if (file.prepare.invalid != surface::InvalidPoints::refuse) return false;
  try {
    return io::checked_format(file.path, file.read) == io::HeightMapFormat::hdf5;
  } catch (const InputError&) {
    return false;  // the whole reading reports it, as the serial program does
  }
}

SolveSetup make_solve_setup(const SolveOptions& options, const SurfaceSharing& share) {
  const FlagSpelling flags(options);
  const Boundary boundary =
      in_context(options.name("boundary"), [&] { return parse_boundary(options.boundary.value_or("free")); });
  const SurfaceChoice choice = make_surface_choice(options, boundary, flags);
  Problem problem = make_problem(problem_options(options), flags);
  if (const auto* file = std::get_if<HeightMapFile>(&choice)) problem.check_padding(file->prepare.pad_factor, flags);
  const std::optional<LayeredMaterial>& coating = problem.coating;
  const std::vector<double>& load_values = problem.load_values;
  const solvers::SolverOptions& solver = problem.solver;
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
    const double stress_peak =
        solve_stress_memory_estimate(grid, stress.depths.size(), coating.has_value(), friction.has_value(),
                                     stress.body.body == stress::StressedBody::body1);
    const double estimate =
        std::max(solve_memory_estimate(grid, solver, load_values.size(), gap_in_heights), stress_peak) +
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
            const double stress_share = stress_peak * static_cast<double>(rows) / static_cast<double>(all_rows);
            return std::max(slab_solve_memory_estimate(grid, solver, rows, load_values.size()), stress_share) +
                   friction_share;
          },
          limit);
    } else {
      require_memory(what, estimate, limit);
    }
  };
  check_outputs_against_inputs(options, output, load_values.size() > 1 || history_steps > 1, solver.fft_planning);

  const auto* builtin = std::get_if<BuiltinSurface>(&choice);
  const auto* file = std::get_if<HeightMapFile>(&choice);
  Surface surface = [&] {
    if (builtin && share.rows) return builtin_surface(options, *builtin, check_grid, share.rows);
    if (file && share.read_hdf5_rows && reads_height_map_in_slabs(*file)) {
      return height_map_surface(*file, boundary, flags, check_grid, &share);
    }
    return share.whole([&] {
      return builtin ? builtin_surface(options, *builtin, check_grid, {})
                     : height_map_surface(*file, boundary, flags, check_grid, nullptr);
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
