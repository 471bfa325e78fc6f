#include "halfspace/fft/even_symbol.hpp"

#include <cassert>

#include "halfspace/fft/real_fft.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::fft {

namespace {

// spectrum[r, c] *= factor(symbol[r, c]) for either precision of the
// spectrum (the symbol stays double; a float spectrum is multiplied by the
// rounded factor), entry 0 by `first` if given (what the factor made of it
// there, perhaps 1/0, is replaced).
template <class Real, class Factor>
void scale_spectrum(const EvenSymbol& symbol, const std::vector<double>& values, std::span<std::complex<Real>> spectrum,
                    Factor&& factor, const double* first = nullptr) {
  const std::size_t rows = symbol.rows();
  const std::size_t cols = symbol.cols();
  assert(spectrum.size() == rows * cols);
  if (rows == 0 || cols == 0) return;
  const std::complex<Real> entry0 = spectrum[0];
  const double* value = values.data();
  if (rows == 1 && !symbol.transposed()) {
    linalg::for_each_index(cols, [&](std::size_t k) { spectrum[k] *= static_cast<Real>(factor(value[k])); });
  } else {
    linalg::for_each_row(rows, cols, [&](std::size_t r) {
      symbol.for_each_entry(
          r, [&](std::size_t k, std::size_t j, double) { spectrum[k] *= static_cast<Real>(factor(value[j])); });
    });
  }
  if (first) spectrum[0] = entry0 * static_cast<Real>(*first);
}

// The same on spectrum rows [first, first + count) alone, serially.
template <class Factor>
void scale_rows(const EvenSymbol& symbol, const std::vector<double>& values, std::span<std::complex<double>> spectrum,
                std::size_t first, std::size_t count, Factor&& factor, const double* at_zero = nullptr) {
  assert(spectrum.size() == symbol.rows() * symbol.cols() && first + count <= symbol.rows());
  if (count == 0 || symbol.cols() == 0) return;
  const std::complex<double> entry0 = spectrum[0];
  const double* value = values.data();
  for (std::size_t r = first; r < first + count; ++r) {
    symbol.for_each_entry(r, [&](std::size_t k, std::size_t j, double) { spectrum[k] *= factor(value[j]); });
  }
  if (at_zero && first == 0) spectrum[0] = entry0 * *at_zero;
}

template <class Real>
void multiply_spectrum(const EvenSymbol& symbol, const std::vector<double>& values,
                       std::span<std::complex<Real>> spectrum) {
  scale_spectrum(symbol, values, spectrum, [](double value) { return value; });
}

// spectrum[r, c] *= inverse.numerator / symbol[r, c], and inverse.at_zero
// at r = c = 0.
template <class Real>
void divide_spectrum(const EvenSymbol& symbol, const std::vector<double>& values, const EvenSymbol::Inverse& inverse,
                     std::span<std::complex<Real>> spectrum) {
  const double numerator = inverse.numerator;
  scale_spectrum(
      symbol, values, spectrum, [numerator](double value) { return numerator / value; }, &inverse.at_zero);
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

void EvenSymbol::multiply(std::span<std::complex<double>> spectrum, std::size_t first, std::size_t count) const {
  scale_rows(*this, values_, spectrum, first, count, [](double value) { return value; });
}

void EvenSymbol::apply(RealFft& fft, std::span<const double> in, std::span<double> out) const {
  assert(fft.spectrum_blocks() == rows_ && fft.spectrum_length() == cols_ && fft.transposed() == transposed_);
  apply_in_precision(fft, in, out, [this](auto spectrum) { multiply(spectrum); });
}

void EvenSymbol::apply(SingleRealFft& fft, std::span<const double> in, std::span<double> out) const {
  assert(fft.spectrum_blocks() == rows_ && fft.spectrum_length() == cols_ && fft.transposed() == transposed_);
  apply_widened(fft, in, out, [this](auto spectrum) { multiply(spectrum); });
}

void EvenSymbol::apply(SingleRealFft& fft, std::span<const float> in, std::span<float> out) const {
  assert(fft.spectrum_blocks() == rows_ && fft.spectrum_length() == cols_ && fft.transposed() == transposed_);
  apply_in_precision(fft, in, out, [this](auto spectrum) { multiply(spectrum); });
}

void EvenSymbol::divide(const Inverse& inverse, std::span<std::complex<double>> spectrum) const {
  divide_spectrum(*this, values_, inverse, spectrum);
}

void EvenSymbol::divide(const Inverse& inverse, std::span<std::complex<double>> spectrum, std::size_t first,
                        std::size_t count) const {
  const double numerator = inverse.numerator;
  scale_rows(
      *this, values_, spectrum, first, count, [numerator](double value) { return numerator / value; },
      &inverse.at_zero);
}

void EvenSymbol::apply_inverse(const Inverse& inverse, SingleRealFft& fft, std::span<const double> in,
                               std::span<double> out) const {
  assert(fft.spectrum_blocks() == rows_ && fft.spectrum_length() == cols_ && fft.transposed() == transposed_);
  apply_widened(fft, in, out, [&](auto spectrum) { divide_spectrum(*this, values_, inverse, spectrum); });
}

void EvenSymbol::apply_inverse(const Inverse& inverse, SingleRealFft& fft, std::span<const float> in,
                               std::span<float> out) const {
  assert(fft.spectrum_blocks() == rows_ && fft.spectrum_length() == cols_ && fft.transposed() == transposed_);
  apply_in_precision(fft, in, out, [&](auto spectrum) { divide_spectrum(*this, values_, inverse, spectrum); });
}

}  // namespace halfspace::fft
