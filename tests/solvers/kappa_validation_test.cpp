// Validation on random self-affine surfaces: at small loads the true contact
// area grows in proportion to the load, A/A0 = kappa p / (E* h'_rms) with
// h'_rms = sqrt(<|grad h|^2>), and kappa lies in the range found by
// boundary-element studies (Hyun et al. 2004; Prodanov, Dapp & Mueser 2014;
// Yastrebov, Anciaux & Molinari 2015, 2017): about 1.8 to 2.3.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "halfspace/analysis/load_sweep.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/surface/self_affine.hpp"
#include "halfspace/surface/statistics.hpp"
#include "halfspace/threads.hpp"
#include "support/pk_solvers.hpp"

namespace halfspace::solvers {
namespace {

// The surfaces: 512^2 periodic, H = 0.8, a pure power law from the domain
// size down to a short cutoff of 8 cells (so each contact spot spans several
// cells), five seeds. Lengths in units of dx, E* = 1: only ratios matter.
constexpr std::size_t kCells = 512;
constexpr double kHurst = 0.8;
constexpr double kShortCutoffCells = 8.0;
constexpr double kRmsSlope = 0.1;
constexpr int kSeeds = 5;
// p / (E* h'_rms) at each step; with kappa ~ 2 the contact fraction runs from
// about 1% to 10%, the small-load regime of the literature.
const std::vector<double> kReducedPressures{0.005, 0.01, 0.02, 0.035, 0.05};

// Bounds. At every load the ratio A/A0 / (p / (E* h'_rms)), averaged over the
// seeds, must lie between the two analytic limits that bracket all numerical
// results: Persson's theory, sqrt(8/pi) = 1.60, and the asperity theory of
// Bush, Gibson & Thomas, sqrt(2 pi) = 2.51. (Single seeds are not held to
// them: at 1% contact a seed has only 4 to 30 contact clusters on this grid
// and its ratio scatters by +-10%.) The least-squares kappa over all seeds
// and loads must lie in the range the boundary-element literature reports,
// 1.8 to 2.3 (Hyun et al. 2004; Yastrebov et al. 2017; shared/REFERENCES.md).
// Measured: kappa = 2.00 (per seed 1.90 to 2.06); the seed-averaged ratio
// falls from 2.26 at 1% contact to 1.99 at 10% (the area grows slightly
// sublinearly, and the smallest contacts span few cells); refining the same
// surfaces to 1024^2 (cutoff 16 cells) lowered kappa by about 2% on the
// first three seeds.
const double kAnalyticLow = std::sqrt(8.0 / std::numbers::pi);
const double kAnalyticHigh = std::sqrt(2.0 * std::numbers::pi);
constexpr double kFittedLow = 1.8;
constexpr double kFittedHigh = 2.3;

TEST(KappaValidationTest, ContactAreaIsProportionalToLoadWithLiteratureKappa) {
  const auto start = std::chrono::steady_clock::now();
  // One thread: ctest runs tests side by side on few cores, where OpenMP
  // teams that wait for each other's cores stall (20x slower measured on 2
  // busy cores); one thread takes about 6 s here.
  const int original_threads = threads();
  set_threads(1);
  const Grid grid = Grid::plane(kCells, kCells, 1.0, 1.0, Boundary::periodic);
  const double e_star = 1.0;
  const std::unique_ptr<ContactSolver> solver =
      make_solver(grid, e_star, testing::test_options(SolverType::pk_multilevel));

  double sum_ax = 0.0;  // least squares through the origin: kappa = sum(A x) / sum(x^2)
  double sum_xx = 0.0;
  std::vector<double> ratio_sums;  // per load, over the seeds
  for (int seed = 1; seed <= kSeeds; ++seed) {
    surface::SelfAffineSpec spec;
    spec.hurst = kHurst;
    spec.short_cutoff = kShortCutoffCells;
    spec.rms_slope = kRmsSlope;
    spec.seed = static_cast<std::uint64_t>(seed);
    const Eigen::ArrayXd heights = surface::make_self_affine_surface(grid, spec);
    const double slope = surface::rms_slope(grid, {heights.data(), grid.size()});
    const Eigen::ArrayXd gap = solvers::initial_gap(grid, {heights.data(), grid.size()});

    std::vector<double> pressures;
    for (const double x : kReducedPressures) pressures.push_back(x * e_star * slope);
    const std::vector<analysis::SweepStep> steps =
        analysis::run_load_sweep(*solver, grid, {gap.data(), grid.size()}, ControlMode::mean_pressure, pressures);

    if (ratio_sums.empty()) ratio_sums.assign(steps.size(), 0.0);
    double seed_ax = 0.0;
    double seed_xx = 0.0;
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const analysis::SweepStep& step = steps[k];
      ASSERT_TRUE(step.result.converged()) << "seed " << seed << " step " << k << ": " << step.result.message;
      const double x = step.result.mean_pressure / (e_star * slope);
      const double area = step.statistics.contact_fraction;
      std::printf("seed %d  p/(E* h'rms) = %.4f  A/A0 = %.4f  ratio %.3f  clusters %lld  iterations %d\n", seed, x,
                  area, area / x, static_cast<long long>(step.statistics.clusters()), step.result.iterations);
      ratio_sums[k] += area / x;
      EXPECT_LT(area, 0.12) << "still the small-load regime";
      EXPECT_GE(step.result.pressure.minCoeff(), 0.0) << "seed " << seed << " step " << k;
      EXPECT_GE(step.result.residual, 0.0) << "seed " << seed << " step " << k;
      seed_ax += area * x;
      seed_xx += x * x;
    }
    std::printf("seed %d: fitted kappa %.3f\n", seed, seed_ax / seed_xx);
    sum_ax += seed_ax;
    sum_xx += seed_xx;
  }
  for (std::size_t k = 0; k < ratio_sums.size(); ++k) {
    const double mean_ratio = ratio_sums[k] / kSeeds;
    std::printf("p/(E* h'rms) = %.4f: ratio %.3f averaged over the seeds\n", kReducedPressures[k], mean_ratio);
    EXPECT_GT(mean_ratio, kAnalyticLow) << "load " << k;
    EXPECT_LT(mean_ratio, kAnalyticHigh) << "load " << k;
  }
  const double kappa = sum_ax / sum_xx;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("kappa = %.3f over %d seeds (literature 1.8-2.3), %.1f s\n", kappa, kSeeds, seconds);
  set_threads(original_threads);
  EXPECT_GT(kappa, kFittedLow);
  EXPECT_LT(kappa, kFittedHigh);
}

}  // namespace
}  // namespace halfspace::solvers
