// Contact statistics of a solved contact spread over MPI processes in slabs
// of rows: the serial analysis::contact_statistics's values, from the slabs
// and small reductions, with no field gathered. Compiled only with
// HALFSPACE_MPI.
#pragma once

#include <span>

#include "halfspace/analysis/contact_statistics.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/slab_fft.hpp"

namespace halfspace::mpi {

// Contact fraction, gap moments and free volume from sums over `comm`; the
// contact clusters labelled on each slab and merged where they touch across
// slab boundaries (and across the domain's edges when the grid is
// periodic) by the first process. `pressure` and `gap` hold this process's
// layout.rows rows of the 2D `grid`. The same statistics on every process;
// the cluster sizes are the serial ones exactly, the sums to rounding (they
// are added in another order). Collective.
analysis::ContactStatistics slab_contact_statistics(const Grid& grid, const SlabLayout& layout,
                                                    std::span<const double> pressure, std::span<const double> gap,
                                                    const MpiCommunicator& comm);

}  // namespace halfspace::mpi
