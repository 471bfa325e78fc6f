// A tangential load step against the normal solve of the same contact: a
// self-affine rough surface on periodic n x n grids at fixed spacing (the
// growing domain of solve_bench.cpp's rough_domain_2d, about 8% contact), the
// normal solve by the default solver (pk-multilevel) and by pk-fourier, then
// two force-controlled tangential steps, Q = 0.5 mu P from rest and back to
// Q = 0.25 mu P (a reversal, warm-started from the first). Solver and step
// objects are made once per grid; each benchmark iteration times the solves
// alone. The counters give iterations per step, the times, their ratio and
// the process's peak memory per grid point. bench/tangential_bench.sh runs
// it over grid sizes and prints the table of docs/development-log.md.
// One thread (the shared machine's other loads make two spin at barriers).
// HALFSPACE_BENCH_LARGE=1 adds 2048^2 and 4096^2.
#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <unistd.h>

#include <Eigen/Core>
#include <chrono>
#include <cstddef>
#include <exception>
#include <fstream>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "bare_fft_pair.hpp"
#include "halfspace/elastic_pair.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/operators/tangential_operator.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/solvers/tangential_solver.hpp"
#include "halfspace/surface/self_affine.hpp"
#include "halfspace/threads.hpp"

namespace halfspace {
namespace {

using Clock = std::chrono::steady_clock;

constexpr ElasticBody kSteel{2.1e11, 0.3};
constexpr double kSpacing = 1e-6;  // m
constexpr double kShortCutoff = 4e-6;
constexpr double kRmsSlope = 0.1;
constexpr double kReducedPressure = 0.04;  // mean pressure / (E* h'_rms)
constexpr double kMu = 0.3;
// The same number for both solvers' (different) relative residuals.
constexpr double kTolerance = 1e-8;
constexpr double kFirstLoad = 0.5;    // Q / (mu P), from rest
constexpr double kSecondLoad = 0.25;  // back again

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The process's resident bytes now (Linux: /proc/self/statm's second
// field, in pages).
double resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  double pages_total = 0.0;
  double pages_resident = 0.0;
  statm >> pages_total >> pages_resident;
  return pages_resident * static_cast<double>(sysconf(_SC_PAGESIZE));
}

double peak_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) * 1024.0;  // Linux: KiB
}

struct StepSetup {
  std::size_t n = 0;
  solvers::TangentialMethod method{};
  std::unique_ptr<Grid> grid;
  ElasticPair pair = ElasticPair::similar(kSteel);
  Eigen::ArrayXd gap;
  Loading loading;
  std::unique_ptr<ContactSolver> multilevel;
  std::unique_ptr<ContactSolver> fourier;
  std::unique_ptr<TangentialOperator> op;
  std::unique_ptr<TangentialSolver> tangential;
};

StepSetup& step_setup(std::size_t n, solvers::TangentialMethod method) {
  static std::unique_ptr<StepSetup> slot;
  if (slot && slot->n == n && slot->method == method) return *slot;
  slot.reset();
  auto setup = std::make_unique<StepSetup>();
  setup->n = n;
  setup->method = method;
  setup->grid = std::make_unique<Grid>(Grid::plane(n, n, kSpacing, kSpacing, Boundary::periodic));
  surface::SelfAffineSpec spec;
  spec.hurst = 0.8;
  spec.short_cutoff = kShortCutoff;
  spec.rms_slope = kRmsSlope;
  spec.seed = 1;
  const Eigen::ArrayXd heights = surface::make_self_affine_surface(*setup->grid, spec);
  setup->gap = solvers::initial_gap(*setup->grid, {heights.data(), setup->grid->size()});
  const double e_star = setup->pair.composite_modulus();
  setup->loading = Loading::mean_pressure(kReducedPressure * e_star * kRmsSlope);
  solvers::SolverOptions settings;
  settings.tolerance = kTolerance;
  settings.fft_planning = FftPlanning::estimate;
  setup->multilevel = solvers::make_solver(*setup->grid, e_star, settings);  // the default type
  settings.type = solvers::SolverType::pk_fourier;
  setup->fourier = solvers::make_solver(*setup->grid, e_star, settings);
  slot = std::move(setup);
  return *slot;
}

