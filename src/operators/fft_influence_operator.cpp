// u = K p by FFT on spectral transforms (serial, or a distributed layout's
// slabs), the symbol on the spectrum entries held here. Periodic grids:
// multiply the pressure spectrum by the kernel 2/(E* |q|) (Stanley & Kato
// 1997), or a coated half-space's 2 M(q t)/(E1* |q|). Free grids: linear
// convolution with Love's (2D) or the strip (1D) coefficients by zero
// padding to 2n per axis (DC-FFT, Liu, Wang & Liu 2000), exact to rounding,
// through the pruned padded transform, the kernel's symbol the DFT of its
// wrap-around coefficients.
#include "halfspace/operators/fft_influence_operator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <string>
#include <utility>

#include "halfspace/error.hpp"
#include "halfspace/kernels/normal_kernel.hpp"

namespace halfspace::operators {
namespace {

// The transforms must be the grid's own (periodic) or its padded ones (free).
std::shared_ptr<SpectralTransforms> checked(const Grid& grid, std::shared_ptr<SpectralTransforms> transforms) {
  const double cells = static_cast<double>(grid.size());
  const double padded = grid.periodic() ? cells : (grid.dimension() == 1 ? 2.0 : 4.0) * cells;
  if (transforms->transform_size() != padded) {
    throw InputError(fmt::format("FftInfluenceOperator: the transforms are not the {} {} grid's ({})",
                                 grid.shape_string(), to_string(grid.boundary()),
                                 grid.periodic() ? "its own" : "zero-padded"));
  }
  return transforms;
}

// K and K^-1 on a periodic grid's transforms: K is the operator's product,
// K^-1 the stiffness on the entries held here.
class HeldForm final : public CirculantForm {
 public:
  HeldForm(InfluenceOperator& op, SpectralTransforms& transforms, EvenSymbol stiffness)
      : CirculantForm(false), op_(op), transforms_(transforms), stiffness_(std::move(stiffness)) {}
  std::size_t local_size() const override { return op_.local_size(); }
  std::size_t size() const override { return op_.grid().size(); }
  std::size_t row_stride() const override { return op_.grid().nx(); }
  void apply(std::span<const double> in, std::span<double> out) override { op_.apply(in, out); }
  void apply_inverse(std::span<const double> in, std::span<double> out) override {
    apply_symbol(transforms_, 0, stiffness_, in, out);
  }

 private:
  InfluenceOperator& op_;
  SpectralTransforms& transforms_;
  EvenSymbol stiffness_;  // 1/(kernel N), 0 at q = 0
};

std::string not_positive_definite(const Grid& grid, double smallest) {
  return fmt::format(
      "the free {} grid's padded influence kernel is not positive definite (smallest eigenvalue {:g} m/Pa), so it "
      "has no inverse (stiffness) to minimise an energy with; use a periodic grid{}",
      grid.shape_string(), smallest,
      grid.dimension() == 1 ? " or a domain shorter than 1 m (the strip kernel's datum)" : "");
}

}  // namespace

struct FftInfluenceOperator::Impl {
  Impl(const Grid& g, const HalfSpace& half_space, std::shared_ptr<SpectralTransforms> t)
      : normal(g, half_space), body(half_space), transforms(checked(g, std::move(t))) {
    if (grid().periodic()) {
      // FFTW's 1/N folded in.
      kernel =
          held_symbol(*transforms, [&](std::size_t, SpectrumMode m) { return normal.periodic_symbol(m.row, m.col); });
      self = normal.self_influence();
      return;
    }
    init_free();
  }

  const Grid& grid() const { return normal.grid(); }

  // The coefficients on the (2ny, 2nx) wrap-around grid, transformed once
  // on the transforms' rows. Being even in each axis, their spectrum is real
  // up to rounding: only its real part is kept, the spectral remainder added
  // per bin; K_ii the inverse DFT at offset 0, summed over every process's
  // bins (or, without a remainder, the coefficient at offset 0).
  void init_free() {
    const std::span<const std::complex<double>> spectrum = transforms->transform_wraparound_rows(
        [&](std::size_t first, std::size_t rows, const SpectralTransforms::Row& row) {
          normal.write_padded_rows(first, rows, row);
        });
    const double inverse_n = 1.0 / transforms->transform_size();
    const bool remainder = normal.spectral_remainder();
    kernel = held_symbol(*transforms, [&](std::size_t k, SpectrumMode m) {
      double value = spectrum[k].real() * inverse_n;
      if (remainder) value += normal.padded_remainder(m.row, m.col) * inverse_n;
      return value;
    });
    if (!remainder) {
      self = normal.self_influence();
      return;
    }
    const std::size_t length = transforms->spectrum_length();
    std::array<double, 1> sum{normal.padded_self_influence(transforms->held(), [&](std::size_t k) {
      return std::pair{kernel.value(k / length, k % length), transforms->mode(k).col};
    })};
    transforms->communicator().sum(sum);
    self = sum[0];
  }

