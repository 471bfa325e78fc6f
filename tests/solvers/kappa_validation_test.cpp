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

#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/solvers/load_sweep.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/surface/self_affine.hpp"
#include "halfspace/surface/statistics.hpp"

namespace halfspace::solvers {
namespace {

// The surfaces: 512^2 periodic, H = 0.8, a pure power law from the domain
// size down to a short cutoff of 8 cells (so each contact spot spans several
// cells), three seeds. Lengths in units of dx, E* = 1: only ratios matter.
constexpr std::size_t kCells = 512;
constexpr double kHurst = 0.8;
constexpr double kShortCutoffCells = 8.0;
constexpr double kRmsSlope = 0.1;
constexpr int kSeeds = 3;
// p / (E* h'_rms) at each step; with kappa ~ 2 the contact fraction runs from
// about 1% to 10%, the small-load regime of the literature.
const std::vector<double> kReducedPressures{0.005, 0.01, 0.02, 0.035, 0.05};

// Bounds. Every single ratio A/A0 / (p / (E* h'_rms)) must lie between the
// two analytic limits, Persson's theory sqrt(8/pi) = 1.60 and the asperity
// theory of Bush, Gibson & Thomas sqrt(2 pi) = 2.51, which bracket all
// numerical results: single seeds at 1% contact have only ~20 contact
// clusters on this grid, so their ratio scatters by about +-10%. The
// least-squares kappa over all seeds and loads must lie in the range the
// boundary-element literature reports, 1.8 to 2.3 (shared/REFERENCES.md).
// Measured on this setup: kappa = 2.05 (per seed 2.0-2.1); refining the same
// surfaces to 1024^2 (cutoff 16 cells) lowers it by about 2%.
const double kPerPointLow = std::sqrt(8.0 / std::numbers::pi);
const double kPerPointHigh = std::sqrt(2.0 * std::numbers::pi);
constexpr double kFittedLow = 1.8;
constexpr double kFittedHigh = 2.3;

TEST(KappaValidationTest, ContactAreaIsProportionalToLoadWithLiteratureKappa) {
  const auto start = std::chrono::steady_clock::now();
  const Grid grid = Grid::plane(kCells, kCells, 1.0, 1.0, Boundary::periodic);
  const double e_star = 1.0;
  const std::unique_ptr<ContactSolver> solver = make_solver(grid, e_star, SolverSettings{});

  double sum_ax = 0.0;  // least squares through the origin: kappa = sum(A x) / sum(x^2)
  double sum_xx = 0.0;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    surface::SelfAffineSpec spec;
    spec.hurst = kHurst;
    spec.short_cutoff = kShortCutoffCells;
    spec.rms_slope = kRmsSlope;
    spec.seed = static_cast<std::uint64_t>(seed);
    const Eigen::ArrayXd heights = surface::make_self_affine_surface(grid, spec);
    const double slope = surface::rms_slope(grid, {heights.data(), grid.size()});
    const Eigen::ArrayXd gap = geometry::initial_gap_from_heights(heights);

    std::vector<double> pressures;
    for (const double x : kReducedPressures) pressures.push_back(x * e_star * slope);
    const std::vector<SweepStep> steps =
        run_load_sweep(*solver, grid, {gap.data(), grid.size()}, ControlMode::mean_pressure, pressures);

    double seed_ax = 0.0;
    double seed_xx = 0.0;
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const SweepStep& step = steps[k];
      ASSERT_TRUE(step.result.converged()) << "seed " << seed << " step " << k << ": " << step.result.message;
      const double x = step.result.mean_pressure / (e_star * slope);
      const double area = step.statistics.contact_fraction;
      std::printf("seed %d  p/(E* h'rms) = %.4f  A/A0 = %.4f  ratio %.3f  clusters %lld  iterations %d\n", seed, x,
                  area, area / x, static_cast<long long>(step.statistics.clusters()), step.result.iterations);
      EXPECT_GT(area / x, kPerPointLow) << "seed " << seed << " step " << k;
      EXPECT_LT(area / x, kPerPointHigh) << "seed " << seed << " step " << k;
      EXPECT_LT(area, 0.12) << "still the small-load regime";
      seed_ax += area * x;
      seed_xx += x * x;
    }
    std::printf("seed %d: fitted kappa %.3f\n", seed, seed_ax / seed_xx);
    sum_ax += seed_ax;
    sum_xx += seed_xx;
  }
  const double kappa = sum_ax / sum_xx;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("kappa = %.3f over %d seeds (literature 1.8-2.3), %.1f s\n", kappa, kSeeds, seconds);
  EXPECT_GT(kappa, kFittedLow);
  EXPECT_LT(kappa, kFittedHigh);
}

}  // namespace
}  // namespace halfspace::solvers
