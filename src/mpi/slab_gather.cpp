// Rows travel as one MPI datatype of nx doubles, so that the counts stay
// within MPI's int even for slabs of more than 2^31 values.
#include "halfspace/mpi/slab_gather.hpp"

#include <cassert>
#include <vector>

namespace halfspace::mpi {
namespace {

// The committed row type and every process's rows and first row (on root).
class RowPlan {
 public:
  RowPlan(const MpiCommunicator& comm, const SlabLayout& layout, int root)
      : counts_(static_cast<std::size_t>(comm.size())), offsets_(counts_.size()) {
    check(MPI_Type_contiguous(static_cast<int>(layout.nx), MPI_DOUBLE, &row_), "MPI_Type_contiguous");
    check(MPI_Type_commit(&row_), "MPI_Type_commit");
    const int rows = static_cast<int>(layout.rows);
    const int first = static_cast<int>(layout.first_row);
    check(MPI_Gather(&rows, 1, MPI_INT, counts_.data(), 1, MPI_INT, root, comm.get()), "MPI_Gather");
    check(MPI_Gather(&first, 1, MPI_INT, offsets_.data(), 1, MPI_INT, root, comm.get()), "MPI_Gather");
  }
  ~RowPlan() { MPI_Type_free(&row_); }
  RowPlan(const RowPlan&) = delete;
  RowPlan& operator=(const RowPlan&) = delete;

  MPI_Datatype row() const { return row_; }
  const int* counts() const { return counts_.data(); }
  const int* offsets() const { return offsets_.data(); }

 private:
  MPI_Datatype row_ = MPI_DATATYPE_NULL;
  std::vector<int> counts_;
  std::vector<int> offsets_;
};

}  // namespace

void gather_rows(const MpiCommunicator& comm, const SlabLayout& layout, std::span<const double> local,
                 std::span<double> whole, int root) {
  assert(local.size() == layout.local_size());
  const bool here = comm.rank() == root;
  assert(!here || whole.size() == layout.nx * layout.ny);
  const RowPlan plan(comm, layout, root);
  check(MPI_Gatherv(local.data(), static_cast<int>(layout.rows), plan.row(), here ? whole.data() : nullptr,
                    plan.counts(), plan.offsets(), plan.row(), root, comm.get()),
        "MPI_Gatherv");
}

void scatter_rows(const MpiCommunicator& comm, const SlabLayout& layout, std::span<const double> whole,
                  std::span<double> local, int root) {
  assert(local.size() == layout.local_size());
  const bool here = comm.rank() == root;
  assert(!here || whole.size() == layout.nx * layout.ny);
  const RowPlan plan(comm, layout, root);
  check(MPI_Scatterv(here ? whole.data() : nullptr, plan.counts(), plan.offsets(), plan.row(), local.data(),
                     static_cast<int>(layout.rows), plan.row(), root, comm.get()),
        "MPI_Scatterv");
}

}  // namespace halfspace::mpi
