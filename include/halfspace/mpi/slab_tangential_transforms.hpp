// The transforms of a TangentialOperator on a 2D grid spread over MPI
// processes in slabs of rows: periodic grids SlabRealFft (spectrum
// transposed, this process's columns kx), free grids SlabPaddedRealFft (the
// zero-padded DC-FFT convolution), one per traction component. Made by
// mpi::DistributedLayout::make_tangential_operator. Compiled only with
// HALFSPACE_MPI.
#pragma once

#include <memory>

#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/operators/tangential_transforms.hpp"

namespace halfspace::mpi {

// Over `comm`, which must outlive them. Collective; throws InputError
// unless `grid` is 2D.
std::unique_ptr<operators::TangentialTransforms> make_slab_tangential_transforms(const Grid& grid,
                                                                                 const MpiCommunicator& comm,
                                                                                 FftPlanning planning);

}  // namespace halfspace::mpi
