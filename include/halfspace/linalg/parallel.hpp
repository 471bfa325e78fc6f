// The one place for elementwise loops and reductions over grid fields.
// Solvers express their vector work through these functions, so that a
// distributed field (MPI slabs, include/halfspace/mpi/) changes only the
// operator and the Communicator the reductions are given: each reduction
// folds the process's own cells, then `global_*` combines the processes.
// Without a Communicator a reduction is over this process alone.
//
// Reductions are deterministic: the index range is cut into kReductionBlocks
// fixed blocks, each summed in order, and the block sums are added in order,
// so the result has the same bits whatever the number of threads.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <utility>

#include "halfspace/linalg/communicator.hpp"

namespace halfspace::linalg {

inline constexpr std::size_t kReductionBlocks = 64;
// Below this many elements a loop runs on one thread: waking the team costs
// more than the work (and stalls badly when the cores are busy).
inline constexpr std::size_t kParallelThreshold = 16384;

// The combination over the processes of `comm` (identity on one process).
template <std::size_t K>
inline std::array<double, K> global_sum(const Communicator& comm, std::array<double, K> local) {
  comm.sum(local);
  return local;
}
inline double global_max(const Communicator& comm, double local) {
  return comm.max(local);
}
inline double global_min(const Communicator& comm, double local) {
  return comm.min(local);
}

// Calls body(i) for i in [0, n), in parallel; body must not write shared state
// other than element i of its fields.
template <class Body>
void for_each_index(std::size_t n, Body&& body) {
  const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    body(static_cast<std::size_t>(i));
  }
}

// Calls body(j) for j in [0, rows), where each call handles a row of
// row_length elements; threaded when the total work is large enough.
template <class Body>
void for_each_row(std::size_t rows, std::size_t row_length, Body&& body) {
  const auto count = static_cast<std::ptrdiff_t>(rows);
#pragma omp parallel for schedule(static) if (rows * row_length > kParallelThreshold)
  for (std::ptrdiff_t j = 0; j < count; ++j) {
    body(static_cast<std::size_t>(j));
  }
}

// A reduction's per-cell function, inlined with everything it calls: GCC's
// inliner gives up on a term of a few dozen lines called four times in the
// unrolled loop below and calls it per cell instead (no vectorisation, the
// lanes in memory), as it did with the Polonsky-Keer passes once they
// handled a hardness cap (docs/development-log.md, 2026-11-29).
#if defined(__GNUC__)
#define HALFSPACE_INLINE_TERM __attribute__((always_inline, flatten))
#else
#define HALFSPACE_INLINE_TERM
#endif

// The fixed-block reduction behind sums and sums_and_range: block b folds its
// indices in order into a copy of `identity` with add(acc, i), and the block
// results are merged in block order with merge(total, part), so the result
// does not depend on the number of threads.
template <class Acc, class Add, class Merge>
Acc reduce_in_blocks(std::size_t n, const Acc& identity, Add&& add, Merge&& merge) {
  std::array<Acc, kReductionBlocks> partial;
  partial.fill(identity);
  const std::size_t block = (n + kReductionBlocks - 1) / kReductionBlocks;
  const auto blocks = static_cast<std::ptrdiff_t>(kReductionBlocks);
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
  for (std::ptrdiff_t b = 0; b < blocks; ++b) {
    const std::size_t begin = std::min(n, static_cast<std::size_t>(b) * block);
    const std::size_t end = std::min(n, begin + block);
    // Four interleaved accumulators: independent chains of additions keep
    // the adder busy instead of waiting on each sum's latency.
    Acc lanes[4] = {identity, identity, identity, identity};
    std::size_t i = begin;
    for (; i + 4 <= end; i += 4) {
      add(lanes[0], i);
      add(lanes[1], i + 1);
      add(lanes[2], i + 2);
      add(lanes[3], i + 3);
    }
    for (; i < end; ++i) add(lanes[0], i);
    merge(lanes[0], lanes[1]);
    merge(lanes[2], lanes[3]);
    merge(lanes[0], lanes[2]);
    partial[static_cast<std::size_t>(b)] = lanes[0];
  }
  Acc total = identity;
  for (const Acc& part : partial) merge(total, part);
  return total;
}

