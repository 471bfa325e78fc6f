// The MPI processes that share one machine's memory. Compiled only with
// HALFSPACE_MPI.
#pragma once

#include "halfspace/mpi/mpi_communicator.hpp"

namespace halfspace::mpi {

struct NodeShare {
  int processes = 1;   // of `comm` on this process's machine (shared memory), this one included
  double bytes = 0.0;  // what they need together
};

// Adds up `bytes` over the processes of `comm` on this process's machine
// (MPI_COMM_TYPE_SHARED). Collective.
NodeShare share_of_node(const MpiCommunicator& comm, double bytes);

}  // namespace halfspace::mpi
