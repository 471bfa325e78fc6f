// The slab transforms behind solvers::Layout, on which the one
// FftInfluenceOperator, FourierPreconditioner and TangentialOperator run: make_solver runs the serial
// solver loops (polonsky_keer.cpp, the multilevel and adhesive solvers)
// unchanged over them, their reductions going through the operator's
// communicator. A hardness cap is elementwise (the projection onto [0, H])
// apart from its load-restoring scale and fill, whose sums and searches are
// reductions over that communicator too.
#include "halfspace/mpi/distributed_layout.hpp"

#include <fmt/format.h>

#include <string>
#include <utility>
#include <variant>

#include "halfspace/mpi/slab_level_transfer.hpp"
#include "halfspace/mpi/slab_spectral_transforms.hpp"

namespace halfspace::mpi {
namespace {

using solvers::SolverOptionError;
using solvers::SolverType;

constexpr const char* kNotYet = "is not available with more than one process yet";

}  // namespace

std::unique_ptr<operators::SpectralTransforms> DistributedLayout::make_transforms(
    const Grid& grid, FftPlanning planning, const operators::TransformsShape& shape) const {
  return make_slab_transforms(grid, comm_, planning, shape);
}

solvers::RowSlab DistributedLayout::rows(const Grid& grid) const {
  const SlabLayout layout = slab_layout(grid.nx(), grid.ny(), comm_);
  return {layout.first_row, layout.rows};
}

void DistributedLayout::check(const Grid& grid, const HalfSpace& /*half_space*/,
                              const solvers::SolverOptions& options) const {
  if (grid.dimension() != 2) {
    throw SolverOptionError(
        "grid", fmt::format("{} ({}D, {})", grid.shape_string(), grid.dimension(), to_string(grid.boundary())),
        fmt::format("{}: only 2D grids are distributed", kNotYet));
  }
  if (options.precision == solvers::Precision::mixed) {
    throw SolverOptionError("precision", "mixed",
                            fmt::format("{}: use precision double (one process solves mixed)", kNotYet));
  }
  if (options.type != SolverType::pk && options.type != SolverType::pk_fourier &&
      options.type != SolverType::pk_multilevel) {
    // A 1D grid runs on the first process (apps/mpi); a 2D one is in slabs.
    throw SolverOptionError("type", std::string(to_string(options.type)),
                            "is not available on slabs of a 2D grid: the dense solvers assemble the whole influence "
                            "matrix (at most 8192 cells) on one process; run it without mpirun, or use solver "
                            "pk-multilevel, pk-fourier or pk");
  }
}

bool DistributedLayout::takes(const Grid& grid, const HalfSpace& half_space,
                              const solvers::SolverOptions& options) const {
  try {
    check(grid, half_space, options);
  } catch (const SolverOptionError&) {
    return false;
  }
  return true;
}

std::unique_ptr<solvers::LevelTransfer> DistributedLayout::level_transfer(const Grid& fine,
                                                                          std::size_t min_cells_per_axis) const {
  return std::make_unique<SlabLevelTransfer>(fine, min_cells_per_axis, comm_);
}

const solvers::Layout& DistributedLayout::level_layout(const solvers::LevelTransfer& transfer,
                                                       const Grid& level) const {
  // Gathered levels are solved on every process alike.
  if (static_cast<const SlabLevelTransfer&>(transfer).gathered(level)) return solvers::redundant_layout();
  return *this;
}

}  // namespace halfspace::mpi
