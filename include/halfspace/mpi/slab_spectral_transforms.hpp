// The spectral transforms (operators/spectral_transforms.hpp) of a 2D grid
// spread over MPI processes in slabs of rows: periodic grids SlabRealFft
// (spectrum transposed, this process's columns kx), free grids
// SlabPaddedRealFft (the zero-padded DC-FFT convolution). Made by
// mpi::DistributedLayout for the normal and tangential operators, the
// Fourier preconditioner and the subsurface stresses. Compiled only with
// HALFSPACE_MPI.
#pragma once

#include <complex>
#include <cstddef>
#include <memory>
#include <span>

#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/operators/spectral_transforms.hpp"

namespace halfspace::mpi {

// Over `comm`, which must outlive them. Collective; throws InputError
// unless `grid` is 2D.
std::unique_ptr<operators::SpectralTransforms> make_slab_transforms(const Grid& grid, const MpiCommunicator& comm,
                                                                    FftPlanning planning,
                                                                    const operators::TransformsShape& shape = {});

}  // namespace halfspace::mpi
