// Pruned zero-padded 2D real FFT. In place in one complex buffer of
// (2ny, nx + 1) entries: the forward transform writes the data rows as real
// rows at stride 2 (nx + 1), transforms them (r2c), zeroes the padding rows'
// spectra, then transforms the columns; the inverse runs the columns and then
// only the data rows back (c2r). FFTW's full 2D transform would also
// transform the ny zero rows and the ny discarded ones: about a quarter of its
// work, measured in docs/development-log.md.
#include "halfspace/fft/padded_real_fft.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <mutex>
#include <new>
#include <stdexcept>

#include "fftw_planner.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/threads.hpp"

namespace halfspace::fft {

using detail::as_fftw;

namespace {

// howmany rows of length n: real rows at `real_stride` (in place over the
// spectrum, or a buffer of their own), spectra at stride n/2 + 1.
fftw_plan row_plan(bool forward, int n, int howmany, double* real, int real_stride, std::complex<double>* spectrum,
                   unsigned flags) {
  const int dims[1] = {n};
  const int spectrum_stride = n / 2 + 1;
  if (forward) {
    return fftw_plan_many_dft_r2c(1, dims, howmany, real, nullptr, 1, real_stride, as_fftw(spectrum), nullptr, 1,
                                  spectrum_stride, flags);
  }
  return fftw_plan_many_dft_c2r(1, dims, howmany, as_fftw(spectrum), nullptr, 1, spectrum_stride, real, nullptr, 1,
                                real_stride, flags);
}

// All columns (cols of them, length rows) of the row-major complex buffer.
fftw_plan column_plan(int sign, int rows, int cols, std::complex<double>* buffer, unsigned flags) {
  const int dims[1] = {rows};
  return fftw_plan_many_dft(1, dims, cols, as_fftw(buffer), nullptr, cols, 1, as_fftw(buffer), nullptr, cols, 1, sign,
                            flags);
}

}  // namespace

PaddedRealFft::PaddedRealFft(std::size_t rows, std::size_t cols, FftPlanning planning)
    : block_rows_(rows), block_cols_(cols) {
  const int padded_cols = detail::checked_extent(2 * cols);
  const int data_rows = detail::checked_extent(rows);
  const int padded_rows = detail::checked_extent(spectrum_rows());
  const int spectrum_columns = detail::checked_extent(spectrum_cols());
  bool planned = false;
  {
    const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
    detail::init_fftw_threads();
    spectrum_ = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(spectrum_size()));
    // A 2D block's rows live in place over the spectrum (the memory that
    // matters); a line gets its own real buffer, where FFTW's threaded 1D
    // plans are faster out of place.
    real_ = rows == 1 ? fftw_alloc_real(2 * cols + 2) : reinterpret_cast<double*>(spectrum_);
    if (spectrum_ != nullptr && real_ != nullptr) {
      fftw_plan_with_nthreads(threads());
      detail::before_planning(planning);
      const unsigned flags = detail::planner_flags(planning) | FFTW_DESTROY_INPUT;
      const int stride = detail::checked_extent(real_stride());
      rows_forward_ = row_plan(true, padded_cols, data_rows, real_, stride, spectrum_, flags);
      rows_backward_ = row_plan(false, padded_cols, data_rows, real_, stride, spectrum_, flags);
      planned = rows_forward_ != nullptr && rows_backward_ != nullptr;
      if (rows > 1) {
        columns_forward_ = column_plan(FFTW_FORWARD, padded_rows, spectrum_columns, spectrum_, flags);
        columns_backward_ = column_plan(FFTW_BACKWARD, padded_rows, spectrum_columns, spectrum_, flags);
        planned = planned && columns_forward_ != nullptr && columns_backward_ != nullptr;
      }
      if (planned) detail::after_planning(planning);
    }
  }
  if (spectrum_ == nullptr || real_ == nullptr) {
    release();
    throw std::bad_alloc();
  }
  if (!planned) {
    release();
    throw std::runtime_error(fmt::format("FFTW could not plan a padded real FFT of a {}x{} block", rows, cols));
  }
  std::fill_n(spectrum_, spectrum_size(), std::complex<double>(0.0, 0.0));
  if (rows == 1) std::fill_n(real_, 2 * cols + 2, 0.0);
}

PaddedRealFft::~PaddedRealFft() {
  release();
}

void PaddedRealFft::forward(std::span<const double> block) {
  assert(block.size() == block_rows_ * block_cols_);
  const std::size_t nx = block_cols_;
  const std::size_t stride = real_stride();
  if (block_rows_ == 1) {  // one long row: split it between the threads
    linalg::for_each_index(stride, [&](std::size_t i) { real_[i] = i < nx ? block[i] : 0.0; });
  } else {
    linalg::for_each_row(block_rows_, stride, [&](std::size_t j) {
      double* row = real_row(j);
      std::copy_n(block.data() + j * nx, nx, row);
      std::fill(row + nx, row + stride, 0.0);
    });
  }
  fftw_execute(rows_forward_);
  if (columns_forward_ == nullptr) return;
  // The padding rows are zero, and so are their row transforms.
  const std::size_t cols = spectrum_cols();
  linalg::for_each_row(spectrum_rows() - block_rows_, cols, [&](std::size_t k) {
    std::fill_n(spectrum_ + (block_rows_ + k) * cols, cols, std::complex<double>(0.0, 0.0));
  });
  fftw_execute(columns_forward_);
}

void PaddedRealFft::forward_all_rows() {
  // The two values past each row's end pad it to the in-place stride.
  for (std::size_t r = 0; r < spectrum_rows(); ++r) std::fill_n(real_row(r) + 2 * block_cols_, 2, 0.0);
  // Planned on the first call and kept: a user that transforms coefficients
  // at every depth (the subsurface stresses) plans once.
  if (all_rows_forward_ == nullptr) {
    const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
    fftw_plan_with_nthreads(threads());
    all_rows_forward_ = row_plan(true, static_cast<int>(2 * block_cols_), static_cast<int>(spectrum_rows()), real_,
                                 static_cast<int>(real_stride()), spectrum_, FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
  }
  if (all_rows_forward_ == nullptr) throw std::runtime_error("FFTW could not plan the rows of a padded real FFT");
  fftw_execute(all_rows_forward_);
  if (columns_forward_ != nullptr) fftw_execute(columns_forward_);
}

void PaddedRealFft::backward(std::span<double> block) {
  assert(block.size() == block_rows_ * block_cols_);
  if (columns_backward_ != nullptr) fftw_execute(columns_backward_);
  fftw_execute(rows_backward_);
  const std::size_t nx = block_cols_;
  if (block_rows_ == 1) {
    linalg::for_each_index(nx, [&](std::size_t i) { block[i] = real_[i]; });
  } else {
    linalg::for_each_row(block_rows_, nx, [&](std::size_t j) { std::copy_n(real_row(j), nx, block.data() + j * nx); });
  }
}

void PaddedRealFft::release() noexcept {
  const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
  for (fftw_plan_s** plan :
       {&rows_forward_, &rows_backward_, &columns_forward_, &columns_backward_, &all_rows_forward_}) {
    if (*plan != nullptr) fftw_destroy_plan(*plan);
    *plan = nullptr;
  }
  if (real_ != reinterpret_cast<double*>(spectrum_)) fftw_free(real_);
  fftw_free(spectrum_);
  spectrum_ = nullptr;
  real_ = nullptr;
}

}  // namespace halfspace::fft
