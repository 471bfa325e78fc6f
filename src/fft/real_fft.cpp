// RAII plan pair for real FFTs, in double and single precision (one
// template over FFTW's fftw_ and fftwf_ calls, fftw_planner.hpp). FFTW's
// planner (and plan destruction) is not thread-safe, so every call into it
// here is serialised by one mutex; only the execution runs unlocked.
// Measured planning loads and saves wisdom (fft_wisdom.cpp) under the same
// lock. A transposed 2D transform (FftLayout::transposed) runs the rows in
// blocks on the threads itself and the kx blocks through one threaded plan.
#include "halfspace/fft/real_fft.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <climits>
#include <cstdint>
#include <mutex>
#include <new>
#if defined(__linux__)
#include <sys/mman.h>
#endif
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "fftw_planner.hpp"
#include "halfspace/error.hpp"
#include "halfspace/threads.hpp"
#include "row_blocks.hpp"

namespace halfspace::fft {
namespace detail {

std::mutex& fftw_planner_mutex() {
  static std::mutex mutex;
  return mutex;
}

void init_fftw_threads() {
  static bool initialised = false;
  if (!initialised) {
    if (fftw_init_threads() == 0 || fftwf_init_threads() == 0) {
      throw std::runtime_error("FFTW thread support could not be initialised");
    }
    initialised = true;
  }
}

int transform_threads(std::size_t reals) {
  return reals < kMinRealsForThreads ? 1 : std::max(1, threads());
}

unsigned planner_flags(FftPlanning planning) {
  switch (planning) {
    case FftPlanning::measure:
      return FFTW_MEASURE;
    case FftPlanning::patient:
      return FFTW_PATIENT;
    case FftPlanning::estimate:
      break;
  }
  return FFTW_ESTIMATE;
}

void advise_huge_pages(void* memory, std::size_t bytes) {
#if defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kPage = 4096;
  const auto begin = (reinterpret_cast<std::uintptr_t>(memory) + kPage - 1) & ~(kPage - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(memory) + bytes) & ~(kPage - 1);
  // Advice only: where the kernel refuses it, the memory keeps small pages.
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)memory;
  (void)bytes;
#endif
}

int checked_extent(std::size_t n) {
  if (n < 1 || n > static_cast<std::size_t>(INT_MAX)) {
    throw InputError(fmt::format("FFT length {} is invalid: must be between 1 and {}", n, INT_MAX));
  }
  return static_cast<int>(n);
}

}  // namespace detail

using detail::as_fftw;
using detail::checked_extent;
using detail::kBlockRows;
using detail::planner_flags;

// Whether Real is single precision (its wisdom is kept apart).
template <class Real>
constexpr bool kSingle = std::is_same_v<Real, float>;
template <class Real>
using F = detail::Fftw<Real>;

template <class Real>
BasicRealFft<Real>::BasicRealFft(std::size_t n, FftPlanning planning, FftOutput output) : rows_(1), cols_(n) {
  const int dims[1] = {checked_extent(n)};
  make_plans(1, dims, planning, output);
}

template <class Real>
BasicRealFft<Real>::BasicRealFft(std::size_t rows, std::size_t cols, FftPlanning planning, FftOutput output,
                                 FftLayout layout)
    : rows_(rows), cols_(cols), transposed_(layout == FftLayout::transposed && rows > 1) {
  const int dims[2] = {checked_extent(rows), checked_extent(cols)};
  make_plans(2, dims, planning, output);
}

template <class Real>
BasicRealFft<Real>::BasicRealFft(std::size_t rows, std::size_t cols, FftPlanning planning,
                                 std::span<std::complex<Real>> workspace, FftLayout layout)
    : rows_(rows), cols_(cols), transposed_(layout == FftLayout::transposed && rows > 1) {
  const std::size_t needed = workspace_size(rows, cols);
  if (workspace.size() < needed) {
    throw InputError(fmt::format("a {}x{} real FFT needs a workspace of {} complex values, but was given {}", rows,
                                 cols, needed, workspace.size()));
  }
  const int dims[2] = {checked_extent(rows), checked_extent(cols)};
  if (rows == 1) {
    make_plans(1, dims + 1, planning, FftOutput::overwrite_input, workspace.data());
  } else {
    make_plans(2, dims, planning, FftOutput::overwrite_input, workspace.data());
  }
}

