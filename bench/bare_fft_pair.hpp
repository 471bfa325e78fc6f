// The floor every FFT product is compared with: an out-of-place r2c and c2r
// plan pair over an n (1D) or n x n (2D) real array, and nothing else (no
// padding, no kernel multiply, no normalisation). The c2r result goes to its
// own array so the unnormalised round trip never feeds back into the input.
#pragma once

#include <fftw3.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string_view>

namespace halfspace::bench {

// HALFSPACE_BENCH_LARGE=1 (scripts/bench.sh --large) registers the large grids
// too: periodic up to 4096^2, free up to 2048^2, which take most of an hour.
inline bool large_sizes_requested() {
  const char* value = std::getenv("HALFSPACE_BENCH_LARGE");
  return value != nullptr && std::string_view(value) == "1";
}

class BareFftPair {
 public:
  // flags: FFTW_ESTIMATE or FFTW_MEASURE, as the product it is compared with.
  BareFftPair(int dimension, std::size_t n, int threads, unsigned flags = FFTW_ESTIMATE) {
    const std::size_t real_size = dimension == 1 ? n : n * n;
    const std::size_t complex_size = dimension == 1 ? n / 2 + 1 : n * (n / 2 + 1);
    input_ = fftw_alloc_real(real_size);
    output_ = fftw_alloc_real(real_size);
    spectrum_ = fftw_alloc_complex(complex_size);
    fftw_plan_with_nthreads(threads);
    const int ni = static_cast<int>(n);
    if (dimension == 1) {
      forward_ = fftw_plan_dft_r2c_1d(ni, input_, spectrum_, flags);
      backward_ = fftw_plan_dft_c2r_1d(ni, spectrum_, output_, flags);
    } else {
      forward_ = fftw_plan_dft_r2c_2d(ni, ni, input_, spectrum_, flags);
      backward_ = fftw_plan_dft_c2r_2d(ni, ni, spectrum_, output_, flags);
    }
    // Filled after planning (measuring overwrites the arrays); out-of-place
    // r2c preserves its input, so this is the data every run sees.
    std::mt19937_64 random(42);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (std::size_t i = 0; i < real_size; ++i) input_[i] = uniform(random);
    run();  // first touch of the pages, outside any timing
  }
  ~BareFftPair() {
    fftw_destroy_plan(backward_);
    fftw_destroy_plan(forward_);
    fftw_free(spectrum_);
    fftw_free(output_);
    fftw_free(input_);
  }
  BareFftPair(const BareFftPair&) = delete;
  BareFftPair& operator=(const BareFftPair&) = delete;

  void run() {
    fftw_execute(forward_);
    fftw_execute(backward_);
  }
  const double* data() const { return output_; }

  // Mean wall seconds of one pair over `repetitions` back-to-back runs.
  double seconds_per_pair(std::int64_t repetitions) {
    const auto start = std::chrono::steady_clock::now();
    for (std::int64_t r = 0; r < repetitions; ++r) run();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
           static_cast<double>(repetitions);
  }

 private:
  double* input_ = nullptr;
  double* output_ = nullptr;
  fftw_complex* spectrum_ = nullptr;
  fftw_plan forward_ = nullptr;
  fftw_plan backward_ = nullptr;
};

}  // namespace halfspace::bench
