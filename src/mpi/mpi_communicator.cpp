// Reductions over MPI processes. Sums gather every process's partial sums and
// add them in rank order, instead of MPI_Allreduce, so that every process
// holds the same bits: the solver's branches (restart, convergence) then go
// the same way on all of them, and a run repeats exactly.
#include "halfspace/mpi/mpi_communicator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <utility>

namespace halfspace::mpi {

void check(int code, const char* call) {
  if (code != MPI_SUCCESS) throw std::runtime_error(fmt::format("{} failed (MPI error {})", call, code));
}

void broadcast(const MpiCommunicator& comm, std::string& text) {
  std::uint64_t size = text.size();
  check(MPI_Bcast(&size, 1, MPI_UINT64_T, 0, comm.get()), "MPI_Bcast");
  text.resize(size);
  check(MPI_Bcast(text.data(), static_cast<int>(size), MPI_CHAR, 0, comm.get()), "MPI_Bcast");
}

MpiCommunicator::MpiCommunicator(MPI_Comm comm) : comm_(comm) {
  check(MPI_Comm_size(comm_, &size_), "MPI_Comm_size");
  check(MPI_Comm_rank(comm_, &rank_), "MPI_Comm_rank");
}

void MpiCommunicator::sum(std::span<double> values) const {
  if (size_ == 1 || values.empty()) return;
  // In chunks, so that the gathered copies cost P x kSumChunk values, not P
  // per value (block deflation sums one value per block of a grid of
  // billions of cells); each value is added in the same rank order as a
  // whole, so the bits do not depend on the chunking.
  constexpr std::size_t kSumChunk = std::size_t{1} << 16;
  const auto processes = static_cast<std::size_t>(size_);
  for (std::size_t begin = 0; begin < values.size(); begin += kSumChunk) {
    const std::size_t k = std::min(kSumChunk, values.size() - begin);
    if (gathered_.size() < k * processes) gathered_.resize(k * processes);
    check(MPI_Allgather(values.data() + begin, static_cast<int>(k), MPI_DOUBLE, gathered_.data(), static_cast<int>(k),
                        MPI_DOUBLE, comm_),
          "MPI_Allgather");
    for (std::size_t j = 0; j < k; ++j) {
      double total = gathered_[j];
      for (std::size_t r = 1; r < processes; ++r) total += gathered_[r * k + j];
      values[begin + j] = total;
    }
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

void MpiCommunicator::fetch_rows(std::span<const std::byte> mine, std::size_t mine_first, std::size_t first,
                                 std::span<std::byte> wanted, std::size_t unit) const {
  if (unit == 0 || mine.size() % unit != 0 || wanted.size() % unit != 0) {
    throw std::runtime_error("MpiCommunicator::fetch_rows: sizes are not whole units");
  }
  const auto size = static_cast<std::size_t>(size_);
  const auto me = static_cast<std::size_t>(rank_);
  // (held first, held rows, wanted first, wanted rows) of every process.
  const std::array<unsigned long long, 4> ranges = {mine_first, mine.size() / unit, first, wanted.size() / unit};
  std::vector<unsigned long long>& every = ranges_;
  every.resize(4 * size);
  check(MPI_Allgather(ranges.data(), 4, MPI_UNSIGNED_LONG_LONG, every.data(), 4, MPI_UNSIGNED_LONG_LONG, comm_),
        "MPI_Allgather");
  auto as_int = [](unsigned long long value) {
    if (value > static_cast<unsigned long long>(INT_MAX)) {
      throw std::runtime_error("MpiCommunicator::fetch_rows: more units than MPI's int counts");
    }
    return static_cast<int>(value);
  };
  // The overlap of rows [a, a + m) and [b, b + n): (first, count).
  auto overlap = [](unsigned long long a, unsigned long long m, unsigned long long b, unsigned long long n) {
    const unsigned long long begin = std::max(a, b);
    const unsigned long long end = std::min(a + m, b + n);
    return std::pair<unsigned long long, unsigned long long>{begin, end > begin ? end - begin : 0};
  };
  std::vector<int>& send_counts = send_counts_;
  std::vector<int>& send_offsets = send_offsets_;
  std::vector<int>& receive_counts = receive_counts_;
  std::vector<int>& receive_offsets = receive_offsets_;
  for (std::vector<int>* v : {&send_counts, &send_offsets, &receive_counts, &receive_offsets}) v->resize(size);
  for (std::size_t p = 0; p < size; ++p) {
    const auto sent = overlap(every[4 * me], every[4 * me + 1], every[4 * p + 2], every[4 * p + 3]);
    send_counts[p] = as_int(sent.second);
    send_offsets[p] = as_int(sent.second > 0 ? sent.first - every[4 * me] : 0);
    const auto received = overlap(every[4 * me + 2], every[4 * me + 3], every[4 * p], every[4 * p + 1]);
    receive_counts[p] = as_int(received.second);
    receive_offsets[p] = as_int(received.second > 0 ? received.first - every[4 * me + 2] : 0);
  }
  MPI_Datatype type = MPI_DATATYPE_NULL;
  check(MPI_Type_contiguous(as_int(unit), MPI_BYTE, &type), "MPI_Type_contiguous");
  check(MPI_Type_commit(&type), "MPI_Type_commit");
  const int code = MPI_Alltoallv(mine.data(), send_counts.data(), send_offsets.data(), type, wanted.data(),
                                 receive_counts.data(), receive_offsets.data(), type, comm_);
  MPI_Type_free(&type);
  check(code, "MPI_Alltoallv");
}

}  // namespace halfspace::mpi