template <class Real>
BasicRealFft<Real>::~BasicRealFft() {
  release();
}

template <class Real>
BasicRealFft<Real>::BasicRealFft(BasicRealFft&& other) noexcept
    : rows_(std::exchange(other.rows_, 0)),
      cols_(std::exchange(other.cols_, 0)),
      input_(std::exchange(other.input_, nullptr)),
      spectrum_(std::exchange(other.spectrum_, nullptr)),
      output_(std::exchange(other.output_, nullptr)),
      forward_plan_(std::exchange(other.forward_plan_, nullptr)),
      backward_plan_(std::exchange(other.backward_plan_, nullptr)),
      transposed_(std::exchange(other.transposed_, false)),
      rows_forward_{std::exchange(other.rows_forward_[0], nullptr), std::exchange(other.rows_forward_[1], nullptr)},
      rows_backward_{std::exchange(other.rows_backward_[0], nullptr), std::exchange(other.rows_backward_[1], nullptr)},
      row_buffers_(std::exchange(other.row_buffers_, nullptr)),
      row_reals_(std::exchange(other.row_reals_, nullptr)),
      columns_forward_{std::exchange(other.columns_forward_[0], nullptr),
                       std::exchange(other.columns_forward_[1], nullptr)},
      columns_backward_{std::exchange(other.columns_backward_[0], nullptr),
                        std::exchange(other.columns_backward_[1], nullptr)},
      columns_aligned_(std::exchange(other.columns_aligned_, false)),
      streaming_(std::exchange(other.streaming_, false)),
      team_(other.team_),
      owns_buffers_(std::exchange(other.owns_buffers_, true)),
      lazy_input_(std::exchange(other.lazy_input_, false)),
      input_alignment_(other.input_alignment_),
      output_alignment_(other.output_alignment_) {}

template <class Real>
BasicRealFft<Real>& BasicRealFft<Real>::operator=(BasicRealFft&& other) noexcept {
  if (this != &other) {
    release();
    rows_ = std::exchange(other.rows_, 0);
    cols_ = std::exchange(other.cols_, 0);
    input_ = std::exchange(other.input_, nullptr);
    spectrum_ = std::exchange(other.spectrum_, nullptr);
    output_ = std::exchange(other.output_, nullptr);
    forward_plan_ = std::exchange(other.forward_plan_, nullptr);
    backward_plan_ = std::exchange(other.backward_plan_, nullptr);
    transposed_ = std::exchange(other.transposed_, false);
    for (int k = 0; k < 2; ++k) {
      rows_forward_[k] = std::exchange(other.rows_forward_[k], nullptr);
      rows_backward_[k] = std::exchange(other.rows_backward_[k], nullptr);
      columns_forward_[k] = std::exchange(other.columns_forward_[k], nullptr);
      columns_backward_[k] = std::exchange(other.columns_backward_[k], nullptr);
    }
    columns_aligned_ = std::exchange(other.columns_aligned_, false);
    streaming_ = std::exchange(other.streaming_, false);
    row_buffers_ = std::exchange(other.row_buffers_, nullptr);
    row_reals_ = std::exchange(other.row_reals_, nullptr);
    team_ = other.team_;
    owns_buffers_ = std::exchange(other.owns_buffers_, true);
    lazy_input_ = std::exchange(other.lazy_input_, false);
    input_alignment_ = other.input_alignment_;
    output_alignment_ = other.output_alignment_;
  }
  return *this;
}

