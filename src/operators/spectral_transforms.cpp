// The serial spectral transforms (the grid's own transforms on periodic
// grids, the pruned padded ones of the DC-FFT on free grids, Liu, Wang & Liu
// 2000) and what every operator on the transforms shares: a symbol laid out
// on the entries held here, and its product.
#include "halfspace/operators/spectral_transforms.hpp"

#include <complex>
#include <stdexcept>
#include <utility>

#include "halfspace/fft/even_symbol.hpp"
#include "halfspace/fft/grid_transform.hpp"
#include "halfspace/fft/padded_real_fft.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::operators {
namespace {

// K and K^-1 as symbols on a transform of the whole padded grid of a free
// one (its padding carries values here).
class WholeGridForm final : public CirculantForm {
 public:
  WholeGridForm(std::unique_ptr<RealFft> fft, EvenSymbol kernel, EvenSymbol stiffness)
      : CirculantForm(true), fft_(std::move(fft)), kernel_(std::move(kernel)), stiffness_(std::move(stiffness)) {}
  std::size_t local_size() const override { return fft_->real_size(); }
  std::size_t size() const override { return fft_->real_size(); }
  std::size_t row_stride() const override { return fft_->real_size() / fft_->rows(); }
  void apply(std::span<const double> in, std::span<double> out) override { kernel_.apply(*fft_, in, out); }
  void apply_inverse(std::span<const double> in, std::span<double> out) override { stiffness_.apply(*fft_, in, out); }

 private:
  std::unique_ptr<RealFft> fft_;
  EvenSymbol kernel_;
  EvenSymbol stiffness_;
};

// The grid's own transforms (periodic, or unpadded; the first possibly in
// a workspace), or the pruned padded ones on free grids.
class SerialSpectralTransforms final : public SpectralTransforms {
 public:
  std::unique_ptr<SpectralTransforms> make_for(const Grid& grid, const TransformsShape& shape) const override {
    return make_serial_transforms(grid, FftPlanning::estimate, shape);
  }
  SerialSpectralTransforms(const Grid& grid, FftPlanning planning, const TransformsShape& shape)
      : grid_(grid), planning_(planning) {
    for (int k = 0; k < shape.count; ++k) {
      if (grid.periodic() || shape.unpadded) {
        own_[k] = k == 0 && !shape.workspace.empty() ? make_grid_transform(grid, planning, shape.workspace)
                                                     : make_grid_transform(grid, planning);
      } else {
        padded_[k] = std::make_unique<PaddedRealFft>(grid.dimension() == 1 ? 1 : grid.ny(), grid.nx(), planning);
      }
    }
  }

  std::size_t local_size() const override { return grid_.size(); }
  const linalg::Communicator& communicator() const override { return linalg::serial_communicator(); }
  std::size_t spectrum_blocks() const override {
    return padded_[0] ? padded_[0]->spectrum_blocks() : own_[0]->spectrum_blocks();
  }
  std::size_t spectrum_length() const override {
    return padded_[0] ? padded_[0]->spectrum_length() : own_[0]->spectrum_length();
  }
  SpectrumMode mode(std::size_t k) const override {
    const std::size_t block = k / spectrum_length();
    const std::size_t entry = k % spectrum_length();
    return transposed() ? SpectrumMode{entry, block} : SpectrumMode{block, entry};
  }
  // 2D transforms are transposed (grid_transform.hpp, padded_real_fft.hpp).
  bool transposed() const override { return padded_[0] ? padded_[0]->transposed() : own_[0]->transposed(); }
  std::size_t spectrum_rows() const override { return padded_[0] ? padded_[0]->spectrum_rows() : own_[0]->rows(); }
  double transform_size() const override {
    return static_cast<double>(padded_[0] ? padded_[0]->padded_size() : grid_.size());
  }

  // The grid's own transform reads and writes the caller's arrays directly
  // where FFTW allows it, else copies through its own buffers.
  std::span<std::complex<double>> forward(int k, std::span<const double> values) override {
    if (padded_[0]) {
      padded_[k]->forward(values);
      return padded_[k]->spectrum();
    }
    RealFft& fft = *own_[k];
    if (!fft.forward_from(values)) {
      std::span<double> input = fft.input();
      linalg::for_each_index(values.size(), [&](std::size_t i) { input[i] = values[i]; });
      fft.forward();
    }
    return fft.spectrum();
  }

  std::span<std::complex<double>> spectrum(int k) override {
    return padded_[0] ? padded_[k]->spectrum() : own_[k]->spectrum();
  }

  void backward(int k, std::span<double> values) override {
    if (padded_[0]) {
      padded_[k]->backward(values);
      return;
    }
    RealFft& fft = *own_[k];
    if (!fft.backward_into(values)) {
      fft.backward();
      std::span<const double> output = fft.output();
      linalg::for_each_index(values.size(), [&](std::size_t i) { values[i] = output[i]; });
    }
  }

  std::span<std::complex<double>> workspace() override { return spectrum(0); }

