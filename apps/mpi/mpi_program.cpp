// `mpirun -np N halfspace solve ...`: every process validates the same
// options (so that they fail alike); the first reads or builds the surface
// and hands every other its slab of rows; all solve with the distributed
// Polonsky-Keer; the first gathers the fields and writes the result file
// through the serial writer, so the file is the serial program's in layout
// and attributes (docs/usage.md#running-on-a-cluster).
#include "mpi_program.hpp"

#include <fmt/format.h>

#include <Eigen/Core>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "../activity.hpp"
#include "../exit_codes.hpp"
#include "../progress.hpp"
#include "../summary.hpp"
#include "../sweep_command.hpp"
#include "halfspace/analysis/contact_statistics.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/result_metadata.hpp"
#include "halfspace/io/result_writer.hpp"
#include "halfspace/mpi/distributed_solver.hpp"
#include "halfspace/mpi/session.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/mpi/slab_gather.hpp"
#include "halfspace/threads.hpp"
#include "mpi_sweep.hpp"

namespace halfspace::app {
namespace {

std::unique_ptr<mpi::Session> session;
std::unique_ptr<mpi::MpiCommunicator> world;

constexpr const char* kNotYet = "is not available with more than one process yet";

// `text` on the first process, to every process.
void broadcast(std::string& text) {
  std::uint64_t size = text.size();
  mpi::check(MPI_Bcast(&size, 1, MPI_UINT64_T, 0, world->get()), "MPI_Bcast");
  text.resize(size);
  mpi::check(MPI_Bcast(text.data(), static_cast<int>(size), MPI_CHAR, 0, world->get()), "MPI_Bcast");
}

// The grid of the first process, to every process.
Grid broadcast(const std::optional<Grid>& grid) {
  std::uint64_t shape[4] = {0, 0, 0, 0};  // dimension, nx, ny, periodic
  double spacing[2] = {0.0, 0.0};
  if (grid) {
    shape[0] = static_cast<std::uint64_t>(grid->dimension());
    shape[1] = grid->nx();
    shape[2] = grid->ny();
    shape[3] = grid->periodic() ? 1 : 0;
    spacing[0] = grid->dx();
    spacing[1] = grid->dy();
  }
  mpi::check(MPI_Bcast(shape, 4, MPI_UINT64_T, 0, world->get()), "MPI_Bcast");
  mpi::check(MPI_Bcast(spacing, 2, MPI_DOUBLE, 0, world->get()), "MPI_Bcast");
  const Boundary boundary = shape[3] == 1 ? Boundary::periodic : Boundary::free;
  return shape[0] == 1 ? Grid::line(shape[1], spacing[0], boundary)
                       : Grid::plane(shape[1], shape[2], spacing[0], spacing[1], boundary);
}

// What the program adds to the solver: refused on several processes until
// it is distributed; on one process the serial program does it.
std::optional<std::string> unsupported_by_program(const SolveSetup& setup) {
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
    // The initial gap max(h) - h of the whole surface, this process's rows
    // (the first process holds all rows, the others their own).
    const Eigen::Map<const Eigen::ArrayXd> local_heights(
        setup.heights.data() + (layout.first_row - setup.first_row) * layout.nx,
        static_cast<Eigen::Index>(layout.local_size()));
    const double highest =
        world->max(local_heights.size() > 0 ? local_heights.maxCoeff() : -std::numeric_limits<double>::infinity());
    const Eigen::ArrayXd gap = highest - local_heights;
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

namespace {

// The first pass of make_distributed_setup stops where the surface would be
// made.
struct SurfaceDeferred {};

// The first process reads or builds the surface and keeps it whole; every
// other gets its slab of rows. Collective.
Surface share_surface(const std::function<Surface()>& make_whole) {
  const bool root = world->rank() == 0;
  std::optional<Surface> whole;
  mpi::run_agreed(*world, [&] {
    if (root) whole.emplace(make_whole());
  });
  if (world->size() == 1) return std::move(*whole);
  const Grid grid = broadcast(whole ? std::optional<Grid>(whole->grid) : std::nullopt);
  std::string source = whole ? whole->source : std::string();
  broadcast(source);
  std::string steps;
  if (whole) {
    for (const std::string& step : whole->preparation) steps += step + '\n';
  }
  broadcast(steps);
  // A 1D grid is not distributed: the others hold no rows (the run is
  // refused before they would need any).
  const mpi::SlabLayout layout = grid.dimension() == 2 ? mpi::slab_layout(grid.nx(), grid.ny(), *world)
                                                       : mpi::SlabLayout{grid.nx(), 1, 0, 0, 0, 0};
  Eigen::ArrayXd local(static_cast<Eigen::Index>(root ? 0 : layout.local_size()));
  if (grid.dimension() == 2) {
    Eigen::ArrayXd mine(static_cast<Eigen::Index>(layout.local_size()));
    mpi::scatter_rows(*world, layout,
                      root ? std::span<const double>(whole->heights.data(), grid.size()) : std::span<const double>(),
                      {mine.data(), layout.local_size()});
    if (!root) local = std::move(mine);
  }
  if (root) return std::move(*whole);
  std::vector<std::string> preparation;
  for (std::size_t begin = 0, end; (end = steps.find('\n', begin)) != std::string::npos; begin = end + 1) {
    preparation.push_back(steps.substr(begin, end - begin));
  }
  return {grid, std::move(local), std::move(source), std::move(preparation), layout.first_row, layout.rows};
}

}  // namespace

SolveSetup make_distributed_setup(const std::function<SolveSetup(const SurfaceSharing& share)>& make) {
  // Twice: first every process checks the options up to the surface without
  // any communication, and all agree on the outcome; only then do they
  // meet in share_surface's collectives, which a process that failed before
  // them would never reach (the others would wait for it forever).
  mpi::run_agreed(*world, [&] {
    try {
      make([](const std::function<Surface()>&) -> Surface { throw SurfaceDeferred{}; });
    } catch (const SurfaceDeferred&) {
    }
  });
  std::optional<SolveSetup> setup;
  mpi::run_agreed(*world, [&] { setup.emplace(make(share_surface)); });
  return std::move(*setup);
}

std::optional<int> run_solve_on_slabs(const SolveSetup& setup) {
  const std::optional<std::string> unsupported = unsupported_by_program(setup);
  const bool root = world->rank() == 0;
  if (world->size() == 1 && (unsupported || !mpi::distributable(setup.grid, setup.solver))) return std::nullopt;
  if (unsupported) throw InputError(*unsupported + ": solve it on one process");
  mpi::check_distributable(setup.grid, setup.solver);

  // Threads first: the FFT plans use the thread count in force when made.
  set_threads(setup.threads);
  if (setup.load_values.size() > 1) return run_sweep_on_slabs(setup, *world);
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
        analysis::contact_statistics(setup.grid, span_of(result.pressure), span_of(result.gap));
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