template <class Real>
void BasicRealFft<Real>::make_plans(int rank, const int* dims, FftPlanning planning, FftOutput output,
                                    std::complex<Real>* workspace) {
  bool allocated = false;
  bool planned = false;
  {
    const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
    detail::init_fftw_threads();
    owns_buffers_ = workspace == nullptr;
    if (owns_buffers_) {
      spectrum_ = reinterpret_cast<std::complex<Real>*>(F<Real>::alloc_complex(spectrum_size()));
      input_ = F<Real>::alloc_real(real_size());
      if (spectrum_ != nullptr) detail::advise_huge_pages(spectrum_, spectrum_size() * sizeof(std::complex<Real>));
    } else {
      spectrum_ = workspace;
      input_ = reinterpret_cast<Real*>(workspace + spectrum_size());
    }
    output_ = output == FftOutput::separate ? F<Real>::alloc_real(real_size()) : input_;
    allocated = input_ != nullptr && output_ != nullptr && spectrum_ != nullptr;
    if (allocated) {
      team_ = detail::transform_threads(real_size());
      F<Real>::plan_with_nthreads(team_);
      detail::before_planning(planning, kSingle<Real>);
      const unsigned flags = planner_flags(planning);
      if (transposed_) {
        planned = make_transposed_plans(flags);
      } else {
        // Out of place both ways: r2c keeps its input (forward_from() relies on
        // it); c2r may destroy the spectrum, which every forward() rewrites.
        forward_plan_ = F<Real>::plan_r2c(rank, dims, input_, as_fftw(spectrum_), flags | FFTW_PRESERVE_INPUT);
        backward_plan_ = F<Real>::plan_c2r(rank, dims, as_fftw(spectrum_), output_, flags | FFTW_DESTROY_INPUT);
        planned = forward_plan_ != nullptr && backward_plan_ != nullptr;
      }
      if (planned) detail::after_planning(planning, kSingle<Real>);
    }
  }
  if (!allocated) {
    release();
    throw std::bad_alloc();
  }
  if (!planned) {
    release();
    throw std::runtime_error(fmt::format("FFTW could not plan a real FFT of size {}x{}", rows_, cols_));
  }
  input_alignment_ = F<Real>::alignment_of(input_);
  output_alignment_ = F<Real>::alignment_of(output_);
  // Measuring planners run trial transforms over the buffers.
  std::fill_n(spectrum_, spectrum_size(), std::complex<Real>(0, 0));
  if (owns_buffers_ && output == FftOutput::overwrite_input) {
    // The solvers transform their own arrays: the real array, planned over,
    // is given back until something asks for it (real_input()).
    const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
    F<Real>::free(input_);
    input_ = nullptr;
    output_ = nullptr;
    lazy_input_ = true;
    return;
  }
  std::fill_n(input_, real_size(), Real{0});
  if (output_ != input_) std::fill_n(output_, real_size(), Real{0});
}

