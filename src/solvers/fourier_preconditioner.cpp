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
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/fft/even_symbol.hpp"
#include "halfspace/fft/grid_transform.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/kernels/normal_kernel.hpp"

namespace halfspace::solvers {
struct FourierPreconditioner::Impl {
  // One of the two transforms: double or single precision.
  Impl(const Grid& g, const HalfSpace& half_space, std::shared_ptr<RealFft> shared,
       std::shared_ptr<SingleRealFft> single_shared = nullptr, const EvenSymbol* operator_kernel = nullptr)
      : grid(g),
        transform(std::move(shared)),
        single(std::move(single_shared)),
        symbol(operator_kernel ? EvenSymbol(0, 0) : kernels::NormalKernel(g, half_space).preconditioner_symbol()),
        kernel(operator_kernel) {
    if (kernel) {
      const double cells = static_cast<double>(g.size());
      inverse = {1.0 / (cells * cells), kernels::NormalKernel(g, half_space).preconditioner_at_zero()};
    }
  }

  // out = M^-1 in through `fft`.
  template <class Fft, class In, class Out>
  void apply(Fft& fft, In in, Out out) const {
    if (kernel) {
      kernel->apply_inverse(inverse, fft, in, out);
    } else {
      symbol.apply(fft, in, out);
    }
  }

  // On spectral transforms of the grid's own spectrum.
  Impl(const Grid& g, const HalfSpace& half_space, std::shared_ptr<operators::SpectralTransforms> t)
      : grid(g), symbol(0, 0), kernel(nullptr), transforms(std::move(t)) {
    if (transforms->transform_size() != static_cast<double>(g.size())) {
      throw InputError(
          fmt::format("FourierPreconditioner: the transforms are not the {} grid's own (unpadded)", g.shape_string()));
    }
    const kernels::NormalKernel normal(g, half_space);
    held = operators::held_values(
        *transforms, [&](operators::SpectrumMode m) { return normal.preconditioner_symbol(m.row, m.col); });
  }

  Grid grid;
  std::shared_ptr<RealFft> transform;     // own, or shared with the operator
  std::shared_ptr<SingleRealFft> single;  // instead of `transform`: mixed precision
  EvenSymbol symbol;                      // E*|q|/(2N) or its layered form, rows folded (even in qy); or empty:
  const EvenSymbol* kernel;               // the operator's K symbol, whose inverse it forms
  EvenSymbol::Inverse inverse;            // 1/N^2 and the mean mode, with `kernel`
  // Instead of the transforms above: spectral transforms and the symbol on
  // the entries held there.
  std::shared_ptr<operators::SpectralTransforms> transforms;
  std::vector<double> held;
};

FourierPreconditioner::FourierPreconditioner(const Grid& grid, const HalfSpace& half_space, FftPlanning planning)
    : impl_(std::make_unique<Impl>(grid, half_space, make_grid_transform(grid, planning))) {}

FourierPreconditioner::FourierPreconditioner(const Grid& grid, const HalfSpace& half_space,
                                             std::shared_ptr<RealFft> transform)
    : impl_(std::make_unique<Impl>(grid, half_space,
                                   checked_grid_transform(grid, std::move(transform), "FourierPreconditioner"))) {}

FourierPreconditioner::FourierPreconditioner(const Grid& grid, const HalfSpace& half_space,
                                             std::shared_ptr<SingleRealFft> transform)
    : impl_(std::make_unique<Impl>(grid, half_space, nullptr,
                                   checked_grid_transform(grid, std::move(transform), "FourierPreconditioner"))) {}

FourierPreconditioner::FourierPreconditioner(const Grid& grid, const HalfSpace& half_space, const EvenSymbol& kernel,
                                             std::shared_ptr<RealFft> transform)
    : impl_(std::make_unique<Impl>(grid, half_space,
                                   checked_grid_transform(grid, std::move(transform), "FourierPreconditioner"), nullptr,
                                   &kernel)) {}

FourierPreconditioner::FourierPreconditioner(const Grid& grid, const HalfSpace& half_space, const EvenSymbol& kernel,
                                             std::shared_ptr<SingleRealFft> transform)
    : impl_(std::make_unique<Impl>(grid, half_space, nullptr,
                                   checked_grid_transform(grid, std::move(transform), "FourierPreconditioner"),
                                   &kernel)) {}

FourierPreconditioner::FourierPreconditioner(const Grid& grid, const HalfSpace& half_space,
                                             std::shared_ptr<operators::SpectralTransforms> transforms)
    : impl_(std::make_unique<Impl>(grid, half_space, std::move(transforms))) {}

FourierPreconditioner::~FourierPreconditioner() = default;

void FourierPreconditioner::apply(std::span<const double> in, std::span<double> out) {
  Impl& m = *impl_;
  // `in` is read before `out` is written, so the two may alias.
  if (m.transforms) {
    operators::apply_symbol(*m.transforms, 0, m.held, in, out);
    return;
  }
  assert(in.size() == m.grid.size() && out.size() == m.grid.size());
  if (m.single) {
    m.apply(*m.single, in, out);
  } else {
    m.apply(*m.transform, in, out);
  }
}

void FourierPreconditioner::apply(std::span<const float> in, std::span<float> out) {
  Impl& m = *impl_;
  assert(in.size() == m.grid.size() && out.size() == m.grid.size());
  if (!m.single) throw std::logic_error("FourierPreconditioner: single-precision vectors need its single transform");
  m.apply(*m.single, in, out);
}

}  // namespace halfspace::solvers
