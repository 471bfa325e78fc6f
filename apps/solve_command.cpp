// The solve pipeline of the program: heights -> initial gap -> operator ->
// solver -> result file. Everything here was validated by make_solve_setup.
#include "solve_command.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <utility>

#include "activity.hpp"
#include "exit_codes.hpp"
#include "friction_command.hpp"
#include "halfspace/analysis/contact_statistics.hpp"
#include "halfspace/io/result_metadata.hpp"
#include "halfspace/io/result_writer.hpp"
#include "halfspace/io/stress_writer.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/stress/stress_volume.hpp"
#include "halfspace/threads.hpp"
#include "plot_tool.hpp"
#include "processes.hpp"
#include "progress.hpp"
#include "solve_options.hpp"
#include "summary.hpp"
#include "sweep_command.hpp"

namespace halfspace::app {

HalfSpace half_space(const SolveSetup& setup) {
  if (setup.coating) return *setup.coating;
  return setup.e_star;
}

int run_solve(const SolveSetup& setup) {
  // Several MPI processes, or one MPI process and a solve it distributes
  // (friction too, on several).
  if (const std::optional<int> code = run_distributed_solve(setup)) return *code;
  return run_solve_here(setup);
}

int run_solve_here(const SolveSetup& setup) {
  return run_solve_at(setup, serial_place(setup));
}

namespace {

// One normal solve (no friction, no sweep) at `place`.
int run_single_solve_at(const SolveSetup& setup, const SolvePlace& place) {
  // The first process plots, from the file once written.
  const std::optional<PlotTool> plot = start_solve(setup, place);
  const bool prints = !setup.quiet && place.first;
  Progress progress(prints, 1, setup.solver.solver_tolerance());
  solvers::SolverOptions settings = setup.solver;
  settings.progress = progress.callback();
  // The solver and its operator are freed inside solve_surface_in_place,
  // before the statistics and the result file are made, so that the peak
  // memory is the solve's, and the heights hold the initial gap during the
  // solve where they can (docs/development-log.md).
  const std::string processes = place.processes > 1 ? fmt::format(", {} processes", place.processes) : "";
  // The surface's statistics before the solve: their transform (three
  // fields) then adds to the heights alone, not to the result's fields.
  std::optional<Activity> activity(std::in_place,
                                   fmt::format("computing the statistics of the {} grid", setup.grid.shape_string()));
  io::ResultMetadata metadata = place.metadata();
  activity.emplace(fmt::format("solving ({} on the {} grid{})", solvers::to_string(setup.solver.type),
                               setup.grid.shape_string(), processes));
  const SolveResult result = solvers::solve_surface_in_place(setup.grid, place.heights, half_space(setup),
                                                             setup.loading, settings, {}, place.layout);
  progress.clear();

  activity.emplace(fmt::format("computing the contact statistics of the {} grid", setup.grid.shape_string()));
  metadata.coating = setup.coating;
  metadata.bodies = setup.pair;
  metadata.contact_statistics = place.contact_statistics(result);
  // Subsurface stresses (--stress-depths), computed depth by depth while the
  // result's /stress group is written (on several processes each its rows).
  if (!setup.stress_depths.empty()) {
    const std::span<const double> pressure(result.pressure.data(), static_cast<std::size_t>(result.pressure.size()));
    io::attach_stress_group(metadata, setup.grid, setup.coating, setup.stress_body, {pressure, {}, {}},
                            setup.stress_depths, place.layout, setup.solver.fft_planning);
    activity.emplace(fmt::format("computing stresses at {} depths and writing {}", setup.stress_depths.size(),
                                 setup.output.string()));
  } else {
    activity.emplace(fmt::format("writing {}", setup.output.string()));
  }
  place.write_result(result, metadata);

  activity.reset();
  if (prints) {
    print_summary(stdout, setup, result);
    std::fflush(stdout);
  }
  const bool plotted = place.first_value(draw_figures(plot, {"maps"}, setup, "the result is written to") ? 1 : 0) != 0;
  if (!result.converged()) {
    if (place.first) fmt::print(stderr, "{}\n", non_convergence_message(setup, result));
    return kExitNotConverged;
  }
  return plotted ? kExitOk : kExitPlotFailed;
}

}  // namespace

int run_solve_at(const SolveSetup& setup, const SolvePlace& place) {
  if (setup.friction) return run_frictional_solve(setup, place);
  if (setup.load_values.size() > 1) {
    const Activity sweep(fmt::format("running the load sweep ({} on the {} grid, {} steps)",
                                     solvers::to_string(setup.solver.type), setup.grid.shape_string(),
                                     setup.load_values.size()));
    return run_sweep_at(setup, place);
  }
  return run_single_solve_at(setup, place);
}

Command add_solve_command(CLI::App& program) {
  CLI::App* solve = program.add_subcommand(
      "solve",
      "Solve one contact problem, or a load sweep, and write the pressure, gap and displacement to an HDF5 file");
  solve->footer("Options can also come from --config FILE.toml; see docs/usage.md.");
  add_solve_options(*solve);
  return {solve, [solve](const std::vector<std::string>& argv) {
            const SolveSetup setup = make_setup_everywhere([&](const SurfaceSharing& share) {
              SolveOptions options = solve_options_from_command_line(*solve, argv);
              std::optional<Activity> activity(std::in_place, "reading the options");
              merge_config_file(options);
              activity.emplace("checking the options and making the surface");
              return make_solve_setup(options, share);
            });
            return run_solve(setup);
          }};
}

}  // namespace halfspace::app
