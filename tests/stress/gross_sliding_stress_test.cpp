// Stresses below a sliding cylinder and sphere: gross sliding, q = mu p along
// x on a library-solved Hertz pressure. The surface stress at the trailing
// edge against McEwen (1949) and Hamilton & Goodman (1966), the depth of the
// largest von Mises stress moving to the surface as mu grows (Johnson 1985,
// sec. 7.2), and the refusals of the sliding traction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "halfspace/elastic_pair.hpp"
#include "halfspace/error.hpp"
#include "halfspace/operators/tangential_operator.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/solvers/tangential_solver.hpp"
#include "halfspace/stress/sliding_traction.hpp"
#include "halfspace/stress/stress_volume.hpp"
#include "support/analytic_solutions.hpp"
#include "support/grid_fields.hpp"
#include "support/pk_solvers.hpp"

namespace halfspace::stress {
namespace {

using halfspace::testing::centred_x;
using halfspace::testing::centred_y;

constexpr double kEStar = 100e9;
constexpr double kRadius = 0.01;

// A rigid cylinder (1D) pressed by `load` (N/m) into a free line grid
// `cells_per_half_width` cells per Hertz half-width, 4 half-widths wide.
struct Contact {
  Grid grid;
  std::vector<double> pressure;
  double half_width;  // Hertz b or a, m
  double peak;        // Hertz p0, Pa
};

Contact cylinder(double load, std::size_t cells_per_half_width) {
  const auto hertz = halfspace::testing::hertz_line(load, kRadius, kEStar);
  const std::size_t n = 4 * cells_per_half_width + 1;
  const Grid grid = Grid::line(n, hertz.half_width / static_cast<double>(cells_per_half_width), Boundary::free);
  std::vector<double> heights(n);
  for (std::size_t i = 0; i < n; ++i) heights[i] = -std::pow(centred_x(grid, i), 2) / (2.0 * kRadius);
  const SolveResult result =
      solvers::solve_surface(grid, heights, kEStar, Loading::force(load),
                             halfspace::testing::test_options(solvers::SolverType::pk_fourier, 1e-10));
  EXPECT_TRUE(result.converged()) << result.message;
  return {grid, std::vector<double>(result.pressure.begin(), result.pressure.end()), hertz.half_width, hertz.peak};
}

Contact sphere(double force, std::size_t cells_per_radius) {
  const auto hertz = halfspace::testing::hertz_point(force, kRadius, kEStar);
  const std::size_t n = 3 * cells_per_radius + 1;
  const double h = hertz.radius / static_cast<double>(cells_per_radius);
  const Grid grid = Grid::plane(n, n, h, h, Boundary::free);
  std::vector<double> heights(grid.size());
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t i = 0; i < n; ++i) {
      heights[j * n + i] = -(std::pow(centred_x(grid, i), 2) + std::pow(centred_y(grid, j), 2)) / (2.0 * kRadius);
    }
  }
  const SolveResult result =
      solvers::solve_surface(grid, heights, kEStar, Loading::force(force),
                             halfspace::testing::test_options(solvers::SolverType::pk_fourier, 1e-10));
  EXPECT_TRUE(result.converged()) << result.message;
  return {grid, std::vector<double>(result.pressure.begin(), result.pressure.end()), hertz.radius, hertz.peak};
}

// sigma_xx at the trailing edge (x = -b or -a, y = 0; a cell centre, the
// grids being odd with a whole number of cells per half-width) a hundredth
// of a cell below the surface, under q = mu p along +x.
double trailing_edge_stress(const Contact& c, double mu, double nu) {
  const SlidingShear q = gross_sliding_shear(c.pressure, mu, 1.0);
  const std::vector<double> depth = {0.01 * c.grid.dx()};
  const StressVolume v = compute_stress_volume(c.grid, {c.pressure, q.x, q.y}, depth, nu);
  const std::size_t row = c.grid.dimension() == 1 ? 0 : c.grid.ny() / 2;
  const auto column = static_cast<std::size_t>(std::lround(c.grid.nx() / 2 - c.half_width / c.grid.dx()));
  EXPECT_NEAR(centred_x(c.grid, column), -c.half_width, 1e-9 * c.half_width);
  return v.components[static_cast<std::size_t>(Component::xx)][row * c.grid.nx() + column];
}

// The cell-constant tractions resolve the square-root edge of q = mu p only
// to O(sqrt(h)) (h the cell size over the half-width): the trailing-edge
// stress converges like sqrt(h), and its extrapolation in sqrt(h) from two
// grids, E0 = (r E(h/r^2)... written out below, leaves O(h).
double extrapolated(double coarse, double fine, double refinement) {
  const double root = std::sqrt(refinement);  // the error's ratio between the grids
  return (root * fine - coarse) / (root - 1.0);
}

