// Private: the lock around FFTW's planner and wisdom (neither is thread-safe)
// and what must happen under it before and after planning.
#pragma once

#include <mutex>

#include "halfspace/fft/fft_planning.hpp"

namespace halfspace::detail {

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

}  // namespace halfspace::detail
