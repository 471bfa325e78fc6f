// The transforms an FFT operator multiplies its symbols on: the whole grid
// on this process (the serial ones, make_serial_transforms: one slab), or this
// process's slab of rows of a grid spread over MPI processes
// (mpi/slab_spectral_transforms.hpp, made by the distributed layout). The
// operators (FftInfluenceOperator, FourierPreconditioner, TangentialOperator)
// compute their symbols and apply them once, on whichever spectrum entries
// the transforms hold here.
#pragma once

#include <complex>
#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/linalg/communicator.hpp"
#include "halfspace/operators/circulant_form.hpp"

// Declared only: the symbol's header reaches the internal transforms
// (fft/real_fft.hpp), which the installed headers must not.
namespace halfspace::fft {
class EvenSymbol;
}  // namespace halfspace::fft

namespace halfspace::operators {

// A mode of the (padded, on free grids) spectrum: the row (ky) and the
// column (kx, 0 <= kx <= nx/2 or nx) of the whole transform.
struct SpectrumMode {
  std::size_t row = 0;
  std::size_t col = 0;
};

// What to transform: how many fields at once, and whether a free grid is
// padded.
struct TransformsShape {
  // One per field transformed at once: 2 (the tangential operator's
  // traction components) or 1 (the normal operator, the preconditioner).
  int count = 2;
  // The grid's own (periodic) transform on a free grid too: the Fourier
  // preconditioner's, which need only approximate K^-1.
  bool unpadded = false;
  // With count 1, on the grid's own transform: FFTW-aligned memory it works
  // in (RealFft's and SlabRealFft's workspace), e.g. a free operator's idle
  // padded buffer (workspace()).
  std::span<std::complex<double>> workspace = {};
};

class SpectralTransforms {
 public:
  virtual ~SpectralTransforms() = default;

  // The field values held here, and the processes the field is spread over.
  virtual std::size_t local_size() const = 0;
  virtual const linalg::Communicator& communicator() const = 0;
  // The spectrum entries held here, as blocks x length (for parallel loops),
  // entry k standing for mode(k).
  virtual std::size_t spectrum_blocks() const = 0;
  virtual std::size_t spectrum_length() const = 0;
  std::size_t held() const { return spectrum_blocks() * spectrum_length(); }
  virtual SpectrumMode mode(std::size_t k) const = 0;
  // Whether a block is a column kx holding every row ky (a slab's
  // transposed spectrum) rather than a row ky (the serial spectrum).
  virtual bool transposed() const = 0;
  // The rows of the whole spectrum (the padded grid's on free grids).
  virtual std::size_t spectrum_rows() const = 0;
  // The N of backward(forward(x)) = N x.
  virtual double transform_size() const = 0;

  // The spectrum of `values` (local_size() values) in transform `k` (0, or
  // 1 where there are two), valid until its backward(). Collective on a
  // distributed grid.
  virtual std::span<std::complex<double>> forward(int k, std::span<const double> values) = 0;
  virtual std::span<std::complex<double>> spectrum(int k) = 0;
  // The unnormalised inverse of spectrum(k) into `values`. Collective.
  virtual void backward(int k, std::span<double> values) = 0;
  // Both transforms at once (count 2): out_k = the unnormalised inverse
  // transform of the spectrum of in_k once multiply(first, count) has
  // worked on the spectrum blocks [first, first + count) of spectrum(0) and
  // spectrum(1) together; it may be called for disjoint ranges on several
  // threads at once. Serially on a transposed transform a few kx columns at
  // a time go forward, are multiplied and go back while they are in cache
  // (the spectrum is read and written once instead of three times); else
  // forward, multiply and backward. The inputs are read before the outputs
  // are written. Collective; allocates nothing.
  using BlockMultiply = std::function<void(std::size_t first, std::size_t count)>;
  virtual void apply_pair(std::span<const double> in_0, std::span<const double> in_1, std::span<double> out_0,
                          std::span<double> out_1, const BlockMultiply& multiply);

