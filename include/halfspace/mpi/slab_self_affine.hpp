// The self-affine random surface of surface::make_self_affine_surface made
// on a slab-distributed 2D grid: each process fills its own columns of the
// transposed spectrum (the random numbers are a hash of the seed and the
// mode, so no process replays a stream or holds another's modes), and the
// inverse transform, the mean and the scale are the serial ones over the
// processes. Compiled only with HALFSPACE_MPI.
#pragma once

#include <Eigen/Core>

#include "halfspace/grid.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/surface/self_affine.hpp"

namespace halfspace::mpi {

// This process's rows (slab_layout) of the surface the serial
// make_self_affine_surface makes for `grid` and `spec` on one process: the
// same modes with the same values, equal to rounding (FFTW-MPI's transform
// and the sums over the processes round differently). The transform is
// planned with one thread, as the serial one, so the heights do not depend
// on the thread count. Throws InputError as SelfAffineSpec::resolved, or
// unless the grid is 2D. Collective.
Eigen::ArrayXd make_self_affine_slab(const Grid& grid, const surface::SelfAffineSpec& spec,
                                     const MpiCommunicator& comm);

}  // namespace halfspace::mpi
