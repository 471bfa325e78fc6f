// The periodic kernel 2/(E*|q|), or a coated half-space's 2 M(q t)/(E1*|q|)
// (layered_fourier.hpp), and its inverse on the transposed spectrum of a
// slab-distributed grid. The multipliers are computed for this process's
// columns kx only; K_ii and the preconditioner's mean mode are computed from
// the whole grid in the serial classes' order, so they have the serial bits.
#include "halfspace/mpi/slab_fourier_operator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

#include "halfspace/error.hpp"
#include "halfspace/kernels/periodic_fourier.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::mpi {
namespace {

// The operator needs a periodic grid; the preconditioner takes a free one too
// (the serial solvers precondition free grids with the unpadded periodic
// symbol as well).
std::shared_ptr<SlabRealFft> checked_transform(const Grid& grid, std::shared_ptr<SlabRealFft> transform,
                                               const char* who, bool periodic_only) {
  if (grid.dimension() != 2 || (periodic_only && !grid.periodic())) {
    throw InputError(fmt::format("{}: needs a {}2D grid, not a {} {}D one", who, periodic_only ? "periodic " : "",
                                 to_string(grid.boundary()), grid.dimension()));
  }
  if (!transform || transform->layout().nx != grid.nx() || transform->layout().ny != grid.ny()) {
    throw InputError(fmt::format("{}: the transform is not the {} grid's", who, grid.shape_string()));
  }
  return transform;
}

// f(|q|) on this process's spectrum columns, [c * ny + r] (SlabRealFft).
template <class Multiplier>
std::vector<double> on_local_spectrum(const kernels::NormalKernel& kernel, const SlabLayout& layout,
                                      Multiplier&& multiplier) {
  std::vector<double> values(layout.columns * layout.ny);
  linalg::for_each_row(layout.columns, layout.ny, [&](std::size_t c) {
    for (std::size_t r = 0; r < layout.ny; ++r) {
      values[c * layout.ny + r] = multiplier(kernel.wavenumber(r, layout.first_column + c));
    }
  });
  return values;
}

// spectrum *= multiplier, then the inverse transform into `out`.
void multiply_and_invert(SlabRealFft& fft, const std::vector<double>& multiplier, std::span<double> out) {
  std::span<std::complex<double>> spectrum = fft.spectrum();
  linalg::for_each_index(spectrum.size(), [&](std::size_t k) { spectrum[k] *= multiplier[k]; });
  fft.backward(out);
}

}  // namespace

SlabFourierOperator::SlabFourierOperator(const Grid& grid, const HalfSpace& half_space,
                                         std::shared_ptr<SlabRealFft> transform)
    : grid_(grid),
      normal_(grid, half_space),
      transform_(checked_transform(grid, std::move(transform), "SlabFourierOperator", true)) {
  // FFTW's transforms are unnormalised: fold 1/N into the kernel.
  const double inverse_n = 1.0 / static_cast<double>(grid.size());
  kernel_ = on_local_spectrum(normal_, transform_->layout(), [&](double q) { return normal_.symbol(q) * inverse_n; });
  self_ = normal_.self_influence();
}

void SlabFourierOperator::apply(std::span<const double> pressure, std::span<double> displacement) {
  assert(pressure.size() == local_size() && displacement.size() == local_size());
  transform_->forward(pressure);
  multiply_and_invert(*transform_, kernel_, displacement);
}

namespace {

// K through the operator, K^-1 on its transform.
class SlabCirculantForm final : public operators::CirculantForm {
 public:
  SlabCirculantForm(SlabFourierOperator& op, std::shared_ptr<SlabRealFft> transform, std::vector<double> stiffness)
      : CirculantForm(false), op_(op), transform_(std::move(transform)), stiffness_(std::move(stiffness)) {}
  std::size_t local_size() const override { return op_.local_size(); }
  std::size_t size() const override { return op_.grid().size(); }
  std::size_t row_stride() const override { return op_.grid().nx(); }
  void apply(std::span<const double> in, std::span<double> out) override { op_.apply(in, out); }
  void apply_inverse(std::span<const double> in, std::span<double> out) override {
    transform_->forward(in);
    multiply_and_invert(*transform_, stiffness_, out);
  }

 private:
  SlabFourierOperator& op_;
  std::shared_ptr<SlabRealFft> transform_;
  std::vector<double> stiffness_;  // 1/(kernel N) on this process's spectrum columns, 0 at q = 0
};

}  // namespace

CirculantForm& SlabFourierOperator::circulant_form() {
  if (!circulant_) {
    // As FftInfluenceOperator's periodic form: the inverse kernel over N.
    const double inverse_n = 1.0 / static_cast<double>(grid_.size());
    std::vector<double> stiffness = on_local_spectrum(
        normal_, transform_->layout(), [&](double q) { return q > 0.0 ? normal_.stiffness(q) * inverse_n : 0.0; });
    circulant_ = std::make_unique<SlabCirculantForm>(*this, transform_, std::move(stiffness));
  }
  return *circulant_;
}

SlabFourierPreconditioner::SlabFourierPreconditioner(const Grid& grid, const HalfSpace& half_space,
                                                     std::shared_ptr<SlabRealFft> transform)
    : transform_(checked_transform(grid, std::move(transform), "SlabFourierPreconditioner", false)) {
  const kernels::NormalKernel kernel(grid, half_space);
  const auto cells = static_cast<double>(grid.size());
  symbol_ = on_local_spectrum(kernel, transform_->layout(), [&](double q) { return kernel.inverse_symbol(q, cells); });
  // The mean mode (unset above) gets the smallest non-zero |q|, the first
  // harmonic along x or y (hypot(q, 0) = q exactly, as FourierPreconditioner
  // finds it).
  const SlabLayout& layout = transform_->layout();
  if (layout.first_column == 0 && layout.columns > 0) {
    const double q_min =
        std::min(kernels::dft_wavenumber(1, grid.nx(), grid.dx()), kernels::dft_wavenumber(1, grid.ny(), grid.dy()));
    symbol_[0] = kernel.inverse_symbol(q_min, cells);
  }
}

void SlabFourierPreconditioner::apply(std::span<const double> in, std::span<double> out) {
  transform_->forward(in);
  multiply_and_invert(*transform_, symbol_, out);
}

}  // namespace halfspace::mpi
