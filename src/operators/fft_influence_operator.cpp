// u = K p by FFT. Periodic grids: multiply the pressure spectrum by the kernel
// 2/(E* |q|) (Stanley & Kato 1997), or a coated half-space's 2 M(q t)/(E1* |q|). Free grids: linear convolution with
// Love's (2D) or the strip (1D) coefficients by zero padding to 2n per axis (DC-FFT, Liu, Wang & Liu 2000), exact to
// rounding, through the pruned padded transform (PaddedRealFft). On spectral transforms (a distributed layout's
// slabs) the same symbols on the entries held there, the free kernel's from its wrap-around coefficients.
#include "halfspace/operators/fft_influence_operator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/fft/even_symbol.hpp"
#include "halfspace/fft/grid_transform.hpp"
#include "halfspace/fft/padded_real_fft.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/kernels/normal_kernel.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::operators {
namespace {

// A shared transform must be the periodic grid's own: apply() hands it the
// grid's arrays and the kernel follows its spectrum's layout.
std::shared_ptr<RealFft> checked_shared_transform(const Grid& grid, std::shared_ptr<RealFft> transform) {
  if (!grid.periodic()) {
    throw InputError("FftInfluenceOperator: a shared transform needs a periodic grid (free grids pad it)");
  }
  return checked_grid_transform(grid, std::move(transform), "FftInfluenceOperator");
}

// K and K^-1 as symbols on one transform: the periodic grid's own (shared
// with the operator), or the whole padded grid's of a free one.
class SymbolForm final : public CirculantForm {
 public:
  SymbolForm(bool padded, std::shared_ptr<RealFft> fft, EvenSymbol kernel, EvenSymbol stiffness)
      : CirculantForm(padded), fft_(std::move(fft)), kernel_(std::move(kernel)), stiffness_(std::move(stiffness)) {}
  std::size_t local_size() const override { return fft_->real_size(); }
  std::size_t size() const override { return fft_->real_size(); }
  std::size_t row_stride() const override { return fft_->real_size() / fft_->rows(); }
  void apply(std::span<const double> in, std::span<double> out) override { kernel_.apply(*fft_, in, out); }
  void apply_inverse(std::span<const double> in, std::span<double> out) override { stiffness_.apply(*fft_, in, out); }

 private:
  std::shared_ptr<RealFft> fft_;
  EvenSymbol kernel_;
  EvenSymbol stiffness_;
};

// K and K^-1 on a periodic grid's spectral transforms: K is the operator's
// product, K^-1 the stiffness on the entries held here.
class HeldForm final : public CirculantForm {
 public:
  HeldForm(InfluenceOperator& op, SpectralTransforms& transforms, std::vector<double> stiffness)
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
  std::vector<double> stiffness_;  // 1/(kernel N), 0 at q = 0
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
  // Periodic: `shared` is the grid's transform. Free: a padded one is made.
  Impl(const Grid& g, const HalfSpace& half_space, std::shared_ptr<RealFft> shared, FftPlanning planning)
      : normal(g, half_space),
        planning(planning),
        transform(std::move(shared)),
        padded(transform ? nullptr
                         : std::make_unique<PaddedRealFft>(g.dimension() == 1 ? 1 : g.ny(), g.nx(), planning)),
        kernel(transform ? transform->rows() : padded->spectrum_rows(),
               transform ? transform->spectrum_cols() : padded->spectrum_cols()) {
    if (grid().periodic()) {
      init_periodic();
    } else {
      init_free();
    }
  }

  // On spectral transforms: the symbol on the entries held there.
  Impl(const Grid& g, const HalfSpace& half_space, std::shared_ptr<SpectralTransforms> t)
      : normal(g, half_space), planning(FftPlanning::estimate), kernel(0, 0), transforms(std::move(t)) {
    if (grid().periodic()) {
      held = held_values(*transforms, [&](SpectrumMode m) { return normal.periodic_symbol(m.row, m.col); });
      self = normal.self_influence();
      return;
    }
    init_free_held();
  }

  const Grid& grid() const { return normal.grid(); }

  // The wrap-around coefficients transformed on the transforms' blocks of
  // rows, the spectral remainder added per bin; K_ii the inverse DFT at
  // offset 0, summed over every process's bins.
  void init_free_held() {
    const std::span<const std::complex<double>> spectrum =
        transforms->transform_wraparound_rows([&](std::size_t first, std::size_t rows, std::span<double> values) {
          normal.write_padded_rows(first, rows, values);
        });
    const double inverse_n = 1.0 / transforms->transform_size();
    const bool remainder = normal.spectral_remainder();
    held.resize(transforms->held());
    linalg::for_each_index(held.size(), [&](std::size_t k) {
      held[k] = spectrum[k].real() * inverse_n;
      if (remainder) {
        const SpectrumMode m = transforms->mode(k);
        held[k] += normal.padded_remainder(m.row, m.col) * inverse_n;
      }
    });
    if (!remainder) {
      self = normal.self_influence();
      return;
    }
    std::array<double, 1> sum{normal.padded_self_influence(held.size(), [&](std::size_t k) {
      return std::pair{held[k], transforms->mode(k).col};
    })};
    transforms->communicator().sum(sum);
    self = sum[0];
  }

