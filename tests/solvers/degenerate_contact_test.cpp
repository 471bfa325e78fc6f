// Contacts that are degenerate for the solvers: rigid flat punches in full
// contact, whose initial gap is flat and whose pressure is singular at the
// edges, checked against the analytic punch solutions; and a numerical
// failure inside the coarse correction, which must reach the result.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/solvers/balancing_preconditioner.hpp"
#include "halfspace/solvers/block_deflation.hpp"
#include "halfspace/solvers/fourier_preconditioner.hpp"
#include "halfspace/solvers/grid_transfer.hpp"
#include "halfspace/solvers/polonsky_keer.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "support/contact_checks.hpp"
#include "support/grid_fields.hpp"
#include "support/pk_solvers.hpp"
#include "support/rough_gap.hpp"

namespace halfspace::solvers {
namespace {

using testing::expect_contact_conditions;
using testing::field_from;

constexpr double kEStar = 1e11;  // Pa
constexpr double kForce = 10.0;  // N in 2D, N/m in 1D
// Force balance holds to rounding under load control.
constexpr double kForceBalance = 1e-10;

SolveResult solve_with(const std::string& solver, const Grid& grid, const Eigen::ArrayXd& gap, const Loading& loading) {
  return make_solver(grid, kEStar, testing::test_options(parse_solver_type(solver)))
      ->solve({gap.data(), grid.size()}, loading);
}

// The FFT solvers.
const char* const kFftSolvers[] = {"pk", "pk-fourier", "pk-multilevel"};

// ---------------------------------------------------------------------------
// Circular flat punch of radius a (Boussinesq): F = 2 a E* delta, pressure
// p(r) = F / (2 pi a sqrt(a^2 - r^2)), so p(0) is half the mean over the punch.
// Built as an initial gap of 0 inside the circle and 2 delta outside, on a
// free grid; outside, the surface of the half-space stays below the punch
// face (u(r) = delta (2/pi) asin(a/r) < delta), so only the face touches.

struct PunchErrors {
  double stiffness_error;  // relative, against 2 a E*
  double centre_error;     // relative, centre pressure against F / (2 pi a^2)
};

PunchErrors circular_punch(std::size_t cells_across, const std::string& solver) {
  const double a = 1e-4;  // m
  const double dx = 2.0 * a / static_cast<double>(cells_across);
  // An even number of cells, a quarter of the diameter of margin on each side.
  const std::size_t n = 2 * ((cells_across * 5 / 4 + 1) / 2);
  const Grid grid = Grid::plane(n, n, dx, dx, Boundary::free);
  const double delta = kForce / (2.0 * a * kEStar);
  const Eigen::ArrayXd gap =
      field_from(grid, [&](double x, double y) { return x * x + y * y <= a * a ? 0.0 : 2 * delta; });
  const SolveResult result = solve_with(solver, grid, gap, Loading::force(kForce));
  EXPECT_TRUE(result.converged()) << solver << ": " << result.message;
  EXPECT_NEAR(result.total_force, kForce, kForceBalance * kForce);
  expect_contact_conditions(result, 1e-8 * delta);
  // Only the face is in contact.
  EXPECT_EQ(((gap > 0.0) && (result.pressure > 0.0)).count(), 0);
  const double stiffness = result.total_force / result.approach;
  // The four cells around the centre.
  const std::size_t h = n / 2;
  const double centre = 0.25 * (result.pressure[static_cast<Eigen::Index>(h * n + h)] +
                                result.pressure[static_cast<Eigen::Index>((h - 1) * n + h)] +
                                result.pressure[static_cast<Eigen::Index>(h * n + h - 1)] +
                                result.pressure[static_cast<Eigen::Index>((h - 1) * n + h - 1)]);
  const double centre_exact = kForce / (2.0 * std::numbers::pi * a * a);
  PunchErrors errors{std::abs(stiffness / (2.0 * a * kEStar) - 1.0), std::abs(centre / centre_exact - 1.0)};
  std::printf("circular punch, %zu cells across, %s: %d iterations, stiffness error %.2e, centre pressure error %.2e\n",
              cells_across, solver.c_str(), result.iterations, errors.stiffness_error, errors.centre_error);
  return errors;
}

TEST(FlatPunchTest, CircularPunchMatchesBoussinesqAndConvergesUnderRefinement) {
  const PunchErrors coarse = circular_punch(32, "pk-multilevel");
  const PunchErrors medium = circular_punch(64, "pk-multilevel");
  const PunchErrors fine = circular_punch(128, "pk-multilevel");
  // Measured: stiffness 0.28 %, 0.19 %, 0.09 % off at 32, 64, 128 cells
  // across; centre pressure 0.6 %, 0.4 %, 0.2 % (the staircase edge and the
  // singular edge pressure averaged over cells).
  EXPECT_LE(coarse.stiffness_error, 0.01);
  EXPECT_LE(fine.stiffness_error, 0.003);
  EXPECT_LE(fine.centre_error, 0.005);
  EXPECT_LT(medium.stiffness_error, coarse.stiffness_error);
  EXPECT_LT(fine.stiffness_error, medium.stiffness_error);
  EXPECT_LT(fine.centre_error, coarse.centre_error);
  for (const char* solver : {"pk", "pk-fourier"}) {
    const PunchErrors other = circular_punch(64, solver);
    EXPECT_NEAR(other.stiffness_error, medium.stiffness_error, 1e-6) << solver;
  }
}

// ---------------------------------------------------------------------------
// Square punch: the flat surface of a free grid in full contact (the CLI's
// `--geometry flat`). Before the gap scale had its floor (polonsky_keer.hpp)
// every solver failed here: the residual became inf, or stalled at O(1).
// References: the stiffness F/delta = 2 beta E* sqrt(A/pi), beta = 1.012
// (King 1987, Int. J. Solids Struct. 23, 1657), a little above the circle of
// the same area; the pressure is singular along the edges and more so at the
// corners, and at the centre below the mean (0.5 of it for the circle).

struct SquarePunch {
  double beta;           // stiffness over 2 E* sqrt(A/pi)
  double centre;         // centre pressure over the mean
  double edge_midpoint;  // pressure of the cell at the middle of an edge over the mean
  double corner;         // pressure of a corner cell over the mean
};

SquarePunch square_punch(std::size_t n, const std::string& solver, const Loading& loading) {
  const double side = 1e-4;  // m
  const Grid grid = Grid::plane(n, n, side / static_cast<double>(n), side / static_cast<double>(n), Boundary::free);
  const Eigen::ArrayXd gap = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(grid.size()));
  const SolveResult result = solve_with(solver, grid, gap, loading);
  EXPECT_TRUE(result.converged()) << solver << ", " << n << "^2: " << result.message;
  EXPECT_EQ(result.contact_fraction, 1.0);
  expect_contact_conditions(result, 1e-8 * result.approach);
  if (loading.load_controlled()) {
    EXPECT_NEAR(result.total_force, kForce, kForceBalance * kForce);
  }
  const double mean = result.mean_pressure;
  const std::size_t h = n / 2;
  auto p = [&](std::size_t j, std::size_t i) { return result.pressure[static_cast<Eigen::Index>(j * n + i)]; };
  SquarePunch punch{result.total_force / result.approach / (2.0 * kEStar * side / std::sqrt(std::numbers::pi)),
                    0.25 * (p(h, h) + p(h - 1, h) + p(h, h - 1) + p(h - 1, h - 1)) / mean,
                    0.5 * (p(0, h) + p(0, h - 1)) / mean, p(0, 0) / mean};
  // Symmetric under the square's reflections, to rounding.
  double asymmetry = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t i = 0; i < n; ++i) {
      asymmetry = std::max({asymmetry, std::abs(p(j, i) - p(i, j)), std::abs(p(j, i) - p(n - 1 - j, i))});
    }
  }
  EXPECT_LE(asymmetry, 1e-8 * result.max_pressure) << solver;
  std::printf("square punch %zu^2, %s, %s control: %d iterations, beta %.4f, centre %.3f, edge %.2f, corner %.2f\n", n,
              solver.c_str(), loading.load_controlled() ? "load" : "displacement", result.iterations, punch.beta,
              punch.centre, punch.edge_midpoint, punch.corner);
  return punch;
}

