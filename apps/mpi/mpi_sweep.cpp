// The distributed load sweep. Every process holds its rows of the gap, of
// the previous step's pressure (the warm start) and of every step's fields,
// until all write their rows of the sweep file at once
// (mpi::write_sweep_slabs); the statistics come from the slabs, and only the
// CSV and the summary table (per step scalars) are the first process's.
// No process holds a whole field.
#include "mpi_sweep.hpp"

#include <fmt/format.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <system_error>
#include <vector>

#include "../activity.hpp"
#include "../exit_codes.hpp"
#include "../progress.hpp"
#include "../solve_command.hpp"
#include "../sweep_command.hpp"
#include "halfspace/analysis/contact_statistics.hpp"
#include "halfspace/analysis/load_sweep.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/result_metadata.hpp"
#include "halfspace/io/sweep_writer.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/mpi/agreement.hpp"
#include "halfspace/mpi/parallel_result_writer.hpp"
#include "halfspace/mpi/session.hpp"
#include "halfspace/mpi/slab_contact_statistics.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/mpi/slab_surface_statistics.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "mpi_program.hpp"

namespace halfspace::app {
namespace {

std::span<const double> span_of(const Eigen::ArrayXd& a) {
  return {a.data(), static_cast<std::size_t>(a.size())};
}

// The loads of the sweep, checked as analysis::run_load_sweep checks them
// (the mean gap reduced over the processes), before the first solve.
std::vector<Loading> checked_loads(const SolveSetup& setup, std::span<const double> gap,
                                   const mpi::MpiCommunicator& world) {
  std::vector<Loading> loads;
  for (const double value : setup.load_values) {
    const Loading loading{setup.loading.mode, value};
    loading.validate();
    loads.push_back(loading);
  }
  if (setup.loading.mode == ControlMode::approach && setup.grid.periodic()) {
    const double mean_gap =
        linalg::sum(world, gap.size(), [&](std::size_t i) { return gap[i]; }) / static_cast<double>(setup.grid.size());
    for (const double value : setup.load_values) solvers::check_periodic_approach(value, mean_gap);
  }
  return loads;
}

// The steps, solved on this process's rows: their fields are these rows,
// their statistics (from the slabs) the same on every process. A failure that only
// some processes meet in the middle of collective work ends them all
// (MPI_Abort), as in the single solve.
std::vector<analysis::SweepStep> solve_steps(const SolveSetup& setup, const mpi::SlabLayout& slab,
                                             std::span<const double> heights, const mpi::DistributedLayout& layout,
                                             const mpi::MpiCommunicator& world) {
  const bool root = world.rank() == 0;
  try {
    const Grid& grid = setup.grid;
    const Eigen::ArrayXd gap = solvers::initial_gap(grid, heights, layout);
    const std::vector<Loading> loads = checked_loads(setup, span_of(gap), world);

    Progress progress(!setup.quiet && root, loads.size(), setup.solver.tolerance);
    solvers::SolverOptions settings = setup.solver;
    settings.progress = progress.callback();
    const std::unique_ptr<solvers::ContactSolver> solver =
        solvers::make_solver(grid, half_space(setup), settings, layout);

    std::vector<analysis::SweepStep> steps;
    Eigen::ArrayXd previous;  // this process's rows of the last step's pressure
    bool previous_converged = false;
    for (std::size_t k = 0; k < loads.size(); ++k) {
      progress.start_step(k, describe_load(loads[k].mode, loads[k].value, grid));
      analysis::SweepStep step;
      step.loading = loads[k];
      step.warm_started = k > 0 && previous_converged;
      step.result =
          solver->solve(span_of(gap), loads[k], step.warm_started ? span_of(previous) : std::span<const double>());
      previous = step.result.pressure;
      previous_converged = step.result.converged();
      step.statistics =
          mpi::slab_contact_statistics(grid, slab, span_of(step.result.pressure), span_of(step.result.gap), world);
      steps.push_back(std::move(step));
    }
    progress.clear();
    return steps;
  } catch (const InputError&) {
    throw;  // found by every process alike (options, loads, reduced values)
  } catch (const std::exception& error) {
    fmt::print(stderr, "error: {} (while {}, on process {} of {})\n", error.what(), Activity::failed_while(),
               world.rank(), world.size());
    std::fflush(stderr);
    mpi::Session::abort(kExitInputError);
  }
}

}  // namespace

int run_sweep_on_slabs(const SolveSetup& setup, std::span<const double> heights,
                       const mpi::DistributedLayout& distributed, const std::optional<PlotTool>& plot) {
  const mpi::MpiCommunicator world = mpi_world();
  const bool root = world.rank() == 0;
  const mpi::SlabLayout layout = mpi::slab_layout(setup.grid.nx(), setup.grid.ny(), world);
  std::optional<Activity> activity(
      std::in_place, fmt::format("solving a load sweep ({} on the {} grid, {} processes)",
                                 solvers::to_string(setup.solver.type), setup.grid.shape_string(), world.size()));
  const std::vector<analysis::SweepStep> steps = solve_steps(setup, layout, heights, distributed, world);
  io::ResultMetadata metadata = io::provenance_metadata(provenance(setup));
  metadata.coating = setup.coating;
  mpi::run_agreed(world, [&] {
    activity.emplace(fmt::format("computing the statistics of the {} grid", setup.grid.shape_string()));
    metadata.surface_statistics = mpi::slab_surface_statistics(setup.grid, layout, heights, world);
  });
  activity.emplace(fmt::format("writing {}", setup.output.string()));
  // A previous sweep's table would not match the new file: removed first, so
  // that an interrupted write leaves no mismatched pair (file-format.md).
  mpi::run_agreed(world, [&] {
    std::error_code ignored;
    if (root) std::filesystem::remove(io::sweep_csv_path(setup.output), ignored);
  });
  mpi::write_sweep_slabs(world, setup.output, setup.grid, layout, heights, steps, metadata);
  int code = kExitOk;
  mpi::run_agreed(world, [&] {
    if (!root) return;
    activity.emplace(fmt::format("writing {}", io::sweep_csv_path(setup.output).string()));
    io::write_sweep_csv(io::sweep_csv_path(setup.output), steps);
    code = report_sweep(setup, steps, plot);
  });
  mpi::check(MPI_Bcast(&code, 1, MPI_INT, 0, world.get()), "MPI_Bcast");
  return code;
}

}  // namespace halfspace::app
