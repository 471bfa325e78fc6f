// Fields of a slab-distributed grid moved between the processes and one of
// them: the rows of every process gathered in order (for a writer on one
// process), or a whole field's rows handed out. Compiled only with
// HALFSPACE_MPI.
#pragma once

#include <span>

#include "halfspace/mpi/slab_fft.hpp"

namespace halfspace::mpi {

// Collective. `local` holds this process's layout.rows rows; on `root`,
// `whole` receives all ny rows (nx * ny values), elsewhere it is ignored
// (may be empty).
void gather_rows(const MpiCommunicator& comm, const SlabLayout& layout, std::span<const double> local,
                 std::span<double> whole, int root = 0);

// The reverse: `root` hands each process its layout.rows rows of `whole`
// (nx * ny values on root, ignored elsewhere) into `local`. Collective.
void scatter_rows(const MpiCommunicator& comm, const SlabLayout& layout, std::span<const double> whole,
                  std::span<double> local, int root = 0);

}  // namespace halfspace::mpi