  // out = transform k's inverse of multiply(first, count) on its spectrum
  // blocks, as apply_pair for one field (a product with a symbol).
  virtual void apply_by_blocks(int k, std::span<const double> in, std::span<double> out, const BlockMultiply& multiply);

  // Transform 0's whole buffer, whose contents matter only from forward()
  // to backward(): a workspace for a transform that runs only between
  // products (the Fourier preconditioner's on a free grid).
  virtual std::span<std::complex<double>> workspace() = 0;

  // Transforms of the same kind for another grid `grid` (serial, or on the
  // same processes' slabs), planned by FFTW's estimate: a coarser grid's
  // (coarsened_influence_operator.hpp), made for a few products. Collective.
  virtual std::unique_ptr<SpectralTransforms> make_for(const Grid& grid, const TransformsShape& shape) const = 0;

  // Free grids: the DFT of the real wrap-around array on the whole padded
  // grid (spectrum_rows() x 2 nx), on the entries held here (a kernel's
  // coefficients, transformed once). `fill(first, rows, row)` writes its
  // rows [first, first + rows) into row(i) (2 nx values each; i counted
  // from first), blocks of rows possibly at once on several threads.
  // Collective.
  using Row = std::function<std::span<double>(std::size_t i)>;
  using WraparoundRows = std::function<void(std::size_t first, std::size_t rows, const Row& row)>;
  virtual std::span<const std::complex<double>> transform_wraparound_rows(const WraparoundRows& fill) = 0;
  // The same with the array given value by value.
  std::span<const std::complex<double>> transform_wraparound(
      const std::function<double(std::size_t row, std::size_t col)>& value);

  // The same DFT on the transform padded_form() works on (serially a
  // transform of the whole padded grid, made here and kept for it; on slabs
  // transform_wraparound_rows), so that the form's symbols are its own
  // transform's eigenvalues. Collective.
  virtual std::span<const std::complex<double>> transform_form_wraparound(const WraparoundRows& fill) {
    return transform_wraparound_rows(fill);
  }

  // Free grids: K as a circulant on the whole padded grid (circulant_form.hpp)
  // from its symbols on the entries held here, 1/N of one transform pair
  // folded in: `kernel` (K) and `stiffness` (K^-1). Collective.
  virtual std::unique_ptr<CirculantForm> padded_form(fft::EvenSymbol kernel, fft::EvenSymbol stiffness) = 0;
};

// The serial transforms: the whole of `grid` on this process, `shape.count`
// of the grid's own transforms (periodic, or unpadded) or of the pruned
// padded ones (free; 1D or 2D). Throws InputError if the workspace is too
// small.
std::unique_ptr<SpectralTransforms> make_serial_transforms(const Grid& grid, FftPlanning planning,
                                                           const TransformsShape& shape = {});

// f(k, mode(k)) on the entries k `transforms` holds here, computed in
// parallel on the stored ones only: f must be even in the row wavenumber ky.
fft::EvenSymbol held_symbol(const SpectralTransforms& transforms,
                            const std::function<double(std::size_t k, SpectrumMode mode)>& f);

// out = `multiply`(spectrum) applied to `in` through transform `k`:
// forward, multiply, backward. `in` is read before `out` is written, so
// they may be the same array. Collective; allocates nothing.
template <class Multiply>
void apply_spectral(SpectralTransforms& transforms, int k, std::span<const double> in, std::span<double> out,
                    Multiply&& multiply) {
  multiply(transforms.forward(k, in));
  transforms.backward(k, out);
}
// The same with the multiplier `symbol` (held_symbol's layout).
void apply_symbol(SpectralTransforms& transforms, int k, const fft::EvenSymbol& symbol, std::span<const double> in,
                  std::span<double> out);

}  // namespace halfspace::operators
