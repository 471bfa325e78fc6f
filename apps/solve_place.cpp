// The serial place: the library's whole-grid statistics and writers; the
// start and the figures of every pipeline.
#include "solve_place.hpp"

#include <fmt/format.h>

#include <cstdio>

#include "halfspace/io/friction_history_writer.hpp"
#include "halfspace/io/result_writer.hpp"
#include "halfspace/io/sweep_writer.hpp"
#include "halfspace/threads.hpp"
#include "sweep_command.hpp"

namespace halfspace::app {

SolvePlace serial_place(const SolveSetup& setup) {
  const Grid& grid = setup.grid;
  const std::span<double> heights(setup.heights.data(), static_cast<std::size_t>(setup.heights.size()));
  SolvePlace place{.layout = solvers::serial_layout(), .heights = heights};
  place.metadata = [&setup, heights] { return io::result_metadata(provenance(setup), setup.grid, heights); };
  place.contact_statistics = [&grid](const SolveResult& normal) {
    return analysis::contact_statistics(grid, {normal.pressure.data(), grid.size()}, {normal.gap.data(), grid.size()});
  };
  place.write_result = [&setup, heights](const SolveResult& normal, const io::ResultMetadata& metadata) {
    io::write_result(setup.output, setup.grid, heights, normal, metadata);
  };
  place.write_history = [&setup, heights](const SolveResult& normal, std::span<const TangentialResult> steps,
                                          std::span<const TangentialLoading> loads,
                                          const io::ResultMetadata& metadata) {
    io::write_friction_history(setup.output, setup.grid, heights, normal, steps, loads, metadata);
  };
  place.write_sweep = [&setup, heights](std::span<const analysis::SweepStep> steps,
                                        const io::ResultMetadata& metadata) {
    io::write_sweep_result(setup.output, setup.grid, heights, steps, metadata);
  };
  return place;
}

std::optional<PlotTool> start_solve(const SolveSetup& setup, const SolvePlace& place) {
  set_threads(setup.threads);
  std::optional<PlotTool> plot;
  place.agree([&] {
    if (setup.plot && place.first) plot = find_plot_tool({"--plot", "drop --plot", {}});
  });
  return plot;
}

bool draw_figures(const std::optional<PlotTool>& plot, std::initializer_list<std::string_view> figures,
                  const SolveSetup& setup, std::string_view written) {
  if (!plot) return true;
  for (const std::string_view figure : figures) {
    const std::string failure = run_plot_tool(*plot, figure, setup.output, setup.quiet);
    if (!failure.empty()) {
      fmt::print(stderr, "error: --plot: {}; {} {}\n", failure, written, setup.output.string());
      return false;
    }
  }
  return true;
}

}  // namespace halfspace::app