// Sums K terms at once: term(i) returns std::array<double, K>; the result is
// the component-wise sum over i in [0, n), reduced over the processes of comm.
template <std::size_t K, class Term>
std::array<double, K> sums(const Communicator& comm, std::size_t n, Term&& term) {
  const auto add_to = [](std::array<double, K>& acc, const std::array<double, K>& t) {
    for (std::size_t k = 0; k < K; ++k) acc[k] += t[k];
  };
  const std::array<double, K> total = reduce_in_blocks(
      n, std::array<double, K>{},
      [&](std::array<double, K>& acc, std::size_t i) HALFSPACE_INLINE_TERM { add_to(acc, term(i)); }, add_to);
  return global_sum(comm, total);
}
template <std::size_t K, class Term>
std::array<double, K> sums(std::size_t n, Term&& term) {
  return sums<K>(serial_communicator(), n, std::forward<Term>(term));
}

// sums<K> and the range of one more value, in one pass: term(i) returns
// std::pair<std::array<double, K>, double>.
template <std::size_t K>
struct SumsAndRange {
  std::array<double, K> sums{};
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();

  void add(const std::array<double, K>& terms, double low, double high) {
    for (std::size_t k = 0; k < K; ++k) sums[k] += terms[k];
    min = std::min(min, low);
    max = std::max(max, high);
  }
};

template <std::size_t K, class Term>
SumsAndRange<K> sums_and_range(const Communicator& comm, std::size_t n, Term&& term) {
  SumsAndRange<K> total = reduce_in_blocks(
      n, SumsAndRange<K>{},
      [&](SumsAndRange<K>& acc, std::size_t i) HALFSPACE_INLINE_TERM {
        const auto [t, value] = term(i);
        acc.add(t, value, value);
      },
      [](SumsAndRange<K>& acc, const SumsAndRange<K>& part) { acc.add(part.sums, part.min, part.max); });
  total.sums = global_sum(comm, total.sums);
  total.min = global_min(comm, total.min);
  total.max = global_max(comm, total.max);
  return total;
}
template <std::size_t K, class Term>
SumsAndRange<K> sums_and_range(std::size_t n, Term&& term) {
  return sums_and_range<K>(serial_communicator(), n, std::forward<Term>(term));
}

// Sum of term(i) over i in [0, n), reduced over the processes of comm.
template <class Term>
double sum(const Communicator& comm, std::size_t n, Term&& term) {
  return sums<1>(comm, n, [&](std::size_t i) { return std::array<double, 1>{term(i)}; })[0];
}
template <class Term>
double sum(std::size_t n, Term&& term) {
  return sum(serial_communicator(), n, std::forward<Term>(term));
}

// Maximum of value(i) over i in [0, n) and the processes of comm (-infinity
// when there are no cells).
template <class Value>
double max_of(const Communicator& comm, std::size_t n, Value&& value) {
  double result = -std::numeric_limits<double>::infinity();
  const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static) reduction(max : result) if (n > kParallelThreshold)
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    result = std::max(result, value(static_cast<std::size_t>(i)));
  }
  return global_max(comm, result);
}
template <class Value>
double max_of(std::size_t n, Value&& value) {
  return max_of(serial_communicator(), n, std::forward<Value>(value));
}

// Minimum of value(i) over i in [0, n) and the processes of comm (+infinity
// when there are no cells).
template <class Value>
double min_of(const Communicator& comm, std::size_t n, Value&& value) {
  double result = std::numeric_limits<double>::infinity();
  const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static) reduction(min : result) if (n > kParallelThreshold)
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    result = std::min(result, value(static_cast<std::size_t>(i)));
  }
  return global_min(comm, result);
}
template <class Value>
double min_of(std::size_t n, Value&& value) {
  return min_of(serial_communicator(), n, std::forward<Value>(value));
}

}  // namespace halfspace::linalg
