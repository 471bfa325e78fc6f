// A grid spread over MPI processes in FFTW-MPI's slabs of rows, as a
// solvers::Layout: its operators are the serial ones on slab transforms
// (slab_spectral_transforms.hpp; periodic or free, homogeneous or coated), its
// multilevel levels SlabLevelTransfer's (small ones gathered, solved whole
// on every process), and what it does not run yet is refused with a message
// that names the alternative, never solved wrongly. Compiled only with
// HALFSPACE_MPI.
#pragma once

#include <memory>

#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/solvers/layout.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::mpi {

class DistributedLayout final : public solvers::Layout {
 public:
  // Over `comm`, which must outlive the layout and everything it makes.
  explicit DistributedLayout(const MpiCommunicator& comm) : comm_(comm) {}

  // The slab transforms (2D grids, periodic or free): this process's rows
  // and spectrum columns, on which the layout's operators run. Collective.
  std::unique_ptr<operators::SpectralTransforms> make_transforms(
      const Grid& grid, FftPlanning planning, const operators::TransformsShape& shape = {}) const override;
  solvers::RowSlab rows(const Grid& grid) const override;
  const linalg::Communicator& communicator() const override { return comm_; }
  // Takes a 2D grid (periodic or free, homogeneous or coated), solver pk,
  // pk-fourier or pk-multilevel (block deflation and the active-set phase
  // as the serial solvers take them), with or without a hardness cap; with
  // adhesion (the adhesive solver, which then replaces the type; on free
  // grids on the operator's padded circulant form). Throws
  // SolverOptionError naming the option and what to use instead, e.g.
  // "type = lemke is not available with more than one process yet: use
  // solver pk-multilevel, pk-fourier or pk".
  void check(const Grid& grid, const HalfSpace& half_space, const solvers::SolverOptions& options) const override;
  // Whether check passes.
  bool takes(const Grid& grid, const HalfSpace& half_space, const solvers::SolverOptions& options) const;
  // SlabLevelTransfer. Collective.
  std::unique_ptr<solvers::LevelTransfer> level_transfer(const Grid& fine,
                                                         std::size_t min_cells_per_axis) const override;
  // This layout for a distributed level, solvers::redundant_layout() for a
  // gathered one.
  const Layout& level_layout(const solvers::LevelTransfer& transfer, const Grid& level) const override;

 private:
  const MpiCommunicator& comm_;
};

}  // namespace halfspace::mpi
