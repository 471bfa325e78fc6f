// The DFT of a real (ny, nx) block zero-padded to (2ny, 2nx), and its inverse
// restricted back to the block: the transforms of the free-boundary (DC-FFT)
// convolution. Half of the padded rows are zero on the way in and discarded
// on the way out, so their row transforms are skipped (a pruned 2D FFT: row
// r2c on the ny data rows, then column c2c over all 2ny rows; the inverse in
// reverse order). A 1D block (ny = 1) is one padded row.
#pragma once

#include <complex>
#include <cstddef>
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
  // The padded transform: (spectrum_rows(), spectrum_cols()) complex values,
  // row r holding the row wavenumber r of the 2ny (or 1) padded rows.
  std::size_t spectrum_rows() const { return block_rows_ == 1 ? 1 : 2 * block_rows_; }
  std::size_t spectrum_cols() const { return block_cols_ + 1; }
  std::size_t spectrum_size() const { return spectrum_rows() * spectrum_cols(); }
  // Number of padded points, the N of backward(forward(x)) = N x.
  std::size_t padded_size() const { return spectrum_rows() * 2 * block_cols_; }

  std::span<std::complex<double>> spectrum() { return {spectrum_, spectrum_size()}; }

  // spectrum = DFT of `block` (row-major, block_rows() x block_cols()) padded with zeros.
  void forward(std::span<const double> block);
  // For one-off transforms of a full padded array (a kernel's coefficients):
  // row r (0 <= r < spectrum_rows()) of 2 block_cols() real values to fill,
  // then forward_all_rows() = the DFT of all of them, every row transformed
  // (its row plan is made on the first call, with estimate planning, and kept).
  std::span<double> padded_row(std::size_t r) { return {real_row(r), 2 * block_cols_}; }
  void forward_all_rows();
  // `block` = the block part of the unnormalised inverse DFT of the spectrum,
  // which it destroys.
  void backward(std::span<double> block);

 private:
  void release() noexcept;
  std::size_t real_stride() const { return 2 * spectrum_cols(); }
  double* real_row(std::size_t r) { return real_ + r * real_stride(); }

  std::size_t block_rows_;
  std::size_t block_cols_;
  std::complex<double>* spectrum_ = nullptr;
  double* real_ = nullptr;                  // the real rows: over the spectrum (2D), or a buffer of their own (1D)
  fftw_plan_s* rows_forward_ = nullptr;     // r2c of the block_rows() data rows
  fftw_plan_s* rows_backward_ = nullptr;    // c2r of the same rows
  fftw_plan_s* columns_forward_ = nullptr;  // c2c down all spectrum_rows(); none in 1D
  fftw_plan_s* columns_backward_ = nullptr;
  fftw_plan_s* all_rows_forward_ = nullptr;  // r2c of all spectrum_rows() rows: forward_all_rows
};

}  // namespace halfspace::fft

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using fft::PaddedRealFft;
}  // namespace halfspace