TEST(FlatPunchTest, SquarePunchConvergesWithEverySolverAndShowsTheEdgeSingularity) {
  for (const char* solver : kFftSolvers) {
    const SquarePunch coarse = square_punch(32, solver, Loading::force(kForce));
    const SquarePunch medium = square_punch(64, solver, Loading::force(kForce));
    const SquarePunch fine = square_punch(128, solver, Loading::force(kForce));
    // Measured beta: 1.0105, 1.0158, 1.0185 at 32^2, 64^2, 128^2, converging
    // (the differences halve) to about 1.021: within 1 % of King's 1.012.
    for (const SquarePunch& punch : {coarse, medium, fine}) {
      EXPECT_GT(punch.beta, 1.0) << solver;
      EXPECT_LT(punch.beta, 1.022) << solver;
      // Centre below the mean (0.496, 0.491, 0.488 measured), edges above it,
      // corners above the edges.
      EXPECT_GT(punch.centre, 0.45) << solver;
      EXPECT_LT(punch.centre, 0.52) << solver;
      EXPECT_GT(punch.edge_midpoint, 2.0 * punch.centre) << solver;
      EXPECT_GT(punch.corner, punch.edge_midpoint) << solver;
    }
    EXPECT_LT(fine.beta - medium.beta, 0.75 * (medium.beta - coarse.beta)) << solver;
    EXPECT_GT(fine.beta, medium.beta) << solver;
    // The singularity: the edge cells' pressure grows as the cells shrink,
    // as 1/sqrt(dx) along an edge.
    EXPECT_GT(fine.edge_midpoint, 1.3 * medium.edge_midpoint) << solver;
    EXPECT_GT(fine.corner, 1.3 * medium.corner) << solver;
  }
}

