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

// spectrum[r, c] *= inverse.numerator / symbol[r, c], and inverse.at_zero
// at r = c = 0.
template <class Real>
void divide_spectrum(const EvenSymbol& symbol, const std::vector<double>& values, const EvenSymbol::Inverse& inverse,
                     std::span<std::complex<Real>> spectrum) {
  const std::size_t rows = symbol.rows();
  const std::size_t cols = symbol.cols();
  assert(spectrum.size() == rows * cols);
  const double numerator = inverse.numerator;
  spectrum[0] *= static_cast<Real>(inverse.at_zero);
  if (rows == 1) {
    linalg::for_each_index(cols - 1,
                           [&](std::size_t k) { spectrum[k + 1] *= static_cast<Real>(numerator / values[k + 1]); });
    return;
  }
  linalg::for_each_row(rows, cols, [&](std::size_t r) {
    std::complex<Real>* row = spectrum.data() + r * cols;
    const double* factor = values.data() + symbol.folded(r) * cols;
    for (std::size_t c = r == 0 ? 1 : 0; c < cols; ++c) row[c] *= static_cast<Real>(numerator / factor[c]);
  });
}

// out = in through `fft` and `multiply` (of the spectrum) in the
// transform's own precision: the fields pass straight through the
// transform's arrays where it allows (forward_from, backward_into), else
// through copies.
template <class Fft, class Real, class Multiply>
void apply_in_precision(Fft& fft, std::span<const Real> in, std::span<Real> out, Multiply&& multiply) {
  if (!fft.forward_from(in)) {
    std::span<Real> input = fft.input();
    linalg::for_each_index(in.size(), [&](std::size_t i) { input[i] = in[i]; });
    fft.forward();
  }
  multiply(fft.spectrum());
  if (!fft.backward_into(out)) {
    fft.backward();
    std::span<const Real> output = fft.output();
    linalg::for_each_index(out.size(), [&](std::size_t i) { out[i] = output[i]; });
  }
}

// The same with double fields through a single-precision transform: `in`
// rounded to float on the way in, the result widened on the way out.
template <class Multiply>
void apply_widened(SingleRealFft& fft, std::span<const double> in, std::span<double> out, Multiply&& multiply) {
  std::span<float> input = fft.input();
  linalg::for_each_index(in.size(), [&](std::size_t i) { input[i] = static_cast<float>(in[i]); });
  fft.forward();
  multiply(fft.spectrum());
  fft.backward();
  std::span<const float> output = fft.output();
  linalg::for_each_index(out.size(), [&](std::size_t i) { out[i] = output[i]; });
}

}  // namespace

void EvenSymbol::multiply(std::span<std::complex<double>> spectrum) const {
  multiply_spectrum(*this, values_, spectrum);
}

void EvenSymbol::multiply(std::span<std::complex<float>> spectrum) const {
  multiply_spectrum(*this, values_, spectrum);
}

void EvenSymbol::apply(RealFft& fft, std::span<const double> in, std::span<double> out) const {
  assert(fft.rows() == rows_ && fft.spectrum_cols() == cols_);
  apply_in_precision(fft, in, out, [this](auto spectrum) { multiply(spectrum); });
}

void EvenSymbol::apply(SingleRealFft& fft, std::span<const double> in, std::span<double> out) const {
  assert(fft.rows() == rows_ && fft.spectrum_cols() == cols_);
  apply_widened(fft, in, out, [this](auto spectrum) { multiply(spectrum); });
}

void EvenSymbol::apply(SingleRealFft& fft, std::span<const float> in, std::span<float> out) const {
  assert(fft.rows() == rows_ && fft.spectrum_cols() == cols_);
  apply_in_precision(fft, in, out, [this](auto spectrum) { multiply(spectrum); });
}

void EvenSymbol::apply_inverse(const Inverse& inverse, RealFft& fft, std::span<const double> in,
                               std::span<double> out) const {
  assert(fft.rows() == rows_ && fft.spectrum_cols() == cols_);
  apply_in_precision(fft, in, out, [&](auto spectrum) { divide_spectrum(*this, values_, inverse, spectrum); });
}

void EvenSymbol::apply_inverse(const Inverse& inverse, SingleRealFft& fft, std::span<const double> in,
                               std::span<double> out) const {
  assert(fft.rows() == rows_ && fft.spectrum_cols() == cols_);
  apply_widened(fft, in, out, [&](auto spectrum) { divide_spectrum(*this, values_, inverse, spectrum); });
}

void EvenSymbol::apply_inverse(const Inverse& inverse, SingleRealFft& fft, std::span<const float> in,
                               std::span<float> out) const {
  assert(fft.rows() == rows_ && fft.spectrum_cols() == cols_);
  apply_in_precision(fft, in, out, [&](auto spectrum) { divide_spectrum(*this, values_, inverse, spectrum); });
}

}  // namespace halfspace::fft
