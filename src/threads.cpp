// The process-wide thread count: OpenMP loops and FFTW plans use the same one.
#include "halfspace/threads.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <atomic>

#include "halfspace/error.hpp"

namespace halfspace {
namespace {

// 0 until set_threads is called: then OpenMP's own default is in force.
std::atomic<int> g_threads{0};

}  // namespace

void set_threads(int threads) {
  if (threads < 1) {
    throw InputError(fmt::format("thread count {} is invalid: must be at least 1", threads));
  }
  omp_set_num_threads(threads);
  g_threads.store(threads);
}

int threads() {
  const int set = g_threads.load();
  return set > 0 ? set : omp_get_max_threads();
}

}  // namespace halfspace
