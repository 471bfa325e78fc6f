// Where the levels of a distributed multilevel solve live: the large levels
// spread over the processes in FFTW-MPI's slabs of rows (the layout of
// their slab operators), the small ones gathered whole on every process
// (solved redundantly by the serial solver: a distributed solve of a few
// thousand cells is all communication). The restriction and prolongation
// are grid_transfer.hpp's arithmetic on the rows each process fetches from
// the others (row_exchange.hpp), so a level's fields have the serial
// multilevel's bits wherever the finer level's do. Compiled only with
// HALFSPACE_MPI.
#pragma once

#include <cstddef>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/row_exchange.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/solvers/level_transfer.hpp"

namespace halfspace::mpi {

class SlabLevelTransfer final : public solvers::LevelTransfer {
 public:
  // Levels of fewer cells are gathered: below 64 x 64 cells a process holds
  // a few rows, and FFTW-MPI's transposes cost more than the redundant
  // serial solve.
  static constexpr std::size_t kGatherBelowCells = std::size_t{1} << 12;

  // The levels of `fine` (a periodic 2D grid, held in slabs) down to
  // coarser_grid's limit of min_cells_per_axis: each coarse level is
  // gathered from the first one with fewer than `gather_below_cells` cells,
  // or on which a process would hold no rows. `comm` must outlive this
  // object. Collective.
  SlabLevelTransfer(const Grid& fine, std::size_t min_cells_per_axis, const MpiCommunicator& comm,
                    std::size_t gather_below_cells = kGatherBelowCells);

  // Whether `grid` (one of the levels) is held whole on every process.
  bool gathered(const Grid& grid) const { return level(grid).gathered; }

  std::size_t local_size(const Grid& grid) const override;
  const linalg::Communicator& communicator(const Grid& grid) const override;
  // Collective while `fine` is distributed.
  void restrict_to_coarse(const Grid& fine, std::span<const double> fine_values,
                          std::span<double> coarse_values) override;
  void prolong_to_fine(const Grid& fine, std::span<const double> coarse_values, std::span<double> fine_values) override;

 private:
  struct Level {
    std::size_t nx = 0;
    std::size_t ny = 0;
    bool gathered = false;
    SlabLayout slab;         // this process's rows were the level distributed
    RowRanges slab_rows;     // every process's rows of `slab`
    RowRanges fine_rows;     // the finer level's rows each process restricts from (2x slab_rows)
    RowRanges coarse_rows;   // the coarser level's rows each process prolongs from (if distributed)
    RowRanges held() const;  // the rows each process holds
  };
  const Level& level(const Grid& grid) const;
  // The level below `fine`, which must have one.
  const Level& coarser(const Level& fine) const;

  const MpiCommunicator& comm_;
  std::vector<Level> levels_;  // finest first
};

}  // namespace halfspace::mpi
