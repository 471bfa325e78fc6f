#include "halfspace/fft/even_symbol.hpp"

#include <cassert>

#include "halfspace/fft/real_fft.hpp"
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

void EvenSymbol::apply(RealFft& fft, std::span<const double> in, std::span<double> out) const {
  assert(fft.rows() == rows_ && fft.spectrum_cols() == cols_);
  if (!fft.forward_from(in)) {
    std::span<double> input = fft.input();
    linalg::for_each_index(in.size(), [&](std::size_t i) { input[i] = in[i]; });
    fft.forward();
  }
  multiply(fft.spectrum());
  if (!fft.backward_into(out)) {
    fft.backward();
    std::span<const double> output = fft.output();
    linalg::for_each_index(out.size(), [&](std::size_t i) { out[i] = output[i]; });
  }
}

}  // namespace halfspace::fft