void tangential_step(benchmark::State& state, std::size_t n, solvers::TangentialMethod method) {
  set_threads(static_cast<int>(state.range(0)));
  StepSetup* setup = nullptr;
  try {
    setup = &step_setup(n, method);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  const std::size_t cells = setup->grid->size();
  const std::span<const double> gap(setup->gap.data(), cells);
  double multilevel_seconds = 0.0;
  double fourier_seconds = 0.0;
  double first_seconds = 0.0;
  double second_seconds = 0.0;
  SolveResult multilevel;
  SolveResult fourier;
  TangentialResult first;
  TangentialResult second;
  TangentialState unloaded;
  double tangential_bytes = 0.0;
  for (auto _ : state) {
    auto start = Clock::now();
    multilevel = setup->multilevel->solve(gap, setup->loading);
    multilevel_seconds += seconds_since(start);
    start = Clock::now();
    fourier = setup->fourier->solve(gap, setup->loading);
    fourier_seconds += seconds_since(start);
    if (!setup->tangential) {
      // The friction's own memory: what the process gains from here on
      // (made after the normal solves, so none of their work is counted).
      tangential_bytes = -resident_bytes();
      setup->op = std::make_unique<TangentialOperator>(*setup->grid, setup->pair);
      solvers::TangentialOptions options;
      options.friction_coefficient = kMu;
      options.tolerance = kTolerance;
      options.max_iterations = 20000;
      options.method = method;
      setup->tangential = std::make_unique<TangentialSolver>(*setup->op, options);
    }
    if (unloaded.size() != cells) unloaded = TangentialState::unloaded(cells);
    const std::span<const double> pressure(multilevel.pressure.data(), cells);
    const double limit = kMu * multilevel.total_force;
    start = Clock::now();
    first = setup->tangential->solve(pressure, TangentialLoading::force(kFirstLoad * limit), unloaded);
    first_seconds += seconds_since(start);
    start = Clock::now();
    second = setup->tangential->solve(pressure, TangentialLoading::force(kSecondLoad * limit), first.state);
    second_seconds += seconds_since(start);
    state.SetIterationTime(first_seconds);
    if (tangential_bytes < 0.0) tangential_bytes += resident_bytes();
  }
  const double runs = static_cast<double>(state.iterations());
  state.counters["contact_fraction"] = multilevel.contact_fraction;
  state.counters["normal_iterations"] = multilevel.iterations;
  state.counters["normal_s"] = multilevel_seconds / runs;
  state.counters["fourier_iterations"] = fourier.iterations;
  state.counters["fourier_s"] = fourier_seconds / runs;
  state.counters["first_iterations"] = first.iterations;
  state.counters["first_s"] = first_seconds / runs;
  state.counters["second_iterations"] = second.iterations;
  state.counters["second_s"] = second_seconds / runs;
  state.counters["first_over_normal"] = first_seconds / multilevel_seconds;
  state.counters["second_over_normal"] = second_seconds / multilevel_seconds;
  state.counters["first_over_fourier"] = first_seconds / fourier_seconds;
  state.counters["stick_fraction"] = first.stick_fraction;
  // The coarse grids' products counted at their cost in fine products.
  state.counters["products_first"] = first.operator_applications + first.preconditioner_applications +
                                     first.coarse.operator_work + first.coarse.preconditioner_work;
  state.counters["peak_B_per_point"] = peak_bytes() / static_cast<double>(cells);
  // The operator, the solver and three states (at rest, step 1, step 2),
  // measured on the first run; a step holds two (previous and its own).
  state.counters["friction_B_per_point"] = tangential_bytes / static_cast<double>(cells);
  const bool converged = multilevel.converged() && fourier.converged() && first.converged() && second.converged();
  state.counters["converged"] = converged ? 1.0 : 0.0;
  if (!converged) state.SetLabel(first.message + " " + second.message);
}

// Names: BM_TangentialStep/<method>/<n>/threads:<t>.
const bool kRegistered = [] {
  std::vector<std::size_t> sizes{256, 512, 1024};
  if (bench::large_sizes_requested()) sizes.insert(sizes.end(), {2048, 4096});
  for (const auto& [name, method] : {std::pair{"conjugate_gradient", solvers::TangentialMethod::conjugate_gradient},
                                     std::pair{"projected_gradient", solvers::TangentialMethod::projected_gradient}}) {
    for (std::size_t n : sizes) {
      const std::string label = std::string("BM_TangentialStep/") + name + "/" + std::to_string(n);
      benchmark::RegisterBenchmark(label.c_str(), tangential_step, n, method)
          ->ArgName("threads")
          ->Arg(1)
          ->Iterations(1)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

}  // namespace
}  // namespace halfspace
