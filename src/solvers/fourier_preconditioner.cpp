// Fourier preconditioner for Polonsky-Keer: multiply the spectrum by E*|q|/2,
// the symbol of the inverse half-space operator (Stanley & Kato 1997 give the
// forward symbol 2/(E*|q|)). Because K acts like a half-order integral, this
// removes the growth of its condition number with the grid size. A coated
// half-space gets the inverse of its own kernel, E1*|q| / (2 M(q t)).
#include "halfspace/solvers/fourier_preconditioner.hpp"

#include <fmt/format.h>

#include <cassert>
#include <complex>
#include <memory>
#include <stdexcept>
#include <utility>

#include "halfspace/error.hpp"
#include "halfspace/fft/even_symbol.hpp"
#include "halfspace/fft/grid_transform.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/kernels/normal_kernel.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"

namespace halfspace::solvers {
namespace {

std::shared_ptr<operators::SpectralTransforms> checked_unpadded(
    const Grid& grid, std::shared_ptr<operators::SpectralTransforms> transforms) {
  if (transforms->transform_size() != static_cast<double>(grid.size())) {
    throw InputError(
        fmt::format("FourierPreconditioner: the transforms are not the {} grid's own (unpadded)", grid.shape_string()));
  }
  return transforms;
}

}  // namespace

struct FourierPreconditioner::Impl {
  // On `t` (double) or `s` (single precision); its own symbol, or the
  // inverse of the operator's `operator_kernel`.
  Impl(const Grid& g, const HalfSpace& half_space, std::shared_ptr<operators::SpectralTransforms> t,
       std::shared_ptr<SingleRealFft> s, const EvenSymbol* operator_kernel)
      : grid(g), transforms(std::move(t)), single(std::move(s)), kernel(operator_kernel) {
    const kernels::NormalKernel normal(g, half_space);
    if (!kernel) {
      symbol = single ? normal.preconditioner_symbol(single->transposed())
                      : operators::held_symbol(*transforms, [&](std::size_t, operators::SpectrumMode m) {
                          return normal.preconditioner_symbol(m.row, m.col);
                        });
      return;
    }
    const double cells = static_cast<double>(g.size());
    inverse = {1.0 / (cells * cells), normal.preconditioner_at_zero()};
    // A slab not holding the mean mode divides its first entry too.
    if (transforms && transforms->held() > 0 && (transforms->mode(0).row != 0 || transforms->mode(0).col != 0)) {
      inverse.at_zero = inverse.numerator / kernel->at(0, 0);
    }
  }

  // spectrum *= M^-1's symbol.
  template <class Spectrum>
  void multiply(Spectrum spectrum) const {
    if (kernel) {
      kernel->divide(inverse, spectrum);
    } else {
      symbol.multiply(spectrum);
    }
  }

  // out = M^-1 in through the single-precision transform.
  template <class In, class Out>
  void apply_single(In in, Out out) const {
    if (kernel) {
      kernel->apply_inverse(inverse, *single, in, out);
    } else {
      symbol.apply(*single, in, out);
    }
  }

  Grid grid;
  std::shared_ptr<operators::SpectralTransforms> transforms;  // own, or shared with the operator
  std::shared_ptr<SingleRealFft> single;                      // instead of `transforms`: mixed precision
  EvenSymbol symbol{0, 0};      // E*|q|/(2N) or its layered form (held_symbol's layout); or empty:
  const EvenSymbol* kernel;     // the operator's K symbol, whose inverse it forms
  EvenSymbol::Inverse inverse;  // 1/N^2 and the mean mode, with `kernel`
};

FourierPreconditioner::FourierPreconditioner(const Grid& grid, const HalfSpace& half_space, FftPlanning planning)
    : FourierPreconditioner(grid, half_space,
                            operators::make_serial_transforms(grid, planning, {.count = 1, .unpadded = true})) {}

FourierPreconditioner::FourierPreconditioner(const Grid& grid, const HalfSpace& half_space,
                                             std::shared_ptr<operators::SpectralTransforms> transforms)
    : impl_(std::make_unique<Impl>(grid, half_space, checked_unpadded(grid, std::move(transforms)), nullptr, nullptr)) {
}

FourierPreconditioner::FourierPreconditioner(const Grid& grid, const HalfSpace& half_space, const EvenSymbol& kernel,
                                             std::shared_ptr<operators::SpectralTransforms> transforms)
    : impl_(std::make_unique<Impl>(grid, half_space, checked_unpadded(grid, std::move(transforms)), nullptr, &kernel)) {
}

FourierPreconditioner::FourierPreconditioner(const Grid& grid, const HalfSpace& half_space,
                                             std::shared_ptr<SingleRealFft> transform)
    : impl_(std::make_unique<Impl>(grid, half_space, nullptr,
                                   checked_grid_transform(grid, std::move(transform), "FourierPreconditioner"),
                                   nullptr)) {}

FourierPreconditioner::FourierPreconditioner(const Grid& grid, const HalfSpace& half_space, const EvenSymbol& kernel,
                                             std::shared_ptr<SingleRealFft> transform)
    : impl_(std::make_unique<Impl>(grid, half_space, nullptr,
                                   checked_grid_transform(grid, std::move(transform), "FourierPreconditioner"),
                                   &kernel)) {}

FourierPreconditioner::~FourierPreconditioner() = default;

void FourierPreconditioner::apply(std::span<const double> in, std::span<double> out) {
  const Impl& m = *impl_;
  // `in` is read before `out` is written, so the two may alias.
  if (m.single) {
    assert(in.size() == m.grid.size() && out.size() == m.grid.size());
    m.apply_single(in, out);
    return;
  }
  const std::span<std::complex<double>> spectrum = m.transforms->spectrum(0);
  m.transforms->apply_by_blocks(0, in, out, [&](std::size_t first, std::size_t count) {
    if (m.kernel) {
      m.kernel->divide(m.inverse, spectrum, first, count);
    } else {
      m.symbol.multiply(spectrum, first, count);
    }
  });
}

void FourierPreconditioner::apply(std::span<const float> in, std::span<float> out) {
  const Impl& m = *impl_;
  assert(in.size() == m.grid.size() && out.size() == m.grid.size());
  if (!m.single) throw std::logic_error("FourierPreconditioner: single-precision vectors need its single transform");
  m.apply_single(in, out);
}

std::unique_ptr<FourierPreconditioner> make_fourier_preconditioner(const operators::FftInfluenceOperator& op,
                                                                   const MakeTransforms& make_transforms) {
  const Grid& grid = op.grid();
  const std::shared_ptr<operators::SpectralTransforms>& transforms = op.transforms();
  if (grid.periodic()) return std::make_unique<FourierPreconditioner>(grid, op.half_space(), op.symbol(), transforms);
  return std::make_unique<FourierPreconditioner>(
      grid, op.half_space(), make_transforms({.count = 1, .unpadded = true, .workspace = transforms->workspace()}));
}

}  // namespace halfspace::solvers
