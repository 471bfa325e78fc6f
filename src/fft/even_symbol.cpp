#include "halfspace/fft/even_symbol.hpp"

#include <cassert>

#include "halfspace/fft/real_fft.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::fft {

namespace {

// spectrum[r, c] *= symbol[r, c] for either precision of the spectrum (the
// symbol stays double; a float spectrum is multiplied by its rounded value).
template <class Real>
void multiply_spectrum(const EvenSymbol& symbol, const std::vector<double>& values,
                       std::span<std::complex<Real>> spectrum) {
  const std::size_t rows = symbol.rows();
  const std::size_t cols = symbol.cols();
  assert(spectrum.size() == rows * cols);
  if (rows == 1) {
    linalg::for_each_index(cols, [&](std::size_t c) { spectrum[c] *= static_cast<Real>(values[c]); });
    return;
  }
  linalg::for_each_row(rows, cols, [&](std::size_t r) {
    std::complex<Real>* row = spectrum.data() + r * cols;
    const double* factor = values.data() + symbol.folded(r) * cols;
    for (std::size_t c = 0; c < cols; ++c) row[c] *= static_cast<Real>(factor[c]);
  });
}

// symbol.apply in the transform's own precision: the fields pass straight
// through the transform's arrays where it allows (forward_from,
// backward_into), else through copies.
template <class Fft, class Real>
void apply_in_precision(const EvenSymbol& symbol, Fft& fft, std::span<const Real> in, std::span<Real> out) {
  assert(fft.rows() == symbol.rows() && fft.spectrum_cols() == symbol.cols());
  if (!fft.forward_from(in)) {
    std::span<Real> input = fft.input();
    linalg::for_each_index(in.size(), [&](std::size_t i) { input[i] = in[i]; });
    fft.forward();
  }
  symbol.multiply(fft.spectrum());
  if (!fft.backward_into(out)) {
    fft.backward();
    std::span<const Real> output = fft.output();
    linalg::for_each_index(out.size(), [&](std::size_t i) { out[i] = output[i]; });
  }
}

}  // namespace

void EvenSymbol::multiply(std::span<std::complex<double>> spectrum) const {
  multiply_spectrum(*this, values_, spectrum);
}

void EvenSymbol::multiply(std::span<std::complex<float>> spectrum) const {
  multiply_spectrum(*this, values_, spectrum);
}

void EvenSymbol::apply(RealFft& fft, std::span<const double> in, std::span<double> out) const {
  apply_in_precision(*this, fft, in, out);
}

void EvenSymbol::apply(SingleRealFft& fft, std::span<const double> in, std::span<double> out) const {
  assert(fft.rows() == rows_ && fft.spectrum_cols() == cols_);
  std::span<float> input = fft.input();
  linalg::for_each_index(in.size(), [&](std::size_t i) { input[i] = static_cast<float>(in[i]); });
  fft.forward();
  multiply(fft.spectrum());
  fft.backward();
  std::span<const float> output = fft.output();
  linalg::for_each_index(out.size(), [&](std::size_t i) { out[i] = output[i]; });
}

void EvenSymbol::apply(SingleRealFft& fft, std::span<const float> in, std::span<float> out) const {
  apply_in_precision(*this, fft, in, out);
}

}  // namespace halfspace::fft
