// One tangential step of bench/tangential_bench.cpp's contact (the growing
// domain's self-affine surface on an n x n periodic grid, Q = 0.5 mu P from
// rest, then back to 0.25 mu P), traced: the residual of every iteration,
// the products, the stick fraction. The pressure of the normal solve is
// kept in a file (the third argument) so that a second run skips it.
// Usage: tangential_trace N [MAX_ITERATIONS] [PRESSURE_FILE] [EVERY] [coarse|fine]
// [active=UPDATES] [normal] [perturb=K] [seed=S] (coarse, fine: TangentialOptions::coarse_start on,
// off, automatic without either;
// active: TangentialOptions::active_set_updates, 10 if no number is given;
// normal: the normal solve made and timed even when the pressure file
// exists, for the step's time against it in the same run; perturb: both
// tangential loads times 1 + K 1e-15, a rounding-level change of the input
// whose iterations should stay near the unperturbed ones; seed: the
// surface's seed, 1 if not given, for another contact of the same
// statistics, which needs its own pressure file). One thread; the counts are
// exact, the times those of a shared machine.
#include <fmt/format.h>

#include <Eigen/Core>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <fstream>
#include <span>
#include <stdexcept>
#include <string>

#include "halfspace/elastic_pair.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/operators/tangential_operator.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/solvers/tangential_solver.hpp"
#include "halfspace/surface/self_affine.hpp"
#include "halfspace/threads.hpp"