// McEwen (1949): a sliding cylinder's trailing edge carries sigma_x = 2 mu p0.
TEST(GrossSlidingStressTest, CylinderTrailingEdgeStressIsMcEwens) {
  // Measured: errors of 0.105, 0.053 and 0.026 p0 at 64, 256 and 1024
  // cells per half-width (mu = 0.5), halving with each fourfold refinement
  // as sqrt(h) does; extrapolated from 256 and 1024, within 4e-5 p0.
  constexpr double kExtrapolated = 1e-3;  // of p0: the O(h) left by the extrapolation
  constexpr double kRawAtFine = 0.035;    // of p0 at 1024 cells per half-width: about sqrt(h)
  const double nu = 0.3;
  const Contact coarse = cylinder(1e5, 256);
  const Contact fine = cylinder(1e5, 1024);
  for (const double mu : {0.1, 0.3, 0.5}) {
    const double expected = 2.0 * mu;
    const double e_coarse = trailing_edge_stress(coarse, mu, nu) / coarse.peak;
    const double e_fine = trailing_edge_stress(fine, mu, nu) / fine.peak;
    const double e0 = extrapolated(e_coarse, e_fine, 4.0);
    std::printf(
        "cylinder, mu = %.1f: trailing-edge sigma_x = %.5f p0 (256 cells/b), %.5f (1024), extrapolated "
        "%.5f; McEwen 2 mu p0 = %.5f p0\n",
        mu, e_coarse, e_fine, e0, expected);
    EXPECT_NEAR(e0, expected, kExtrapolated) << "mu = " << mu;
    EXPECT_NEAR(e_fine, expected, kRawAtFine) << "mu = " << mu;
    // The error halves under a fourfold refinement (sqrt(h)).
    const double ratio = (expected - e_coarse) / (expected - e_fine);
    EXPECT_GT(ratio, 1.7) << "mu = " << mu;
    EXPECT_LT(ratio, 2.3) << "mu = " << mu;
  }
}

// Hamilton & Goodman (1966): a sliding sphere's trailing edge carries
// sigma_x = p0 ((1 - 2 nu)/3 + (4 + nu) pi mu / 8).
TEST(GrossSlidingStressTest, SphereTrailingEdgeStressIsHamiltonGoodmans) {
  // Measured: errors of 0.077 and 0.054 p0 at 24 and 48 cells per radius
  // (mu = 0.3); extrapolated, within 3e-4 p0.
  constexpr double kExtrapolated = 3e-3;  // of p0: the O(h) left by the extrapolation
  constexpr double kRawAtFine = 0.15;     // of p0 at 48 cells per radius: about sqrt(h)
  const double nu = 0.3;
  const Contact coarse = sphere(10.0, 24);
  const Contact fine = sphere(10.0, 48);
  for (const double mu : {0.1, 0.3, 0.5}) {
    const double expected = (1.0 - 2.0 * nu) / 3.0 + (4.0 + nu) * std::numbers::pi * mu / 8.0;
    const double e_coarse = trailing_edge_stress(coarse, mu, nu) / coarse.peak;
    const double e_fine = trailing_edge_stress(fine, mu, nu) / fine.peak;
    const double e0 = extrapolated(e_coarse, e_fine, 2.0);
    std::printf(
        "sphere, mu = %.1f: trailing-edge sigma_x = %.5f p0 (24 cells/a), %.5f (48), extrapolated %.5f; "
        "Hamilton-Goodman %.5f p0\n",
        mu, e_coarse, e_fine, e0, expected);
    EXPECT_NEAR(e0, expected, kExtrapolated) << "mu = " << mu;
    EXPECT_NEAR(e_fine, expected, kRawAtFine) << "mu = " << mu;
    EXPECT_LT(std::abs(expected - e_fine), std::abs(expected - e_coarse)) << "mu = " << mu;
  }
}

// The largest von Mises stress below a sliding cylinder (plane strain) at
// 0.002 b (the surface) and from 0.3 b to b in steps of 0.02 b, and its
// position.
VonMisesMaximum deepest_yield(const Contact& c, double mu, double nu) {
  const SlidingShear q = gross_sliding_shear(c.pressure, mu, 1.0);
  std::vector<double> depths = {0.002 * c.half_width};
  for (int k = 0; k <= 35; ++k) depths.push_back(c.half_width * (0.3 + 0.02 * k));
  return compute_stress_volume(c.grid, {c.pressure, q.x, q.y}, depths, nu).max_von_mises;
}

