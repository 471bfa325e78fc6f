// The slab spectral transforms. A free grid's kernel coefficients fill the
// whole (2ny, 2nx) wrap-around grid, whose padding rows the slab transform
// never holds (slab_padded_fft.hpp); its DFT is the sum of the padded DFTs
// of its four (ny, nx) quadrants Q_ab (a, b in {0, 1}, offset by a ny rows
// and b nx columns), each shifted:
//   W(ky, kx) = sum_ab (-1)^(a ky + b kx) F[Q_ab](ky, kx),
// so each process evaluates only its rows of each quadrant.
//
// The padded circulant form (the adhesive energy's grid) is the whole
// (2ny, 2nx) wrap-around grid, its padding rows ny + j held by the process
// holding row j: each half is transformed as a top half by the pruned
// transform, and a shift by ny rows multiplies the spectrum by (-1)^ky, so
// the whole spectrum is A + (-1)^ky B, and the bottom half of an inverse is
// the top half of the inverse of (-1)^ky times the spectrum.
#include "halfspace/mpi/slab_spectral_transforms.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <complex>
#include <memory>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/fft/even_symbol.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/mpi/slab_padded_fft.hpp"

namespace halfspace::mpi {
namespace {

using operators::SpectrumMode;

// The spectrum held here: this process's columns kx from `first_column`,
// each `length` rows ky long ([c * length + r]).
struct Columns {
  std::size_t first_column = 0;
  std::size_t columns = 0;
  std::size_t length = 0;

  SpectrumMode mode(std::size_t k) const { return {k % length, first_column + k / length}; }
};

// What both kinds share: `count` transforms of the grid's slab (`Fft`,
// periodic or padded), their spectra held as columns `length` rows long.
template <class Fft>
class SlabTransforms : public operators::SpectralTransforms {
 public:
  SlabTransforms(const Grid& grid, const MpiCommunicator& comm, FftPlanning planning,
                 const operators::TransformsShape& shape, std::size_t length)
      : comm_(comm), planning_(planning) {
    for (int k = 0; k < shape.count; ++k) {
      if constexpr (std::is_same_v<Fft, SlabRealFft>) {
        fft_[k] = std::make_unique<Fft>(grid.nx(), grid.ny(), comm, planning,
                                        k == 0 ? shape.workspace : std::span<std::complex<double>>{});
      } else {
        fft_[k] = std::make_unique<Fft>(grid.nx(), grid.ny(), comm, planning);
      }
    }
    held_ = {fft_[0]->layout().first_column, fft_[0]->layout().columns, length};
  }

  const linalg::Communicator& communicator() const override { return comm_; }
  std::unique_ptr<operators::SpectralTransforms> make_for(const Grid& grid,
                                                          const operators::TransformsShape& shape) const override {
    return make_slab_transforms(grid, comm_, FftPlanning::estimate, shape);
  }
  std::size_t spectrum_blocks() const override { return held_.columns; }
  std::size_t spectrum_length() const override { return held_.length; }
  SpectrumMode mode(std::size_t k) const override { return held_.mode(k); }
  bool transposed() const override { return true; }
  std::size_t spectrum_rows() const override { return held_.length; }
  std::span<std::complex<double>> forward(int k, std::span<const double> values) override {
    fft_[k]->forward(values);
    return fft_[k]->spectrum();
  }
  std::span<std::complex<double>> spectrum(int k) override { return fft_[k]->spectrum(); }
  void backward(int k, std::span<double> values) override { fft_[k]->backward(values); }

 protected:
  const MpiCommunicator& comm_;
  FftPlanning planning_;
  std::unique_ptr<Fft> fft_[2];
  Columns held_;
};

class PeriodicSlabTransforms final : public SlabTransforms<SlabRealFft> {
 public:
  PeriodicSlabTransforms(const Grid& grid, const MpiCommunicator& comm, FftPlanning planning,
                         const operators::TransformsShape& shape)
      : SlabTransforms(grid, comm, planning, shape, grid.ny()), cells_(static_cast<double>(grid.size())) {}

  std::size_t local_size() const override { return fft_[0]->layout().local_size(); }
  double transform_size() const override { return cells_; }
  std::span<std::complex<double>> workspace() override { return fft_[0]->spectrum(); }
  std::span<const std::complex<double>> transform_wraparound_rows(const WraparoundRows& /*fill*/) override {
    throw std::logic_error("a periodic grid's symbols are analytic: no wrap-around coefficients");
  }
  std::unique_ptr<operators::CirculantForm> padded_form(EvenSymbol /*kernel*/, EvenSymbol /*stiffness*/) override {
    throw std::logic_error("a periodic grid's circulant form is the grid itself");
  }

 private:
  double cells_;
};

// K and K^-1 on the whole padded grid, this process's rows j and ny + j,
// each 2nx wide: local arrays [the rows j | the rows ny + j].
class SlabPaddedCirculantForm final : public operators::CirculantForm {
 public:
  // `top` is the operator's transform (its buffer used only inside a
  // product); `kernel` and `stiffness` on this process's columns (2ny rows
  // each, folded), with 1/N of one transform pair in.
  SlabPaddedCirculantForm(SlabPaddedRealFft& top, std::unique_ptr<SlabPaddedRealFft> bottom, EvenSymbol kernel,
                          EvenSymbol stiffness)
      : CirculantForm(true),
        top_(top),
        bottom_(std::move(bottom)),
        kernel_(std::move(kernel)),
        stiffness_(std::move(stiffness)) {}
  std::size_t local_size() const override { return 4 * top_.layout().local_size(); }
  std::size_t size() const override { return static_cast<std::size_t>(top_.padded_size()); }
  std::size_t row_stride() const override { return 2 * top_.layout().nx; }
  void apply(std::span<const double> in, std::span<double> out) override { multiply(in, out, kernel_); }
  void apply_inverse(std::span<const double> in, std::span<double> out) override { multiply(in, out, stiffness_); }

