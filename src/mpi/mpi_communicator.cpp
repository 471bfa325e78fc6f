// Reductions over MPI processes. Sums gather every process's partial sums and
// add them in rank order, instead of MPI_Allreduce, so that every process
// holds the same bits: the solver's branches (restart, convergence) then go
// the same way on all of them, and a run repeats exactly.
#include "halfspace/mpi/mpi_communicator.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace halfspace::mpi {

void check(int code, const char* call) {
  if (code != MPI_SUCCESS) throw std::runtime_error(fmt::format("{} failed (MPI error {})", call, code));
}

MpiCommunicator::MpiCommunicator(MPI_Comm comm) : comm_(comm) {
  check(MPI_Comm_size(comm_, &size_), "MPI_Comm_size");
  check(MPI_Comm_rank(comm_, &rank_), "MPI_Comm_rank");
}

void MpiCommunicator::sum(std::span<double> values) const {
  const std::size_t k = values.size();
  if (size_ == 1 || k == 0) return;
  if (gathered_.size() < k * static_cast<std::size_t>(size_)) gathered_.resize(k * static_cast<std::size_t>(size_));
  check(MPI_Allgather(values.data(), static_cast<int>(k), MPI_DOUBLE, gathered_.data(), static_cast<int>(k), MPI_DOUBLE,
                      comm_),
        "MPI_Allgather");
  for (std::size_t j = 0; j < k; ++j) {
    double total = gathered_[j];
    for (std::size_t r = 1; r < static_cast<std::size_t>(size_); ++r) total += gathered_[r * k + j];
    values[j] = total;
  }
}

double MpiCommunicator::max(double local) const {
  double result = local;
  check(MPI_Allreduce(&local, &result, 1, MPI_DOUBLE, MPI_MAX, comm_), "MPI_Allreduce");
  return result;
}

double MpiCommunicator::min(double local) const {
  double result = local;
  check(MPI_Allreduce(&local, &result, 1, MPI_DOUBLE, MPI_MIN, comm_), "MPI_Allreduce");
  return result;
}

}  // namespace halfspace::mpi