TEST(FlatPunchTest, SquarePunchUnderDisplacementControlHasTheSameStiffness) {
  const SquarePunch loaded = square_punch(64, "pk-multilevel", Loading::force(kForce));
  for (const char* solver : kFftSolvers) {
    const double side = 1e-4;
    const double approach = kForce / (loaded.beta * 2.0 * kEStar * side / std::sqrt(std::numbers::pi));
    const SquarePunch moved = square_punch(64, solver, Loading::approach(approach));
    EXPECT_NEAR(moved.beta, loaded.beta, 1e-6 * loaded.beta) << solver;
    EXPECT_NEAR(moved.centre, loaded.centre, 1e-6) << solver;
  }
}

// The dense path reports its residual with the same gap scale: Lemke's
// square punch is "converged", and pressures agree with the FFT solvers'.
TEST(FlatPunchTest, LemkeSquarePunchConvergesAndAgrees) {
  const std::size_t n = 16;
  const Grid grid = Grid::plane(n, n, 1e-4 / n, 1e-4 / n, Boundary::free);
  const Eigen::ArrayXd gap = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(grid.size()));
  const SolveResult dense = solve_with("lemke", grid, gap, Loading::force(kForce));
  ASSERT_TRUE(dense.converged()) << dense.message;
  EXPECT_LE(dense.residual, 1e-10);
  for (const char* solver : kFftSolvers) {
    const SolveResult result = solve_with(solver, grid, gap, Loading::force(kForce));
    ASSERT_TRUE(result.converged()) << solver << ": " << result.message;
    EXPECT_LE((result.pressure - dense.pressure).abs().maxCoeff(), 1e-6 * dense.max_pressure) << solver;
    EXPECT_NEAR(result.approach, dense.approach, 1e-6 * dense.approach) << solver;
  }
}

// ---------------------------------------------------------------------------
// Strip punch (1D, plane strain) of half-width a, the whole free grid in
// contact: p(x) = F / (pi sqrt(a^2 - x^2)) (Johnson 1985, sec. 2.8), so the
// centre pressure is 2/pi of the mean. Each cell is compared with the exact
// average of p over it.

TEST(FlatPunchTest, StripPunchMatchesTheAnalyticPressure) {
  for (const char* solver : kFftSolvers) {
    for (std::size_t n : {128, 512}) {
      const double width = 1e-4;
      const double a = 0.5 * width;
      const double dx = width / static_cast<double>(n);
      const Grid grid = Grid::line(n, dx, Boundary::free);
      const Eigen::ArrayXd gap = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(n));
      const SolveResult result = solve_with(solver, grid, gap, Loading::force(kForce));
      ASSERT_TRUE(result.converged()) << solver << ": " << result.message;
      EXPECT_NEAR(result.total_force, kForce, kForceBalance * kForce);
      auto cell_average = [&](std::size_t i) {
        const double left = -a + static_cast<double>(i) * dx;
        const double right = std::min(left + dx, a);
        return kForce * (std::asin(right / a) - std::asin(std::max(left / a, -1.0))) / (std::numbers::pi * dx);
      };
      double worst_interior = 0.0;
      for (std::size_t i = 1; i + 1 < n; ++i) {
        const auto k = static_cast<Eigen::Index>(i);
        worst_interior = std::max(worst_interior, std::abs(result.pressure[k] / cell_average(i) - 1.0));
        ASSERT_NEAR(result.pressure[k], result.pressure[static_cast<Eigen::Index>(n - 1 - i)],
                    1e-8 * result.max_pressure);
      }
      const double edge = result.pressure[0] / cell_average(0);
      const double centre =
          0.5 *
          (result.pressure[static_cast<Eigen::Index>(n / 2)] + result.pressure[static_cast<Eigen::Index>(n / 2 - 1)]) /
          result.mean_pressure;
      std::printf("strip punch n=%zu, %s: %d iterations, worst interior cell %.2e, edge cell %.3f, centre %.4f\n", n,
                  solver, result.iterations, worst_interior, edge, centre);
      // Measured: 2.5 % at the cell next to the edge, the edge cell 4.5 %
      // low (the square-root singularity inside one cell), the centre 0.1 %.
      EXPECT_LE(worst_interior, 0.03) << solver;
      EXPECT_NEAR(edge, 1.0, 0.06) << solver;
      EXPECT_NEAR(centre, 2.0 / std::numbers::pi, 0.003) << solver;
      EXPECT_GT(result.pressure[0], result.pressure[1]);
      EXPECT_GT(result.pressure[1], result.pressure[static_cast<Eigen::Index>(n / 2)]);
    }
  }
}

