// Products of sizes (cells, padded cells, byte counts) that may not fit in
// std::size_t. A grid of 2^32 x 2^32 cells has 2^64 of them: computed
// unchecked, that wraps to 0 and the arrays made from it are far too small.
#pragma once

#include <cstddef>
#include <limits>
#include <optional>

namespace halfspace {

// The most cells a grid may have (Grid::line and Grid::plane refuse more):
// every array a solve makes on it, the zero-padded complex spectrum of a
// free grid included (4 padded cells per cell, 16 bytes each), then has a
// byte count that fits in std::size_t.
inline constexpr std::size_t kMaxGridCells = std::numeric_limits<std::size_t>::max() / 64;

// a * b, or nothing if the product does not fit in std::size_t.
constexpr std::optional<std::size_t> checked_multiply(std::size_t a, std::size_t b) {
  std::size_t product = 0;
  if (__builtin_mul_overflow(a, b, &product)) return std::nullopt;
  return product;
}

// a + b, or nothing if the sum does not fit in std::size_t.
constexpr std::optional<std::size_t> checked_add(std::size_t a, std::size_t b) {
  std::size_t sum = 0;
  if (__builtin_add_overflow(a, b, &sum)) return std::nullopt;
  return sum;
}

}  // namespace halfspace
