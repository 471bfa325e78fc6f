// `mpirun -np N halfspace solve ...`: every process validates the same
// options (so that they fail alike); each builds its slab of rows of a
// built-in surface, or reads it from an HDF5 height map (parallel HDF5),
// while any other height map is read whole by the first process, which
// hands every other its slab and keeps only its own; all solve with the
// distributed Polonsky-Keer; the statistics come from the slabs and small
// reductions, and all write their rows of the result file at once, so no
// process ever holds a whole field. The file is the serial program's in
// layout and attributes (docs/usage.md#running-on-a-cluster).
#include "mpi_program.hpp"

#include <fmt/format.h>

#include <Eigen/Core>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <system_error>

#include "../activity.hpp"
#include "../exit_codes.hpp"
#include "../memory_check.hpp"
#include "../plot_tool.hpp"
#include "../progress.hpp"
#include "../solve_command.hpp"
#include "../summary.hpp"
#include "../sweep_command.hpp"
#include "halfspace/analysis/contact_statistics.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/result_metadata.hpp"
#include "halfspace/io/result_writer.hpp"
#include "halfspace/io/sweep_writer.hpp"
#include "halfspace/mpi/distributed_layout.hpp"
#include "halfspace/mpi/node_memory.hpp"
#include "halfspace/mpi/parallel_height_map_reader.hpp"
#include "halfspace/mpi/parallel_result_writer.hpp"
#include "halfspace/mpi/row_exchange.hpp"
#include "halfspace/mpi/session.hpp"
#include "halfspace/mpi/slab_contact_statistics.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/mpi/slab_surface_statistics.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/threads.hpp"

namespace halfspace::app {

// The grid of the first process, to every process.
Grid broadcast_grid(const mpi::MpiCommunicator& world, const std::optional<Grid>& grid) {
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
  mpi::check(MPI_Bcast(shape, 4, MPI_UINT64_T, 0, world.get()), "MPI_Bcast");
  mpi::check(MPI_Bcast(spacing, 2, MPI_DOUBLE, 0, world.get()), "MPI_Bcast");
  const Boundary boundary = shape[3] == 1 ? Boundary::periodic : Boundary::free;
  return shape[0] == 1 ? Grid::line(shape[1], spacing[0], boundary)
                       : Grid::plane(shape[1], shape[2], spacing[0], spacing[1], boundary);
}

namespace {

// The place of a solve on this process's rows: the slab statistics and the
// parallel writers, every hook collective. `setup`, `world` and `slab` must
// outlive it.
SolvePlace slab_place(const SolveSetup& setup, std::span<double> heights, const mpi::DistributedLayout& layout,
                      const mpi::MpiCommunicator& world, const mpi::SlabLayout& slab) {
  const auto span_of = [](const Eigen::ArrayXd& a) {
    return std::span<const double>(a.data(), static_cast<std::size_t>(a.size()));
  };
  SolvePlace place{.layout = layout, .heights = heights, .first = world.rank() == 0, .processes = world.size()};
  place.metadata = [&setup, &world, &slab, heights] {
    io::ResultMetadata metadata = io::provenance_metadata(provenance(setup));
    mpi::run_agreed(
        world, [&] { metadata.surface_statistics = mpi::slab_surface_statistics(setup.grid, slab, heights, world); });
    return metadata;
  };
  place.contact_statistics = [&setup, &world, &slab, span_of](const SolveResult& normal) {
    std::optional<analysis::ContactStatistics> statistics;
    mpi::run_agreed(world, [&] {
      statistics = mpi::slab_contact_statistics(setup.grid, slab, span_of(normal.pressure), span_of(normal.gap), world);
    });
    return *statistics;
  };
  place.write_result = [&setup, &world, &slab, heights](const SolveResult& normal, const io::ResultMetadata& metadata) {
    mpi::write_result_slabs(world, setup.output, setup.grid, slab, heights, normal, metadata);
  };
  place.write_history = [&setup, &world, &slab, heights](
                            const SolveResult& normal, std::span<const TangentialResult> steps,
                            std::span<const TangentialLoading> loads, const io::ResultMetadata& metadata) {
    mpi::write_friction_history_slabs(world, setup.output, setup.grid, slab, heights, normal, steps, loads, metadata);
  };
  place.write_sweep = [&setup, &world, &slab, heights](std::span<const analysis::SweepStep> steps,
                                                       const io::ResultMetadata& metadata) {
    const bool root = world.rank() == 0;
    const std::filesystem::path csv = io::sweep_csv_path(setup.output);
    // A previous sweep's table would not match the new file: removed first,
    // so that an interrupted write leaves no mismatched pair
    // (file-format.md); the first process writes the table once every
    // process has written its rows of the file.
    mpi::run_agreed(world, [&] {
      std::error_code ignored;
      if (root) std::filesystem::remove(csv, ignored);
    });
    mpi::write_sweep_slabs(world, setup.output, setup.grid, slab, heights, steps, metadata);
    mpi::run_agreed(world, [&] {
      if (root) io::write_sweep_csv(csv, steps);
    });
  };
  place.agree = [&world](const std::function<void()>& step) { mpi::run_agreed(world, step); };
  place.first_value = [&world](int value) {
    mpi::check(MPI_Bcast(&value, 1, MPI_INT, 0, world.get()), "MPI_Bcast");
    return value;
  };
  return place;
}

}  // namespace

int run_on_slabs(const mpi::MpiCommunicator& world, const std::function<int()>& run) {
  try {
    return run();
  } catch (const InputError&) {
    throw;  // found by every process alike (options, reduced values)
  } catch (const std::exception& error) {
    fmt::print(stderr, "error: {} (while {}, on process {} of {})\n", error.what(), Activity::failed_while(),
               world.rank(), world.size());
    std::fflush(stderr);
    mpi::Session::abort(kExitInputError);
  }
}

mpi::MpiCommunicator mpi_world() {
  return mpi::MpiCommunicator(MPI_COMM_WORLD);
}

struct Processes::Session {
  Session(int& argc, char**& argv) : mpi(argc, argv) {}
  mpi::Session mpi;
};
Processes::Processes(int& argc, char**& argv) : session_(std::make_unique<Session>(argc, argv)) {}
Processes::~Processes() = default;

int process_count() {
  return mpi_world().size();
}

bool prints_messages() {
  return mpi_world().rank() == 0;
}

void agree_everywhere(const std::function<void()>& step) {
  mpi::run_agreed(mpi_world(), step);
}

int run_on_first_process(const std::function<int()>& run) {
  const mpi::MpiCommunicator world = mpi_world();
  int code = kExitOk;
  mpi::run_agreed(world, [&] {
    if (world.rank() == 0) code = run();
  });
  mpi::check(MPI_Bcast(&code, 1, MPI_INT, 0, world.get()), "MPI_Bcast");
  return code;
}

namespace {

// The first pass of make_setup_everywhere stops where the surface would be
// made.
struct SurfaceDeferred {};

// How the processes make one setup's surface: the hooks of SurfaceSharing
// over MPI_COMM_WORLD, and what they know of each other meanwhile.
class DistributedSurface {
 public:
  DistributedSurface() : processes_on_node_(mpi::share_of_node(world_, 0.0).processes) {}

