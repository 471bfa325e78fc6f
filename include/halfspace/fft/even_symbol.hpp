// A real multiplier on a RealFft spectrum that is even in the row
// wavenumber, as every half-space kernel and preconditioner symbol is
// (they depend on |q|). Rows r and rows - r carry the same values, so only
// rows 0 .. rows/2 are stored: half the memory of a full symbol, and half
// the symbol traffic of each multiplication.
#pragma once

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

#include "halfspace/fft/real_fft.hpp"

namespace halfspace::fft {

class EvenSymbol {
 public:
  // For a spectrum of `rows` rows of `cols` (complex) entries; all zero.
  EvenSymbol(std::size_t rows, std::size_t cols) : rows_(rows), cols_(cols), values_(stored_rows() * cols, 0.0) {}

  std::size_t rows() const { return rows_; }
  std::size_t cols() const { return cols_; }
  // Rows 0 .. rows/2; row r > rows/2 reads row rows - r.
  std::size_t stored_rows() const { return rows_ / 2 + 1 < rows_ ? rows_ / 2 + 1 : rows_; }
  double& at(std::size_t stored_row, std::size_t col) { return values_[stored_row * cols_ + col]; }
  double at(std::size_t stored_row, std::size_t col) const { return values_[stored_row * cols_ + col]; }
  // The stored row that spectrum row r uses.
  std::size_t folded(std::size_t row) const { return row < stored_rows() ? row : rows_ - row; }

  // spectrum[r, c] *= symbol[r, c], in parallel over rows (or over the
  // entries of a single row).
  void multiply(std::span<std::complex<double>> spectrum) const;
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
  // (where a kernel's symbol may vanish), made entry by entry as it is
  // applied: a symbol's inverse without storing it (the Fourier
  // preconditioner on the operator's kernel). The same three forms as apply.
  struct Inverse {
    double numerator = 1.0;
    double at_zero = 0.0;
  };
  void apply_inverse(const Inverse& inverse, RealFft& fft, std::span<const double> in, std::span<double> out) const;
  void apply_inverse(const Inverse& inverse, SingleRealFft& fft, std::span<const double> in,
                     std::span<double> out) const;
  void apply_inverse(const Inverse& inverse, SingleRealFft& fft, std::span<const float> in, std::span<float> out) const;

 private:
  std::size_t rows_;
  std::size_t cols_;
  std::vector<double> values_;
};

}  // namespace halfspace::fft

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using fft::EvenSymbol;
}  // namespace halfspace
