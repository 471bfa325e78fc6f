// The sweep pipeline of the program: heights -> initial gap -> solver -> one
// warm-started solve per load -> result file, CSV, summary table, figures.
#include "sweep_command.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <span>
#include <vector>

#include "exit_codes.hpp"
#include "halfspace/analysis/adhesion_sweep.hpp"
#include "halfspace/analysis/load_sweep.hpp"
#include "halfspace/io/result_metadata.hpp"
#include "halfspace/io/sweep_writer.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/threads.hpp"
#include "halfspace/version.hpp"
#include "plot_tool.hpp"
#include "progress.hpp"
#include "solve_command.hpp"

namespace halfspace::app {
namespace {

std::string_view load_unit(ControlMode mode, const Grid& grid) {
  switch (mode) {
    case ControlMode::force:
      return grid.dimension() == 1 ? "N/m" : "N";
    case ControlMode::mean_pressure:
      return "Pa";
    case ControlMode::approach:
      return "m";
  }
  return "";
}

std::string_view load_name(ControlMode mode) {
  switch (mode) {
    case ControlMode::force:
      return "force";
    case ControlMode::mean_pressure:
      return "mean pressure";
    case ControlMode::approach:
      return "approach";
  }
  return "";
}

void print_sweep_summary(std::FILE* out, const SolveSetup& setup, std::span<const analysis::SweepStep> steps,
                         const std::filesystem::path& csv) {
  const Grid& grid = setup.grid;
  const ControlMode mode = setup.loading.mode;
  const auto row = [&](std::string_view label, const std::string& value) {
    fmt::print(out, "  {:<17} {}\n", label, value);
  };
  fmt::print(out, "halfspace {} ({}) solve: load sweep\n", kVersion, kGitHash);
  row("surface", setup.height_source);
  row("grid",
      fmt::format("{} cells ({}D), {} boundary", grid.shape_string(), grid.dimension(), to_string(grid.boundary())));
  row("E*", fmt::format("{:.6g} Pa", setup.e_star));
  if (const auto& c = setup.coating) row("coating", coating_text(*c));
  row("load", fmt::format("{} sweep, {} steps from {:.6g} to {:.6g} {}", load_name(mode), steps.size(),
                          setup.load_values.front(), setup.load_values.back(), load_unit(mode, grid)));
  row("solver", fmt::format("{}, {} thread{}, tolerance {:.1e}", steps.front().result.solver, setup.threads,
                            setup.threads == 1 ? "" : "s", steps.front().result.tolerance));
  fmt::print(out, "\n  {:>4}  {:>12}  {:>12}  {:>12}  {:>10}  {:>8}  {:>6}  {:>9}  {:>8}\n", "step",
             fmt::format("load ({})", load_unit(mode, grid)), "p_mean (Pa)", "approach (m)", "contact", "clusters",
             "iter", "residual", "time (s)");
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const analysis::SweepStep& s = steps[k];
    fmt::print(out, "  {:>4}  {:>12.5g}  {:>12.5g}  {:>12.5g}  {:>10.4g}  {:>8}  {:>6}  {:>9.2e}  {:>8.3f}{}\n", k,
               s.loading.value, s.result.mean_pressure, s.result.approach, s.result.contact_fraction,
               s.statistics.clusters(), s.result.iterations, s.result.residual, s.result.wall_seconds,
               s.result.converged() ? "" : "  not converged");
  }
  fmt::print(out, "\n");
  if (setup.solver.adhesion) {
    const double pull_off = analysis::pull_off_force(steps);
    row("pull-off force", std::isnan(pull_off)
                              ? std::string("none (no unloading branch)")
                              : fmt::format("{:.6g} {}", pull_off, grid.dimension() == 1 ? "N/m" : "N"));
  }
  row("output", fmt::format("{} (fields per step), {} (summary table)", setup.output.string(), csv.string()));
}

}  // namespace

io::SolveProvenance provenance(const SolveSetup& setup) {
  return {setup.e_star,      setup.loading.mode,  setup.threads,    setup.command_line,
          setup.config_text, setup.height_source, setup.preparation};
}

std::string describe_load(ControlMode mode, double value, const Grid& grid) {
  return fmt::format("{} {:.6g} {}", load_name(mode), value, load_unit(mode, grid));
}

int run_sweep_at(const SolveSetup& setup, const SolvePlace& place) {
  // The first process plots, from the file once written.
  const std::optional<PlotTool> plot = start_solve(setup, place);
  Progress progress(!setup.quiet && place.first, setup.load_values.size(), setup.solver.solver_tolerance());
  solvers::SolverOptions settings = setup.solver;
  settings.progress = progress.callback();
  analysis::LoadSweepOptions options;
  options.signed_loads = setup.solver.adhesion.has_value();
  options.on_step_start = [&](std::size_t step, std::size_t, const Loading& loading) {
    progress.start_step(step, describe_load(loading.mode, loading.value, setup.grid));
  };
  options.statistics = place.contact_statistics;
  const std::vector<analysis::SweepStep> steps =
      analysis::sweep_surface(setup.grid, place.heights, half_space(setup), setup.loading.mode, setup.load_values,
                              settings, options, place.layout);
  progress.clear();

  io::ResultMetadata metadata = place.metadata();
  metadata.coating = setup.coating;
  metadata.bodies = setup.pair;
  place.write_sweep(steps, metadata);
  int code = kExitOk;
  place.agree([&] {
    if (place.first) code = report_sweep(setup, steps, plot);
  });
  return place.first_value(code);
}

int report_sweep(const SolveSetup& setup, std::span<const analysis::SweepStep> steps,
                 const std::optional<PlotTool>& plot) {
  const std::filesystem::path csv = io::sweep_csv_path(setup.output);

  if (!setup.quiet) {
    print_sweep_summary(stdout, setup, steps, csv);
    std::fflush(stdout);
  }
  // The maps of the last step, and the sweep's curves.
  const bool plotted = draw_figures(plot, {"maps", "sweep"}, setup, "the results are written to");

  std::vector<std::size_t> failed;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    if (!steps[k].result.converged()) failed.push_back(k);
  }
  if (!failed.empty()) {
    const SolveResult& first = steps[failed.front()].result;
    fmt::print(stderr,
               "error: solver did not converge at {} of {} steps ({}); step {} stopped with {} after {} "
               "iterations (residual {:.3e}, tolerance {:.3e}); results written to {}\n",
               failed.size(), steps.size(), fmt::join(failed, ", "), failed.front(), to_string(first.status),
               first.iterations, first.residual, first.tolerance, setup.output.string());
    return kExitNotConverged;
  }
  return plotted ? kExitOk : kExitPlotFailed;
}

}  // namespace halfspace::app
