// The serial spectral transforms (the grid's own transforms on periodic
// grids, the pruned padded ones of the DC-FFT on free grids, Liu, Wang & Liu
// 2000) and what every operator on the transforms shares: a symbol laid out
// on the entries held here, and its product.
#include "halfspace/operators/spectral_transforms.hpp"

#include <complex>
#include <stdexcept>
#include <utility>

#include "halfspace/fft/grid_transform.hpp"
#include "halfspace/fft/padded_real_fft.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::operators {
namespace {

// The grid's own transform per component on periodic grids (shared with
// nothing), the pruned padded one on free grids.
class SerialSpectralTransforms final : public SpectralTransforms {
 public:
  SerialSpectralTransforms(const Grid& grid, FftPlanning planning) : size_(grid.size()) {
    if (grid.periodic()) {
      for (auto& t : periodic_) t = make_grid_transform(grid, planning);
    } else {
      for (auto& t : padded_)
        t = std::make_unique<PaddedRealFft>(grid.dimension() == 1 ? 1 : grid.ny(), grid.nx(), planning);
    }
  }

  std::size_t local_size() const override { return size_; }
  const linalg::Communicator& communicator() const override { return linalg::serial_communicator(); }
  std::size_t spectrum_blocks() const override { return spectrum_rows(); }
  std::size_t spectrum_length() const override {
    return padded_[0] ? padded_[0]->spectrum_cols() : periodic_[0]->spectrum_cols();
  }
  SpectrumMode mode(std::size_t k) const override { return {k / spectrum_length(), k % spectrum_length()}; }
  std::size_t spectrum_rows() const override { return padded_[0] ? padded_[0]->spectrum_rows() : periodic_[0]->rows(); }
  double transform_size() const override {
    return padded_[0] ? static_cast<double>(padded_[0]->padded_size()) : static_cast<double>(size_);
  }

  std::span<std::complex<double>> forward(int k, std::span<const double> values) override {
    if (padded_[0]) {
      padded_[k]->forward(values);
      return padded_[k]->spectrum();
    }
    RealFft& fft = *periodic_[k];
    if (!fft.forward_from(values)) {
      std::span<double> input = fft.input();
      linalg::for_each_index(values.size(), [&](std::size_t i) { input[i] = values[i]; });
      fft.forward();
    }
    return fft.spectrum();
  }

  std::span<std::complex<double>> spectrum(int k) override {
    return padded_[0] ? padded_[k]->spectrum() : periodic_[k]->spectrum();
  }

  void backward(int k, std::span<double> values) override {
    if (padded_[0]) {
      padded_[k]->backward(values);
      return;
    }
    RealFft& fft = *periodic_[k];
    if (!fft.backward_into(values)) {
      fft.backward();
      std::span<const double> output = fft.output();
      linalg::for_each_index(values.size(), [&](std::size_t i) { values[i] = output[i]; });
    }
  }

  std::span<std::complex<double>> workspace() override { return spectrum(0); }

  // Row by row, in parallel, straight into the padded rows.
  std::span<const std::complex<double>> transform_wraparound_rows(const WraparoundRows& fill) override {
    PaddedRealFft& fft = *padded_[0];
    linalg::for_each_row(fft.spectrum_rows(), 2 * fft.spectrum_cols(),
                         [&](std::size_t r) { fill(r, 1, fft.padded_row(r)); });
    fft.forward_all_rows();
    return fft.spectrum();
  }

  // The serial FftInfluenceOperator forms its padded grid on a transform of
  // the whole padded grid instead (its symbols rows folded).
  std::unique_ptr<CirculantForm> padded_form(std::vector<double> /*kernel*/,
                                             std::vector<double> /*stiffness*/) override {
    throw std::logic_error("the serial transforms make no padded circulant form");
  }

 private:
  std::size_t size_;
  std::shared_ptr<RealFft> periodic_[2];      // periodic grids: one transform per component
  std::unique_ptr<PaddedRealFft> padded_[2];  // free grids
};

}  // namespace

std::span<const std::complex<double>> SpectralTransforms::transform_wraparound(
    const std::function<double(std::size_t row, std::size_t col)>& value) {
  return transform_wraparound_rows([&](std::size_t first, std::size_t rows, std::span<double> values) {
    const std::size_t width = values.size() / rows;
    linalg::for_each_row(rows, width, [&](std::size_t i) {
      for (std::size_t c = 0; c < width; ++c) values[i * width + c] = value(first + i, c);
    });
  });
}

std::unique_ptr<SpectralTransforms> make_serial_transforms(const Grid& grid, FftPlanning planning) {
  return std::make_unique<SerialSpectralTransforms>(grid, planning);
}

std::vector<double> held_values(const SpectralTransforms& transforms, const std::function<double(SpectrumMode)>& f) {
  std::vector<double> values(transforms.held());
  const std::size_t length = transforms.spectrum_length();
  linalg::for_each_row(transforms.spectrum_blocks(), length, [&](std::size_t block) {
    for (std::size_t k = block * length; k < (block + 1) * length; ++k) values[k] = f(transforms.mode(k));
  });
  return values;
}

void apply_symbol(SpectralTransforms& transforms, int k, const std::vector<double>& symbol, std::span<const double> in,
                  std::span<double> out) {
  const std::span<std::complex<double>> spectrum = transforms.forward(k, in);
  const std::size_t length = transforms.spectrum_length();
  const double* s = symbol.data();
  linalg::for_each_row(transforms.spectrum_blocks(), length, [&](std::size_t block) {
    for (std::size_t i = block * length; i < (block + 1) * length; ++i) spectrum[i] *= s[i];
  });
  transforms.backward(k, out);
}

}  // namespace halfspace::operators