// Johnson (1985, sec. 7.2): below a sliding cylinder the largest von Mises
// stress (nu = 0.3) lies at about 0.7 b without friction and rises as mu
// grows, reaching the surface at mu of about 0.3.
TEST(GrossSlidingStressTest, CylinderYieldMovesToTheSurfaceAsFrictionGrows) {
  // Hertz (mu = 0): 0.557 p0 at 0.70 b (Johnson's figures, rounded).
  constexpr double kFrictionless = 0.005;  // of p0: 256 cells per half-width
  const double nu = 0.3;
  const Contact c = cylinder(1e5, 256);
  const double centre = 0.5 * static_cast<double>(c.grid.nx() - 1) * c.grid.dx();
  const double shallowest = 0.002 * c.half_width;
  double previous_depth = HUGE_VAL;
  double surface_mu = HUGE_VAL;
  for (const double mu : {0.0, 0.1, 0.2, 0.25, 0.26, 0.27, 0.28, 0.3, 0.4}) {
    const VonMisesMaximum m = deepest_yield(c, mu, nu);
    std::printf("cylinder, mu = %.2f: largest von Mises %.4f p0 at x = %.4f b, z = %.4f b\n", mu, m.value / c.peak,
                (m.x - centre) / c.half_width, m.z / c.half_width);
    if (mu == 0.0) {
      EXPECT_NEAR(m.value / c.peak, 0.557, kFrictionless);
      EXPECT_NEAR(m.z / c.half_width, 0.70, 0.02);  // the depths' spacing
    }
    EXPECT_LE(m.z, previous_depth) << "mu = " << mu;
    previous_depth = m.z;
    if (m.z == shallowest && surface_mu == HUGE_VAL) surface_mu = mu;
  }
  std::printf("the largest von Mises stress reaches the surface at mu = %.2f\n", surface_mu);
  EXPECT_GE(surface_mu, 0.25);
  EXPECT_LE(surface_mu, 0.3);
}

// The tangential solver under a force of exactly mu P slides grossly: its
// shear is the sliding traction's, sign included (q along the force).
TEST(GrossSlidingStressTest, SlidingTractionIsTheTangentialSolversGrossSliding) {
  constexpr double kRounding = 1e-12;  // of mu p0
  const double mu = 0.4;
  const Contact c = sphere(10.0, 12);
  const ElasticPair pair = ElasticPair::similar({2.1e11, 0.3});
  TangentialOperator op(c.grid, pair);
  solvers::TangentialOptions options;
  options.friction_coefficient = mu;
  TangentialSolver solver(op, options);
  double normal_force = 0.0;
  for (const double p : c.pressure) normal_force += p * c.grid.dx() * c.grid.dy();
  const double angle = 0.3;  // a direction off the axes
  const TangentialResult result = solver.solve(
      c.pressure, TangentialLoading::force(mu * normal_force * std::cos(angle), mu * normal_force * std::sin(angle)),
      TangentialState::unloaded(c.grid.size()));
  ASSERT_TRUE(result.gross_sliding) << result.message;
  const SlidingShear q = gross_sliding_shear(c.pressure, mu, std::cos(angle), std::sin(angle));
  double worst = 0.0;
  for (std::size_t k = 0; k < c.grid.size(); ++k) {
    worst = std::max(worst, std::hypot(result.state.shear_x[static_cast<Eigen::Index>(k)] - q.x[k],
                                       result.state.shear_y[static_cast<Eigen::Index>(k)] - q.y[k]));
  }
  EXPECT_LT(worst, kRounding * mu * c.peak);
}

TEST(GrossSlidingStressTest, SlidingTractionIsMuPAlongTheDirection) {
  const std::vector<double> pressure = {0.0, 1e6, 3e6};
  const SlidingShear q = gross_sliding_shear(pressure, 0.5, 3.0, -4.0);
  EXPECT_DOUBLE_EQ(q.x[2], 0.5 * 3e6 * 0.6);
  EXPECT_DOUBLE_EQ(q.y[2], -0.5 * 3e6 * 0.8);
  EXPECT_EQ(q.x[0], 0.0);
  const auto message = [&](double mu, double dx, double dy, std::vector<double> p) {
    try {
      gross_sliding_shear(p, mu, dx, dy);
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message(-0.1, 1.0, 0.0, pressure), "friction coefficient mu = -0.1 is invalid: it must be finite and >= 0");
  EXPECT_EQ(message(0.2, 0.0, 0.0, pressure), "sliding direction (0, 0) is invalid: it must be finite and not zero");
  EXPECT_EQ(message(0.2, 1.0, 0.0, {1.0, -2.0}),
            "gross sliding: pressure value -2 Pa at index 1 is invalid: it must be finite and >= 0");
}

}  // namespace
}  // namespace halfspace::stress
