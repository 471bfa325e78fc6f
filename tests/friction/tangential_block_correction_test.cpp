// The tangential coarse correction (TangentialOptions::
// coarse_correction_block, src/solvers/tangential_block_correction.hpp): its
// coarse matrix is the Galerkin matrix Z^T C Z made by fine products, the
// correction is exact on its coarse space (C Z y0 gives back y0), under a
// fixed load it moves no force, and a tangential step with it reaches the
// step without it on a rough periodic contact (checked apart from the
// residual by a fresh product).
#include "solvers/tangential_block_correction.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "friction/friction_checks.hpp"
#include "halfspace/error.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/solvers/tangential_solver.hpp"
#include "halfspace/surface/self_affine.hpp"
#include "support/pk_solvers.hpp"

namespace halfspace {
namespace {

using solvers::tangential::TangentialBlockCorrection;

constexpr ElasticBody kSteel{2.1e11, 0.3};
constexpr double kMu = 0.3;

// A set of about 40 % of the cells, some blocks left empty.
std::vector<std::uint8_t> random_set(const Grid& grid, std::size_t block, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<std::uint8_t> set(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const std::size_t bx = (i % grid.nx()) / block;
    const std::size_t by = (i / grid.nx()) / block;
    set[i] = (bx + by != 1) && uniform(random) < 0.4 ? 1 : 0;
  }
  return set;
}

// Z y: block value on the set's cells.
void prolong(const Grid& grid, std::size_t block, const std::vector<std::uint8_t>& set, std::span<const double> y,
             std::vector<double>& zx, std::vector<double>& zy) {
  const std::size_t m = y.size() / 2;
  const std::size_t blocks_x = grid.nx() / block;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const std::size_t I = ((i / grid.nx()) / block) * blocks_x + (i % grid.nx()) / block;
    zx[i] = set[i] ? y[I] : 0.0;
    zy[i] = set[i] ? y[m + I] : 0.0;
  }
}

// On 3 x 3 blocks of a periodic grid every block pair is a neighbour pair,
// so the coarse matrix is exact: it equals Z^T C Z column by column, and
// the correction solves C Z y0 back to y0.
TEST(TangentialBlockCorrection, ExactOnItsCoarseSpace) {
  constexpr std::size_t kBlock = 8;
  const Grid grid = Grid::plane(3 * kBlock, 3 * kBlock, 1e-6, 1e-6, Boundary::periodic);
  TangentialOperator op(grid, ElasticPair::similar(kSteel));
  ASSERT_TRUE(TangentialBlockCorrection::applies(op, kBlock));
  TangentialBlockCorrection correction(op, kBlock, 1e-13);
  const std::vector<std::uint8_t> set = random_set(grid, kBlock, 5);
  correction.update([&](std::size_t i) { return set[i] != 0; });
  ASSERT_TRUE(correction.ready());
  const std::size_t m = correction.coarse_size();
  ASSERT_EQ(m, 9U);
  const std::size_t n = grid.size();
  std::vector<double> zx(n), zy(n), ux(n), uy(n), column(2 * m), unit(2 * m), coarse(2 * m);
  // Each column of A against Z^T C Z e_J by a fine product.
  double largest = 0.0;
  double worst = 0.0;
  for (std::size_t J = 0; J < 2 * m; ++J) {
    std::fill(unit.begin(), unit.end(), 0.0);
    unit[J] = 1.0;
    prolong(grid, kBlock, set, unit, zx, zy);
    op.apply(zx, zy, ux, uy);
    std::fill(column.begin(), column.end(), 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      if (!set[i]) continue;
      const std::size_t I = ((i / grid.nx()) / kBlock) * 3 + (i % grid.nx()) / kBlock;
      column[I] += ux[i];
      column[m + I] += uy[i];
    }
    correction.apply_coarse(unit, coarse);
    for (std::size_t I = 0; I < 2 * m; ++I) {
      largest = std::max(largest, std::abs(column[I]));
      worst = std::max(worst, std::abs(coarse[I] - column[I]));
    }
  }
  std::printf("coarse matrix against Z^T C Z: %.2e of its largest entry\n", worst / largest);
  EXPECT_LE(worst, 1e-12 * largest);
  // C Z y0 back to y0 (no constraint), and Z y added on the set only.
  std::mt19937 random(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> y0(2 * m);
  for (std::size_t I = 0; I < m; ++I) {
    const bool empty = I == 1 || I == 3;  // the blocks random_set leaves empty
    y0[I] = empty ? 0.0 : normal(random);
    y0[m + I] = empty ? 0.0 : normal(random);
  }
  prolong(grid, kBlock, set, y0, zx, zy);
  op.apply(zx, zy, ux, uy);
  correction.solve(ux, uy, false);
  double error = 0.0;
  for (std::size_t I = 0; I < 2 * m; ++I) error = std::max(error, std::abs(correction.coarse_solution()[I] - y0[I]));
  std::printf("coarse solve of C Z y0: error %.2e\n", error);
  EXPECT_LE(error, 1e-9);
  std::vector<double> ax(n, 0.0), ay(n, 0.0);
  correction.add(ax, ay);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(ax[i], zx[i], 1e-9);
    EXPECT_NEAR(ay[i], zy[i], 1e-9);
  }
}

// Under a fixed load the correction moves no force: sum Z y = 0 for each
// component, whatever the right-hand side.
TEST(TangentialBlockCorrection, FixedLoadCorrectionMovesNoForce) {
  constexpr std::size_t kBlock = 8;
  const Grid grid = Grid::plane(48, 48, 1e-6, 1e-6, Boundary::periodic);
  TangentialOperator op(grid, ElasticPair::similar(kSteel));
  TangentialBlockCorrection correction(op, kBlock, 1e-10);
  const std::vector<std::uint8_t> set = random_set(grid, kBlock, 11);
  correction.update([&](std::size_t i) { return set[i] != 0; });
  ASSERT_TRUE(correction.ready());
  std::mt19937 random(13);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> rx(grid.size()), ry(grid.size()), zx(grid.size(), 0.0), zy(grid.size(), 0.0);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    rx[i] = 1.0 + normal(random);  // a mean part the constraint must absorb
    ry[i] = -0.5 + normal(random);
  }
  correction.solve(rx, ry, true);
  correction.add(zx, zy);
  double sum_x = 0.0;
  double sum_y = 0.0;
  double size = 0.0;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    sum_x += zx[i];
    sum_y += zy[i];
    size = std::max(size, std::hypot(zx[i], zy[i]));
  }
  ASSERT_GT(size, 0.0);
  EXPECT_LE(std::abs(sum_x), 1e-10 * size * static_cast<double>(grid.size()));
  EXPECT_LE(std::abs(sum_y), 1e-10 * size * static_cast<double>(grid.size()));
}

