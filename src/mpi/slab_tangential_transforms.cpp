// The slab transforms of the tangential operator. A free grid's kernel
// coefficients fill the whole (2ny, 2nx) wrap-around grid, whose padding
// rows the slab transform never holds (slab_padded_fft.hpp); its DFT is the
// sum of the padded DFTs of its four (ny, nx) quadrants Q_ab (a, b in
// {0, 1}, offset by a ny rows and b nx columns), each shifted:
//   W(ky, kx) = sum_ab (-1)^(a ky + b kx) F[Q_ab](ky, kx),
// so each process evaluates only its rows of each quadrant.
#include "halfspace/mpi/slab_tangential_transforms.hpp"

#include <fmt/format.h>

#include <complex>
#include <span>
#include <stdexcept>
#include <vector>

#include "halfspace/error.hpp"
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

// What both kinds share: two transforms of the grid's slab (`Fft`, periodic
// or padded), their spectra held as columns `length` rows long.
template <class Fft>
class SlabTransforms : public operators::TangentialTransforms {
 public:
  SlabTransforms(const Grid& grid, const MpiCommunicator& comm, FftPlanning planning, std::size_t length)
      : comm_(comm) {
    for (auto& t : fft_) t = std::make_unique<Fft>(grid.nx(), grid.ny(), comm, planning);
    held_ = {fft_[0]->layout().first_column, fft_[0]->layout().columns, length};
  }

  const linalg::Communicator& communicator() const override { return comm_; }
  std::size_t spectrum_blocks() const override { return held_.columns; }
  std::size_t spectrum_length() const override { return held_.length; }
  SpectrumMode mode(std::size_t k) const override { return held_.mode(k); }
  std::size_t spectrum_rows() const override { return held_.length; }
  std::span<std::complex<double>> forward(int k, std::span<const double> values) override {
    fft_[k]->forward(values);
    return fft_[k]->spectrum();
  }
  std::span<std::complex<double>> spectrum(int k) override { return fft_[k]->spectrum(); }
  void backward(int k, std::span<double> values) override { fft_[k]->backward(values); }

 protected:
  const MpiCommunicator& comm_;
  std::unique_ptr<Fft> fft_[2];
  Columns held_;
};

class PeriodicSlabTransforms final : public SlabTransforms<SlabRealFft> {
 public:
  PeriodicSlabTransforms(const Grid& grid, const MpiCommunicator& comm, FftPlanning planning)
      : SlabTransforms(grid, comm, planning, grid.ny()), cells_(static_cast<double>(grid.size())) {}

  std::size_t local_size() const override { return fft_[0]->layout().local_size(); }
  double transform_size() const override { return cells_; }
  std::span<const std::complex<double>> transform_wraparound(
      const std::function<double(std::size_t, std::size_t)>& /*value*/) override {
    throw std::logic_error("a periodic grid's tangential symbol is analytic: no wrap-around coefficients");
  }

 private:
  double cells_;
};

class FreeSlabTransforms final : public SlabTransforms<SlabPaddedRealFft> {
 public:
  FreeSlabTransforms(const Grid& grid, const MpiCommunicator& comm, FftPlanning planning)
      : SlabTransforms(grid, comm, planning, 2 * grid.ny()), nx_(grid.nx()), ny_(grid.ny()) {}

  std::size_t local_size() const override { return fft_[0]->layout().rows * nx_; }
  double transform_size() const override { return fft_[0]->padded_size(); }

  // The quadrants' shifted spectra added up in transform 1's spectrum, idle
  // while the operator is made.
  std::span<const std::complex<double>> transform_wraparound(
      const std::function<double(std::size_t, std::size_t)>& value) override {
    const std::size_t first_row = fft_[0]->layout().first_row;
    const std::size_t rows = fft_[0]->layout().rows;
    std::vector<double> quadrant(rows * nx_);
    const std::span<std::complex<double>> sum = fft_[1]->spectrum();
    const std::size_t held = held_.columns * held_.length;
    for (std::size_t a = 0; a < 2; ++a) {
      for (std::size_t b = 0; b < 2; ++b) {
        linalg::for_each_row(rows, nx_, [&](std::size_t i) {
          for (std::size_t c = 0; c < nx_; ++c) quadrant[i * nx_ + c] = value(first_row + i + a * ny_, c + b * nx_);
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
    return sum.first(held);
  }

 private:
  std::size_t nx_;
  std::size_t ny_;
};

}  // namespace

std::unique_ptr<operators::TangentialTransforms> make_slab_tangential_transforms(const Grid& grid,
                                                                                 const MpiCommunicator& comm,
                                                                                 FftPlanning planning) {
  if (grid.dimension() != 2) {
    throw InputError(
        fmt::format("the distributed tangential operator needs a 2D grid, not a {}D one", grid.dimension()));
  }
  if (grid.periodic()) return std::make_unique<PeriodicSlabTransforms>(grid, comm, planning);
  return std::make_unique<FreeSlabTransforms>(grid, comm, planning);
}

}  // namespace halfspace::mpi
