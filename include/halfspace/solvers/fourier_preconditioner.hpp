// The Fourier preconditioner E*|q|/2: the exact inverse of the periodic
// half-space kernel 2/(E*|q|) (or a coated one's), used as an approximate
// inverse of K on any grid.
#pragma once

#include <memory>

#include "halfspace/fft/even_symbol.hpp"
#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/half_space.hpp"
#include "halfspace/operators/spectral_transforms.hpp"
#include "halfspace/solvers/preconditioner.hpp"

namespace halfspace::solvers {

class FourierPreconditioner final : public Preconditioner {
 public:
  // The inverse of the half-space's kernel (kernels/normal_kernel.hpp),
  // E*|q|/2 homogeneous, E1*|q| / (2 M(q t)) coated. Plans an unpadded
  // transform of the grid (free grids too: the preconditioner need only be
  // close to K^-1, not equal to it). The mean mode, where the inverse
  // vanishes, gets the value of the smallest non-zero wavenumber so that
  // M^-1 stays positive definite. Throws InputError for an invalid modulus
  // or coating.
  FourierPreconditioner(const Grid& grid, const HalfSpace& half_space, FftPlanning planning = FftPlanning::estimate);
  // The same with `transform` (the grid's (ny, nx), or nx in 1D, transform)
  // instead of one of its own, e.g. the one a periodic FftInfluenceOperator
  // uses: the solver applies the two one after the other, so one set of
  // buffers serves both. Nothing sharing it may run while apply() does.
  // Throws InputError if the transform's shape is not the grid's.
  FourierPreconditioner(const Grid& grid, const HalfSpace& half_space, std::shared_ptr<RealFft> transform);
  // The same through a single-precision transform (a mixed-precision
  // solve, solver_options.hpp's Precision): M^-1 need only approximate
  // K^-1, so rounding it to float costs no accuracy of the solution.
  FourierPreconditioner(const Grid& grid, const HalfSpace& half_space, std::shared_ptr<SingleRealFft> transform);
  // On a periodic grid, through either transform: the inverse of the
  // operator's own symbol `kernel` (FftInfluenceOperator::periodic_symbol(),
  // which must outlive this), 1/(N^2 kernel) formed as it is applied (the
  // same values to rounding, no symbol stored), the mean mode as above.
  FourierPreconditioner(const Grid& grid, const HalfSpace& half_space, const EvenSymbol& kernel,
                        std::shared_ptr<RealFft> transform);
  FourierPreconditioner(const Grid& grid, const HalfSpace& half_space, const EvenSymbol& kernel,
                        std::shared_ptr<SingleRealFft> transform);
  // The same on `transforms` (transform 0 used; a distributed layout's
  // slab transforms of the grid's own, unpadded spectrum, on free grids
  // too), the symbol on the spectrum entries held here. Collective; throws
  // InputError if the transforms are padded.
  FourierPreconditioner(const Grid& grid, const HalfSpace& half_space,
                        std::shared_ptr<operators::SpectralTransforms> transforms);
  ~FourierPreconditioner() override;

  void apply(std::span<const double> in, std::span<double> out) override;
  // The same on single-precision arrays (mixed precision's work vectors),
  // through the single-precision transform it was made with. Throws
  // std::logic_error if it was made with a double one.
  void apply(std::span<const float> in, std::span<float> out);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace halfspace::solvers
