// Reductions over MPI processes. Sums gather every process's partial sums and
// add them in rank order, instead of MPI_Allreduce, so that every process
// holds the same bits: the solver's branches (restart, convergence) then go
// the same way on all of them, and a run repeats exactly.
#include "halfspace/mpi/mpi_communicator.hpp"

#include <fmt/format.h>

#include <climits>
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

void MpiCommunicator::concatenate(std::span<const std::byte> mine, std::span<std::byte> all, std::size_t unit) const {
  if (unit == 0 || mine.size() % unit != 0 || mine.size() / unit > static_cast<std::size_t>(INT_MAX)) {
    throw std::runtime_error("MpiCommunicator::concatenate: sizes are not whole units within MPI's int counts");
  }
  const int units = static_cast<int>(mine.size() / unit);
  std::vector<int> counts(static_cast<std::size_t>(size_)), offsets(counts.size());
  check(MPI_Allgather(&units, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_), "MPI_Allgather");
  long long total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    if (total > INT_MAX) throw std::runtime_error("MpiCommunicator::concatenate: more units than MPI's int counts");
    offsets[r] = static_cast<int>(total);
    total += counts[r];
  }
  if (static_cast<std::size_t>(total) * unit != all.size()) {
    throw std::runtime_error("MpiCommunicator::concatenate: the whole does not hold every process's part");
  }
  MPI_Datatype type = MPI_DATATYPE_NULL;
  check(MPI_Type_contiguous(static_cast<int>(unit), MPI_BYTE, &type), "MPI_Type_contiguous");
  check(MPI_Type_commit(&type), "MPI_Type_commit");
  const int code = MPI_Allgatherv(mine.data(), units, type, all.data(), counts.data(), offsets.data(), type, comm_);
  MPI_Type_free(&type);
  check(code, "MPI_Allgatherv");
}

}  // namespace halfspace::mpi
