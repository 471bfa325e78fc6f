#include "halfspace/fft/even_symbol.hpp"

#include <cassert>
#include <type_traits>

#include "halfspace/fft/real_fft.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::fft {

namespace {

// spectrum[r, c] *= factor(symbol[r, c]) on spectrum rows [first, first +
// count), serially, for either precision of the spectrum (the symbol stays
// double; a float spectrum is multiplied by the rounded factor); entry 0
// by `at_zero` if given and held here (what the factor made of it there,
// perhaps 1/0, is replaced).
template <class Real, class Factor>
void scale_rows(const EvenSymbol& symbol, const std::vector<double>& values, std::span<std::complex<Real>> spectrum,
                std::size_t first, std::size_t count, Factor&& factor, const double* at_zero) {
  assert(spectrum.size() == symbol.rows() * symbol.cols() && first + count <= symbol.rows());
  if (count == 0 || symbol.cols() == 0) return;
  const std::complex<Real> entry0 = spectrum[0];
  const double* value = values.data();
  for (std::size_t r = first; r < first + count; ++r) {
    symbol.for_each_entry(
        r, [&](std::size_t k, std::size_t j, double) { spectrum[k] *= static_cast<Real>(factor(value[j])); });
  }
  if (at_zero && first == 0) spectrum[0] = entry0 * static_cast<Real>(*at_zero);
}

// The same on the whole spectrum, in parallel over rows (or over the
// entries of a single row, not transposed).
template <class Real, class Factor>
void scale_spectrum(const EvenSymbol& symbol, const std::vector<double>& values, std::span<std::complex<Real>> spectrum,
                    Factor&& factor, const double* at_zero) {
  const std::size_t rows = symbol.rows();
  const std::size_t cols = symbol.cols();
  assert(spectrum.size() == rows * cols);
  if (rows == 0 || cols == 0) return;
  if (rows > 1 || symbol.transposed()) {
    linalg::for_each_row(rows, cols, [&](std::size_t r) {
      scale_rows(symbol, values, spectrum, r, 1, factor, r == 0 ? at_zero : nullptr);
    });
    return;
  }
  const std::complex<Real> entry0 = spectrum[0];
  const double* value = values.data();
  linalg::for_each_index(cols, [&](std::size_t k) { spectrum[k] *= static_cast<Real>(factor(value[k])); });
  if (at_zero) spectrum[0] = entry0 * static_cast<Real>(*at_zero);
}

const auto kIdentity = [](double value) { return value; };

// The factor numerator / value of EvenSymbol::Inverse.
struct Reciprocal {
  double numerator;
  double operator()(double value) const { return numerator / value; }
};

// out = in through `fft` with the spectrum scaled (scale_rows), in the
// transform's own precision or, for a float transform, from and to double
// fields (rounded on the way in, widened on the way out). A few kx columns
// at a time where the transform and the arrays allow it (as
// transform_by_columns), else through the whole spectrum, the fields
// passing straight through the transform's arrays where FFTW allows it,
// else through copies.
template <class Real, class Value, class Factor>
void apply_scaled(const EvenSymbol& symbol, const std::vector<double>& values, BasicRealFft<Real>& fft,
                  std::span<const Value> in, std::span<Value> out, Factor&& factor, const double* at_zero) {
  assert(fft.spectrum_blocks() == symbol.rows() && fft.spectrum_length() == symbol.cols() &&
         fft.transposed() == symbol.transposed());
  const std::span<std::complex<Real>> spectrum = fft.spectrum();
  constexpr bool kSame = std::is_same_v<Real, Value>;
  bool fused = false;
  if constexpr (kSame) {
    fused = fft.columns_in_parts() && fft.takes_input(in) && fft.takes_output(out);
  } else {
    fused = fft.takes_double_rows();
  }
  if (fused) {
    transform_by_columns(fft, in, out, [&](std::size_t first, std::size_t count) {
      scale_rows(symbol, values, spectrum, first, count, factor, at_zero);
    });
    return;
  }
  const auto straight_in = [&] {
    if constexpr (kSame) return fft.forward_from(in);
    return false;
  };
  const auto straight_out = [&] {
    if constexpr (kSame) return fft.backward_into(out);
    return false;
  };
  if (!straight_in()) {
    std::span<Real> input = fft.input();
    linalg::for_each_index(in.size(), [&](std::size_t i) { input[i] = static_cast<Real>(in[i]); });
    fft.forward();
  }
  scale_spectrum(symbol, values, spectrum, factor, at_zero);
  if (!straight_out()) {
    fft.backward();
    std::span<const Real> output = fft.output();
    linalg::for_each_index(out.size(), [&](std::size_t i) { out[i] = output[i]; });
  }
}

}  // namespace

void EvenSymbol::multiply(std::span<std::complex<double>> spectrum) const {
  scale_spectrum(*this, values_, spectrum, kIdentity, nullptr);
}

void EvenSymbol::multiply(std::span<std::complex<double>> spectrum, std::size_t first, std::size_t count) const {
  scale_rows(*this, values_, spectrum, first, count, kIdentity, nullptr);
}

void EvenSymbol::multiply(std::span<std::complex<float>> spectrum) const {
  scale_spectrum(*this, values_, spectrum, kIdentity, nullptr);
}

void EvenSymbol::apply(RealFft& fft, std::span<const double> in, std::span<double> out) const {
  apply_scaled(*this, values_, fft, in, out, kIdentity, nullptr);
}

void EvenSymbol::apply(SingleRealFft& fft, std::span<const double> in, std::span<double> out) const {
  apply_scaled(*this, values_, fft, in, out, kIdentity, nullptr);
}

void EvenSymbol::apply(SingleRealFft& fft, std::span<const float> in, std::span<float> out) const {
  apply_scaled(*this, values_, fft, in, out, kIdentity, nullptr);
}

void EvenSymbol::divide(const Inverse& inverse, std::span<std::complex<double>> spectrum) const {
  scale_spectrum(*this, values_, spectrum, Reciprocal{inverse.numerator}, &inverse.at_zero);
}

void EvenSymbol::divide(const Inverse& inverse, std::span<std::complex<double>> spectrum, std::size_t first,
                        std::size_t count) const {
  scale_rows(*this, values_, spectrum, first, count, Reciprocal{inverse.numerator}, &inverse.at_zero);
}

void EvenSymbol::apply_inverse(const Inverse& inverse, SingleRealFft& fft, std::span<const double> in,
                               std::span<double> out) const {
  apply_scaled(*this, values_, fft, in, out, Reciprocal{inverse.numerator}, &inverse.at_zero);
}

void EvenSymbol::apply_inverse(const Inverse& inverse, SingleRealFft& fft, std::span<const float> in,
                               std::span<float> out) const {
  apply_scaled(*this, values_, fft, in, out, Reciprocal{inverse.numerator}, &inverse.at_zero);
}

}  // namespace halfspace::fft