namespace {

using namespace halfspace;

constexpr ElasticBody kSteel{2.1e11, 0.3};
constexpr double kSpacing = 1e-6;  // m, as tangential_bench.cpp
constexpr double kShortCutoff = 4e-6;
constexpr double kRmsSlope = 0.1;
constexpr double kReducedPressure = 0.04;
constexpr double kMu = 0.3;
constexpr double kTolerance = 1e-8;

// The process's CPU time: one thread, so on a shared machine a steadier
// measure than the wall clock (which counts the time other jobs hold the core).
double cpu_seconds() {
  return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

Eigen::ArrayXd normal_pressure(const Grid& grid, const ElasticPair& pair, const std::string& file, bool timed,
                               unsigned seed) {
  Eigen::ArrayXd pressure(static_cast<Eigen::Index>(grid.size()));
  if (!file.empty() && !timed) {
    std::ifstream in(file, std::ios::binary);
    if (in.read(reinterpret_cast<char*>(pressure.data()), static_cast<std::streamsize>(grid.size() * sizeof(double)))) {
      return pressure;
    }
  }
  surface::SelfAffineSpec spec;
  spec.hurst = 0.8;
  spec.short_cutoff = kShortCutoff;
  spec.rms_slope = kRmsSlope;
  spec.seed = seed;
  const Eigen::ArrayXd heights = surface::make_self_affine_surface(grid, spec);
  const Eigen::ArrayXd gap = solvers::initial_gap(grid, {heights.data(), grid.size()});
  const double e_star = pair.composite_modulus();
  solvers::SolverOptions settings;
  settings.tolerance = kTolerance;
  settings.fft_planning = FftPlanning::estimate;
  auto solver = solvers::make_solver(grid, e_star, settings);
  const double cpu = cpu_seconds();
  const SolveResult normal =
      solver->solve({gap.data(), grid.size()}, Loading::mean_pressure(kReducedPressure * e_star * kRmsSlope));
  fmt::print("normal solve: {} iterations, {:.3f} s ({:.3f} s CPU), contact {:.4f}, {}\n", normal.iterations,
             normal.wall_seconds, cpu_seconds() - cpu, normal.contact_fraction,
             normal.converged() ? "converged" : normal.message);
  pressure = normal.pressure;
  if (!file.empty()) {
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(pressure.data()),
              static_cast<std::streamsize>(grid.size() * sizeof(double)));
  }
  return pressure;
}

void report(const char* name, const TangentialResult& r, double cpu) {
  fmt::print(
      "{}: {} iterations, {:.3f} s ({:.3f} s CPU), {} C products, {} M products, residual {:.3e}, stick {:.4f}, force "
      "{:.6g}, {}\n",
      name, r.iterations, r.wall_seconds, cpu, r.operator_applications, r.preconditioner_applications, r.residual,
      r.stick_fraction, r.force_x, r.converged() ? "converged" : r.message);
  fmt::print("  active-set phase: {} updates, {} inner iterations\n", r.active_set_updates, r.active_set_iterations);
  fmt::print(
      "  coarse: {} levels, {} iterations, worth {:.1f} C and {:.1f} M products; all products {:.1f}\n",
      r.coarse.levels, r.coarse.iterations, r.coarse.operator_work, r.coarse.preconditioner_work,
      r.operator_applications + r.preconditioner_applications + r.coarse.operator_work + r.coarse.preconditioner_work);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 2) {
      std::fprintf(stderr,
                   "usage: tangential_trace N [MAX_ITERATIONS] [PRESSURE_FILE] [EVERY] [coarse|fine] [active=UPDATES] "
                   "[normal] [perturb=K] [seed=S]\n");
      return 2;
    }
    const auto n = static_cast<std::size_t>(std::stoul(argv[1]));
    const int cap = argc > 2 ? std::stoi(argv[2]) : 20000;
    const std::string file = argc > 3 ? argv[3] : "";
    const int every = argc > 4 ? std::stoi(argv[4]) : 1;
    TangentialCoarseStart coarse_start = TangentialCoarseStart::automatic;
    int active_set_updates = 0;
    bool timed = false;
    double scale = 1.0;
    unsigned seed = 1;
    for (int a = 5; a < argc; ++a) {
      const std::string arg = argv[a];
      if (arg == "coarse" || arg == "fine") {
        coarse_start = arg == "coarse" ? TangentialCoarseStart::on : TangentialCoarseStart::off;
      } else if (arg == "normal") {
        timed = true;
      } else if (arg.starts_with("perturb=")) {
        scale = 1.0 + std::stod(arg.substr(8)) * 1e-15;
      } else if (arg.starts_with("seed=")) {
        seed = static_cast<unsigned>(std::stoul(arg.substr(5)));
      } else if (arg.starts_with("active")) {
        active_set_updates = arg.size() > 7 ? std::stoi(arg.substr(7)) : 10;
      } else {
        throw std::invalid_argument("unknown argument " + arg +
                                    ": allowed are coarse, fine, active[=UPDATES], normal, perturb=K and seed=S");
      }
    }
    set_threads(1);
    const Grid grid = Grid::plane(n, n, kSpacing, kSpacing, Boundary::periodic);
    const ElasticPair pair = ElasticPair::similar(kSteel);
    const Eigen::ArrayXd pressure = normal_pressure(grid, pair, file, timed, seed);
    const double load = pressure.sum() * grid.cell_area();
    TangentialOperator op(grid, pair);
    solvers::TangentialOptions options;
    options.friction_coefficient = kMu;
    options.tolerance = kTolerance;
    options.max_iterations = cap;
    options.coarse_start = coarse_start;
    options.active_set_updates = active_set_updates;
    options.progress = [every](int iteration, double residual) {
      if (iteration % every == 0) fmt::print("  {:5d} {:.3e}\n", iteration, residual);
      std::fflush(stdout);
      return solvers::IterationDecision::proceed;
    };
    TangentialSolver solver(op, options);
    const std::span<const double> p(pressure.data(), grid.size());
    double cpu = cpu_seconds();
    const TangentialResult first =
        solver.solve(p, TangentialLoading::force(scale * 0.5 * kMu * load), TangentialState::unloaded(grid.size()));
    report("step 1", first, cpu_seconds() - cpu);
    cpu = cpu_seconds();
    const TangentialResult second = solver.solve(p, TangentialLoading::force(scale * 0.25 * kMu * load), first.state);
    report("step 2", second, cpu_seconds() - cpu);
    return first.converged() && second.converged() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
