// The frictional solve of the program (friction_command.hpp): everything was
// validated by make_solve_setup (the problem builder, halfspace/problem.hpp).
#include "friction_command.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "activity.hpp"
#include "exit_codes.hpp"
#include "halfspace/analysis/contact_statistics.hpp"
#include "halfspace/io/friction_history_writer.hpp"
#include "halfspace/io/result_metadata.hpp"
#include "halfspace/io/stress_writer.hpp"
#include "halfspace/solvers/frictional_solve.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/threads.hpp"
#include "plot_tool.hpp"
#include "progress.hpp"
#include "summary.hpp"
#include "sweep_command.hpp"

namespace halfspace::app {
namespace {

std::string describe_tangential(const TangentialLoading& loading, const Grid& grid) {
  if (loading.control == TangentialControl::displacement) {
    return fmt::format("tangential displacement ({:.6g}, {:.6g}) m", loading.x, loading.y);
  }
  return fmt::format("tangential force ({:.6g}, {:.6g}) {}", loading.x, loading.y, grid.dimension() == 1 ? "N/m" : "N");
}

void print_friction_summary(std::FILE* out, const SolveSetup& setup, const FrictionalSolveResult& result) {
  const std::span<const TangentialResult> steps = result.steps;
  const Grid& grid = setup.grid;
  const std::string_view force = grid.dimension() == 1 ? "N/m" : "N";
  const ElasticPair& pair = *setup.pair;
  if (pair.coating()) {
    fmt::print(out, "friction:            mu = {:g}; the coated half-space against the rigid surface\n",
               setup.friction->tangential.friction_coefficient);
  } else {
    fmt::print(out, "friction:            mu = {:g}; E1 = {:g} Pa, nu1 = {:g}, E2 = {:g} Pa, nu2 = {:g}\n",
               setup.friction->tangential.friction_coefficient, pair.body1().youngs_modulus,
               pair.body1().poissons_ratio, pair.body2().youngs_modulus, pair.body2().poissons_ratio);
  }
  if (!pair.similar()) {
    int alternations = 0;
    for (const TangentialResult& step : steps) alternations += step.coupling_alternations;
    fmt::print(out, "coupling:            Dundurs' beta = {:.4g}{}; {}\n", result.dundurs_beta,
               pair.coating() ? " (the layer's)" : "",
               result.coupled
                   ? fmt::format("normal and tangential solved together ({} alternations in the steps)", alternations)
                   : std::string("ignored (--no-coupling): the frictionless pressure"));
  }
  if (steps.empty()) return;
  const TangentialResult& last = steps.back();
  double dissipated = 0.0;
  int iterations = 0;
  for (const TangentialResult& step : steps) {
    dissipated += step.dissipated_energy;
    // A coupled step's work is every alternation's tangential solve, not
    // only the last one's.
    iterations += step.coupled ? step.coupling_tangential_iterations : step.iterations;
  }
  fmt::print(out, "tangential steps:    {}{} ({} iterations in all)\n", steps.size(),
             setup.friction->sliding_direction ? " (gross sliding)" : "", iterations);
  fmt::print(out, "tangential force:    ({:.6g}, {:.6g}) {} (mu P = {:.6g} {})\n", last.force_x, last.force_y, force,
             last.friction_coefficient * last.normal_force, force);
  fmt::print(out, "tangential approach: ({:.6g}, {:.6g}) m\n", last.state.approach_x, last.state.approach_y);
  fmt::print(out, "stick fraction:      {:.4f} of the contact cells (slip {:.4f})\n", last.stick_fraction,
             last.slip_fraction);
  fmt::print(out, "dissipated energy:   {:.6g} {}\n", dissipated, grid.dimension() == 1 ? "J/m" : "J");
}

}  // namespace

int run_frictional_solve(const SolveSetup& setup, const SolvePlace& place) {
  const solvers::FrictionOptions& options = *setup.friction;
  const ElasticPair& pair = *setup.pair;
  // The first process plots, from the file once written.
  const std::optional<PlotTool> plot = start_solve(setup, place);
  const std::span<const double> heights = place.heights;
  const bool prints = !setup.quiet && place.first;

  std::optional<Activity> activity(std::in_place,
                                   fmt::format("solving the normal contact ({} on the {} grid)",
                                               solvers::to_string(setup.solver.type), setup.grid.shape_string()));
  FrictionalSolveResult result;
  result.requested_steps = options.steps();
  if (options.coupled(pair)) {
    // Dissimilar bodies: every step solves the normal and tangential
    // problems together (coupled_step.hpp), each step with its own pressure.
    activity.emplace(
        fmt::format("solving the coupled normal and tangential contact (Dundurs' beta = {:.3g}, {} "
                    "step{}) on the {} grid",
                    pair.dundurs_beta(), options.steps(), options.steps() == 1 ? "" : "s", setup.grid.shape_string()));
    result = solvers::solve_frictional_surface(setup.grid, heights, pair, setup.loading, setup.solver, options,
                                               place.layout);
  } else {
    Progress progress(prints, 1, setup.solver.solver_tolerance());
    solvers::SolverOptions settings = setup.solver;
    settings.progress = progress.callback();
    result.normal =
        solvers::solve_surface(setup.grid, heights, pair.half_space(), setup.loading, settings, {}, place.layout);
  }
  if (result.normal.converged() && !options.coupled(pair)) {
    result.dundurs_beta = pair.dundurs_beta();
    activity.emplace(fmt::format("solving {} tangential step{} on the {} grid", options.steps(),
                                 options.steps() == 1 ? "" : "s", setup.grid.shape_string()));
    Progress progress(prints, options.steps(), options.tangential.tolerance);
    solvers::FrictionOptions friction = options;
    std::size_t shown = options.steps();
    if (progress.active()) {
      friction.progress = [&](std::size_t step, int iteration, double residual) {
        if (step != shown) {
          shown = step;
          progress.start_step(step, options.sliding_direction ? std::string("gross sliding")
                                                              : describe_tangential(options.history[step], setup.grid));
        }
        progress.iteration(iteration, residual);
        return solvers::IterationDecision::proceed;
      };
    }
    result.steps = solvers::solve_tangential_history(setup.grid, pair, result.normal, friction,
                                                     setup.solver.fft_planning, place.layout);
  }
  // The loads of the steps solved.
  const std::vector<TangentialLoading> loads(
      options.history.begin(),
      options.history.begin() + static_cast<std::ptrdiff_t>(std::min(options.history.size(), result.steps.size())));

  // A coupled single step writes its own pressure (under its shear); a
  // history the normal loading's at the root and, coupled, each step's own
  // in the step's group.
  const bool history = options.steps() > 1 && !result.steps.empty();
  const SolveResult& normal =
      result.coupled && !history && !result.step_normals.empty() ? result.step_normals.front() : result.normal;
  activity.emplace(fmt::format("computing the statistics of the {} grid", setup.grid.shape_string()));
  io::ResultMetadata metadata = place.metadata();
  metadata.coating = setup.coating;
  metadata.bodies = setup.pair;
  metadata.contact_statistics = place.contact_statistics(normal);
  activity.emplace(fmt::format("writing {}", setup.output.string()));
  if (history) {
    for (const SolveResult& step : result.step_normals) metadata.step_normals.push_back(&step);
    place.write_history(result.normal, result.steps, loads, metadata);
  } else {
    if (!result.steps.empty()) metadata.tangential = &result.steps.front();
    // Subsurface stresses (--stress-depths) under the pressure and the step's
    // shear, written while the result is (on several processes each its rows).
    // Body 1 (a coated body, or --stress-body 1) takes the traction on it, -q.
    if (!setup.stress_depths.empty() && !result.steps.empty()) {
      const TangentialResult& step = result.steps.front();
      const auto field = [](const Eigen::ArrayXd& f) {
        return std::span<const double>(f.data(), static_cast<std::size_t>(f.size()));
      };
      io::attach_stress_group(metadata, setup.grid, setup.coating, setup.stress_body,
                              {field(normal.pressure), field(step.state.shear_x), field(step.state.shear_y)},
                              setup.stress_depths, place.layout, setup.solver.fft_planning);
      activity.emplace(fmt::format("computing stresses at {} depths and writing {}", setup.stress_depths.size(),
                                   setup.output.string()));
    }
    place.write_result(normal, metadata);
  }
  activity.reset();
  if (prints) {
    print_summary(stdout, setup, normal);
    print_friction_summary(stdout, setup, result);
    if (history) fmt::print("history table:       {}\n", io::history_csv_path(setup.output).string());
    std::fflush(stdout);
  }
  // The normal maps, then the loop (a history) and the stick/slip map.
  const bool plotted =
      place.first_value(draw_figures(plot, {"maps", "friction"}, setup, "the result is written to") ? 1 : 0) != 0;
  if (!result.converged()) {
    if (place.first) {
      fmt::print(stderr, "error: {}; the result is written to {} with the steps solved\n", result.failure(),
                 setup.output.string());
    }
    return kExitNotConverged;
  }
  return plotted ? kExitOk : kExitPlotFailed;
}

}  // namespace halfspace::app
