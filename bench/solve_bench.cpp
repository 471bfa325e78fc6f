// Whole Polonsky-Keer solves at tolerance 1e-10 on the FFT operator, plain (pk),
// Fourier-preconditioned (pk-fourier) and started from coarser grids
// (pk-multilevel), with 1 and 2 threads: a Hertz sphere on free grids, and
// self-affine rough surfaces on periodic grids, both refined in a fixed domain
// (rough_periodic_2d) and in a domain growing at fixed spacing
// (rough_domain_2d). HALFSPACE_BENCH_LARGE=1 adds the large grids.
#include <benchmark/benchmark.h>
#include <fftw3.h>

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <numbers>
#include <random>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "bare_fft_pair.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/solvers/fourier_preconditioner.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/surface/self_affine.hpp"
#include "halfspace/threads.hpp"

namespace halfspace {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kEStar = 1.1e11;  // Pa, steel on steel
constexpr double kTolerance = 1e-10;

// Hertz: the sphere of the validation tests, on a square three contact radii wide.
constexpr double kSphereRadius = 0.01;  // m
constexpr double kForce = 10.0;         // N

// Rough surface: one fixed surface, sampled at every grid size, so the three
// sizes are refinements of the same problem. Its spectrum is self-affine,
// C(q) ~ q^(-2(1 + H)), between the box mode 2 pi / L and kCutoffModes box
// modes (4 cells per shortest wavelength on the 256^2 grid, 16 on 1024^2).
constexpr double kHurst = 0.8;
constexpr double kBoxSize = 1e-3;    // m
constexpr double kRmsHeight = 1e-6;  // m
constexpr int kCutoffModes = 64;
constexpr std::uint64_t kSurfaceSeed = 2024;
// Mean pressure as a fraction of E* times the rms slope: by the linear law
// A/A0 ~ 2 p / (E* h'_rms) this puts about 10% of the surface in contact.
constexpr double kReducedPressure = 0.05;

// Growing domain: the surfaces of docs/performance.md, spacing 1 um,
// power law from the domain size down to 4 um, so an n x n grid is n um
// across and holds ever more contact spots; about 8% contact.
constexpr double kDomainSpacing = 1e-6;      // m
constexpr double kDomainShortCutoff = 4e-6;  // m
constexpr double kDomainRmsSlope = 0.1;
constexpr double kDomainReducedPressure = 0.04;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct RoughSurface {
  Eigen::ArrayXd heights;  // m, (n, n) row-major
  double rms_slope;        // sqrt(<|grad h|^2>)
};

// Fourier filtering of Gaussian white noise. The coefficients are drawn in an
// order that does not depend on n, then placed into the n x (n/2 + 1) half
// spectrum and brought to real space by FFTW's c2r, which sums
// h(x) = sum_k c_k exp(i q_k . x) with the kx < 0 half implied by symmetry.
RoughSurface self_affine_surface(std::size_t n) {
  struct Mode {
    int kx, ky;
    std::complex<double> c;
  };
  std::vector<Mode> modes;
  std::mt19937_64 random(kSurfaceSeed);
  std::normal_distribution<double> normal(0.0, 1.0);
  double mean_square = 0.0;        // sum |c|^2 over the full spectrum
  double mean_square_slope = 0.0;  // sum |c|^2 q^2
  const double q0 = 2.0 * std::numbers::pi / kBoxSize;
  for (int kx = 0; kx <= kCutoffModes; ++kx) {
    for (int ky = -kCutoffModes; ky <= kCutoffModes; ++ky) {
      const int k2 = kx * kx + ky * ky;
      // The kx = 0 column holds both ky and -ky: draw ky > 0, mirror below.
      if (k2 == 0 || k2 > kCutoffModes * kCutoffModes || (kx == 0 && ky < 0)) continue;
      const double q = q0 * std::sqrt(static_cast<double>(k2));
      const double re = normal(random);
      const double im = normal(random);
      const std::complex<double> c = std::pow(q, -(1.0 + kHurst)) * std::complex<double>(re, im) / std::sqrt(2.0);
      modes.push_back({kx, ky, c});
      // Each stored mode stands for itself and its conjugate partner.
      mean_square += 2.0 * std::norm(c);
      mean_square_slope += 2.0 * std::norm(c) * q * q;
    }
  }

  const std::size_t half = n / 2 + 1;
  fftw_complex* spectrum = fftw_alloc_complex(n * half);
  std::fill_n(&spectrum[0][0], 2 * n * half, 0.0);
  const auto row = [n](int ky) { return static_cast<std::size_t>((ky + static_cast<int>(n)) % static_cast<int>(n)); };
  for (const Mode& m : modes) {
    const auto kx = static_cast<std::size_t>(m.kx);
    spectrum[row(m.ky) * half + kx][0] = m.c.real();
    spectrum[row(m.ky) * half + kx][1] = m.c.imag();
    if (m.kx == 0) {
      spectrum[row(-m.ky) * half][0] = m.c.real();
      spectrum[row(-m.ky) * half][1] = -m.c.imag();
    }
  }
  RoughSurface surface{Eigen::ArrayXd(static_cast<Eigen::Index>(n * n)), 0.0};
  fftw_plan_with_nthreads(1);
  const int ni = static_cast<int>(n);
  fftw_plan plan = fftw_plan_dft_c2r_2d(ni, ni, spectrum, surface.heights.data(), FFTW_ESTIMATE);
  fftw_execute(plan);
  fftw_destroy_plan(plan);
  fftw_free(spectrum);

  // Parseval: the grid mean of h^2 is mean_square, whatever n (all modes lie
  // below the Nyquist frequency of the smallest grid).
  const double scale = kRmsHeight / std::sqrt(mean_square);
  surface.heights *= scale;
  surface.rms_slope = scale * std::sqrt(mean_square_slope);
  return surface;
}

struct SolveCase {
  std::string solver;  // a solvers::SolverType name: "pk", "pk-fourier" or "pk-multilevel"
  std::string shape;   // "hertz_free_2d", "rough_periodic_2d" or "rough_domain_2d"
};

// Kept between Google Benchmark's calls of one benchmark: the solver exactly
// as solvers::make_solver builds it for the CLI (ESTIMATE planning), the
// initial gap, and a separate operator and preconditioner of the same kind,
// only to time one product of each alone. One slot at a time.
struct SolveSetup {
  std::tuple<std::string, std::string, std::size_t, int> key;
  std::unique_ptr<Grid> grid;
  std::unique_ptr<ContactSolver> solver;
  std::unique_ptr<FftInfluenceOperator> op;
  std::unique_ptr<solvers::FourierPreconditioner> preconditioner;
  std::unique_ptr<bench::BareFftPair> floor;  // of the operator's transform size
  Eigen::ArrayXd initial_gap;
  Loading loading;
};

SolveSetup& solve_setup(const SolveCase& solve_case, std::size_t n, int threads) {
  static std::unique_ptr<SolveSetup> slot;
  const auto key = std::make_tuple(solve_case.solver, solve_case.shape, n, threads);
  if (slot && slot->key == key) return *slot;
  slot.reset();
  auto setup = std::make_unique<SolveSetup>();
  setup->key = key;
  set_threads(threads);  // before the operator makes its plans
  if (solve_case.shape == "rough_periodic_2d") {
    const double dx = kBoxSize / static_cast<double>(n);
    setup->grid = std::make_unique<Grid>(Grid::plane(n, n, dx, dx, Boundary::periodic));
    const RoughSurface surface = self_affine_surface(n);
    setup->initial_gap = solvers::initial_gap(*setup->grid, {surface.heights.data(), setup->grid->size()});
    setup->loading = Loading::mean_pressure(kReducedPressure * kEStar * surface.rms_slope);
  } else if (solve_case.shape == "rough_domain_2d") {
    setup->grid = std::make_unique<Grid>(Grid::plane(n, n, kDomainSpacing, kDomainSpacing, Boundary::periodic));
    surface::SelfAffineSpec spec;
    spec.hurst = kHurst;
    spec.short_cutoff = kDomainShortCutoff;
    spec.rms_slope = kDomainRmsSlope;
    spec.seed = 1;
    const Eigen::ArrayXd heights = surface::make_self_affine_surface(*setup->grid, spec);
    setup->initial_gap = solvers::initial_gap(*setup->grid, {heights.data(), setup->grid->size()});
    setup->loading = Loading::mean_pressure(kDomainReducedPressure * kEStar * kDomainRmsSlope);
  } else {
    const double contact_radius = std::cbrt(3.0 * kForce * kSphereRadius / (4.0 * kEStar));
    const double dx = 3.0 * contact_radius / static_cast<double>(n);
    setup->grid = std::make_unique<Grid>(Grid::plane(n, n, dx, dx, Boundary::free));
    geometry::SurfaceSpec sphere;
    sphere.shape = geometry::SurfaceShape::sphere;
    sphere.radius = kSphereRadius;
    const Eigen::ArrayXd heights = geometry::make_surface_heights(*setup->grid, sphere);
    setup->initial_gap = solvers::initial_gap(*setup->grid, {heights.data(), setup->grid->size()});
    setup->loading = Loading::force(kForce);
  }
  solvers::SolverOptions settings;
  settings.type = solvers::parse_solver_type(solve_case.solver);
  settings.tolerance = kTolerance;
  settings.fft_planning = FftPlanning::estimate;
  setup->solver = solvers::make_solver(*setup->grid, kEStar, settings);
  setup->op = std::make_unique<FftInfluenceOperator>(*setup->grid, kEStar);
  if (solve_case.solver != "pk") {
    setup->preconditioner = std::make_unique<solvers::FourierPreconditioner>(*setup->grid, kEStar);
  }
  const std::size_t transform_n = setup->grid->periodic() ? n : 2 * n;
  setup->floor = std::make_unique<bench::BareFftPair>(2, transform_n, threads);
  slot = std::move(setup);
  return *slot;
}

// Mean wall seconds of apply(in, out) alone (at least 3 runs and 0.2 s), to
// split a solve's time into transforms and the solver's own vector work.
template <class Product>
double seconds_per_apply(Product& product, std::span<const double> in, std::span<double> out) {
  const auto start = Clock::now();
  int runs = 0;
  double elapsed = 0.0;
  while (runs < 3 || elapsed < 0.2) {
    product.apply(in, out);
    ++runs;
    elapsed = seconds_since(start);
  }
  return elapsed / runs;
}

void solve(benchmark::State& state, const SolveCase& solve_case, std::size_t n) {
  const int threads = static_cast<int>(state.range(0));
  SolveSetup* setup = nullptr;
  try {
    setup = &solve_setup(solve_case, n, threads);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  set_threads(threads);
  const std::span<const double> gap(setup->initial_gap.data(), setup->grid->size());
  SolveResult result;
  const auto start = Clock::now();
  for (auto _ : state) {
    result = setup->solver->solve(gap, setup->loading);
    benchmark::DoNotOptimize(result.pressure.data());
  }
  const double solve_seconds = seconds_since(start) / static_cast<double>(state.iterations());

  std::vector<double> scratch(setup->grid->size());
  const std::span<const double> pressure(result.pressure.data(), setup->grid->size());
  const double apply_seconds = seconds_per_apply(*setup->op, pressure, scratch);
  const double preconditioner_seconds =
      setup->preconditioner ? seconds_per_apply(*setup->preconditioner, pressure, scratch) : 0.0;
  const double floor_seconds = setup->floor->seconds_per_pair(
      std::max<std::int64_t>(3, static_cast<std::int64_t>(0.2 / std::max(apply_seconds, 1e-6))));
  const double applications = result.operator_applications;
  const double preconditioner_applications = result.preconditioner_applications;
  state.counters["threads"] = threads;
  state.counters["iterations"] = result.iterations;
  state.counters["operator_applications"] = applications;
  state.counters["preconditioner_applications"] = preconditioner_applications;
  state.counters["s_per_application"] = solve_seconds / applications;
  state.counters["s_per_iteration"] = solve_seconds / std::max(result.iterations, 1);
  state.counters["apply_alone_s"] = apply_seconds;
  state.counters["fft_pair_s"] = floor_seconds;
  // One iteration against one bare FFT pair of the operator's transform size.
  state.counters["iteration_per_fft_pair"] = solve_seconds / std::max(result.iterations, 1) / floor_seconds;
  // pk-multilevel's coarse grids, in products of this grid.
  state.counters["coarse_work"] = result.coarse.operator_work + result.coarse.preconditioner_work;
  // Share of the solve spent in K and M^-1 products (FFT pairs and their
  // copies); the rest is the solver's own elementwise loops and reductions.
  state.counters["transform_share"] =
      (applications * apply_seconds + preconditioner_applications * preconditioner_seconds) / solve_seconds;
  state.counters["converged"] = result.converged() ? 1.0 : 0.0;
  state.counters["residual"] = result.residual;
  state.counters["contact_fraction"] = result.contact_fraction;
  if (!result.converged()) state.SetLabel(result.message);
}

// Names: BM_Solve/<solver>/<shape>/<n>/threads:<t>.
const bool kRegistered = [] {
  const auto add = [](const SolveCase& c, std::size_t n) {
    const std::string name = "BM_Solve/" + c.solver + "/" + c.shape + "/" + std::to_string(n);
    benchmark::RegisterBenchmark(name.c_str(), solve, c, n)
        ->ArgName("threads")
        ->Arg(1)
        ->Arg(2)
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
  };
  const bool large = bench::large_sizes_requested();
  std::vector<std::size_t> free_sizes{128, 256, 512};
  std::vector<std::size_t> periodic_sizes{256, 512, 1024};
  if (large) {
    free_sizes.insert(free_sizes.end(), {1024, 2048});
    periodic_sizes.insert(periodic_sizes.end(), {2048, 4096});
  }
  for (const std::string solver : {"pk", "pk-fourier", "pk-multilevel"}) {
    for (std::size_t n : free_sizes) add({solver, "hertz_free_2d"}, n);
    for (std::size_t n : periodic_sizes) add({solver, "rough_periodic_2d"}, n);
    for (std::size_t n : periodic_sizes) add({solver, "rough_domain_2d"}, n);
  }
  return true;
}();

}  // namespace
}  // namespace halfspace
