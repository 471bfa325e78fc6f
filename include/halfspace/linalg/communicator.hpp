// The processes a distributed field is spread over, as reductions see them.
// Every reduction in linalg/parallel.hpp takes one, so that a problem solved
// redundantly on every process (a small gathered one) reduces over one
// process while the distributed one around it reduces over all.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

namespace halfspace::linalg {

class Communicator {
 public:
  virtual ~Communicator() = default;
  // How many processes hold parts of the field, and this one's index.
  virtual int size() const = 0;
  virtual int rank() const = 0;
  // values[k] = the sum over the processes of their values[k], with the same
  // bits on every process (a fixed order of addition).
  virtual void sum(std::span<double> values) const = 0;
  // The largest and smallest of the processes' values.
  virtual double max(double local) const = 0;
  virtual double min(double local) const = 0;
  // Every process's `mine`, in rank order, into `all` on every process (a
  // distributed field's slabs made whole); the sizes are multiples of
  // `unit` bytes (a row), and `all` holds their sum.
  virtual void concatenate(std::span<const std::byte> mine, std::span<std::byte> all, std::size_t unit) const = 0;
  // Rows of a field held in slabs of `unit`-byte rows, in rank order (this
  // process's slab `mine` starting at row `mine_first`): the rows from
  // `first` on that fill `wanted`, fetched from the processes that hold
  // them. Each process may want a different range (or none); collective.
  virtual void fetch_rows(std::span<const std::byte> mine, std::size_t mine_first, std::size_t first,
                          std::span<std::byte> wanted, std::size_t unit) const = 0;
};

// The rows held by the processes before this one, each holding `rows`
// whole rows of a field in slabs in rank order: this process's first row.
// Collective.
inline std::size_t first_row_held(const Communicator& comm, std::size_t rows) {
  if (comm.size() == 1) return 0;
  std::vector<std::uint64_t> every(static_cast<std::size_t>(comm.size()), 0);
  const std::uint64_t mine = rows;
  comm.concatenate(std::as_bytes(std::span(&mine, 1)), std::as_writable_bytes(std::span(every)), sizeof(mine));
  std::size_t first = 0;
  for (int p = 0; p < comm.rank(); ++p) first += every[static_cast<std::size_t>(p)];
  return first;
}

// The first process's `values` on every process (each passing as many).
// Collective.
inline void broadcast_from_first(const Communicator& comm, std::span<double> values) {
  if (comm.size() == 1) return;
  std::vector<double> all(values.size());
  const std::span<const double> mine = comm.rank() == 0 ? std::span<const double>(values) : std::span<const double>();
  comm.concatenate(std::as_bytes(mine), std::as_writable_bytes(std::span(all)), sizeof(double));
  std::copy(all.begin(), all.end(), values.begin());
}

// One process holding the whole field: every reduction is the identity.
class SerialCommunicator final : public Communicator {
 public:
  int size() const override { return 1; }
  int rank() const override { return 0; }
  void sum(std::span<double> /*values*/) const override {}
  double max(double local) const override { return local; }
  double min(double local) const override { return local; }
  void concatenate(std::span<const std::byte> mine, std::span<std::byte> all, std::size_t /*unit*/) const override {
    if (!mine.empty()) std::memcpy(all.data(), mine.data(), mine.size());
  }
  void fetch_rows(std::span<const std::byte> mine, std::size_t mine_first, std::size_t first,
                  std::span<std::byte> wanted, std::size_t unit) const override {
    if (!wanted.empty()) std::memcpy(wanted.data(), mine.data() + (first - mine_first) * unit, wanted.size());
  }
};

// The one SerialCommunicator, the default of every reduction.
inline const Communicator& serial_communicator() {
  static const SerialCommunicator serial;
  return serial;
}

}  // namespace halfspace::linalg