template <class Real>
bool BasicRealFft<Real>::make_transposed_plans(unsigned flags) {
  const int rows = static_cast<int>(rows_);
  const int cols = static_cast<int>(cols_);
  const int h = static_cast<int>(spectrum_cols());
  // Streaming stores need entries aligned to their size (a workspace's may not be).
  streaming_ = reinterpret_cast<std::uintptr_t>(spectrum_) % sizeof(std::complex<Real>) == 0 &&
               spectrum_size() * sizeof(std::complex<Real>) > detail::kStreamingSpectrumBytes;
  row_buffers_ = reinterpret_cast<std::complex<Real>*>(
      F<Real>::alloc_complex(static_cast<std::size_t>(team_) * kBlockRows * spectrum_cols()));
  if (row_buffers_ == nullptr) return false;
  if constexpr (!std::is_same_v<Real, double>) {
    row_reals_ = F<Real>::alloc_real(static_cast<std::size_t>(team_) * kBlockRows * cols_);
    if (row_reals_ == nullptr) return false;
  }
  // The rows' plans run one per thread, inside transposed_forward's loop.
  F<Real>::plan_with_nthreads(1);
  const int counts[2] = {rows >= static_cast<int>(kBlockRows) ? static_cast<int>(kBlockRows) : 0,
                         rows % static_cast<int>(kBlockRows)};
  for (int k = 0; k < 2; ++k) {
    if (counts[k] == 0) continue;
    rows_forward_[k] = F<Real>::plan_many_r2c(1, &cols, counts[k], input_, nullptr, 1, cols, as_fftw(row_buffers_),
                                              nullptr, 1, h, flags | FFTW_PRESERVE_INPUT);
    rows_backward_[k] = F<Real>::plan_many_c2r(1, &cols, counts[k], as_fftw(row_buffers_), nullptr, 1, h, output_,
                                               nullptr, 1, cols, flags | FFTW_DESTROY_INPUT);
    if (rows_forward_[k] == nullptr || rows_backward_[k] == nullptr) return false;
  }
  // The columns' plans for transform_columns, on one thread each.
  const int column_counts[2] = {h >= static_cast<int>(kColumnBlock) ? static_cast<int>(kColumnBlock) : 0, 1};
  for (int k = 0; k < 2; ++k) {
    if (column_counts[k] == 0) continue;
    columns_forward_[k] = F<Real>::plan_many_c2c(1, &rows, column_counts[k], as_fftw(spectrum_), nullptr, 1, rows,
                                                 as_fftw(spectrum_), nullptr, 1, rows, FFTW_FORWARD, flags);
    columns_backward_[k] = F<Real>::plan_many_c2c(1, &rows, column_counts[k], as_fftw(spectrum_), nullptr, 1, rows,
                                                  as_fftw(spectrum_), nullptr, 1, rows, FFTW_BACKWARD, flags);
    if (columns_forward_[k] == nullptr || columns_backward_[k] == nullptr) return false;
  }
  columns_aligned_ = F<Real>::alignment_of(reinterpret_cast<Real*>(spectrum_ + rows_)) ==
                     F<Real>::alignment_of(reinterpret_cast<Real*>(spectrum_));
  F<Real>::plan_with_nthreads(team_);
  forward_plan_ = F<Real>::plan_many_c2c(1, &rows, h, as_fftw(spectrum_), nullptr, 1, rows, as_fftw(spectrum_), nullptr,
                                         1, rows, FFTW_FORWARD, flags);
  backward_plan_ = F<Real>::plan_many_c2c(1, &rows, h, as_fftw(spectrum_), nullptr, 1, rows, as_fftw(spectrum_),
                                          nullptr, 1, rows, FFTW_BACKWARD, flags);
  return forward_plan_ != nullptr && backward_plan_ != nullptr;
}

template <class Real>
std::complex<Real>* BasicRealFft<Real>::row_buffer(int thread) const {
  return row_buffers_ + static_cast<std::size_t>(thread) * kBlockRows * spectrum_cols();
}

template <class Real>
Real* BasicRealFft<Real>::row_real(int thread) const {
  return row_reals_ + static_cast<std::size_t>(thread) * kBlockRows * cols_;
}

template <class Real>
void BasicRealFft<Real>::transposed_forward(const Real* in) {
  transposed_forward_rows(in);
  F<Real>::execute_c2c(forward_plan_, as_fftw(spectrum_), as_fftw(spectrum_));
}

template <class Real>
void BasicRealFft<Real>::transposed_forward_rows(const Real* in) {
  // Each block's rows into the thread's buffer, then scattered down the
  // kx blocks: count consecutive entries of each.
  detail::for_each_row_block(rows_, team_, [&](int thread, std::size_t first, std::size_t count) {
    std::complex<Real>* const buffer = row_buffer(thread);
    // Planned with FFTW_PRESERVE_INPUT: never written through.
    F<Real>::execute_r2c(rows_forward_[count == kBlockRows ? 0 : 1], const_cast<Real*>(in + first * cols_),
                         as_fftw(buffer));
    scatter_rows(buffer, first, count);
  });
}

