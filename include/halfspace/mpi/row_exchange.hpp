// Rows of a distributed (ny, nx) field fetched by the processes that need
// them from those that hold them: the restriction and prolongation between
// the slabs of two grids of a multilevel solve, whose row boundaries need
// not line up, move only the rows a process does not hold itself; a whole
// field on the first process handed out in slabs; a slab's neighbouring
// rows. Compiled only with HALFSPACE_MPI.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "halfspace/mpi/mpi_communicator.hpp"

namespace halfspace::mpi {

// A range of rows of every process, rank by rank.
struct RowRanges {
  std::vector<std::size_t> first;
  std::vector<std::size_t> rows;
  bool everywhere = false;  // every process holds every row (made by all())

  // Every process's (first, rows), gathered. Collective.
  static RowRanges gather(const MpiCommunicator& comm, std::size_t first, std::size_t rows);
  // Every one of `size` processes holding all `ny` rows.
  static RowRanges all(int size, std::size_t ny);
};

// Collective. Each process wants its range `wanted` of rows (nx values each)
// in `out`; `held` says which rows each process holds in `local`: disjoint
// slabs in rank order, or all rows on every process (then nothing travels).
void fetch_rows(const MpiCommunicator& comm, std::size_t nx, const RowRanges& held, std::span<const double> local,
                const RowRanges& wanted, std::span<double> out);

// Collective. The first process's `whole` field (every row, nx values each;
// empty elsewhere) handed out: each process receives its rows from
// `first_row` on into `local`.
void scatter_rows(const MpiCommunicator& comm, std::size_t nx, std::span<const double> whole, std::size_t first_row,
                  std::span<double> local);

}  // namespace halfspace::mpi
