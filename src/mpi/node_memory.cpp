// One communicator per machine (MPI_Comm_split_type), used once and freed.
#include "halfspace/mpi/node_memory.hpp"

namespace halfspace::mpi {

NodeShare share_of_node(const MpiCommunicator& comm, double bytes) {
  MPI_Comm node = MPI_COMM_NULL;
  check(MPI_Comm_split_type(comm.get(), MPI_COMM_TYPE_SHARED, comm.rank(), MPI_INFO_NULL, &node),
        "MPI_Comm_split_type");
  NodeShare share;
  int code = MPI_Comm_size(node, &share.processes);
  if (code == MPI_SUCCESS) code = MPI_Allreduce(&bytes, &share.bytes, 1, MPI_DOUBLE, MPI_SUM, node);
  MPI_Comm_free(&node);
  check(code, "MPI_Allreduce");
  return share;
}

}  // namespace halfspace::mpi