template <class Real>
void BasicRealFft<Real>::scatter_rows(const std::complex<Real>* buffer, std::size_t first, std::size_t count) {
  detail::scatter_block(buffer, spectrum_cols(), spectrum_, rows_, first, count, streaming_);
}

template <class Real>
void BasicRealFft<Real>::gather_rows(std::complex<Real>* buffer, std::size_t first, std::size_t count) const {
  detail::gather_block(static_cast<const std::complex<Real>*>(spectrum_), rows_, buffer, spectrum_cols(), first, count);
}

template <class Real>
void BasicRealFft<Real>::transposed_backward(Real* out) {
  F<Real>::execute_c2c(backward_plan_, as_fftw(spectrum_), as_fftw(spectrum_));
  transposed_backward_rows(out);
}

template <class Real>
void BasicRealFft<Real>::transposed_backward_rows(Real* out) {
  detail::for_each_row_block(rows_, team_, [&](int thread, std::size_t first, std::size_t count) {
    std::complex<Real>* const buffer = row_buffer(thread);
    gather_rows(buffer, first, count);
    F<Real>::execute_c2r(rows_backward_[count == kBlockRows ? 0 : 1], as_fftw(buffer), out + first * cols_);
  });
}

template <class Real>
void BasicRealFft<Real>::forward_rows_from(std::span<const Real> values) {
  assert(columns_in_parts() && takes_input(values));
  transposed_forward_rows(values.data());
}

template <class Real>
bool BasicRealFft<Real>::takes_double_rows() const {
  return !std::is_same_v<Real, double> && columns_in_parts() && row_reals_ != nullptr &&
         F<Real>::alignment_of(row_reals_) == input_alignment_ &&
         F<Real>::alignment_of(row_reals_) == output_alignment_;
}

template <class Real>
void BasicRealFft<Real>::forward_rows_from(std::span<const double> values) requires(!std::is_same_v<Real, double>) {
  assert(takes_double_rows() && values.size() == real_size());
  detail::for_each_row_block(rows_, team_, [&](int thread, std::size_t first, std::size_t count) {
    Real* const real = row_real(thread);
    const double* const from = values.data() + first * cols_;
    for (std::size_t i = 0; i < count * cols_; ++i) real[i] = static_cast<Real>(from[i]);
    std::complex<Real>* const buffer = row_buffer(thread);
    F<Real>::execute_r2c(rows_forward_[count == kBlockRows ? 0 : 1], real, as_fftw(buffer));
    scatter_rows(buffer, first, count);
  });
}

template <class Real>
void BasicRealFft<Real>::backward_rows_into(std::span<double> values) requires(!std::is_same_v<Real, double>) {
  assert(takes_double_rows() && values.size() == real_size());
  detail::for_each_row_block(rows_, team_, [&](int thread, std::size_t first, std::size_t count) {
    std::complex<Real>* const buffer = row_buffer(thread);
    gather_rows(buffer, first, count);
    Real* const real = row_real(thread);
    F<Real>::execute_c2r(rows_backward_[count == kBlockRows ? 0 : 1], as_fftw(buffer), real);
    double* const to = values.data() + first * cols_;
    for (std::size_t i = 0; i < count * cols_; ++i) to[i] = real[i];
  });
}

template <class Real>
void BasicRealFft<Real>::transform_columns(std::size_t first, std::size_t count, bool forward) {
  assert(columns_in_parts() && first + count <= spectrum_cols());
  Plan const* plans = forward ? columns_forward_ : columns_backward_;
  std::complex<Real>* column = spectrum_ + first * rows_;
  for (; count >= kColumnBlock && plans[0] != nullptr; count -= kColumnBlock, column += kColumnBlock * rows_) {
    F<Real>::execute_c2c(plans[0], as_fftw(column), as_fftw(column));
  }
  for (; count > 0; --count, column += rows_) F<Real>::execute_c2c(plans[1], as_fftw(column), as_fftw(column));
}

template <class Real>
void BasicRealFft<Real>::backward_rows_into(std::span<Real> values) {
  assert(columns_in_parts() && takes_output(values));
  transposed_backward_rows(values.data());
}

