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
#include <functional>
#include <optional>
#include <utility>

#include "halfspace/error.hpp"
#include "halfspace/kernels/layered_fourier.hpp"
#include "halfspace/kernels/periodic_fourier.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/material.hpp"

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
std::vector<double> on_local_spectrum(const Grid& grid, const SlabLayout& layout, Multiplier&& multiplier) {
  std::vector<double> values(layout.columns * layout.ny);
  linalg::for_each_row(layout.columns, layout.ny, [&](std::size_t c) {
    const double qx = kernels::dft_wavenumber(layout.first_column + c, grid.nx(), grid.dx());
    for (std::size_t r = 0; r < layout.ny; ++r) {
      values[c * layout.ny + r] = multiplier(std::hypot(qx, kernels::dft_wavenumber(r, grid.ny(), grid.dy())));
    }
  });
  return values;
}

// The kernel u(q)/p(q) of `elasticity` (m/Pa), 0 at q = 0, as
// FftInfluenceOperator's periodic kernel.
std::function<double(double)> kernel_of(const SlabElasticity& elasticity) {
  if (const auto* material = std::get_if<LayeredMaterial>(&elasticity)) {
    return [layered = kernels::LayeredKernel(*material)](double q) { return layered.spectrum(q); };
  }
  const double e_star = checked_composite_modulus(std::get<double>(elasticity));
  return [e_star](double q) { return kernels::periodic_kernel_spectrum(q, e_star); };
}

// The preconditioner's symbol 1/(kernel N) as FourierPreconditioner forms
// it: E*|q|/(2N) for the homogeneous half-space, 1/(kernel(q) N) coated.
std::function<double(double)> inverse_kernel_of(const SlabElasticity& elasticity, double cells) {
  if (const auto* material = std::get_if<LayeredMaterial>(&elasticity)) {
    return
        [layered = kernels::LayeredKernel(*material), cells](double q) { return 1.0 / (layered.spectrum(q) * cells); };
  }
  const double scale = 0.5 * checked_composite_modulus(std::get<double>(elasticity)) / cells;
  return [scale](double q) { return q * scale; };
}

// spectrum *= multiplier, then the inverse transform into `out`.
void multiply_and_invert(SlabRealFft& fft, const std::vector<double>& multiplier, std::span<double> out) {
  std::span<std::complex<double>> spectrum = fft.spectrum();
  linalg::for_each_index(spectrum.size(), [&](std::size_t k) { spectrum[k] *= multiplier[k]; });
  fft.backward(out);
}

}  // namespace

SlabFourierOperator::SlabFourierOperator(const Grid& grid, const SlabElasticity& elasticity,
                                         std::shared_ptr<SlabRealFft> transform)
    : grid_(grid),
      elasticity_(elasticity),
      transform_(checked_transform(grid, std::move(transform), "SlabFourierOperator", true)) {
  const std::function<double(double)> spectrum = kernel_of(elasticity);
  // FFTW's transforms are unnormalised: fold 1/N into the kernel.
  const double inverse_n = 1.0 / static_cast<double>(grid.size());
  kernel_ = on_local_spectrum(grid, transform_->layout(), [&](double q) { return spectrum(q) * inverse_n; });
  // K_ii = (1/N) sum over the whole spectrum, in FftInfluenceOperator's order.
  double sum = 0.0;
  for (std::size_t r = 0; r < grid.ny(); ++r) {
    const double qy = kernels::dft_wavenumber(r, grid.ny(), grid.dy());
    for (std::size_t c = 0; c < grid.nx(); ++c) {
      sum += spectrum(std::hypot(kernels::dft_wavenumber(c, grid.nx(), grid.dx()), qy));
    }
  }
  self_ = sum * inverse_n;
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
    // As FftInfluenceOperator's periodic form: E*|q|/2 or the coated
    // kernel's inverse, over N.
    const double inverse_n = 1.0 / static_cast<double>(grid_.size());
    const auto* coating = std::get_if<LayeredMaterial>(&elasticity_);
    const std::optional<kernels::LayeredKernel> layered =
        coating ? std::optional<kernels::LayeredKernel>(*coating) : std::nullopt;
    const double e_star = coating ? 0.0 : std::get<double>(elasticity_);
    std::vector<double> stiffness = on_local_spectrum(grid_, transform_->layout(), [&](double q) {
      return q > 0.0 ? (layered ? 1.0 / layered->spectrum(q) : 0.5 * e_star * q) * inverse_n : 0.0;
    });
    circulant_ = std::make_unique<SlabCirculantForm>(*this, transform_, std::move(stiffness));
  }
  return *circulant_;
}

SlabFourierPreconditioner::SlabFourierPreconditioner(const Grid& grid, const SlabElasticity& elasticity,
                                                     std::shared_ptr<SlabRealFft> transform)
    : transform_(checked_transform(grid, std::move(transform), "SlabFourierPreconditioner", false)) {
  const std::function<double(double)> inverse_kernel = inverse_kernel_of(elasticity, static_cast<double>(grid.size()));
  symbol_ = on_local_spectrum(grid, transform_->layout(), inverse_kernel);
  // The mean mode (zero above) gets the smallest non-zero |q|, the first
  // harmonic along x or y (hypot(q, 0) = q exactly, as FourierPreconditioner
  // finds it).
  const SlabLayout& layout = transform_->layout();
  if (layout.first_column == 0 && layout.columns > 0) {
    const double q_min =
        std::min(kernels::dft_wavenumber(1, grid.nx(), grid.dx()), kernels::dft_wavenumber(1, grid.ny(), grid.dy()));
    symbol_[0] = inverse_kernel(q_min);
  }
}

void SlabFourierPreconditioner::apply(std::span<const double> in, std::span<double> out) {
  transform_->forward(in);
  multiply_and_invert(*transform_, symbol_, out);
}

}  // namespace halfspace::mpi
