// Rows travel as one MPI datatype of nx doubles, so that the counts stay
// within MPI's int even for slabs of more than 2^31 values.
#include "halfspace/mpi/slab_gather.hpp"

#include <cassert>
#include <vector>

namespace halfspace::mpi {

void gather_rows(const MpiCommunicator& comm, const SlabLayout& layout, std::span<const double> local,
                 std::span<double> whole, int root) {
  assert(local.size() == layout.local_size());
  MPI_Datatype row = MPI_DATATYPE_NULL;
  check(MPI_Type_contiguous(static_cast<int>(layout.nx), MPI_DOUBLE, &row), "MPI_Type_contiguous");
  check(MPI_Type_commit(&row), "MPI_Type_commit");
  const int size = comm.size();
  std::vector<int> counts(static_cast<std::size_t>(size));
  std::vector<int> offsets(static_cast<std::size_t>(size));
  const int rows = static_cast<int>(layout.rows);
  const int first = static_cast<int>(layout.first_row);
  check(MPI_Gather(&rows, 1, MPI_INT, counts.data(), 1, MPI_INT, root, comm.get()), "MPI_Gather");
  check(MPI_Gather(&first, 1, MPI_INT, offsets.data(), 1, MPI_INT, root, comm.get()), "MPI_Gather");
  const bool here = comm.rank() == root;
  assert(!here || whole.size() == layout.nx * layout.ny);
  const int code = MPI_Gatherv(local.data(), rows, row, here ? whole.data() : nullptr, counts.data(), offsets.data(),
                               row, root, comm.get());
  MPI_Type_free(&row);
  check(code, "MPI_Gatherv");
}

}  // namespace halfspace::mpi