template <class Real>
Real* BasicRealFft<Real>::real_input() {
  if (input_ == nullptr && lazy_input_) {
    Real* made = nullptr;
    {
      const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
      made = F<Real>::alloc_real(real_size());
    }
    if (made == nullptr) throw std::bad_alloc();
    std::fill_n(made, real_size(), Real{0});
    input_ = made;
    output_ = made;
  }
  return input_;
}

// New-array execution throughout: the real array may not be the one planned
// over (it is made on first use with FftOutput::overwrite_input), and FFTW
// allows any arrays of the planned alignment; FFTW's allocation gives that.
template <class Real>
void BasicRealFft<Real>::forward() {
  assert(forward_plan_ != nullptr);
  if (transposed_) {
    transposed_forward(real_input());
    return;
  }
  F<Real>::execute_r2c(forward_plan_, real_input(), as_fftw(spectrum_));
}

template <class Real>
void BasicRealFft<Real>::backward() {
  assert(backward_plan_ != nullptr);
  real_input();
  if (transposed_) {
    transposed_backward(output_);
    return;
  }
  F<Real>::execute_c2r(backward_plan_, as_fftw(spectrum_), output_);
}

template <class Real>
bool BasicRealFft<Real>::takes_input(std::span<const Real> values) const {
  return values.size() == real_size() && F<Real>::alignment_of(const_cast<Real*>(values.data())) == input_alignment_;
}

template <class Real>
bool BasicRealFft<Real>::takes_output(std::span<const Real> values) const {
  return values.size() == real_size() && F<Real>::alignment_of(const_cast<Real*>(values.data())) == output_alignment_;
}

template <class Real>
bool BasicRealFft<Real>::forward_from(std::span<const Real> values) {
  assert(forward_plan_ != nullptr);
  // The plan was made with FFTW_PRESERVE_INPUT, so the const_cast is never written through.
  Real* data = const_cast<Real*>(values.data());
  if (values.size() != real_size() || F<Real>::alignment_of(data) != input_alignment_) return false;
  if (transposed_) {
    transposed_forward(data);
    return true;
  }
  F<Real>::execute_r2c(forward_plan_, data, as_fftw(spectrum_));
  return true;
}

template <class Real>
bool BasicRealFft<Real>::backward_into(std::span<Real> values) {
  assert(backward_plan_ != nullptr);
  if (values.size() != real_size() || F<Real>::alignment_of(values.data()) != output_alignment_) {
    return false;
  }
  if (transposed_) {
    transposed_backward(values.data());
    return true;
  }
  F<Real>::execute_c2r(backward_plan_, as_fftw(spectrum_), values.data());
  return true;
}

template <class Real>
void BasicRealFft<Real>::release() noexcept {
  if (input_ == nullptr && output_ == nullptr && spectrum_ == nullptr && forward_plan_ == nullptr &&
      backward_plan_ == nullptr && row_buffers_ == nullptr && row_reals_ == nullptr) {
    return;
  }
  const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
  for (Plan* plan :
       {&forward_plan_, &backward_plan_, &rows_forward_[0], &rows_forward_[1], &rows_backward_[0], &rows_backward_[1],
        &columns_forward_[0], &columns_forward_[1], &columns_backward_[0], &columns_backward_[1]}) {
    if (*plan != nullptr) F<Real>::destroy_plan(*plan);
    *plan = nullptr;
  }
  F<Real>::free(row_buffers_);
  row_buffers_ = nullptr;
  F<Real>::free(row_reals_);
  row_reals_ = nullptr;
  if (output_ != input_) F<Real>::free(output_);
  if (owns_buffers_) {
    F<Real>::free(input_);
    F<Real>::free(spectrum_);
  }
  input_ = nullptr;
  output_ = nullptr;
  spectrum_ = nullptr;
}

template class BasicRealFft<double>;
template class BasicRealFft<float>;

}  // namespace halfspace::fft
