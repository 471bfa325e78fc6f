// RAII plan pair for real FFTs. FFTW's planner (and plan destruction) is not
// thread-safe, so every call into it here is serialised by one mutex; only
// fftw_execute runs unlocked. Measured planning loads and saves wisdom
// (fft_wisdom.cpp) under the same lock.
#include "halfspace/fft/real_fft.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <climits>
#include <mutex>
#include <new>
#include <stdexcept>
#include <utility>

#include "fftw_planner.hpp"
#include "halfspace/error.hpp"
#include "halfspace/threads.hpp"

namespace halfspace::fft {
namespace detail {

std::mutex& fftw_planner_mutex() {
  static std::mutex mutex;
  return mutex;
}

void init_fftw_threads() {
  static bool initialised = false;
  if (!initialised) {
    if (fftw_init_threads() == 0) throw std::runtime_error("FFTW thread support could not be initialised");
    initialised = true;
  }
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

int checked_extent(std::size_t n) {
  if (n < 1 || n > static_cast<std::size_t>(INT_MAX)) {
    throw InputError(fmt::format("FFT length {} is invalid: must be between 1 and {}", n, INT_MAX));
  }
  return static_cast<int>(n);
}

}  // namespace detail

using detail::as_fftw;
using detail::checked_extent;
using detail::planner_flags;

RealFft::RealFft(std::size_t n, FftPlanning planning, FftOutput output) : rows_(1), cols_(n) {
  const int dims[1] = {checked_extent(n)};
  make_plans(1, dims, planning, output);
}

RealFft::RealFft(std::size_t rows, std::size_t cols, FftPlanning planning, FftOutput output)
    : rows_(rows), cols_(cols) {
  const int dims[2] = {checked_extent(rows), checked_extent(cols)};
  make_plans(2, dims, planning, output);
}

RealFft::RealFft(std::size_t rows, std::size_t cols, FftPlanning planning, std::span<std::complex<double>> workspace)
    : rows_(rows), cols_(cols) {
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

RealFft::~RealFft() {
  release();
}

RealFft::RealFft(RealFft&& other) noexcept
    : rows_(std::exchange(other.rows_, 0)),
      cols_(std::exchange(other.cols_, 0)),
      input_(std::exchange(other.input_, nullptr)),
      spectrum_(std::exchange(other.spectrum_, nullptr)),
      output_(std::exchange(other.output_, nullptr)),
      forward_plan_(std::exchange(other.forward_plan_, nullptr)),
      backward_plan_(std::exchange(other.backward_plan_, nullptr)),
      owns_buffers_(std::exchange(other.owns_buffers_, true)),
      lazy_input_(std::exchange(other.lazy_input_, false)),
      input_alignment_(other.input_alignment_),
      output_alignment_(other.output_alignment_) {}

RealFft& RealFft::operator=(RealFft&& other) noexcept {
  if (this != &other) {
    release();
    rows_ = std::exchange(other.rows_, 0);
    cols_ = std::exchange(other.cols_, 0);
    input_ = std::exchange(other.input_, nullptr);
    spectrum_ = std::exchange(other.spectrum_, nullptr);
    output_ = std::exchange(other.output_, nullptr);
    forward_plan_ = std::exchange(other.forward_plan_, nullptr);
    backward_plan_ = std::exchange(other.backward_plan_, nullptr);
    owns_buffers_ = std::exchange(other.owns_buffers_, true);
    lazy_input_ = std::exchange(other.lazy_input_, false);
    input_alignment_ = other.input_alignment_;
    output_alignment_ = other.output_alignment_;
  }
  return *this;
}

void RealFft::make_plans(int rank, const int* dims, FftPlanning planning, FftOutput output,
                         std::complex<double>* workspace) {
  bool allocated = false;
  bool planned = false;
  {
    const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
    detail::init_fftw_threads();
    owns_buffers_ = workspace == nullptr;
    if (owns_buffers_) {
      spectrum_ = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(spectrum_size()));
      input_ = fftw_alloc_real(real_size());
    } else {
      spectrum_ = workspace;
      input_ = reinterpret_cast<double*>(workspace + spectrum_size());
    }
    output_ = output == FftOutput::separate ? fftw_alloc_real(real_size()) : input_;
    allocated = input_ != nullptr && output_ != nullptr && spectrum_ != nullptr;
    if (allocated) {
      fftw_plan_with_nthreads(threads());
      detail::before_planning(planning);
      const unsigned flags = planner_flags(planning);
      // Out of place both ways: r2c keeps its input (forward_from() relies on
      // it); c2r may destroy the spectrum, which every forward() rewrites.
      forward_plan_ = fftw_plan_dft_r2c(rank, dims, input_, as_fftw(spectrum_), flags | FFTW_PRESERVE_INPUT);
      backward_plan_ = fftw_plan_dft_c2r(rank, dims, as_fftw(spectrum_), output_, flags | FFTW_DESTROY_INPUT);
      planned = forward_plan_ != nullptr && backward_plan_ != nullptr;
      if (planned) detail::after_planning(planning);
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
  input_alignment_ = fftw_alignment_of(input_);
  output_alignment_ = fftw_alignment_of(output_);
  // Measuring planners run trial transforms over the buffers.
  std::fill_n(spectrum_, spectrum_size(), std::complex<double>(0.0, 0.0));
  if (owns_buffers_ && output == FftOutput::overwrite_input) {
    // The solvers transform their own arrays: the real array, planned over,
    // is given back until something asks for it (real_input()).
    const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
    fftw_free(input_);
    input_ = nullptr;
    output_ = nullptr;
    lazy_input_ = true;
    return;
  }
  std::fill_n(input_, real_size(), 0.0);
  if (output_ != input_) std::fill_n(output_, real_size(), 0.0);
}

double* RealFft::real_input() {
  if (input_ == nullptr && lazy_input_) {
    double* made = nullptr;
    {
      const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
      made = fftw_alloc_real(real_size());
    }
    if (made == nullptr) throw std::bad_alloc();
    std::fill_n(made, real_size(), 0.0);
    input_ = made;
    output_ = made;
  }
  return input_;
}

// New-array execution throughout: the real array may not be the one planned
// over (it is made on first use with FftOutput::overwrite_input), and FFTW
// allows any arrays of the planned alignment; fftw_alloc_real gives that.
void RealFft::forward() {
  assert(forward_plan_ != nullptr);
  fftw_execute_dft_r2c(forward_plan_, real_input(), as_fftw(spectrum_));
}

void RealFft::backward() {
  assert(backward_plan_ != nullptr);
  real_input();
  fftw_execute_dft_c2r(backward_plan_, as_fftw(spectrum_), output_);
}

bool RealFft::forward_from(std::span<const double> values) {
  assert(forward_plan_ != nullptr);
  // The plan was made with FFTW_PRESERVE_INPUT, so the const_cast is never written through.
  double* data = const_cast<double*>(values.data());
  if (values.size() != real_size() || fftw_alignment_of(data) != input_alignment_) return false;
  fftw_execute_dft_r2c(forward_plan_, data, as_fftw(spectrum_));
  return true;
}

bool RealFft::backward_into(std::span<double> values) {
  assert(backward_plan_ != nullptr);
  if (values.size() != real_size() || fftw_alignment_of(values.data()) != output_alignment_) {
    return false;
  }
  fftw_execute_dft_c2r(backward_plan_, as_fftw(spectrum_), values.data());
  return true;
}

void RealFft::release() noexcept {
  if (input_ == nullptr && output_ == nullptr && spectrum_ == nullptr && forward_plan_ == nullptr &&
      backward_plan_ == nullptr) {
    return;
  }
  const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
  if (forward_plan_ != nullptr) fftw_destroy_plan(forward_plan_);
  if (backward_plan_ != nullptr) fftw_destroy_plan(backward_plan_);
  if (output_ != input_) fftw_free(output_);
  if (owns_buffers_) {
    fftw_free(input_);
    fftw_free(spectrum_);
  }
  forward_plan_ = nullptr;
  backward_plan_ = nullptr;
  input_ = nullptr;
  output_ = nullptr;
  spectrum_ = nullptr;
}

}  // namespace halfspace::fft
