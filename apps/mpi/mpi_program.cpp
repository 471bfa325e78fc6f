// `mpirun -np N halfspace solve ...`: every process validates the same
// options and reads the surface (so that they fail alike), keeps its slab
// of rows of the initial gap, and solves with the distributed
// Polonsky-Keer; the first process gathers the fields and writes the result
// file through the serial writer, so the file is the serial program's in
// layout and attributes (docs/usage.md#running-on-a-cluster).
#include "mpi_program.hpp"

#include <fmt/format.h>

#include <Eigen/Core>
#include <cstdio>
#include <exception>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "../activity.hpp"
#include "../exit_codes.hpp"
#include "../progress.hpp"
#include "../summary.hpp"
#include "../sweep_command.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/result_metadata.hpp"
#include "halfspace/io/result_writer.hpp"
#include "halfspace/mpi/distributed_solver.hpp"
#include "halfspace/mpi/session.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/mpi/slab_gather.hpp"
#include "halfspace/surface/statistics.hpp"
#include "halfspace/threads.hpp"

namespace halfspace::app {
namespace {

std::unique_ptr<mpi::Session> session;
std::unique_ptr<mpi::MpiCommunicator> world;

constexpr const char* kNotYet = "is not available with more than one process yet";

// What the program adds to the solver: refused on several processes until
// it is distributed; on one process the serial program does it.
std::optional<std::string> unsupported_by_program(const SolveSetup& setup) {
  if (setup.load_values.size() > 1) return fmt::format("a load sweep ({} loads) {}", setup.load_values.size(), kNotYet);
  if (!setup.stress_depths.empty()) return fmt::format("subsurface stresses (stress depths) {}", kNotYet);
  if (setup.coating) return fmt::format("a coated half-space {}", kNotYet);
  if (setup.plot) return fmt::format("plot {}", kNotYet);
  return std::nullopt;
}

// The solve on this process's rows; a failure that only some processes
// meet in the middle of collective work ends them all (MPI_Abort), since the
// others wait in a transform or a reduction and cannot learn of it.
SolveResult solve_slab(const SolveSetup& setup, const mpi::SlabLayout& layout, const solvers::SolverOptions& settings) {
  try {
    // The initial gap max(h) - h of the whole surface, this process's rows.
    const Eigen::Map<const Eigen::ArrayXd> local_heights(setup.heights.data() + layout.first_row * layout.nx,
                                                         static_cast<Eigen::Index>(layout.local_size()));
    const Eigen::ArrayXd gap = setup.heights.maxCoeff() - local_heights;
    const std::unique_ptr<solvers::ContactSolver> solver =
        mpi::make_distributed_solver(setup.grid, setup.e_star, settings, *world);
    return solver->solve({gap.data(), static_cast<std::size_t>(gap.size())}, setup.loading, {});
  } catch (const InputError&) {
    throw;  // found by every process alike (options, reduced values)
  } catch (const std::exception& error) {
    fmt::print(stderr, "error: {} (while {}, on process {} of {})\n", error.what(), Activity::failed_while(),
               world->rank(), world->size());
    std::fflush(stderr);
    mpi::Session::abort(kExitInputError);
  }
}

}  // namespace

void start_mpi(int& argc, char**& argv) {
  session = std::make_unique<mpi::Session>(argc, argv);
  world = std::make_unique<mpi::MpiCommunicator>(MPI_COMM_WORLD);
}

void stop_mpi() {
  world.reset();
  session.reset();
}

const mpi::MpiCommunicator& mpi_world() {
  return *world;
}

std::optional<int> run_solve_on_slabs(const SolveSetup& setup) {
  const std::optional<std::string> unsupported = unsupported_by_program(setup);
  const bool root = world->rank() == 0;
  if (world->size() == 1 && (unsupported || !mpi::distributable(setup.grid, setup.solver))) return std::nullopt;
  if (unsupported) throw InputError(*unsupported + ": solve it on one process");
  mpi::check_distributable(setup.grid, setup.solver);

  // Threads first: the FFT plans use the thread count in force when made.
  set_threads(setup.threads);
  Progress progress(!setup.quiet && root, 1, setup.solver.tolerance);
  solvers::SolverOptions settings = setup.solver;
  settings.progress = progress.callback();
  const mpi::SlabLayout layout = mpi::slab_layout(setup.grid.nx(), setup.grid.ny(), *world);
  std::optional<Activity> activity(
      std::in_place, fmt::format("solving ({} on the {} grid, {} processes)", solvers::to_string(setup.solver.type),
                                 setup.grid.shape_string(), world->size()));
  SolveResult result = solve_slab(setup, layout, settings);
  progress.clear();

  // The whole fields on the first process, which writes the file.
  activity.emplace(fmt::format("gathering the {} grid's fields", setup.grid.shape_string()));
  const auto whole = static_cast<Eigen::Index>(root ? setup.grid.size() : 0);
  Eigen::ArrayXd pressure(whole), displacement(whole), gap(whole);
  const auto span_of = [](const Eigen::ArrayXd& a) {
    return std::span<const double>(a.data(), static_cast<std::size_t>(a.size()));
  };
  mpi::gather_rows(*world, layout, span_of(result.pressure), {pressure.data(), static_cast<std::size_t>(whole)});
  mpi::gather_rows(*world, layout, span_of(result.displacement),
                   {displacement.data(), static_cast<std::size_t>(whole)});
  mpi::gather_rows(*world, layout, span_of(result.gap), {gap.data(), static_cast<std::size_t>(whole)});
  result.pressure = std::move(pressure);
  result.displacement = std::move(displacement);
  result.gap = std::move(gap);

  const std::span<const double> heights(setup.heights.data(), static_cast<std::size_t>(setup.heights.size()));
  mpi::run_agreed(*world, [&] {
    if (!root) return;
    activity.emplace(fmt::format("computing the statistics of the {} grid", setup.grid.shape_string()));
    io::ResultMetadata metadata = io::result_metadata(provenance(setup), setup.grid, heights);
    metadata.contact_statistics =
        surface::contact_statistics(setup.grid, span_of(result.pressure), span_of(result.gap));
    activity.emplace(fmt::format("writing {}", setup.output.string()));
    io::write_result(setup.output, setup.grid, heights, result, metadata);
  });
  activity.reset();
  if (root && !setup.quiet) {
    print_summary(stdout, setup, result);
    std::fflush(stdout);
  }
  if (!result.converged()) {
    if (root) fmt::print(stderr, "{}\n", non_convergence_message(setup, result));
    return kExitNotConverged;
  }
  return kExitOk;
}

}  // namespace halfspace::app
