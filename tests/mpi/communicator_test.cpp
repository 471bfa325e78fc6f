// MpiCommunicator against what its contract says (run by ctest under
// mpiexec -np 1, 2 and 3 in the MPI build): sum() adds the processes'
// values in rank order, bit for bit, also past its internal chunk of 2^16
// values and at the chunk's edges; max() and min() are the processes'
// extremes. Exits non-zero on a mismatch, printing it.
#include <cstdio>
#include <vector>

#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/session.hpp"

namespace {

using namespace halfspace;

// A value of process `rank` at index `j` whose sums round differently in
// another order (different magnitudes), so that order is what is checked.
double value(int rank, std::size_t j) {
  return (rank % 2 == 0 ? 1e16 : 1.0) * (1.0 + 1e-3 * static_cast<double>(j % 977)) + 0.1 * rank;
}

int check_sum(const mpi::MpiCommunicator& comm, std::size_t count) {
  std::vector<double> values(count);
  for (std::size_t j = 0; j < count; ++j) values[j] = value(comm.rank(), j);
  comm.sum(values);
  int mismatches = 0;
  for (std::size_t j = 0; j < count; ++j) {
    double want = value(0, j);
    for (int r = 1; r < comm.size(); ++r) want += value(r, j);
    if (values[j] != want) {
      if (mismatches == 0 && comm.rank() == 0) {
        std::printf("FAIL sum of %zu values: [%zu] = %.17g, rank-order sum %.17g\n", count, j, values[j], want);
      }
      ++mismatches;
    }
  }
  return mismatches;
}

}  // namespace

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  int failures = 0;
  {
    const mpi::MpiCommunicator world(MPI_COMM_WORLD);
    for (const std::size_t count :
         {std::size_t{1}, std::size_t{65535}, std::size_t{65536}, std::size_t{65537}, std::size_t{3 * 65536 + 17}}) {
      failures += check_sum(world, count) > 0 ? 1 : 0;
    }
    const double rank = world.rank();
    if (world.max(rank) != world.size() - 1 || world.min(-rank) != -(world.size() - 1)) {
      if (world.rank() == 0) std::printf("FAIL max/min of the ranks\n");
      ++failures;
    }
    int total = failures;
    MPI_Allreduce(&failures, &total, 1, MPI_INT, MPI_SUM, world.get());
    failures = total;
  }
  if (failures > 0 && session.rank() == 0) std::printf("%d mismatch(es)\n", failures);
  return failures == 0 ? 0 : 1;
}
