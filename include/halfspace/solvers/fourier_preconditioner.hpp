// The Fourier preconditioner E*|q|/2: the exact inverse of the periodic
// half-space kernel 2/(E*|q|) (or a coated one's), used as an approximate
// inverse of K on any grid.
#pragma once

#include <functional>
#include <memory>

#include "halfspace/fft/even_symbol.hpp"
#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/half_space.hpp"
#include "halfspace/operators/spectral_transforms.hpp"
#include "halfspace/solvers/preconditioner.hpp"

namespace halfspace::operators {
class FftInfluenceOperator;
}  // namespace halfspace::operators

namespace halfspace::solvers {

class FourierPreconditioner final : public Preconditioner {
 public:
  // The inverse of the half-space's kernel (kernels/normal_kernel.hpp),
  // E*|q|/2 homogeneous, E1*|q| / (2 M(q t)) coated, on the grid's own
  // (unpadded) transform, free grids too: the preconditioner need only be
  // close to K^-1, not equal to it. The mean mode, where the inverse
  // vanishes, gets the value of the smallest non-zero wavenumber so that
  // M^-1 stays positive definite. Plans serial transforms of its own.
  // Throws InputError for an invalid modulus or coating.
  FourierPreconditioner(const Grid& grid, const HalfSpace& half_space, FftPlanning planning = FftPlanning::estimate);
  // The same on `transforms` (transform 0 used; serial or a distributed
  // layout's slabs), the symbol on the spectrum entries held there.
  // Collective; throws InputError if they are not the grid's own.
  FourierPreconditioner(const Grid& grid, const HalfSpace& half_space,
                        std::shared_ptr<operators::SpectralTransforms> transforms);
  // On a periodic grid, the inverse of the operator's own symbol `kernel`
  // (FftInfluenceOperator::symbol(), which must outlive this) on the
  // operator's `transforms`: the solver applies the two one after the
  // other, so one transform serves both, and 1/(N^2 kernel) is formed as
  // it is applied (the same values to rounding, no symbol stored), the
  // mean mode as above.
  FourierPreconditioner(const Grid& grid, const HalfSpace& half_space, const EvenSymbol& kernel,
                        std::shared_ptr<operators::SpectralTransforms> transforms);
  // Through a single-precision transform of the grid (a mixed-precision
  // solve, solver_options.hpp's Precision; serial only): M^-1 need only
  // approximate K^-1, so rounding it to float costs no accuracy of the
  // solution. With `kernel`, its inverse as above. Throws InputError if the
  // transform's shape is not the grid's.
  FourierPreconditioner(const Grid& grid, const HalfSpace& half_space, std::shared_ptr<SingleRealFft> transform);
  FourierPreconditioner(const Grid& grid, const HalfSpace& half_space, const EvenSymbol& kernel,
                        std::shared_ptr<SingleRealFft> transform);
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

// Makes transforms of a shape for op's grid (a layout's, or
// SpectralTransforms::make_for).
using MakeTransforms =
    std::function<std::unique_ptr<operators::SpectralTransforms>(const operators::TransformsShape& shape)>;

// The Fourier preconditioner of `op` and its half-space: on a periodic grid
// the inverse of op's own symbol on op's transforms; on a free grid on the
// grid's own (unpadded) transform that `make_transforms` makes, working in
// op's idle workspace. Layout::make_operators and the films' dry contact
// (src/lubrication/dry_contact_memo.cpp) make it so.
std::unique_ptr<FourierPreconditioner> make_fourier_preconditioner(const operators::FftInfluenceOperator& op,
                                                                   const MakeTransforms& make_transforms);

}  // namespace halfspace::solvers