  // Periodic: the stiffness on the entries held here. Free: the padded
  // grid's form from the kernel's eigenvalues k on the form's transform,
  // which must be positive (K^-1 is 1/(N k) with 1/N of the pair).
  std::unique_ptr<CirculantForm> make_circulant_form(InfluenceOperator& op) {
    if (grid().periodic()) {
      const double inverse_n = 1.0 / static_cast<double>(grid().size());
      // The mean mode has no stiffness: solvers hold it by a constraint.
      return std::make_unique<HeldForm>(op, *transforms, held_symbol(*transforms, [&](std::size_t, SpectrumMode m) {
                                          const double q = normal.wavenumber(m.row, m.col);
                                          return q > 0.0 ? normal.stiffness(q) * inverse_n : 0.0;
                                        }));
    }
    // The coefficients transformed again on the form's own transform: its
    // unnormalised eigenvalues k (the spectral remainder added per bin).
    const std::span<const std::complex<double>> spectrum = transforms->transform_form_wraparound(
        [&](std::size_t first, std::size_t rows, const SpectralTransforms::Row& row) {
          normal.write_padded_rows(first, rows, row);
        });
    const bool remainder = normal.spectral_remainder();
    EvenSymbol kernel_form = held_symbol(*transforms, [&](std::size_t k, SpectrumMode m) {
      double value = spectrum[k].real();
      if (remainder) value += normal.padded_remainder(m.row, m.col) * 1.0;
      return value;
    });
    double smallest = std::numeric_limits<double>::infinity();
    for (const double k : kernel_form.stored()) smallest = std::min(smallest, k);
    smallest = -transforms->communicator().max(-smallest);
    if (!(smallest > 0.0)) throw InputError(not_positive_definite(grid(), smallest));
    const double inverse_m = 1.0 / transforms->transform_size();
    EvenSymbol stiffness = kernel_form;
    for (double& k : stiffness.stored()) k = k > 0.0 ? inverse_m / k : 0.0;
    for (double& k : kernel_form.stored()) k *= inverse_m;
    return transforms->padded_form(std::move(kernel_form), std::move(stiffness));
  }

  kernels::NormalKernel normal;
  HalfSpace body;
  std::shared_ptr<SpectralTransforms> transforms;  // own, or shared with a preconditioner
  EvenSymbol kernel{0, 0};                         // 1/N folded in
  double self = 0.0;
  std::unique_ptr<CirculantForm> circulant;  // made on first use
};

FftInfluenceOperator::FftInfluenceOperator(const Grid& grid, const HalfSpace& half_space, FftPlanning planning)
    : FftInfluenceOperator(grid, half_space, make_serial_transforms(grid, planning, {.count = 1})) {}

FftInfluenceOperator::FftInfluenceOperator(const Grid& grid, const HalfSpace& half_space,
                                           std::shared_ptr<SpectralTransforms> transforms)
    : impl_(std::make_unique<Impl>(grid, half_space, std::move(transforms))) {}

FftInfluenceOperator::~FftInfluenceOperator() = default;

const Grid& FftInfluenceOperator::grid() const {
  return impl_->grid();
}

std::size_t FftInfluenceOperator::local_size() const {
  return impl_->transforms->local_size();
}

const linalg::Communicator& FftInfluenceOperator::communicator() const {
  return impl_->transforms->communicator();
}

std::unique_ptr<SpectralTransforms> FftInfluenceOperator::transforms_for(const Grid& grid) const {
  return transforms()->make_for(grid, {.count = 1});
}

double FftInfluenceOperator::self_influence() const {
  return impl_->self;
}

void FftInfluenceOperator::apply(std::span<const double> pressure, std::span<double> displacement) {
  assert(pressure.size() == local_size() && displacement.size() == local_size());
  // In place is safe: the forward transform reads all of the input into the
  // spectrum before the backward one writes the output.
  assert(pressure.data() == displacement.data() || pressure.data() + pressure.size() <= displacement.data() ||
         displacement.data() + displacement.size() <= pressure.data());
  apply_symbol(*impl_->transforms, 0, impl_->kernel, pressure, displacement);
}

const std::shared_ptr<SpectralTransforms>& FftInfluenceOperator::transforms() const {
  return impl_->transforms;
}

const HalfSpace& FftInfluenceOperator::half_space() const {
  return impl_->body;
}

const EvenSymbol& FftInfluenceOperator::symbol() const {
  return impl_->kernel;
}

CirculantForm& FftInfluenceOperator::circulant_form() {
  Impl& m = *impl_;
  if (!m.circulant) m.circulant = m.make_circulant_form(*this);
  return *m.circulant;
}

}  // namespace halfspace::operators
