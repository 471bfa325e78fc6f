// Private: the lock around FFTW's planner and wisdom (neither is thread-safe)
// and what must happen under it before and after planning.
#pragma once

#include <fftw3.h>

#include <complex>
#include <cstddef>
#include <mutex>

#include "halfspace/fft/fft_planning.hpp"

namespace halfspace::fft::detail {

// FFTW's planner flags for `planning`.
unsigned planner_flags(FftPlanning planning);

// Asks the kernel (Linux, where transparent huge pages are on "madvise")
// to back the whole pages of [memory, memory + bytes) by huge pages: a
// large transform's passes and the transposed layout's scatter touch a
// new 4 KiB page every few entries, and the TLB misses cost more than the
// arithmetic. Before first touch, so the faults map huge pages. Advice
// only; nothing fails without it.
void advise_huge_pages(void* memory, std::size_t bytes);

// n as FFTW's int extent; throws InputError naming n unless 1 <= n <= INT_MAX.
int checked_extent(std::size_t n);

// std::complex<double> is layout-compatible with double[2] ([complex.numbers]),
// which is what fftw_complex is; the FFTW manual sanctions this cast.
inline fftw_complex* as_fftw(std::complex<double>* z) {
  return reinterpret_cast<fftw_complex*>(z);
}
inline fftwf_complex* as_fftw(std::complex<float>* z) {
  return reinterpret_cast<fftwf_complex*>(z);
}

// FFTW's calls for each precision (fftw_ for double, fftwf_ for float), so
// that one template serves both.
template <class Real>
struct Fftw;
template <>
struct Fftw<double> {
  using plan = fftw_plan;
  static constexpr auto alloc_real = fftw_alloc_real;
  static constexpr auto alloc_complex = fftw_alloc_complex;
  static constexpr auto free = fftw_free;
  static constexpr auto plan_with_nthreads = fftw_plan_with_nthreads;
  static constexpr auto plan_r2c = fftw_plan_dft_r2c;
  static constexpr auto plan_c2r = fftw_plan_dft_c2r;
  static constexpr auto plan_many_r2c = fftw_plan_many_dft_r2c;
  static constexpr auto plan_many_c2r = fftw_plan_many_dft_c2r;
  static constexpr auto plan_many_c2c = fftw_plan_many_dft;
  static constexpr auto execute_r2c = fftw_execute_dft_r2c;
  static constexpr auto execute_c2r = fftw_execute_dft_c2r;
  static constexpr auto execute_c2c = fftw_execute_dft;
  static constexpr auto destroy_plan = fftw_destroy_plan;
  static constexpr auto alignment_of = fftw_alignment_of;
};
template <>
struct Fftw<float> {
  using plan = fftwf_plan;
  static constexpr auto alloc_real = fftwf_alloc_real;
  static constexpr auto alloc_complex = fftwf_alloc_complex;
  static constexpr auto free = fftwf_free;
  static constexpr auto plan_with_nthreads = fftwf_plan_with_nthreads;
  static constexpr auto plan_r2c = fftwf_plan_dft_r2c;
  static constexpr auto plan_c2r = fftwf_plan_dft_c2r;
  static constexpr auto plan_many_r2c = fftwf_plan_many_dft_r2c;
  static constexpr auto plan_many_c2r = fftwf_plan_many_dft_c2r;
  static constexpr auto plan_many_c2c = fftwf_plan_many_dft;
  static constexpr auto execute_r2c = fftwf_execute_dft_r2c;
  static constexpr auto execute_c2r = fftwf_execute_dft_c2r;
  static constexpr auto execute_c2c = fftwf_execute_dft;
  static constexpr auto destroy_plan = fftwf_destroy_plan;
  static constexpr auto alignment_of = fftwf_alignment_of;
};

// Held for every call into FFTW other than fftw_execute.
std::mutex& fftw_planner_mutex();

// Threads for one transform of `reals` real values: the program's threads,
// or one below kMinRealsForThreads (256^2). A waiting OpenMP thread
// (passive, as the program makes them) takes tens of microseconds to wake,
// about what a whole 128^2 transform pair takes on one thread: with two
// threads a bare 128^2 pair ran 4x slower than on one, and the mixed film
// of 64^2 cells (its padded 128^2 transforms) 1.2x slower (development log,
// 2026-12-01).
inline constexpr std::size_t kMinRealsForThreads = std::size_t{1} << 16;
int transform_threads(std::size_t reals);

// The lock held: sets up FFTW's thread support (both precisions), once per process. Must come
// before planning and before importing wisdom (wisdom names the threaded
// solvers, which exist only after it). Throws std::runtime_error on failure.
void init_fftw_threads();

// The lock held, around making plans at `planning`. Measure and patient
// plans load the installed wisdom store's text (fft_wisdom.hpp) once per
// process before planning and save FFTW's wisdom to it after planning if it
// grew; estimate plans leave the store alone, so they are the same from run
// to run. Never throw. Single-precision plans (`single`) keep their wisdom
// apart: FFTW holds the two precisions' wisdom apart.
void before_planning(FftPlanning planning, bool single = false) noexcept;
void after_planning(FftPlanning planning, bool single = false) noexcept;

}  // namespace halfspace::fft::detail