 private:
  void multiply(std::span<const double> in, std::span<double> out, const EvenSymbol& symbol) {
    assert(in.size() == local_size() && out.size() == local_size());
    const std::size_t half = local_size() / 2;
    // In place is safe: both halves are read before either is written.
    top_.forward_wide(in.first(half));
    bottom_->forward_wide(in.subspan(half));
    const std::size_t padded_rows = 2 * top_.layout().ny;
    std::complex<double>* a = top_.spectrum().data();
    std::complex<double>* b = bottom_->spectrum().data();
    linalg::for_each_row(top_.layout().columns, padded_rows, [&](std::size_t c) {
      for (std::size_t r = 0; r < padded_rows; ++r) {
        const std::size_t k = c * padded_rows + r;
        const double sign = r % 2 == 0 ? 1.0 : -1.0;
        const std::complex<double> product = (a[k] + sign * b[k]) * symbol.at(c, symbol.folded(r));
        a[k] = product;
        b[k] = sign * product;
      }
    });
    top_.backward_wide(out.first(half));
    bottom_->backward_wide(out.subspan(half));
  }

  SlabPaddedRealFft& top_;
  std::unique_ptr<SlabPaddedRealFft> bottom_;
  EvenSymbol kernel_;
  EvenSymbol stiffness_;
};

class FreeSlabTransforms final : public SlabTransforms<SlabPaddedRealFft> {
 public:
  FreeSlabTransforms(const Grid& grid, const MpiCommunicator& comm, FftPlanning planning,
                     const operators::TransformsShape& shape)
      : SlabTransforms(grid, comm, planning, shape, 2 * grid.ny()), nx_(grid.nx()), ny_(grid.ny()) {}

  std::size_t local_size() const override { return fft_[0]->layout().rows * nx_; }
  double transform_size() const override { return fft_[0]->padded_size(); }
  std::span<std::complex<double>> workspace() override { return fft_[0]->buffer(); }

  // The rows j and ny + j of the wrap-around grid, then the quadrants'
  // shifted spectra added up, left in transform 0's spectrum (idle while
  // the operator is made).
  std::span<const std::complex<double>> transform_wraparound_rows(const WraparoundRows& fill) override {
    const std::size_t first_row = fft_[0]->layout().first_row;
    const std::size_t rows = fft_[0]->layout().rows;
    const std::size_t width = 2 * nx_;
    std::vector<double> wide(rows * width);
    std::vector<double> quadrant(rows * nx_);
    const std::size_t held = held_.columns * held_.length;
    std::vector<std::complex<double>> sum(held);
    for (std::size_t a = 0; a < 2; ++a) {
      if (rows > 0) {
        fill(first_row + a * ny_, rows, [&](std::size_t i) { return std::span(wide).subspan(i * width, width); });
      }
      for (std::size_t b = 0; b < 2; ++b) {
        linalg::for_each_row(rows, nx_, [&](std::size_t i) {
          for (std::size_t c = 0; c < nx_; ++c) quadrant[i * nx_ + c] = wide[i * width + c + b * nx_];
        });
        fft_[0]->forward(quadrant);
        const std::span<const std::complex<double>> part = fft_[0]->spectrum();
        const bool first = a == 0 && b == 0;
        linalg::for_each_index(held, [&](std::size_t k) {
          const SpectrumMode m = held_.mode(k);
          const bool negative = (a * m.row + b * m.col) % 2 == 1;
          const std::complex<double> term = negative ? -part[k] : part[k];
          sum[k] = first ? term : sum[k] + term;
        });
      }
    }
    const std::span<std::complex<double>> spectrum = fft_[0]->spectrum().first(held);
    std::copy(sum.begin(), sum.end(), spectrum.begin());
    return spectrum;
  }

  std::unique_ptr<operators::CirculantForm> padded_form(EvenSymbol kernel, EvenSymbol stiffness) override {
    return std::make_unique<SlabPaddedCirculantForm>(*fft_[0],
                                                     std::make_unique<SlabPaddedRealFft>(nx_, ny_, comm_, planning_),
                                                     std::move(kernel), std::move(stiffness));
  }

 private:
  std::size_t nx_;
  std::size_t ny_;
};

}  // namespace

std::unique_ptr<operators::SpectralTransforms> make_slab_transforms(const Grid& grid, const MpiCommunicator& comm,
                                                                    FftPlanning planning,
                                                                    const operators::TransformsShape& shape) {
  if (grid.dimension() != 2) {
    throw InputError(fmt::format("the distributed operators need a 2D grid, not a {}D one", grid.dimension()));
  }
  if (shape.count < 1 || shape.count > 2) throw std::logic_error("slab transforms: count must be 1 or 2");
  if (grid.periodic() || shape.unpadded) return std::make_unique<PeriodicSlabTransforms>(grid, comm, planning, shape);
  return std::make_unique<FreeSlabTransforms>(grid, comm, planning, shape);
}

}  // namespace halfspace::mpi
