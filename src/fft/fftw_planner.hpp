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

// n as FFTW's int extent; throws InputError naming n unless 1 <= n <= INT_MAX.
int checked_extent(std::size_t n);

// std::complex<double> is layout-compatible with double[2] ([complex.numbers]),
// which is what fftw_complex is; the FFTW manual sanctions this cast.
inline fftw_complex* as_fftw(std::complex<double>* z) {
  return reinterpret_cast<fftw_complex*>(z);
}

// Held for every call into FFTW other than fftw_execute.
std::mutex& fftw_planner_mutex();

// The lock held: sets up FFTW's thread support, once per process. Must come
// before planning and before importing wisdom (wisdom names the threaded
// solvers, which exist only after it). Throws std::runtime_error on failure.
void init_fftw_threads();

// The lock held, around making plans at `planning`. Measure and patient
// plans load the wisdom file (fft_wisdom_path) once per process before
// planning and save FFTW's wisdom after planning if it grew; estimate plans
// leave the file alone, so they are the same from run to run. Never throw.
void before_planning(FftPlanning planning) noexcept;
void after_planning(FftPlanning planning) noexcept;

}  // namespace halfspace::fft::detail
