// The rms height and slope of a surface spread over MPI processes in slabs
// of rows: surface::surface_statistics's values (to rounding: sums added in
// another order), with no field gathered. Compiled only with HALFSPACE_MPI.
#pragma once

#include <span>

#include "halfspace/grid.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/surface/statistics.hpp"

namespace halfspace::mpi {

// `heights` holds this process's layout.rows rows of the 2D `grid`. The
// slope is spectral on a periodic grid (a slab transform of the heights),
// numpy.gradient's differences otherwise (each process given the rows next
// to its slab). The same values on every process. Collective.
surface::SurfaceStatistics slab_surface_statistics(const Grid& grid, const SlabLayout& layout,
                                                   std::span<const double> heights, const MpiCommunicator& comm);

}  // namespace halfspace::mpi