// ---------------------------------------------------------------------------
// A coarse solve of the block deflation that stops short of its tolerance
// leaves the correction inexact; the solve still converges (the correction
// only preconditions), but the result must say so.

SolveResult deflated_fine_solve(int coarse_max_iterations) {
  const double e_star = 1.0;
  const Grid grid = Grid::plane(256, 256, 1.0, 1.0, Boundary::periodic);
  const Eigen::ArrayXd gap = testing::self_affine_gap(grid, 3);
  const Loading load = Loading::mean_pressure(0.004);  // about 8 % contact
  // pk-multilevel's fine solve: started from the coarse grid's solution, where
  // the settled iteration is slow enough for the correction to join
  // (deflated_solver_test.cpp).
  const Grid coarse = *coarser_grid(grid, 32);
  Eigen::ArrayXd coarse_gap(static_cast<Eigen::Index>(coarse.size()));
  restrict_by_average(grid, {gap.data(), grid.size()}, {coarse_gap.data(), coarse.size()});
  const SolveResult coarse_result = make_solver(coarse, e_star, testing::test_options(SolverType::pk_multilevel, 1e-4))
                                        ->solve({coarse_gap.data(), coarse.size()}, load);
  Eigen::ArrayXd start(static_cast<Eigen::Index>(grid.size()));
  prolong_constant(grid, {coarse_result.pressure.data(), coarse.size()}, {start.data(), grid.size()});

  FftInfluenceOperator op(grid, e_star);
  FourierPreconditioner preconditioner(grid, e_star);
  BlockDeflationOptions deflation_options;
  deflation_options.block = 32;
  deflation_options.coarse_max_iterations = coarse_max_iterations;
  BlockDeflation deflation(grid, deflation_options);
  BalancingPreconditioner balancing(op, preconditioner, deflation);
  PolonskyKeerOptions options;
  options.form = PolonskyKeerForm::projected;
  PolonskyKeer solver(op, options, {}, &balancing);
  return solver.solve({gap.data(), grid.size()}, load, {start.data(), grid.size()});
}

TEST(CoarseSolveWarningTest, UnconvergedCoarseSolvesReachTheResult) {
  const SolveResult exact = deflated_fine_solve(BlockDeflationOptions{}.coarse_max_iterations);
  ASSERT_TRUE(exact.converged()) << exact.message;
  ASSERT_GT(exact.deflation.deflated_iterations, 0) << "the correction must join for this test to mean anything";
  EXPECT_EQ(exact.deflation.unconverged_coarse_solves, 0);
  EXPECT_TRUE(exact.warnings.empty());

  // One CG step cannot solve the 64-block coarse system to 1e-8.
  const SolveResult inexact = deflated_fine_solve(1);
  ASSERT_GT(inexact.deflation.deflated_iterations, 0);
  EXPECT_GT(inexact.deflation.unconverged_coarse_solves, 0);
  EXPECT_LE(inexact.deflation.unconverged_coarse_solves, 2 * inexact.deflation.deflated_iterations);
  ASSERT_EQ(inexact.warnings.size(), 1U);
  EXPECT_NE(inexact.warnings[0].find("coarse solves stopped short of their tolerance"), std::string::npos)
      << inexact.warnings[0];
  std::printf("%s\n", inexact.warnings[0].c_str());
}

}  // namespace
}  // namespace halfspace::solvers
