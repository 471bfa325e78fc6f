// Thread count for OpenMP loops and FFTW transforms, set together.
//
// OpenMP threads that wait for work spin on a core unless OMP_WAIT_POLICY is
// passive. On a machine shared with other processes that spinning takes the
// cores the others need, and a solve runs 15-30 times slower than alone.
// The halfspace program makes the policy passive itself (docs/usage.md,
// Threads); a program that links the library should call
// use_passive_openmp_waiting (openmp_waiting.hpp) first thing in main, or
// set OMP_WAIT_POLICY=passive in its environment before it starts (the GNU
// OpenMP runtime reads it when it is loaded, before main).
#pragma once

namespace halfspace {

// Hardware threads of the machine (std::thread::hardware_concurrency), at
// least 1.
int hardware_threads();

// The largest thread count set_threads accepts: kThreadsPerHardwareThread
// times hardware_threads(). More threads than that only add scheduling and
// start-up cost (10,000 threads take minutes to start and join).
inline constexpr int kThreadsPerHardwareThread = 4;
int max_threads();

// The threads a run uses when none is asked for: the CPUs this process may
// run on (its affinity mask, e.g. from taskset or a batch scheduler),
// limited by a cgroup CPU quota (cpu.max, or cpu.cfs_quota_us) rounded up,
// or OMP_NUM_THREADS when set to a count from 1 to max_threads().
int default_threads();

// Sets the number of threads used by elementwise loops (OpenMP) and by FFT
// plans made afterwards (FFTW threads). Throws InputError unless 1 <= threads
// <= max_threads().
void set_threads(int threads);

// The thread count currently in force.
int threads();

}  // namespace halfspace