// The rough periodic contact of rough_contact_test.cpp.
SolveResult rough_contact(const Grid& grid) {
  surface::SelfAffineSpec spec;
  spec.hurst = 0.8;
  spec.short_cutoff = 4e-6;
  spec.rms_slope = 0.1;
  spec.seed = 3;
  const Eigen::ArrayXd heights = surface::make_self_affine_surface(grid, spec);
  const Eigen::ArrayXd gap = solvers::initial_gap(grid, {heights.data(), grid.size()});
  const double e_star = ElasticPair::similar(kSteel).composite_modulus();
  const auto normal = solvers::make_solver(grid, e_star, testing::test_options(solvers::SolverType::pk_fourier));
  return normal->solve({gap.data(), grid.size()}, Loading::mean_pressure(0.04 * e_star * 0.1));
}

solvers::TangentialOptions options(std::size_t block, int active_set_updates) {
  solvers::TangentialOptions o;
  o.friction_coefficient = kMu;
  o.tolerance = 1e-10;
  o.max_iterations = 20000;
  o.coarse_correction_block = block;
  o.active_set_updates = active_set_updates;
  return o;
}

// Force from rest (oblique), reversed, then displacement control, by the
// default conjugate gradients and by the active-set phase, with and
// without the correction: the same steps, each meeting the Coulomb
// conditions by a fresh product.
TEST(TangentialBlockCorrection, RoughContactGivesTheUncorrectedStep) {
  const Grid grid = Grid::plane(64, 64, 1e-6, 1e-6, Boundary::periodic);
  const SolveResult contact = rough_contact(grid);
  ASSERT_TRUE(contact.converged());
  TangentialOperator op(grid, ElasticPair::similar(kSteel));
  const double limit = kMu * contact.total_force;
  const double traction_limit = kMu * contact.pressure.maxCoeff();
  const std::span<const double> p(contact.pressure.data(), grid.size());
  for (const int updates : {0, 30}) {
    TangentialSolver corrected(op, options(8, updates));
    TangentialSolver plain(op, options(0, updates));
    TangentialState previous = TangentialState::unloaded(grid.size());
    double first_approach = 0.0;
    const char* names[] = {"rough, oblique force", "rough, reversed", "rough, displacement"};
    for (int k = 0; k < 3; ++k) {
      const double further = previous.approach_x + 0.3 * (first_approach - previous.approach_x);
      const TangentialLoading loading = k == 0   ? TangentialLoading::force(0.5 * limit, 0.2 * limit)
                                        : k == 1 ? TangentialLoading::force(0.1 * limit, 0.0)
                                                 : TangentialLoading::displacement(further, previous.approach_y);
      const TangentialResult with = corrected.solve(p, loading, previous);
      const TangentialResult without = plain.solve(p, loading, previous);
      ASSERT_TRUE(with.converged()) << names[k] << ": " << with.message;
      ASSERT_TRUE(without.converged()) << names[k] << ": " << without.message;
      EXPECT_GT(with.coarse_corrections, 0) << names[k];
      EXPECT_EQ(without.coarse_corrections, 0) << names[k];
      const double traction = std::max((with.state.shear_x - without.state.shear_x).abs().maxCoeff(),
                                       (with.state.shear_y - without.state.shear_y).abs().maxCoeff());
      const double scale = std::max((without.state.displacement_x - previous.displacement_x).abs().maxCoeff(),
                                    (without.state.displacement_y - previous.displacement_y).abs().maxCoeff());
      const double approach = std::hypot(with.state.approach_x - without.state.approach_x,
                                         with.state.approach_y - without.state.approach_y);
      std::printf(
          "%s (%d updates): corrected %d iterations (%d C + %d M), plain %d (%d C + %d M); traction difference "
          "%.2e mu p_max, approach %.2e\n",
          names[k], updates, with.iterations, with.operator_applications, with.preconditioner_applications,
          without.iterations, without.operator_applications, without.preconditioner_applications,
          traction / traction_limit, approach / scale);
      // Both to tolerance 1e-10: they differed by 5e-10 mu p_max at most.
      EXPECT_LE(traction, 1e-7 * traction_limit) << names[k];
      EXPECT_LE(approach, 1e-8 * scale) << names[k];
      EXPECT_NEAR(with.stick_fraction, without.stick_fraction, 0.005) << names[k];
      testing::expect_coulomb_conditions(op, contact.pressure, kMu, previous, with, 1e-6 * scale, 1e-2);
      if (k == 0) first_approach = without.state.approach_x;
      previous = without.state;
    }
  }
}

// A grid the correction does not apply to is refused, naming the option.
TEST(TangentialBlockCorrection, UnsuitedGridIsRefusedByName) {
  for (const auto& [grid, block] : {std::pair{Grid::plane(64, 64, 1e-6, 1e-6, Boundary::free), std::size_t{8}},
                                    std::pair{Grid::plane(64, 64, 1e-6, 1e-6, Boundary::periodic), std::size_t{24}}}) {
    TangentialOperator op(grid, ElasticPair::similar(kSteel));
    try {
      TangentialSolver solver(op, options(block, 0));
      ADD_FAILURE() << "coarse_correction_block " << block << " accepted on " << grid.shape_string();
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("coarse_correction_block"), std::string::npos) << error.what();
    }
  }
}

}  // namespace
}  // namespace halfspace