  // On spectral transforms: periodic, the stiffness on the entries held
  // here; free, the padded grid's form from the kernel's eigenvalues k = N
  // symbol, which must be positive (K^-1 is 1/(N k) with 1/N of the pair).
  std::unique_ptr<CirculantForm> make_held_form(InfluenceOperator& op) {
    if (grid().periodic()) {
      const double inverse_n = 1.0 / static_cast<double>(grid().size());
      return std::make_unique<HeldForm>(op, *transforms, held_values(*transforms, [&](SpectrumMode m) {
                                          const double q = normal.wavenumber(m.row, m.col);
                                          return q > 0.0 ? normal.stiffness(q) * inverse_n : 0.0;
                                        }));
    }
    const double n = transforms->transform_size();
    double smallest = std::numeric_limits<double>::infinity();
    for (const double value : held) smallest = std::min(smallest, value * n);
    smallest = -transforms->communicator().max(-smallest);
    if (!(smallest > 0.0)) throw InputError(not_positive_definite(grid(), smallest));
    std::vector<double> stiffness(held.size());
    linalg::for_each_index(held.size(), [&](std::size_t k) { stiffness[k] = 1.0 / (n * (n * held[k])); });
    return transforms->padded_form(held, std::move(stiffness));
  }

  // The symbol with FFTW's 1/N folded in.
  void init_periodic() {
    kernel = normal.periodic_symbol();
    self = normal.self_influence();
  }

  // The coefficients on the (2ny, 2nx) wrap-around grid, transformed once
  // through the pruned transform. Being even in each axis, their spectrum
  // is real up to rounding: only its real part is kept.
  void init_free() {
    const std::vector<double> quadrant = normal.free_quadrant(0, grid().dimension() == 1 ? 1 : grid().ny() + 1);
    normal.write_padded(quadrant, padded->spectrum_rows(), [&](std::size_t r) { return padded->padded_row(r); });
    padded->forward_all_rows();
    const double inverse_n = 1.0 / static_cast<double>(padded->padded_size());
    std::span<const std::complex<double>> spectrum = padded->spectrum();
    for (std::size_t r = 0; r < kernel.stored_rows(); ++r) {
      for (std::size_t c = 0; c < kernel.cols(); ++c)
        kernel.at(r, c) = spectrum[r * kernel.cols() + c].real() * inverse_n;
    }
    normal.add_spectral_remainder(kernel, inverse_n);
    // K_ii: the coefficient at offset 0 (NormalKernel::self_influence, in
    // hand), or the padded symbol's with a spectral remainder.
    self = normal.spectral_remainder() ? normal.padded_self_influence(kernel) : quadrant[0];
  }

  // The circulant form: periodic grids multiply by the inverse kernel on
  // their own transform; free ones invert the padded kernel's spectrum on a
  // transform of the whole padded grid (its padding carries values here).
  std::unique_ptr<CirculantForm> make_circulant_form() {
    EvenSymbol stiffness(kernel.rows(), kernel.cols());
    const Grid& grid = this->grid();
    if (grid.periodic()) {
      const double inverse_n = 1.0 / static_cast<double>(grid.size());
      for (std::size_t r = 0; r < kernel.stored_rows(); ++r) {
        for (std::size_t c = 0; c < kernel.cols(); ++c) {
          const double q = normal.wavenumber(r, c);
          // The mean mode has no stiffness: solvers hold it by a constraint.
          if (q > 0.0) stiffness.at(r, c) = normal.stiffness(q) * inverse_n;
        }
      }
      return std::make_unique<SymbolForm>(false, transform, kernel, std::move(stiffness));
    }
    // The same coefficients transformed whole (the padding rows too), the
    // kernel and its inverse from the unnormalised eigenvalues k.
    const bool line = grid.dimension() == 1;
    auto fft = line ? std::make_shared<RealFft>(2 * grid.nx(), planning)
                    : std::make_shared<RealFft>(2 * grid.ny(), 2 * grid.nx(), planning);
    const std::size_t padded_cols = 2 * grid.nx();
    normal.write_padded(normal.free_quadrant(0, line ? 1 : grid.ny() + 1), kernel.rows(),
                        [&](std::size_t r) { return fft->input().subspan(r * padded_cols, padded_cols); });
    fft->forward();
    EvenSymbol eigenvalues(kernel.rows(), kernel.cols());
    const std::span<const std::complex<double>> spectrum = fft->spectrum();
    for (std::size_t r = 0; r < kernel.stored_rows(); ++r) {
      for (std::size_t c = 0; c < kernel.cols(); ++c) eigenvalues.at(r, c) = spectrum[r * kernel.cols() + c].real();
    }
    normal.add_spectral_remainder(eigenvalues, 1.0);
    const double inverse_m = 1.0 / static_cast<double>(padded->padded_size());
    EvenSymbol whole(kernel.rows(), kernel.cols());
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t r = 0; r < kernel.stored_rows(); ++r) {
      for (std::size_t c = 0; c < kernel.cols(); ++c) {
        const double k = eigenvalues.at(r, c);
        smallest = std::min(smallest, k);
        whole.at(r, c) = k * inverse_m;
        stiffness.at(r, c) = k > 0.0 ? inverse_m / k : 0.0;
      }
    }
    if (!(smallest > 0.0)) throw InputError(not_positive_definite(grid, smallest));
    return std::make_unique<SymbolForm>(true, std::move(fft), std::move(whole), std::move(stiffness));
  }

