// An MPI communicator as the reductions of linalg/parallel.hpp see it: sums
// added in rank order (the same bits on every process, whatever algorithm
// the MPI library picks), ranges by MPI_MAX and MPI_MIN. Compiled only with
// HALFSPACE_MPI.
#pragma once

#include <mpi.h>

#include <span>
#include <string>
#include <vector>

#include "halfspace/linalg/communicator.hpp"

namespace halfspace::mpi {

class MpiCommunicator final : public linalg::Communicator {
 public:
  // Uses `comm` (not owned: it must outlive this object). Collective.
  explicit MpiCommunicator(MPI_Comm comm);

  MPI_Comm get() const { return comm_; }
  int size() const override { return size_; }
  int rank() const override { return rank_; }
  // Allocates only the first time it reduces more values than before.
  void sum(std::span<double> values) const override;
  double max(double local) const override;
  double min(double local) const override;
  // MPI_Allgatherv of whole units (an MPI datatype of `unit` bytes, so that
  // the counts stay within MPI's int).
  void concatenate(std::span<const std::byte> mine, std::span<std::byte> all, std::size_t unit) const override;
  // Every process's held and wanted ranges gathered, then one MPI_Alltoallv
  // of whole units (as row_exchange.cpp does for fields of doubles).
  // Allocates only the first time (its scratch is kept): a Newton-Krylov
  // solve on slabs fetches halo rows in every iteration.
  void fetch_rows(std::span<const std::byte> mine, std::size_t mine_first, std::size_t first,
                  std::span<std::byte> wanted, std::size_t unit) const override;

 private:
  MPI_Comm comm_;
  int size_ = 1;
  int rank_ = 0;
  mutable std::vector<double> gathered_;  // every process's values, rank by rank
  // fetch_rows's scratch: every process's ranges, and the Alltoallv's counts
  // and offsets.
  mutable std::vector<unsigned long long> ranges_;
  mutable std::vector<int> send_counts_, send_offsets_, receive_counts_, receive_offsets_;
};

// Throws std::runtime_error naming `call` unless `code` is MPI_SUCCESS (MPI's
// default handler aborts first; this is for communicators that return).
void check(int code, const char* call);

// The first process's `text` on every process. Collective.
void broadcast(const MpiCommunicator& comm, std::string& text);

}  // namespace halfspace::mpi
