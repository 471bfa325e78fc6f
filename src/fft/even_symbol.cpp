#include "halfspace/fft/even_symbol.hpp"

#include <cassert>

#include "halfspace/linalg/parallel.hpp"

namespace halfspace::fft {

void EvenSymbol::multiply(std::span<std::complex<double>> spectrum) const {
  assert(spectrum.size() == rows_ * cols_);
  if (rows_ == 1) {
    linalg::for_each_index(cols_, [&](std::size_t c) { spectrum[c] *= values_[c]; });
    return;
  }
  linalg::for_each_row(rows_, cols_, [&](std::size_t r) {
    std::complex<double>* row = spectrum.data() + r * cols_;
    const double* symbol = values_.data() + folded(r) * cols_;
    for (std::size_t c = 0; c < cols_; ++c) row[c] *= symbol[c];
  });
}

}  // namespace halfspace::fft
