// A real multiplier on a spectrum that is even in the row wavenumber ky, as
// every half-space kernel and preconditioner symbol is (they depend on |q|).
// The spectrum is laid out as rows x cols entries, ky being the row (a
// RealFft's, row-major) or, transposed, the column (a slab transform's
// columns kx, each holding every ky). Entries ky and n - ky carry the same
// value, so only ky = 0 .. n/2 are stored: half the memory of a full
// symbol, and half the symbol traffic of each multiplication.
#pragma once

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

#include "halfspace/fft/real_fft.hpp"

namespace halfspace::fft {

class EvenSymbol {
 public:
  // For a spectrum of `rows` rows of `cols` (complex) entries, ky along
  // the columns if `transposed`; all zero.
  EvenSymbol(std::size_t rows, std::size_t cols, bool transposed = false)
      : rows_(rows), cols_(cols), transposed_(transposed), values_(stored_rows() * stored_cols(), 0.0) {}

  std::size_t rows() const { return rows_; }
  std::size_t cols() const { return cols_; }
  bool transposed() const { return transposed_; }
  // The stored rows and columns: ky = 0 .. n/2 of n along the folded axis.
  std::size_t stored_rows() const { return transposed_ ? rows_ : half(rows_); }
  std::size_t stored_cols() const { return transposed_ ? half(cols_) : cols_; }
  double& at(std::size_t stored_row, std::size_t stored_col) {
    return values_[stored_row * stored_cols() + stored_col];
  }
  double at(std::size_t stored_row, std::size_t stored_col) const {
    return values_[stored_row * stored_cols() + stored_col];
  }
  // The value at spectrum entry (row, col).
  double value(std::size_t row, std::size_t col) const {
    return transposed_ ? at(row, folded(col)) : at(folded(row), col);
  }
  // Every stored value (row-major), e.g. to map them one by one.
  std::span<double> stored() { return values_; }
  std::span<const double> stored() const { return values_; }
  // The stored row (column, transposed) that spectrum row (column) k uses:
  // k <= n/2 itself, else n - k.
  std::size_t folded(std::size_t k) const {
    const std::size_t n = transposed_ ? cols_ : rows_;
    return k < half(n) ? k : n - k;
  }
  // run(k, j, sign) for the entries k of spectrum row r (cols() each): j
  // the stored value it uses, sign -1 where ky is mirrored (n - ky: an odd
  // part's value is there the stored one's negative), else +1. The one walk
  // of the folded layout, for the multipliers here and the tangential ones.
  template <class Run>
  void for_each_entry(std::size_t r, Run&& run) const {
    const std::size_t begin = r * cols_;
    if (!transposed_) {
      const std::size_t stored = folded(r);
      const double sign = stored == r ? 1.0 : -1.0;
      for (std::size_t c = 0; c < cols_; ++c) run(begin + c, stored * cols_ + c, sign);
      return;
    }
    const std::size_t stored = stored_cols();
    for (std::size_t c = 0; c < stored; ++c) run(begin + c, r * stored + c, 1.0);
    for (std::size_t c = stored; c < cols_; ++c) run(begin + c, r * stored + cols_ - c, -1.0);
  }

  // spectrum[r, c] *= symbol[r, c], in parallel over rows (or over the
  // entries of a single row, not transposed).
  void multiply(std::span<std::complex<double>> spectrum) const;
  // The same on spectrum rows [first, first + count) alone, on this
  // thread (the products that multiply a few kx columns at a time).
  void multiply(std::span<std::complex<double>> spectrum, std::size_t first, std::size_t count) const;
  // out = the multiplier applied to `in` through `fft` (of this symbol's
  // shape): the forward transform, multiply(), the backward one, each array
  // transformed directly where FFTW allows it, else copied through the
  // transform's buffers. `in` is read before `out` is written, so the two
  // may be the same array. Allocates nothing.
  void apply(RealFft& fft, std::span<const double> in, std::span<double> out) const;
  // The same through a single-precision transform: `in` rounded to float
  // on the way in, the result widened on the way out (the inner products of
  // a mixed-precision solve; relative error about 1e-7 of the product).
  void multiply(std::span<std::complex<float>> spectrum) const;
  void apply(SingleRealFft& fft, std::span<const double> in, std::span<double> out) const;
  // And on single-precision arrays, transformed directly where FFTW allows
  // it (mixed precision's work vectors).
  void apply(SingleRealFft& fft, std::span<const float> in, std::span<float> out) const;

  // The inverse multiplier numerator / symbol[r, c], at_zero at r = c = 0
  // (the mean mode, where a kernel's symbol may vanish; a slab's first
  // entry need not be that mode), made entry by entry as it is applied: a
  // symbol's inverse without storing it (the Fourier preconditioner on the
  // operator's kernel). The same forms as multiply and apply.
  struct Inverse {
    double numerator = 1.0;
    double at_zero = 0.0;
  };
  void divide(const Inverse& inverse, std::span<std::complex<double>> spectrum) const;
  void divide(const Inverse& inverse, std::span<std::complex<double>> spectrum, std::size_t first,
              std::size_t count) const;
  void apply_inverse(const Inverse& inverse, SingleRealFft& fft, std::span<const double> in,
                     std::span<double> out) const;
  void apply_inverse(const Inverse& inverse, SingleRealFft& fft, std::span<const float> in, std::span<float> out) const;

 private:
  static std::size_t half(std::size_t n) { return n / 2 + 1 < n ? n / 2 + 1 : n; }

  std::size_t rows_;
  std::size_t cols_;
  bool transposed_;
  std::vector<double> values_;
};

}  // namespace halfspace::fft

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using fft::EvenSymbol;
}  // namespace halfspace
