// The DFT of a real (ny, nx) block zero-padded to (2ny, 2nx), and its inverse
// restricted back to the block: the transforms of the free-boundary (DC-FFT)
// convolution. Half of the padded rows are zero on the way in and discarded
// on the way out, so their row transforms are skipped (a pruned 2D FFT: row
// r2c on the ny data rows, then c2c along ky over all 2ny rows; the inverse
// in reverse order). In 2D the spectrum is transposed (kx-major, as
// RealFft's FftLayout::transposed): the rows go 16 at a time through a
// small buffer per thread and are scattered into the kx blocks, whose
// transforms then run on contiguous memory. A 1D block (ny = 1) is one
// padded row.
#pragma once

#include <complex>
#include <cstddef>
#include <functional>
#include <span>

#include "halfspace/fft/fft_planning.hpp"

struct fftw_plan_s;

namespace halfspace::fft {

class PaddedRealFft {
 public:
  // For a block of `rows` x `cols` (rows = 1: a 1D block of `cols` values).
  // Plans under FFTW's planner lock with the thread count in force, like
  // RealFft. Throws InputError if an extent is 0 or too large for FFTW.
  PaddedRealFft(std::size_t rows, std::size_t cols, FftPlanning planning);
  ~PaddedRealFft();
  PaddedRealFft(const PaddedRealFft&) = delete;
  PaddedRealFft& operator=(const PaddedRealFft&) = delete;

  std::size_t block_rows() const { return block_rows_; }
  std::size_t block_cols() const { return block_cols_; }
  // The padded transform: spectrum_rows() row wavenumbers (the 2ny, or 1,
  // padded rows) by spectrum_cols() column wavenumbers, held as
  // spectrum_blocks() x spectrum_length(): in 2D transposed, each kx a block
  // of every ky (entry (ky, kx) at kx * spectrum_rows() + ky); in 1D one row.
  std::size_t spectrum_rows() const { return block_rows_ == 1 ? 1 : 2 * block_rows_; }
  std::size_t spectrum_cols() const { return block_cols_ + 1; }
  std::size_t spectrum_size() const { return spectrum_rows() * spectrum_cols(); }
  bool transposed() const { return block_rows_ > 1; }
  std::size_t spectrum_blocks() const { return transposed() ? spectrum_cols() : 1; }
  std::size_t spectrum_length() const { return transposed() ? spectrum_rows() : spectrum_cols(); }
  // Number of padded points, the N of backward(forward(x)) = N x.
  std::size_t padded_size() const { return spectrum_rows() * 2 * block_cols_; }

  std::span<std::complex<double>> spectrum() { return {spectrum_, spectrum_size()}; }

  // spectrum = DFT of `block` (row-major, block_rows() x block_cols()) padded with zeros.
  void forward(std::span<const double> block);
  // For one-off transforms of a full padded array (a kernel's coefficients):
  // `fill(first, rows, row)` writes padded rows [first, first + rows) into
  // row(i) (2 block_cols() values each; i counted from first), called for
  // blocks of rows, possibly at once on several threads; then the spectrum
  // is the DFT of all spectrum_rows() rows.
  using Row = std::function<std::span<double>(std::size_t i)>;
  using Rows = std::function<void(std::size_t first, std::size_t rows, const Row& row)>;
  void forward_rows(const Rows& fill);
  // `block` = the block part of the unnormalised inverse DFT of the spectrum,
  // which it destroys.
  void backward(std::span<double> block);

 private:
  void release() noexcept;
  // The real rows of a thread's buffer (2D: a block of rows,
  // src/fft/row_blocks.hpp) or the one row (1D), each real_stride() values:
  // 2 block_cols() and room for the r2c's last entry.
  std::size_t real_stride() const { return 2 * spectrum_cols(); }
  double* buffer_row(int thread, std::size_t r) const;
  // 2D: the row transforms of a thread's count buffer rows (in place), and
  // their spectra scattered into rows [first, first + count) of the kx
  // blocks, or gathered from there.
  void scatter_rows(int thread, std::size_t first, std::size_t count);
  void gather_rows(int thread, std::size_t first, std::size_t count);
  // The plan of `plans` (rows_forward_ or rows_backward_) for a block of
  // `count` rows.
  fftw_plan_s* plan_for(fftw_plan_s* const* plans, std::size_t count) const;

  std::size_t block_rows_;
  std::size_t block_cols_;
  std::complex<double>* spectrum_ = nullptr;
  double* real_ = nullptr;  // 2D: a block of rows per thread; 1D: the padded row
  int buffers_ = 1;         // threads with a buffer (2D)
  // r2c in a buffer (in place) of a full block of rows, of the data rows left
  // over and of all padded rows left over (1D: the row, into the spectrum);
  // c2r of the first two.
  fftw_plan_s* rows_forward_[3] = {};
  fftw_plan_s* rows_backward_[2] = {};
  fftw_plan_s* columns_forward_ = nullptr;  // 2D: c2c of each kx block, in place
  fftw_plan_s* columns_backward_ = nullptr;
};

}  // namespace halfspace::fft

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using fft::PaddedRealFft;
}  // namespace halfspace