  kernels::NormalKernel normal;
  FftPlanning planning;
  std::shared_ptr<RealFft> transform;     // periodic grids: own, or shared with a preconditioner
  std::unique_ptr<PaddedRealFft> padded;  // free grids
  EvenSymbol kernel;                      // real kernel spectrum, rows folded (even in qy)
  double self = 0.0;
  std::unique_ptr<CirculantForm> circulant;  // made on first use
  // Instead of the three above: spectral transforms, the symbol on the
  // entries held there (1/N folded in).
  std::shared_ptr<SpectralTransforms> transforms;
  std::vector<double> held;
};

FftInfluenceOperator::FftInfluenceOperator(const Grid& grid, const HalfSpace& half_space, FftPlanning planning)
    : impl_(std::make_unique<Impl>(grid, half_space, grid.periodic() ? make_grid_transform(grid, planning) : nullptr,
                                   planning)) {}

FftInfluenceOperator::FftInfluenceOperator(const Grid& grid, const HalfSpace& half_space,
                                           std::shared_ptr<RealFft> transform)
    : impl_(std::make_unique<Impl>(grid, half_space, checked_shared_transform(grid, std::move(transform)),
                                   FftPlanning::estimate)) {}

FftInfluenceOperator::FftInfluenceOperator(const Grid& grid, const HalfSpace& half_space,
                                           std::shared_ptr<SpectralTransforms> transforms)
    : impl_(std::make_unique<Impl>(grid, half_space, std::move(transforms))) {}

FftInfluenceOperator::~FftInfluenceOperator() = default;

const Grid& FftInfluenceOperator::grid() const {
  return impl_->grid();
}

std::size_t FftInfluenceOperator::local_size() const {
  return impl_->transforms ? impl_->transforms->local_size() : impl_->grid().size();
}

const linalg::Communicator& FftInfluenceOperator::communicator() const {
  return impl_->transforms ? impl_->transforms->communicator() : linalg::serial_communicator();
}

double FftInfluenceOperator::self_influence() const {
  return impl_->self;
}

std::span<std::complex<double>> FftInfluenceOperator::scratch() {
  if (impl_->grid().periodic()) return {};
  return impl_->transforms ? impl_->transforms->workspace() : impl_->padded->spectrum();
}

void FftInfluenceOperator::apply(std::span<const double> pressure, std::span<double> displacement) {
  Impl& m = *impl_;
  assert(pressure.size() == local_size() && displacement.size() == local_size());
  // In place is safe: the forward transform reads all of the input into the
  // spectrum before the backward one writes the output.
  assert(pressure.data() == displacement.data() || pressure.data() + pressure.size() <= displacement.data() ||
         displacement.data() + displacement.size() <= pressure.data());

  if (m.transforms) {
    apply_symbol(*m.transforms, 0, m.held, pressure, displacement);
    return;
  }
  if (m.padded) {
    m.padded->forward(pressure);
    m.kernel.multiply(m.padded->spectrum());
    m.padded->backward(displacement);
    return;
  }
  // Periodic grids transform the caller's arrays directly when FFTW allows
  // it, else copy through the transform's own buffers.
  m.kernel.apply(*m.transform, pressure, displacement);
}

const EvenSymbol& FftInfluenceOperator::periodic_symbol() const {
  if (impl_->padded) throw InputError("FftInfluenceOperator: a free grid's symbol is its padded grid's, not periodic");
  if (impl_->transforms) throw InputError("FftInfluenceOperator: on spectral transforms the symbol is held in parts");
  return impl_->kernel;
}

CirculantForm& FftInfluenceOperator::circulant_form() {
  Impl& m = *impl_;
  if (!m.circulant) m.circulant = m.transforms ? m.make_held_form(*this) : m.make_circulant_form();
  return *m.circulant;
}

}  // namespace halfspace::operators
