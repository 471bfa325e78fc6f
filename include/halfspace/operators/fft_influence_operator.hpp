// K p applied matrix-free by FFT convolution (real-to-complex FFTW plans made
// once). Periodic grids multiply by the Fourier kernel 2/(E* |q|); free grids
// convolve with Love's (2D) or plane-strain strip (1D) coefficients by zero
// padding to twice the size per axis (DC-FFT, Liu, Wang & Liu 2000).
#pragma once

#include <complex>
#include <memory>

#include "halfspace/fft/even_symbol.hpp"
#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/half_space.hpp"
#include "halfspace/operators/influence_operator.hpp"
#include "halfspace/operators/spectral_transforms.hpp"

namespace halfspace::operators {

class FftInfluenceOperator final : public InfluenceOperator {
 public:
  // The half-space's kernel (kernels/normal_kernel.hpp): homogeneous (E*,
  // Pa) or coated, on serial transforms of its own (make_serial_transforms,
  // one transform), the threads in force (set_threads) used by their plans.
  // Throws InputError for an invalid modulus or coating.
  FftInfluenceOperator(const Grid& grid, const HalfSpace& half_space, FftPlanning planning = FftPlanning::estimate);
  // The same on `transforms` (transform 0 used): the grid's own (periodic)
  // or the padded ones (free), serial or a distributed layout's slab
  // transforms of the 2D `grid` (fields hold this process's cells, the
  // symbol the spectrum entries held here, reductions go over its
  // communicator). They may be shared (a FourierPreconditioner's, a
  // single-precision transform in their workspace): nothing sharing them
  // may run while apply() does. Collective; throws InputError if they are
  // not the grid's.
  FftInfluenceOperator(const Grid& grid, const HalfSpace& half_space, std::shared_ptr<SpectralTransforms> transforms);
  ~FftInfluenceOperator() override;
  FftInfluenceOperator(const FftInfluenceOperator&) = delete;
  FftInfluenceOperator& operator=(const FftInfluenceOperator&) = delete;

  const Grid& grid() const override;
  std::size_t local_size() const override;
  const linalg::Communicator& communicator() const override;
  void apply(std::span<const double> pressure, std::span<double> displacement) override;
  double self_influence() const override;
  // Its transforms' kind (serial or slabs) for `grid`.
  std::unique_ptr<SpectralTransforms> transforms_for(const Grid& grid) const override;
  // Periodic: the kernel and its inverse on the transforms. Free: K on the
  // whole padded grid (SpectralTransforms::padded_form: serially a transform
  // of the whole padded grid, 4 ny nx reals and half as many complex values
  // more; on slabs this process's rows j and ny + j). Throws InputError if
  // the free grid's padded kernel is not positive definite (the 1D strip
  // kernel, with its datum at 1 m, can be so on domains longer than about 1 m).
  CirculantForm& circulant_form() override;

  // The half-space it was made for.
  const HalfSpace& half_space() const;
  // The transforms it multiplies on (their workspace() is idle between
  // products: a free grid's preconditioner or a single-precision transform
  // may work in it).
  const std::shared_ptr<SpectralTransforms>& transforms() const;
  // The kernel's symbol on the entries the transforms hold (FFTW's 1/N
  // folded in, ky folded: held_symbol's layout), which a Fourier
  // preconditioner inverts and a single-precision product on a periodic
  // grid multiplies by (single_precision_fft_operator.hpp). Lives as long as
  // the operator.
  const EvenSymbol& symbol() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace halfspace::operators

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using operators::FftInfluenceOperator;
}  // namespace halfspace
