// The serial place: the library's whole-grid statistics and writers.
#include "solve_place.hpp"

#include "halfspace/io/friction_history_writer.hpp"
#include "halfspace/io/result_writer.hpp"
#include "halfspace/io/sweep_writer.hpp"
#include "sweep_command.hpp"

namespace halfspace::app {

SolvePlace serial_place(const SolveSetup& setup) {
  const Grid& grid = setup.grid;
  const std::span<const double> heights(setup.heights.data(), static_cast<std::size_t>(setup.heights.size()));
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

}  // namespace halfspace::app
