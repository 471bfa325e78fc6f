// Pruned zero-padded 2D real FFT. The forward transform takes the data rows
// 16 at a time into a small buffer per thread, zero-padded to 2nx,
// transforms them there (r2c in place) and scatters their spectra into the
// kx blocks of the transposed spectrum; the padding rows' entries are zero;
// then each kx block (2ny entries, contiguous) is transformed (c2c). The
// inverse runs the kx blocks and then only the data rows back (c2r). FFTW's
// full 2D transform would also transform the ny zero rows and the ny
// discarded ones (about a quarter of its work, docs/development-log.md), and
// its column pass strides a row apart (RealFft's FftLayout::transposed).
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
#include "row_blocks.hpp"

namespace halfspace::fft {

using detail::as_fftw;
using detail::kBlockRows;

namespace {

// howmany rows of length n: real rows at `real_stride` (in place over
// `spectrum`, or a buffer of their own), spectra at stride n/2 + 1.
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

// Each of `blocks` contiguous blocks of `length` values, in place.
fftw_plan block_plan(int sign, int length, int blocks, std::complex<double>* buffer, unsigned flags) {
  const int dims[1] = {length};
  return fftw_plan_many_dft(1, dims, blocks, as_fftw(buffer), nullptr, 1, length, as_fftw(buffer), nullptr, 1, length,
                            sign, flags);
}

}  // namespace

PaddedRealFft::PaddedRealFft(std::size_t rows, std::size_t cols, FftPlanning planning)
    : block_rows_(rows), block_cols_(cols) {
  const int padded_cols = detail::checked_extent(2 * cols);
  detail::checked_extent(rows);
  const int padded_rows = detail::checked_extent(spectrum_rows());
  const int spectrum_columns = detail::checked_extent(spectrum_cols());
  const int stride = detail::checked_extent(real_stride());
  bool allocated = false;
  bool planned = false;
  {
    const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
    detail::init_fftw_threads();
    spectrum_ = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(spectrum_size()));
    if (spectrum_ != nullptr) detail::advise_huge_pages(spectrum_, spectrum_size() * sizeof(std::complex<double>));
    const int team = detail::transform_threads((rows == 1 ? 1 : 2 * rows) * 2 * cols);  // the padded grid's reals
    buffers_ = rows == 1 ? 1 : team;
    real_ = fftw_alloc_real((rows == 1 ? 1 : static_cast<std::size_t>(buffers_) * kBlockRows) * real_stride());
    allocated = spectrum_ != nullptr && real_ != nullptr;
    if (allocated) {
      detail::before_planning(planning);
      const unsigned flags = detail::planner_flags(planning) | FFTW_DESTROY_INPUT;
      if (rows == 1) {
        // One long row: FFTW's threaded 1D plans, out of place.
        fftw_plan_with_nthreads(team);
        rows_forward_[0] = row_plan(true, padded_cols, 1, real_, stride, spectrum_, flags);
        rows_backward_[0] = row_plan(false, padded_cols, 1, real_, stride, spectrum_, flags);
        planned = rows_forward_[0] != nullptr && rows_backward_[0] != nullptr;
      } else {
        // The rows' plans run one per thread (detail::for_each_row_block), in place
        // in the thread's buffer.
        fftw_plan_with_nthreads(1);
        auto* in_buffer = reinterpret_cast<std::complex<double>*>(real_);
        const std::size_t counts[3] = {2 * rows >= kBlockRows ? kBlockRows : 0, rows % kBlockRows,
                                       (2 * rows) % kBlockRows};
        planned = true;
        for (int k = 0; k < 3; ++k) {
          if (counts[k] == 0) continue;
          const int count = static_cast<int>(counts[k]);
          rows_forward_[k] = row_plan(true, padded_cols, count, real_, stride, in_buffer, flags);
          planned = planned && rows_forward_[k] != nullptr;
          if (k < 2) {
            rows_backward_[k] = row_plan(false, padded_cols, count, real_, stride, in_buffer, flags);
            planned = planned && rows_backward_[k] != nullptr;
          }
        }
        fftw_plan_with_nthreads(team);
        columns_forward_ = block_plan(FFTW_FORWARD, padded_rows, spectrum_columns, spectrum_, flags);
        columns_backward_ = block_plan(FFTW_BACKWARD, padded_rows, spectrum_columns, spectrum_, flags);
        planned = planned && columns_forward_ != nullptr && columns_backward_ != nullptr;
      }
      if (planned) detail::after_planning(planning);
    }
  }
  if (!allocated) {
    release();
    throw std::bad_alloc();
  }
  if (!planned) {
    release();
    throw std::runtime_error(fmt::format("FFTW could not plan a padded real FFT of a {}x{} block", rows, cols));
  }
  std::fill_n(spectrum_, spectrum_size(), std::complex<double>(0.0, 0.0));
  std::fill_n(real_, (rows == 1 ? 1 : static_cast<std::size_t>(buffers_) * kBlockRows) * real_stride(), 0.0);
}

