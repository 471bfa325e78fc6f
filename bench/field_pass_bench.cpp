// What one elementwise pass over the grid's fields costs against a bare FFT
// pair of the same size: the yardstick for the solver's vector work. A
// Polonsky-Keer iteration reads and writes pressure, displacement, direction
// and its image, and reads the initial gap, in passes that each wait for the
// previous pass's sums; at the field cost measured here, that traffic alone
// bounds how close an iteration can come to two products
// (docs/development-log.md, "How close an iteration can come").
//
// BM_FieldPass/<variant>/<n>/threads:<t>, one pass over n x n cells that
// reads four fields, writes one and sums two products, the shape of the
// solver's passes:
//   stream  a plain OpenMP loop with one reduction: the machine's streaming cost
//   linalg  the same through linalg::sums, as the solvers do (deterministic
//           fixed-block reduction, four accumulators)
// Counters: fft_pair_s (the bare pair, timed right after for the same number
// of repetitions), pair_per_pass and pair_per_field (the pass over one pair,
// and over one pair per field touched: five here).
#include <benchmark/benchmark.h>
#include <fftw3.h>

#include <array>
#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

#include "bare_fft_pair.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/threads.hpp"

namespace halfspace {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kFieldsTouched = 5;  // four read, one written

struct Fields {
  explicit Fields(std::size_t n) : a(n), b(n), c(n), d(n), out(n) {
    for (std::size_t i = 0; i < n; ++i) {
      a[i] = static_cast<double>(i % 7) - 3.0;  // half the cells "in contact" (a > 0)
      b[i] = 1.0 + static_cast<double>(i % 5);
      c[i] = 0.5 * static_cast<double>(i % 3);
      d[i] = 1.0 / (1.0 + static_cast<double>(i % 11));
    }
  }
  std::vector<double> a, b, c, d, out;
};

double stream_pass(Fields& f) {
  const auto n = static_cast<std::ptrdiff_t>(f.a.size());
  const double* a = f.a.data();
  const double* b = f.b.data();
  const double* c = f.c.data();
  const double* d = f.d.data();
  double* out = f.out.data();
  double sum = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : sum)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const double value = b[i] + c[i] - d[i];
    out[i] = value;
    sum += a[i] > 0.0 ? value * d[i] : 0.0;
  }
  return sum;
}

double linalg_pass(Fields& f) {
  const double* a = f.a.data();
  const double* b = f.b.data();
  const double* c = f.c.data();
  const double* d = f.d.data();
  double* out = f.out.data();
  const auto [masked, total] = linalg::sums<2>(f.a.size(), [&](std::size_t i) {
    const double value = b[i] + c[i] - d[i];
    out[i] = value;
    const double inside = a[i] > 0.0 ? 1.0 : 0.0;
    return std::array<double, 2>{inside * (value * d[i]), value};
  });
  return masked + total;
}

void field_pass(benchmark::State& state, bool through_linalg, std::size_t n) {
  const int threads = static_cast<int>(state.range(0));
  set_threads(threads);
  Fields fields(n * n);
  bench::BareFftPair pair(2, n, threads);
  // The loop's own time, then the pair for as many runs right after it (as
  // operator_bench.cpp does): both figures from back-to-back runs.
  const auto start = Clock::now();
  for (auto _ : state) {
    benchmark::DoNotOptimize(through_linalg ? linalg_pass(fields) : stream_pass(fields));
    benchmark::ClobberMemory();
  }
  const double pass_seconds =
      std::chrono::duration<double>(Clock::now() - start).count() / static_cast<double>(state.iterations());
  const double pair_seconds = pair.seconds_per_pair(state.iterations());
  state.counters["threads"] = threads;
  state.counters["fft_pair_s"] = pair_seconds;
  state.counters["pair_per_pass"] = pass_seconds / pair_seconds;
  state.counters["pair_per_field"] = pass_seconds / pair_seconds / kFieldsTouched;
}

const bool kRegistered = [] {
  std::vector<std::size_t> sizes{256, 512, 1024, 2048};
  if (bench::large_sizes_requested()) sizes.push_back(4096);
  for (const bool through_linalg : {false, true}) {
    for (std::size_t n : sizes) {
      const std::string name =
          std::string("BM_FieldPass/") + (through_linalg ? "linalg/" : "stream/") + std::to_string(n);
      benchmark::RegisterBenchmark(name.c_str(), field_pass, through_linalg, n)
          ->ArgName("threads")
          ->Arg(1)
          ->Arg(2)
          ->UseRealTime()
          ->Unit(benchmark::kMicrosecond);
    }
  }
  return true;
}();

}  // namespace
}  // namespace halfspace
