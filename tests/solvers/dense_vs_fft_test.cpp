// The dense solvers (Lemke, LCPquad on the assembled matrix) against
// Polonsky-Keer on the FFT operator, on small 2D grids, free and periodic: a
// Hertz sphere and a random rough patch. Same kernels, so the same LCP: the
// pressures must agree to the solvers' accuracy, not to a discretisation
// error.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <span>

#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/solvers/lcp_quad.hpp"
#include "halfspace/solvers/lemke.hpp"
#include "halfspace/solvers/polonsky_keer.hpp"
#include "support/contact_checks.hpp"
#include "support/grid_fields.hpp"

namespace halfspace {
namespace {

using testing::field_from;

constexpr std::size_t kCells = 16;  // per side: 256 unknowns, a 258 x 258 Lemke tableau
constexpr double kSpacing = 1e-6;   // m
constexpr double kEStar = 1e11;     // Pa
// Polonsky-Keer at residual 1e-12 against Lemke's exact pivoting.
constexpr double kPkTolerance = 1e-12;
constexpr double kLemkeVsPk = 1e-8;  // of the maximum pressure
// The interior-point method at its 1e-12 stopping tolerance.
constexpr double kLcpQuadVsLemke = 1e-6;  // of the maximum pressure
// Approaches agree like the pressures, relative to the height range.
constexpr double kApproachTolerance = 1e-8;

Eigen::ArrayXd sphere_gap(const Grid& grid) {
  return field_from(grid, [](double x, double y) { return (x * x + y * y) / (2.0 * 1e-4); });
}

// Heights: i.i.d. normal (fixed seed) smoothed by a 3 x 3 mean (periodic
// wrap), so that contacts form clusters; initial gap max(h) - h.
Eigen::ArrayXd rough_gap(const Grid& grid, std::uint32_t seed) {
  std::mt19937 generator(seed);
  std::normal_distribution<double> normal(0.0, 1e-7);
  const auto n = static_cast<Eigen::Index>(kCells);
  Eigen::ArrayXXd noise(n, n);
  for (Eigen::Index k = 0; k < noise.size(); ++k) noise(k) = normal(generator);
  Eigen::ArrayXd height(grid.size());
  for (Eigen::Index j = 0; j < n; ++j) {
    for (Eigen::Index i = 0; i < n; ++i) {
      double sum = 0.0;
      for (Eigen::Index dj = -1; dj <= 1; ++dj) {
        for (Eigen::Index di = -1; di <= 1; ++di) sum += noise((j + dj + n) % n, (i + di + n) % n);
      }
      height[j * n + i] = sum / 9.0;
    }
  }
  return height.maxCoeff() - height;
}

struct Comparison {
  double lemke_vs_pk;          // max |dp| / max p
  double lcpquad_vs_lemke;     // max |dp| / max p
  double approach_difference;  // |delta_lemke - delta_pk| / ptp(g0)
  double contact_fraction;
};

Comparison compare(const Grid& grid, const Eigen::ArrayXd& gap, const Loading& loading, const char* what) {
  const std::span<const double> g0(gap.data(), grid.size());
  solvers::Lemke lemke(grid, kEStar);
  const SolveResult dense = lemke.solve(g0, loading);
  solvers::LcpQuad lcpquad(grid, kEStar);
  const SolveResult quad = lcpquad.solve(g0, loading);
  FftInfluenceOperator op(grid, kEStar);
  solvers::PolonskyKeerOptions options;
  options.tolerance = kPkTolerance;
  solvers::PolonskyKeer pk(op, options);
  const SolveResult fft = pk.solve(g0, loading);
  EXPECT_TRUE(dense.converged()) << what << ": " << dense.message;
  EXPECT_TRUE(quad.converged()) << what << ": " << quad.message;
  EXPECT_TRUE(fft.converged()) << what << ": " << fft.message;

  const double peak = dense.max_pressure;
  Eigen::Index at_pk = 0;
  Eigen::Index at_quad = 0;
  const Comparison c{(dense.pressure - fft.pressure).abs().maxCoeff(&at_pk) / peak,
                     (quad.pressure - dense.pressure).abs().maxCoeff(&at_quad) / peak,
                     std::abs(dense.approach - fft.approach) / (gap.maxCoeff() - gap.minCoeff()),
                     dense.contact_fraction};
  std::printf(
      "%s: contact %.2f, %d pivots, %d IPM iterations, %d PK iterations; |Lemke-PK| %.2e at cell %ld, "
      "|LCPquad-Lemke| %.2e at cell %ld, approach %.2e\n",
      what, c.contact_fraction, dense.iterations, quad.iterations, fft.iterations, c.lemke_vs_pk,
      static_cast<long>(at_pk), c.lcpquad_vs_lemke, static_cast<long>(at_quad), c.approach_difference);
  return c;
}

void expect_agreement(const Comparison& c) {
  EXPECT_LE(c.lemke_vs_pk, kLemkeVsPk);
  EXPECT_LE(c.lcpquad_vs_lemke, kLcpQuadVsLemke);
  EXPECT_LE(c.approach_difference, kApproachTolerance);
  // The setup must produce a partial contact, or the comparison says little.
  EXPECT_GT(c.contact_fraction, 0.01);
  EXPECT_LT(c.contact_fraction, 0.9);
}

TEST(DenseVsFftTest, HertzSphereOnFreeGrid) {
  const Grid grid = Grid::plane(kCells, kCells, kSpacing, kSpacing, Boundary::free);
  expect_agreement(compare(grid, sphere_gap(grid), Loading::force(0.02), "free sphere, force"));
}

TEST(DenseVsFftTest, HertzSphereOnFreeGridUnderDisplacementControl) {
  const Grid grid = Grid::plane(kCells, kCells, kSpacing, kSpacing, Boundary::free);
  expect_agreement(compare(grid, sphere_gap(grid), Loading::approach(2e-7), "free sphere, approach"));
}

TEST(DenseVsFftTest, HertzSphereOnPeriodicGrid) {
  const Grid grid = Grid::plane(kCells, kCells, kSpacing, kSpacing, Boundary::periodic);
  expect_agreement(compare(grid, sphere_gap(grid), Loading::mean_pressure(5e7), "periodic sphere, mean pressure"));
}

TEST(DenseVsFftTest, RoughPatchOnFreeGrid) {
  const Grid grid = Grid::plane(kCells, kCells, kSpacing, kSpacing, Boundary::free);
  expect_agreement(compare(grid, rough_gap(grid, 5), Loading::mean_pressure(1e9), "free rough patch"));
}

TEST(DenseVsFftTest, RoughPatchOnPeriodicGrid) {
  const Grid grid = Grid::plane(kCells, kCells, kSpacing, kSpacing, Boundary::periodic);
  expect_agreement(compare(grid, rough_gap(grid, 6), Loading::mean_pressure(1e9), "periodic rough patch"));
}

}  // namespace
}  // namespace halfspace