PaddedRealFft::~PaddedRealFft() {
  release();
}

fftw_plan_s* PaddedRealFft::plan_for(fftw_plan_s* const* plans, std::size_t count) const {
  if (count == kBlockRows) return plans[0];
  return count == block_rows_ % kBlockRows ? plans[1] : plans[2];
}

double* PaddedRealFft::buffer_row(int thread, std::size_t r) const {
  return real_ + (static_cast<std::size_t>(thread) * kBlockRows + r) * real_stride();
}

void PaddedRealFft::scatter_rows(int thread, std::size_t first, std::size_t count) {
  double* const real = buffer_row(thread, 0);
  fftw_execute_dft_r2c(plan_for(rows_forward_, count), real, as_fftw(reinterpret_cast<std::complex<double>*>(real)));
  const auto* spectra = reinterpret_cast<const std::complex<double>*>(real);
  detail::scatter_block(spectra, spectrum_cols(), spectrum_, spectrum_rows(), first, count, false);
}

void PaddedRealFft::gather_rows(int thread, std::size_t first, std::size_t count) {
  double* const real = buffer_row(thread, 0);
  auto* const spectra = reinterpret_cast<std::complex<double>*>(real);
  detail::gather_block(static_cast<const std::complex<double>*>(spectrum_), spectrum_rows(), spectra, spectrum_cols(),
                       first, count);
  fftw_execute_dft_c2r(plan_for(rows_backward_, count), as_fftw(spectra), real);
}

void PaddedRealFft::forward(std::span<const double> block) {
  assert(block.size() == block_rows_ * block_cols_);
  const std::size_t nx = block_cols_;
  if (block_rows_ == 1) {  // one long row: split it between the threads
    linalg::for_each_index(real_stride(), [&](std::size_t i) { real_[i] = i < nx ? block[i] : 0.0; });
    fftw_execute(rows_forward_[0]);
    return;
  }
  detail::for_each_row_block(block_rows_, buffers_, [&](int thread, std::size_t first, std::size_t count) {
    for (std::size_t r = 0; r < count; ++r) {
      double* const row = buffer_row(thread, r);
      std::copy_n(block.data() + (first + r) * nx, nx, row);
      std::fill(row + nx, row + 2 * nx, 0.0);
    }
    scatter_rows(thread, first, count);
  });
  // The padding rows are zero, and so are their row transforms.
  const std::size_t length = spectrum_rows();
  linalg::for_each_row(spectrum_cols(), length - block_rows_, [&](std::size_t c) {
    std::fill_n(spectrum_ + c * length + block_rows_, length - block_rows_, std::complex<double>(0.0, 0.0));
  });
  fftw_execute(columns_forward_);
}

void PaddedRealFft::forward_rows(const Rows& fill) {
  const std::size_t width = 2 * block_cols_;
  if (block_rows_ == 1) {
    fill(0, 1, [&](std::size_t) { return std::span<double>(real_, width); });
    fftw_execute(rows_forward_[0]);
    return;
  }
  detail::for_each_row_block(spectrum_rows(), buffers_, [&](int thread, std::size_t first, std::size_t count) {
    fill(first, count, [&](std::size_t i) { return std::span<double>(buffer_row(thread, i), width); });
    scatter_rows(thread, first, count);
  });
  fftw_execute(columns_forward_);
}

void PaddedRealFft::backward(std::span<double> block) {
  assert(block.size() == block_rows_ * block_cols_);
  const std::size_t nx = block_cols_;
  if (block_rows_ == 1) {
    fftw_execute(rows_backward_[0]);
    linalg::for_each_index(nx, [&](std::size_t i) { block[i] = real_[i]; });
    return;
  }
  fftw_execute(columns_backward_);
  detail::for_each_row_block(block_rows_, buffers_, [&](int thread, std::size_t first, std::size_t count) {
    gather_rows(thread, first, count);
    for (std::size_t r = 0; r < count; ++r) std::copy_n(buffer_row(thread, r), nx, block.data() + (first + r) * nx);
  });
}

void PaddedRealFft::release() noexcept {
  const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
  for (fftw_plan_s** plan : {&rows_forward_[0], &rows_forward_[1], &rows_forward_[2], &rows_backward_[0],
                             &rows_backward_[1], &columns_forward_, &columns_backward_}) {
    if (*plan != nullptr) fftw_destroy_plan(*plan);
    *plan = nullptr;
  }
  fftw_free(real_);
  fftw_free(spectrum_);
  spectrum_ = nullptr;
  real_ = nullptr;
}

}  // namespace halfspace::fft
