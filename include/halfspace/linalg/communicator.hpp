// The processes a distributed field is spread over, as reductions see them.
// Every reduction in linalg/parallel.hpp takes one, so that a problem solved
// redundantly on every process (a small gathered one) reduces over one
// process while the distributed one around it reduces over all.
#pragma once

#include <cstddef>
#include <cstring>
#include <span>

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
