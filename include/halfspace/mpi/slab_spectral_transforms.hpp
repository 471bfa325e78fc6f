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

struct SlabTransformsShape {
  // One per field transformed at once: 2 (the tangential operator's
  // traction components) or 1 (the normal operator, the preconditioner).
  int count = 2;
  // The grid's own (periodic) transform on a free grid too: the Fourier
  // preconditioner's, which need only approximate K^-1.
  bool unpadded = false;
  // With count 1 and unpadded: FFTW-aligned memory the transform works in
  // (SlabRealFft's workspace), e.g. a free operator's idle padded buffer.
  std::span<std::complex<double>> workspace = {};
};

// Over `comm`, which must outlive them. Collective; throws InputError
// unless `grid` is 2D.
std::unique_ptr<operators::SpectralTransforms> make_slab_transforms(const Grid& grid, const MpiCommunicator& comm,
                                                                    FftPlanning planning,
                                                                    const SlabTransformsShape& shape = {});

}  // namespace halfspace::mpi
