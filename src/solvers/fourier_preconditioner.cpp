// Fourier preconditioner for Polonsky-Keer: multiply the spectrum by E*|q|/2,
// the symbol of the inverse half-space operator (Stanley & Kato 1997 give the
// forward symbol 2/(E*|q|)). Because K acts like a half-order integral, this
// removes the growth of its condition number with the grid size. A coated
// half-space gets the inverse of its own kernel, E1*|q| / (2 M(q t)).
#include "halfspace/solvers/fourier_preconditioner.hpp"

#include <cassert>
#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "halfspace/fft/even_symbol.hpp"
#include "halfspace/fft/grid_transform.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/kernels/normal_kernel.hpp"

namespace halfspace::solvers {
struct FourierPreconditioner::Impl {
  Impl(const Grid& g, const HalfSpace& half_space, std::shared_ptr<RealFft> shared)
      : grid(g), transform(std::move(shared)), fft(*transform), symbol(fft.rows(), fft.spectrum_cols()) {
    // FFTW's transforms are unnormalised: fold 1/N into the symbol.
    const kernels::NormalKernel kernel(g, half_space);
    const auto cells = static_cast<double>(grid.size());
    double q_min = std::numeric_limits<double>::infinity();
    for (std::size_t r = 0; r < symbol.stored_rows(); ++r) {
      for (std::size_t c = 0; c < symbol.cols(); ++c) {
        const double q = kernel.wavenumber(r, c);
        if (q > 0.0) {
          symbol.at(r, c) = kernel.inverse_symbol(q, cells);
          q_min = std::min(q_min, q);
        }
      }
    }
    symbol.at(0, 0) = kernel.inverse_symbol(q_min, cells);
  }

  Grid grid;
  std::shared_ptr<RealFft> transform;  // own, or shared with the operator
  RealFft& fft;
  EvenSymbol symbol;  // E*|q|/(2N) or its layered form, rows folded (even in qy)
};

FourierPreconditioner::FourierPreconditioner(const Grid& grid, const HalfSpace& half_space, FftPlanning planning)
    : impl_(std::make_unique<Impl>(grid, half_space, make_grid_transform(grid, planning))) {}

FourierPreconditioner::FourierPreconditioner(const Grid& grid, const HalfSpace& half_space,
                                             std::shared_ptr<RealFft> transform)
    : impl_(std::make_unique<Impl>(grid, half_space,
                                   checked_grid_transform(grid, std::move(transform), "FourierPreconditioner"))) {}

FourierPreconditioner::~FourierPreconditioner() = default;

void FourierPreconditioner::apply(std::span<const double> in, std::span<double> out) {
  Impl& m = *impl_;
  assert(in.size() == m.grid.size() && out.size() == m.grid.size());
  // `in` is read before `out` is written, so the two may alias.
  m.symbol.apply(m.fft, in, out);
}

}  // namespace halfspace::solvers
