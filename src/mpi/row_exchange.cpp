// One MPI_Alltoallv of whole rows (an MPI datatype of nx doubles, so that
// counts count rows and stay within MPI's int for slabs of more than 2^31
// values): each process sends the part of
// every other's wanted range that it holds, and receives its wanted range
// from the holders in rank order, straight into place.
#include "halfspace/mpi/row_exchange.hpp"

#include <algorithm>
#include <cassert>
#include <climits>
#include <cstring>
#include <stdexcept>

namespace halfspace::mpi {
namespace {

// The overlap of rows [a, a + m) and [b, b + n): (first, count), count 0 if none.
std::pair<std::size_t, std::size_t> overlap(std::size_t a, std::size_t m, std::size_t b, std::size_t n) {
  const std::size_t begin = std::max(a, b);
  const std::size_t end = std::min(a + m, b + n);
  return {begin, end > begin ? end - begin : 0};
}

int as_int(std::size_t value) {
  if (value > static_cast<std::size_t>(INT_MAX)) throw std::runtime_error("a row exchange exceeds MPI's int counts");
  return static_cast<int>(value);
}

}  // namespace

RowRanges RowRanges::gather(const MpiCommunicator& comm, std::size_t first, std::size_t rows) {
  const auto size = static_cast<std::size_t>(comm.size());
  std::vector<unsigned long long> mine = {first, rows};
  std::vector<unsigned long long> every(2 * size);
  check(MPI_Allgather(mine.data(), 2, MPI_UNSIGNED_LONG_LONG, every.data(), 2, MPI_UNSIGNED_LONG_LONG, comm.get()),
        "MPI_Allgather");
  RowRanges ranges;
  for (std::size_t p = 0; p < size; ++p) {
    ranges.first.push_back(every[2 * p]);
    ranges.rows.push_back(every[2 * p + 1]);
  }
  return ranges;
}

RowRanges RowRanges::all(int size, std::size_t ny) {
  return {std::vector<std::size_t>(static_cast<std::size_t>(size), 0),
          std::vector<std::size_t>(static_cast<std::size_t>(size), ny), true};
}

void fetch_rows(const MpiCommunicator& comm, std::size_t nx, const RowRanges& held, std::span<const double> local,
                const RowRanges& wanted, std::span<double> out) {
  const auto me = static_cast<std::size_t>(comm.rank());
  const auto size = static_cast<std::size_t>(comm.size());
  assert(held.first.size() == size && wanted.first.size() == size);
  assert(local.size() == held.rows[me] * nx && out.size() == wanted.rows[me] * nx);
  if (size == 1 || held.everywhere) {
    // Every process holds every row it could want.
    assert(wanted.first[me] >= held.first[me] && wanted.first[me] + wanted.rows[me] <= held.first[me] + held.rows[me]);
    if (wanted.rows[me] > 0) {
      std::memcpy(out.data(), local.data() + (wanted.first[me] - held.first[me]) * nx,
                  wanted.rows[me] * nx * sizeof(double));
    }
    return;
  }
  std::vector<int> send_counts(size), send_offsets(size), receive_counts(size), receive_offsets(size);
  for (std::size_t p = 0; p < size; ++p) {
    const auto [send_first, send_rows] = overlap(held.first[me], held.rows[me], wanted.first[p], wanted.rows[p]);
    send_counts[p] = as_int(send_rows);
    send_offsets[p] = as_int(send_rows > 0 ? send_first - held.first[me] : 0);
    const auto [receive_first, receive_rows] = overlap(wanted.first[me], wanted.rows[me], held.first[p], held.rows[p]);
    receive_counts[p] = as_int(receive_rows);
    receive_offsets[p] = as_int(receive_rows > 0 ? receive_first - wanted.first[me] : 0);
  }
  MPI_Datatype row = MPI_DATATYPE_NULL;
  check(MPI_Type_contiguous(as_int(nx), MPI_DOUBLE, &row), "MPI_Type_contiguous");
  check(MPI_Type_commit(&row), "MPI_Type_commit");
  const int code = MPI_Alltoallv(local.data(), send_counts.data(), send_offsets.data(), row, out.data(),
                                 receive_counts.data(), receive_offsets.data(), row, comm.get());
  MPI_Type_free(&row);
  check(code, "MPI_Alltoallv");
}

void scatter_rows(const MpiCommunicator& comm, std::size_t nx, std::span<const double> whole, std::size_t first_row,
                  std::span<double> local) {
  fetch_rows(comm, nx, RowRanges::gather(comm, 0, whole.size() / nx), whole,
             RowRanges::gather(comm, first_row, local.size() / nx), local);
}

}  // namespace halfspace::mpi
