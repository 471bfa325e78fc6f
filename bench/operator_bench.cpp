// One application of FftInfluenceOperator against its floor, a bare FFTW r2c + c2r
// pair of the same transform size (2n per axis for free grids) and thread count,
// both FFTW_ESTIMATE (plus a FFTW_MEASURE operator). Holds halfspace_bench's main().
#include <fftw3.h>

#include <benchmark/benchmark.h>

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

#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/threads.hpp"
#include "halfspace/version.hpp"

namespace halfspace {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kEStar = 1.1e11;   // Pa; the value does not change the cost
constexpr double kSpacing = 1e-6;   // m
constexpr std::uint64_t kSeed = 42;
const std::vector<int> kThreadCounts = {1, 2};

// Transform sizes per axis. Periodic grids of size n and free grids of size
// n/2 (padded to n) share each bare-pair measurement.
const std::vector<std::size_t> kTransformSizes2d = {256, 512, 1024, 2048};
const std::vector<std::size_t> kTransformSizes1d = {std::size_t{1} << 12, std::size_t{1} << 16, std::size_t{1} << 20};
// Periodic 2D sizes also run with FftPlanning::measure, to show what the
// ESTIMATE default leaves on the table.
const std::vector<std::size_t> kMeasuredSizes2d = {256, 512, 1024, 2048};

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// An out-of-place r2c and c2r plan over an n (1D) or n x n (2D) real array:
// the two transforms every operator application needs, and nothing else (no
// padding, no kernel multiply, no normalisation). The c2r result goes to its
// own array so the unnormalised round trip never feeds back into the input.
class BareFftPair {
 public:
  BareFftPair(int dimension, std::size_t n, int threads) {
    const std::size_t real_size = dimension == 1 ? n : n * n;
    const std::size_t complex_size = dimension == 1 ? n / 2 + 1 : n * (n / 2 + 1);
    input_ = fftw_alloc_real(real_size);
    output_ = fftw_alloc_real(real_size);
    spectrum_ = fftw_alloc_complex(complex_size);
    fftw_plan_with_nthreads(threads);
    const int ni = static_cast<int>(n);
    if (dimension == 1) {
      forward_ = fftw_plan_dft_r2c_1d(ni, input_, spectrum_, FFTW_ESTIMATE);
      backward_ = fftw_plan_dft_c2r_1d(ni, spectrum_, output_, FFTW_ESTIMATE);
    } else {
      forward_ = fftw_plan_dft_r2c_2d(ni, ni, input_, spectrum_, FFTW_ESTIMATE);
      backward_ = fftw_plan_dft_c2r_2d(ni, ni, spectrum_, output_, FFTW_ESTIMATE);
    }
    // Planned before filling: FFTW_ESTIMATE leaves the arrays alone anyway,
    // and out-of-place r2c preserves its input, so this is the data every run sees.
    std::mt19937_64 random(kSeed);
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
    const auto start = Clock::now();
    for (std::int64_t r = 0; r < repetitions; ++r) run();
    return seconds_since(start) / static_cast<double>(repetitions);
  }

 private:
  double* input_ = nullptr;
  double* output_ = nullptr;
  fftw_complex* spectrum_ = nullptr;
  fftw_plan forward_ = nullptr;
  fftw_plan backward_ = nullptr;
};

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
  setup->floor = std::make_unique<BareFftPair>(kind.dimension, transform_n, threads);
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
  const auto register_size = [&](int dimension, std::size_t t, const OperatorKind& periodic,
                                 const OperatorKind& free) {
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
  const OperatorKind periodic_2d_measure{"periodic_2d_measure", 2, Boundary::periodic, FftPlanning::measure};
  for (std::size_t t : kMeasuredSizes2d) {
    configure(benchmark::RegisterBenchmark(
        ("BM_OperatorApply/" + periodic_2d_measure.name + "/" + std::to_string(t)).c_str(), operator_apply,
        periodic_2d_measure, t));
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
  benchmark::AddCustomContext("fft_planning",
                              "FFTW_ESTIMATE (operator default and bare pair); *_measure rows: FFTW_MEASURE, no wisdom file");
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
