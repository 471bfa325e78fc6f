// K p applied matrix-free by FFT convolution (real-to-complex FFTW plans made
// once). Periodic grids multiply by the Fourier kernel 2/(E* |q|); free grids
// convolve with Love's (2D) or plane-strain strip (1D) coefficients by zero
// padding to twice the size per axis (DC-FFT, Liu, Wang & Liu 2000).
#pragma once

#include <complex>
#include <memory>

#include "halfspace/fft/even_symbol.hpp"
#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/half_space.hpp"
#include "halfspace/operators/influence_operator.hpp"
#include "halfspace/operators/spectral_transforms.hpp"

namespace halfspace::operators {

class FftInfluenceOperator final : public InfluenceOperator {
 public:
  // The half-space's kernel (kernels/normal_kernel.hpp): homogeneous (E*,
  // Pa) or coated. Makes the plans and the kernel spectrum; the threads in
  // force (set_threads) are used by the plans. Throws InputError for an
  // invalid modulus or coating.
  FftInfluenceOperator(const Grid& grid, const HalfSpace& half_space, FftPlanning planning = FftPlanning::estimate);
  // The same on a periodic grid, with `transform` (the grid's own (ny, nx),
  // or nx in 1D, transform; FftOutput::overwrite_input saves most) instead
  // of a transform of its own, so that a FourierPreconditioner can share its
  // buffers. Nothing sharing it may run while apply() does. Throws InputError
  // if the grid is not periodic or the transform's shape is not the grid's.
  FftInfluenceOperator(const Grid& grid, const HalfSpace& half_space, std::shared_ptr<RealFft> transform);
  // The same on `transforms` (transform 0 used; a distributed layout's slab
  // transforms of the 2D `grid`, periodic or padded): fields hold this
  // process's cells, the symbol the spectrum entries held here, reductions
  // go over its communicator. Collective.
  FftInfluenceOperator(const Grid& grid, const HalfSpace& half_space, std::shared_ptr<SpectralTransforms> transforms);
  ~FftInfluenceOperator() override;
  FftInfluenceOperator(const FftInfluenceOperator&) = delete;
  FftInfluenceOperator& operator=(const FftInfluenceOperator&) = delete;

  const Grid& grid() const override;
  std::size_t local_size() const override;
  const linalg::Communicator& communicator() const override;
  void apply(std::span<const double> pressure, std::span<double> displacement) override;
  double self_influence() const override;
  // Periodic: the grid's transform (shared) with the kernel and its inverse.
  // Free: a transform of the whole padded grid (4 ny nx reals and half as
  // many complex values more; on slab transforms, SpectralTransforms::
  // padded_form, this process's rows j and ny + j). Throws InputError if the free grid's padded
  // kernel is not positive definite (the 1D strip kernel, with its datum at
  // 1 m, can be so on domains longer than about 1 m).
  CirculantForm& circulant_form() override;

  // Free grids: the padded transform's buffer (SpectralTransforms::
  // workspace on slabs), whose contents matter only
  // inside apply(), for a transform that runs only between products (the
  // preconditioner's: make_grid_transform with a workspace), which saves
  // that transform's own arrays. Empty on periodic grids (their transform
  // can be shared whole instead). Lives as long as the operator.
  std::span<std::complex<double>> scratch();

  // Periodic grids: the kernel's symbol (FFTW's 1/N folded in, rows
  // folded), which a single-precision product on the same grid multiplies
  // by too (single_precision_fft_operator.hpp). Lives as long as the
  // operator. Throws InputError on a free grid (its symbol is the padded
  // grid's) or on spectral transforms (made with the constructor above).
  const EvenSymbol& periodic_symbol() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace halfspace::operators

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using operators::FftInfluenceOperator;
}  // namespace halfspace