  SurfaceSharing sharing() {
    SurfaceSharing share;
    share.whole = [this](const std::function<Surface()>& make_whole) { return share_surface(make_whole); };
    share.rows = [this](const Grid& grid) {
      const mpi::SlabLayout layout = mpi::slab_layout(grid.nx(), grid.ny(), world_);
      return RowRange{layout.first_row, layout.rows};
    };
    share.read_hdf5_rows = [this](const std::filesystem::path& path, const std::string& dataset) {
      return mpi::read_height_map_slab(world_, path, dataset);
    };
    share.communicator = &world_;
    share.check_memory =
        [this](const std::string& request, const Grid& grid, const std::function<double(std::size_t rows)>& estimate,
               const std::optional<MemoryLimit>& limit) { check_process_memory(request, grid, estimate, limit); };
    return share;
  }

 private:
  // The first process reads or builds the surface whole and keeps its own
  // rows; every other gets its slab of rows. Collective.
  Surface share_surface(const std::function<Surface()>& make_whole) {
    const bool root = world_.rank() == 0;
    std::optional<Surface> whole;
    mpi::run_agreed(world_, [&] {
      if (!root) return;
      whole_on_first_ = true;
      try {
        whole.emplace(make_whole());
      } catch (...) {
        whole_on_first_ = false;
        throw;
      }
      whole_on_first_ = false;
    });
    if (world_.size() == 1) return std::move(*whole);
    const Grid grid = broadcast_grid(world_, whole ? std::optional<Grid>(whole->grid) : std::nullopt);
    std::string source = whole ? whole->source : std::string();
    mpi::broadcast(world_, source);
    std::string steps;
    if (whole) {
      for (const std::string& step : whole->preparation) steps += step + '\n';
    }
    mpi::broadcast(world_, steps);
    // A 1D grid is not distributed: the first process keeps it, the others
    // hold no rows (the run is refused before they would need any).
    if (grid.dimension() == 1) {
      if (root) return std::move(*whole);
      return {grid, Eigen::ArrayXd(), std::move(source), {}, 0, 0};
    }
    const mpi::SlabLayout layout = mpi::slab_layout(grid.nx(), grid.ny(), world_);
    Eigen::ArrayXd local(static_cast<Eigen::Index>(layout.local_size()));
    mpi::scatter_rows(world_, grid.nx(),
                      root ? std::span<const double>(whole->heights.data(), grid.size()) : std::span<const double>(),
                      layout.first_row, {local.data(), layout.local_size()});
    whole.reset();  // the first process too keeps only its rows
    std::vector<std::string> preparation;
    for (std::size_t begin = 0, end; (end = steps.find('\n', begin)) != std::string::npos; begin = end + 1) {
      preparation.push_back(steps.substr(begin, end - begin));
    }
    return {grid, std::move(local), std::move(source), std::move(preparation), layout.first_row, layout.rows};
  }