  void apply_pair(std::span<const double> in_0, std::span<const double> in_1, std::span<double> out_0,
                  std::span<double> out_1, const BlockMultiply& multiply) override {
    if (padded_[0] || !own_[1] || !own_[0]->columns_in_parts() || !own_[1]->columns_in_parts() ||
        !own_[0]->takes_input(in_0) || !own_[1]->takes_input(in_1) || !own_[0]->takes_output(out_0) ||
        !own_[1]->takes_output(out_1)) {
      SpectralTransforms::apply_pair(in_0, in_1, out_0, out_1, multiply);
      return;
    }
    fft::transform_pair_by_columns(*own_[0], *own_[1], in_0, in_1, out_0, out_1, multiply);
  }

  void apply_by_blocks(int k, std::span<const double> in, std::span<double> out,
                       const BlockMultiply& multiply) override {
    if (padded_[0] || !own_[k]->columns_in_parts() || !own_[k]->takes_input(in) || !own_[k]->takes_output(out)) {
      SpectralTransforms::apply_by_blocks(k, in, out, multiply);
      return;
    }
    fft::transform_by_columns(*own_[k], in, out, multiply);
  }

  // Straight into the padded transform's rows, a block at a time.
  std::span<const std::complex<double>> transform_wraparound_rows(const WraparoundRows& fill) override {
    PaddedRealFft& fft = *padded_[0];
    fft.forward_rows(fill);
    return fft.spectrum();
  }

  // A transform of the whole padded grid of its own (the pruned ones never
  // hold the padding), in their layout, so that the symbols on them serve
  // it.
  std::span<const std::complex<double>> transform_form_wraparound(const WraparoundRows& fill) override {
    if (!padded_[0]) throw std::logic_error("a periodic grid's circulant form is the grid itself");
    const std::size_t width = 2 * grid_.nx();
    whole_ = grid_.dimension() == 1 ? std::make_unique<RealFft>(width, planning_)
                                    : std::make_unique<RealFft>(2 * grid_.ny(), width, planning_, FftOutput::separate,
                                                                FftLayout::transposed);
    fill(0, padded_[0]->spectrum_rows(), [&](std::size_t r) { return whole_->input().subspan(r * width, width); });
    whole_->forward();
    return whole_->spectrum();
  }

  std::unique_ptr<CirculantForm> padded_form(EvenSymbol kernel, EvenSymbol stiffness) override {
    if (!whole_) throw std::logic_error("padded_form: transform_form_wraparound first");
    return std::make_unique<WholeGridForm>(std::move(whole_), std::move(kernel), std::move(stiffness));
  }

 private:
  Grid grid_;
  FftPlanning planning_;
  std::shared_ptr<RealFft> own_[2];           // the grid's own transforms
  std::unique_ptr<PaddedRealFft> padded_[2];  // or the padded ones (free grids)
  std::unique_ptr<RealFft> whole_;            // the whole padded grid's, until padded_form takes it
};

}  // namespace

std::span<const std::complex<double>> SpectralTransforms::transform_wraparound(
    const std::function<double(std::size_t row, std::size_t col)>& value) {
  return transform_wraparound_rows([&](std::size_t first, std::size_t rows, const Row& row) {
    linalg::for_each_row(rows, 2 * spectrum_length(), [&](std::size_t i) {
      const std::span<double> values = row(i);
      for (std::size_t c = 0; c < values.size(); ++c) values[c] = value(first + i, c);
    });
  });
}

void SpectralTransforms::apply_pair(std::span<const double> in_0, std::span<const double> in_1, std::span<double> out_0,
                                    std::span<double> out_1, const BlockMultiply& multiply) {
  forward(0, in_0);
  forward(1, in_1);
  linalg::for_each_row(spectrum_blocks(), spectrum_length(), [&](std::size_t block) { multiply(block, 1); });
  backward(0, out_0);
  backward(1, out_1);
}

void SpectralTransforms::apply_by_blocks(int k, std::span<const double> in, std::span<double> out,
                                         const BlockMultiply& multiply) {
  forward(k, in);
  linalg::for_each_row(spectrum_blocks(), spectrum_length(), [&](std::size_t block) { multiply(block, 1); });
  backward(k, out);
}

std::unique_ptr<SpectralTransforms> make_serial_transforms(const Grid& grid, FftPlanning planning,
                                                           const TransformsShape& shape) {
  if (shape.count < 1 || shape.count > 2) throw std::logic_error("spectral transforms: count must be 1 or 2");
  return std::make_unique<SerialSpectralTransforms>(grid, planning, shape);
}

void apply_symbol(SpectralTransforms& transforms, int k, const EvenSymbol& symbol, std::span<const double> in,
                  std::span<double> out) {
  const std::span<std::complex<double>> spectrum = transforms.spectrum(k);
  transforms.apply_by_blocks(k, in, out,
                             [&](std::size_t first, std::size_t count) { symbol.multiply(spectrum, first, count); });
}

EvenSymbol held_symbol(const SpectralTransforms& transforms,
                       const std::function<double(std::size_t k, SpectrumMode mode)>& f) {
  EvenSymbol symbol(transforms.spectrum_blocks(), transforms.spectrum_length(), transforms.transposed());
  const std::size_t length = transforms.spectrum_length();
  linalg::for_each_row(symbol.stored_rows(), symbol.stored_cols(), [&](std::size_t r) {
    for (std::size_t c = 0; c < symbol.stored_cols(); ++c) {
      const std::size_t k = r * length + c;
      symbol.at(r, c) = f(k, transforms.mode(k));
    }
  });
  return symbol;
}

}  // namespace halfspace::operators
