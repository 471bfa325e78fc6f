// One application of FftInfluenceOperator against its floor, a bare FFTW r2c + c2r
// pair of the same transform size (2n per axis for free grids), thread count and
// planning (FFTW_ESTIMATE, and FFTW_MEASURE for the *_measure rows). Holds
// halfspace_bench's main(). HALFSPACE_BENCH_LARGE=1 adds the large sizes.
#include <benchmark/benchmark.h>
#include <fftw3.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "bare_fft_pair.hpp"
#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/threads.hpp"
#include "halfspace/version.hpp"

namespace halfspace {
namespace {

using bench::BareFftPair;
using Clock = std::chrono::steady_clock;

constexpr double kEStar = 1.1e11;  // Pa; the value does not change the cost
constexpr double kSpacing = 1e-6;  // m
constexpr std::uint64_t kSeed = 42;
const std::vector<int> kThreadCounts = {1, 2};

// Transform sizes per axis. Periodic grids of size n and free grids of size
// n/2 (padded to n) share each bare-pair measurement.
const std::vector<std::size_t> kTransformSizes2d = {256, 512, 1024, 2048};
const std::vector<std::size_t> kLargeTransformSizes2d = {4096};
const std::vector<std::size_t> kTransformSizes1d = {std::size_t{1} << 12, std::size_t{1} << 16, std::size_t{1} << 20};
// Periodic 2D sizes also run with FftPlanning::measure, to show what the
// ESTIMATE default leaves on the table.
const std::vector<std::size_t> kMeasuredSizes2d = {256, 512, 1024, 2048};

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct OperatorKind {
  std::string name;
  int dimension;
  Boundary boundary;
  FftPlanning planning = FftPlanning::estimate;
};

Grid make_grid(const OperatorKind& kind, std::size_t n) {
  return kind.dimension == 1 ? Grid::line(n, kSpacing, kind.boundary)
                             : Grid::plane(n, n, kSpacing, kSpacing, kind.boundary);
}

// Google Benchmark calls a benchmark function several times while it picks the
// iteration count; the operator (plans, kernel spectrum) and the fields are
// kept between those calls. One slot, so only one large case is alive at once.
struct ApplySetup {
  std::tuple<std::string, std::size_t, int> key;
  std::unique_ptr<FftInfluenceOperator> op;
  std::unique_ptr<BareFftPair> floor;
  double construct_seconds = 0.0;  // FftInfluenceOperator constructor: plans and kernel spectrum
  std::vector<double> pressure;
  std::vector<double> displacement;
};

ApplySetup& apply_setup(const OperatorKind& kind, std::size_t n, int threads) {
  static std::unique_ptr<ApplySetup> slot;
  const auto key = std::make_tuple(kind.name, n, threads);
  if (slot && slot->key == key) return *slot;
  slot.reset();  // free the previous case before allocating the next
  auto setup = std::make_unique<ApplySetup>();
  setup->key = key;
  set_threads(threads);  // before the plans are made
  const Grid grid = make_grid(kind, n);
  const auto start = Clock::now();
  setup->op = std::make_unique<FftInfluenceOperator>(grid, kEStar, kind.planning);
  setup->construct_seconds = seconds_since(start);
  // Measured plans leave wisdom behind that later plans of the same size
  // would reuse, ESTIMATE ones included: forget it, so the bare pair here and
  // every later benchmark plan as if it had never been measured.
  if (kind.planning != FftPlanning::estimate) fftw_forget_wisdom();
  const std::size_t transform_n = grid.periodic() ? n : 2 * n;
  // The floor is planned like the operator: measured rows against a measured pair.
  setup->floor = std::make_unique<BareFftPair>(kind.dimension, transform_n, threads,
                                               kind.planning == FftPlanning::estimate ? FFTW_ESTIMATE : FFTW_MEASURE);
  if (kind.planning != FftPlanning::estimate) fftw_forget_wisdom();
  setup->pressure.resize(grid.size());
  setup->displacement.assign(grid.size(), 0.0);
  std::mt19937_64 random(kSeed);
  std::uniform_real_distribution<double> uniform(0.0, 1e6);  // Pa
  for (double& p : setup->pressure) p = uniform(random);
  setup->op->apply(setup->pressure, setup->displacement);  // first touch
  slot = std::move(setup);
  return *slot;
}

void bare_fft_pair(benchmark::State& state, int dimension, std::size_t n) {
  const int threads = static_cast<int>(state.range(0));
  set_threads(threads);
  BareFftPair pair(dimension, n, threads);
  for (auto _ : state) {
    pair.run();
    benchmark::DoNotOptimize(pair.data());
    benchmark::ClobberMemory();
  }
  state.counters["transform_n"] = static_cast<double>(n);
  state.counters["threads"] = threads;
}

// Times op.apply, then the bare pair of the same transform size for the same
// number of repetitions right after it, so the ratio compares like with like
// (same cache state, same load on the machine).
void operator_apply(benchmark::State& state, const OperatorKind& kind, std::size_t n) {
  const int threads = static_cast<int>(state.range(0));
  ApplySetup* setup = nullptr;
  try {
    setup = &apply_setup(kind, n, threads);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  set_threads(threads);  // the OpenMP loops of apply() read it at run time
  const std::span<const double> pressure(setup->pressure);
  const std::span<double> displacement(setup->displacement);
  const auto start = Clock::now();
  for (auto _ : state) {
    setup->op->apply(pressure, displacement);
    benchmark::DoNotOptimize(setup->displacement.data());
    benchmark::ClobberMemory();
  }
  const double apply_seconds = seconds_since(start) / static_cast<double>(state.iterations());
  const double pair_seconds = setup->floor->seconds_per_pair(state.iterations());
  const std::size_t transform_n = kind.boundary == Boundary::periodic ? n : 2 * n;
  state.counters["transform_n"] = static_cast<double>(transform_n);
  state.counters["threads"] = threads;
  state.counters["fft_pair_s"] = pair_seconds;
  state.counters["ratio"] = apply_seconds / pair_seconds;
  state.counters["construct_s"] = setup->construct_seconds;
}

// Registered per transform size: the bare pair, then the periodic operator of
// that size, then the free operator padded to it.
const bool kRegistered = [] {
  const OperatorKind periodic_2d{"periodic_2d", 2, Boundary::periodic};
  const OperatorKind free_2d{"free_2d", 2, Boundary::free};
  const OperatorKind periodic_1d{"periodic_1d", 1, Boundary::periodic};
  const OperatorKind free_1d{"free_1d", 1, Boundary::free};
  const auto configure = [](benchmark::internal::Benchmark* b) {
    b->ArgName("threads")->UseRealTime()->Unit(benchmark::kMicrosecond);
    for (int t : kThreadCounts) b->Arg(t);
  };
  const auto register_size = [&](int dimension, std::size_t t, const OperatorKind& periodic, const OperatorKind& free) {
    const std::string tag = dimension == 1 ? "1d/" : "2d/";
    configure(benchmark::RegisterBenchmark(("BM_BareFftPair/" + tag + std::to_string(t)).c_str(), bare_fft_pair,
                                           dimension, t));
    configure(benchmark::RegisterBenchmark(("BM_OperatorApply/" + periodic.name + "/" + std::to_string(t)).c_str(),
                                           operator_apply, periodic, t));
    configure(benchmark::RegisterBenchmark(("BM_OperatorApply/" + free.name + "/" + std::to_string(t / 2)).c_str(),
                                           operator_apply, free, t / 2));
  };
  for (std::size_t t : kTransformSizes1d) register_size(1, t, periodic_1d, free_1d);
  for (std::size_t t : kTransformSizes2d) register_size(2, t, periodic_2d, free_2d);
  if (bench::large_sizes_requested()) {
    for (std::size_t t : kLargeTransformSizes2d) register_size(2, t, periodic_2d, free_2d);
  }
  const OperatorKind periodic_2d_measure{"periodic_2d_measure", 2, Boundary::periodic, FftPlanning::measure};
  for (std::size_t t : kMeasuredSizes2d) {
    configure(
        benchmark::RegisterBenchmark(("BM_OperatorApply/" + periodic_2d_measure.name + "/" + std::to_string(t)).c_str(),
                                     operator_apply, periodic_2d_measure, t));
  }
  return true;
}();

}  // namespace
}  // namespace halfspace

int main(int argc, char** argv) {
  // Measured plans would otherwise load and save the user's wisdom file
  // (halfspace/fft/fft_wisdom.hpp): planning time would depend on earlier
  // runs, and a benchmark should leave no cache behind.
  setenv("HALFSPACE_FFTW_WISDOM", "off", 1);
  // FFTW's thread support must be initialised before the first plan; the call
  // is idempotent, so the library may make it again.
  fftw_init_threads();
  benchmark::AddCustomContext("halfspace_version", halfspace::kVersion);
  benchmark::AddCustomContext("halfspace_git", halfspace::kGitHash);
  benchmark::AddCustomContext("fftw_version", fftw_version);
  benchmark::AddCustomContext(
      "fft_planning",
      "FFTW_ESTIMATE (operator default and bare pair); *_measure rows: FFTW_MEASURE for both, no wisdom file");
  benchmark::AddCustomContext(
      "large_sizes", halfspace::bench::large_sizes_requested() ? "yes" : "no (HALFSPACE_BENCH_LARGE=1 adds them)");
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