  // The memory check of a distributed run: what one process needs for the
  // largest slab (slab_solve_memory_estimate), against what its machine has,
  // where the needs of the processes on one machine add up (they share its
  // memory); --max-memory bounds each process. Collective, except while the
  // first process reads a surface alone: it then also holds the whole map
  // (read and prepared), and counts the other processes on its machine as
  // needing as much as it does for its slab.
  void check_process_memory(const std::string& request, const Grid& grid,
                            const std::function<double(std::size_t rows)>& estimate,
                            const std::optional<MemoryLimit>& limit) const {
    const auto processes = static_cast<std::size_t>(world_.size());
    const std::size_t rows = grid.dimension() == 1 ? 1 : grid.ny();
    const double mine = estimate(grid.dimension() == 1 ? rows : (rows + processes - 1) / processes);
    const bool per_process = limit && limit->given;
    const auto check = [&](double together, int on_node, double extra) {
      if (per_process) {
        require_memory(fmt::format("{}, per process of {}", request, processes), mine + extra, limit);
      } else {
        require_memory(fmt::format("{}, on {} processes ({} on this machine, together)", request, processes, on_node),
                       together + extra, limit);
      }
    };
    if (whole_on_first_) {
      check(mine * processes_on_node_, processes_on_node_, 2.0 * 8.0 * static_cast<double>(grid.size()));
      return;
    }
    mpi::run_agreed(world_, [&] {
      const mpi::NodeShare node = mpi::share_of_node(world_, mine);
      check(node.bytes, node.processes, 0.0);
    });
  }

  const mpi::MpiCommunicator world_ = mpi_world();
  int processes_on_node_ = 1;
  bool whole_on_first_ = false;  // while the first process reads or builds a whole surface alone
};

// The first pass: no process communicates, so every hook stops it.
SurfaceSharing deferred_sharing() {
  SurfaceSharing share;
  share.whole = [](const std::function<Surface()>&) -> Surface { throw SurfaceDeferred{}; };
  share.rows = [](const Grid&) -> RowRange { throw SurfaceDeferred{}; };
  share.read_hdf5_rows = [](const std::filesystem::path&, const std::string&) -> io::HeightMapRows {
    throw SurfaceDeferred{};
  };
  share.check_memory = [](const std::string&, const Grid&, const std::function<double(std::size_t)>&,
                          const std::optional<MemoryLimit>&) { throw SurfaceDeferred{}; };
  return share;
}

}  // namespace

SolveSetup make_setup_everywhere(const std::function<SolveSetup(const SurfaceSharing& share)>& make) {
  DistributedSurface surface;
  const mpi::MpiCommunicator world = mpi_world();
  // Twice: first every process checks the options up to the surface without
  // any communication, and all agree on the outcome; only then do they
  // meet in the surface's collectives, which a process that failed before
  // them would never reach (the others would wait for it forever).
  mpi::run_agreed(world, [&] {
    try {
      make(deferred_sharing());
    } catch (const SurfaceDeferred&) {
    }
  });
  std::optional<SolveSetup> setup;
  mpi::run_agreed(world, [&] { setup.emplace(make(surface.sharing())); });
  return std::move(*setup);
}

std::optional<int> run_distributed_solve(const SolveSetup& setup) {
  const mpi::MpiCommunicator world = mpi_world();
  const mpi::DistributedLayout layout(world);
  if (setup.grid.dimension() == 1 && world.size() > 1) {
    // A 1D grid is one row (at most a few million cells): the first process,
    // which holds the surface, runs the serial program (stresses, coatings
    // and plots included).
    return run_on_first_process([&] { return run_solve_here(setup); });
  }
  // One process solves friction serially (with stresses and plots).
  if (world.size() == 1 && (setup.friction || !layout.takes(setup.grid, half_space(setup), setup.solver))) {
    return std::nullopt;
  }
  layout.check(setup.grid, half_space(setup), setup.solver);

  // Threads first: the FFT plans use the thread count in force when made.
  set_threads(setup.threads);
  const mpi::SlabLayout slab = mpi::slab_layout(setup.grid.nx(), setup.grid.ny(), world);
  // This process's rows of the surface (the first process may hold all).
  const std::span<double> heights(setup.heights.data() + (slab.first_row - setup.first_row) * slab.nx,
                                  slab.local_size());
  const SolvePlace place = slab_place(setup, heights, layout, world, slab);
  return run_on_slabs(world, [&] { return run_solve_at(setup, place); });
}

}  // namespace halfspace::app
