// Tangential steps on a rough periodic contact (many separate spots, some
// sticking, some slipping), solved by both methods: each result meets the
// Coulomb conditions, checked by a fresh product apart from the solver's
// residual, and the two methods (preconditioned conjugate gradients on the
// stick/slip sets, and projected gradients) agree on the traction, the
// approach and the stick set.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "friction/friction_checks.hpp"
#include "halfspace/error.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/solvers/tangential_solver.hpp"
#include "halfspace/surface/self_affine.hpp"
#include "support/pk_solvers.hpp"

namespace halfspace {
namespace {

constexpr ElasticBody kSteel{2.1e11, 0.3};
constexpr double kMu = 0.3;
constexpr std::size_t kCells = 64;
constexpr double kSpacing = 1e-6;  // m

struct RoughContact {
  Grid grid;
  SolveResult contact;
};

RoughContact rough_contact(const ElasticPair& pair = ElasticPair::similar(kSteel), std::uint64_t seed = 3) {
  const Grid grid = Grid::plane(kCells, kCells, kSpacing, kSpacing, Boundary::periodic);
  surface::SelfAffineSpec spec;
  spec.hurst = 0.8;
  spec.short_cutoff = 4e-6;
  spec.rms_slope = 0.1;
  spec.seed = seed;
  const Eigen::ArrayXd heights = surface::make_self_affine_surface(grid, spec);
  const Eigen::ArrayXd gap = solvers::initial_gap(grid, {heights.data(), grid.size()});
  const double e_star = pair.composite_modulus();
  const auto normal = solvers::make_solver(grid, e_star, testing::test_options(solvers::SolverType::pk_fourier));
  return {grid, normal->solve({gap.data(), grid.size()}, Loading::mean_pressure(0.04 * e_star * 0.1))};
}

TangentialResult step(TangentialOperator& op, solvers::TangentialMethod method, const Eigen::ArrayXd& pressure,
                      const TangentialLoading& loading, const TangentialState& previous, int release_period = 5,
                      bool coarse_start = true, double mu = kMu, const Eigen::ArrayXd* fixed_x = nullptr,
                      const Eigen::ArrayXd* fixed_y = nullptr) {
  solvers::TangentialOptions options;
  options.friction_coefficient = mu;
  options.tolerance = 1e-10;
  options.max_iterations = 50000;
  options.method = method;
  options.release_period = release_period;
  options.coarse_start = coarse_start ? TangentialCoarseStart::on : TangentialCoarseStart::off;
  TangentialSolver solver(op, options);
  const std::size_t n = op.local_size();
  if (fixed_x != nullptr) {
    return solver.solve({pressure.data(), n}, loading, previous, {fixed_x->data(), n}, {fixed_y->data(), n});
  }
  return solver.solve({pressure.data(), n}, loading, previous);
}

// Both methods on one step; the conjugate gradients' result checked and
// compared. Returns the conjugate gradients' result for the next step.
TangentialResult expect_methods_agree(TangentialOperator& op, const Eigen::ArrayXd& pressure,
                                      const TangentialLoading& loading, const TangentialState& previous,
                                      const char* what) {
  const TangentialResult cg = step(op, solvers::TangentialMethod::conjugate_gradient, pressure, loading, previous);
  const TangentialResult pg = step(op, solvers::TangentialMethod::projected_gradient, pressure, loading, previous);
  EXPECT_TRUE(cg.converged()) << what << ": " << cg.message;
  EXPECT_TRUE(pg.converged()) << what << ": " << pg.message;
  const double limit = kMu * pressure.maxCoeff();
  const double traction = std::max((cg.state.shear_x - pg.state.shear_x).abs().maxCoeff(),
                                   (cg.state.shear_y - pg.state.shear_y).abs().maxCoeff());
  const double scale = std::max((cg.state.displacement_x - previous.displacement_x).abs().maxCoeff(),
                                (cg.state.displacement_y - previous.displacement_y).abs().maxCoeff());
  const double approach =
      std::hypot(cg.state.approach_x - pg.state.approach_x, cg.state.approach_y - pg.state.approach_y);
  std::printf(
      "rough %zu^2, %s: stick %.3f (projected gradients %.3f), traction difference %.2e mu p_max, approach %.2e, "
      "iterations %d against %d\n",
      kCells, what, cg.stick_fraction, pg.stick_fraction, traction / limit, approach / scale, cg.iterations,
      pg.iterations);
  EXPECT_LE(traction, 1e-3 * limit) << what;
  EXPECT_LE(approach, 1e-4 * scale) << what;
  EXPECT_NEAR(cg.stick_fraction, pg.stick_fraction, 0.01) << what;
  EXPECT_GT(cg.stick_fraction, 0.05) << what;  // partial slip: both sets matter
  EXPECT_LT(cg.stick_fraction, 0.95) << what;
  testing::expect_coulomb_conditions(op, pressure, kMu, previous, cg, 1e-6 * scale, 1e-2);
  return cg;
}

TEST(RoughFriction, ConjugateGradientsMeetCoulombAndAgreeWithProjectedGradients) {
  const auto [grid, contact] = rough_contact();
  ASSERT_TRUE(contact.converged());
  ASSERT_GT(contact.contact_fraction, 0.02);
  TangentialOperator op(grid, ElasticPair::similar(kSteel));
  const double limit = kMu * contact.total_force;
  const TangentialState unloaded = TangentialState::unloaded(grid.size());
  // Force control, oblique, from rest; then a reversal; then displacement
  // control a little further on.
  const TangentialResult first = expect_methods_agree(
      op, contact.pressure, TangentialLoading::force(0.5 * limit, 0.2 * limit), unloaded, "oblique force");
  EXPECT_NEAR(first.force_x, 0.5 * limit, 1e-9 * limit);
  EXPECT_NEAR(first.force_y, 0.2 * limit, 1e-9 * limit);
  const TangentialResult second = expect_methods_agree(op, contact.pressure, TangentialLoading::force(0.1 * limit, 0.0),
                                                       first.state, "reversed force");
  EXPECT_NEAR(second.force_x, 0.1 * limit, 1e-9 * limit);
  const double further = second.state.approach_x + 0.3 * (first.state.approach_x - second.state.approach_x);
  expect_methods_agree(op, contact.pressure, TangentialLoading::displacement(further, second.state.approach_y),
                       second.state, "displacement");
}

// A steel surface pressed by a rigid rough one at small mu (Dundurs' beta =
// 0.286, beta/mu 5.7 and 14): the pressure's coupling displacement pulls
// each spot's surface inwards and most cells slip. The tangential half of
// the coupled problem (the pressure and its coupling displacement given) at
// zero force from rest once stalled: every cell slipping, the reduced
// gradient zero, and the residual above the tolerance for 10000 iterations,
// because the approach was taken as the mean displacement, not the one the
// slip conditions fix (seeds 1 and 2 at mu = 0.02 and seed 2 at 0.05 failed
// so in the program). Both methods now meet Coulomb's conditions, checked
// by a fresh product, and agree.
TEST(RoughFriction, CoupledPressingAtSmallMuMeetsCoulombWithBothMethods) {
  const ElasticPair pair = ElasticPair::on_rigid(kSteel);
  for (const std::uint64_t seed : {1, 2}) {
    const auto [grid, contact] = rough_contact(pair, seed);
    ASSERT_TRUE(contact.converged());
    TangentialOperator op(grid, pair);
    const std::size_t n = grid.size();
    Eigen::ArrayXd fixed_x(static_cast<Eigen::Index>(n));
    Eigen::ArrayXd fixed_y(static_cast<Eigen::Index>(n));
    op.apply_pressure_coupling({contact.pressure.data(), n}, {fixed_x.data(), n}, {fixed_y.data(), n});
    const TangentialState unloaded = TangentialState::unloaded(n);
    for (const double mu : {0.02, 0.05}) {
      const TangentialResult cg = step(op, solvers::TangentialMethod::conjugate_gradient, contact.pressure,
                                       TangentialLoading::force(0.0), unloaded, 5, false, mu, &fixed_x, &fixed_y);
      const TangentialResult pg = step(op, solvers::TangentialMethod::projected_gradient, contact.pressure,
                                       TangentialLoading::force(0.0), unloaded, 5, false, mu, &fixed_x, &fixed_y);
      ASSERT_TRUE(cg.converged()) << "seed " << seed << ", mu " << mu << ": " << cg.message;
      ASSERT_TRUE(pg.converged()) << "seed " << seed << ", mu " << mu << ": " << pg.message;
      const double limit = mu * contact.pressure.maxCoeff();
      const double traction = std::max((cg.state.shear_x - pg.state.shear_x).abs().maxCoeff(),
                                       (cg.state.shear_y - pg.state.shear_y).abs().maxCoeff());
      const double scale = std::max(cg.state.displacement_x.abs().maxCoeff(), cg.state.displacement_y.abs().maxCoeff());
      std::printf(
          "rough %zu^2 on rigid, seed %d, mu %.2f: stick %.3f (projected gradients %.3f), traction "
          "difference %.2e mu p_max, iterations %d against %d\n",
          kCells, static_cast<int>(seed), mu, cg.stick_fraction, pg.stick_fraction, traction / limit, cg.iterations,
          pg.iterations);
      EXPECT_LE(traction, 1e-3 * limit);
      EXPECT_NEAR(cg.force_x, 0.0, 1e-9 * mu * contact.total_force);
      EXPECT_NEAR(cg.force_y, 0.0, 1e-9 * mu * contact.total_force);
      EXPECT_LT(cg.stick_fraction, 0.9);  // most cells slip
      testing::expect_coulomb_conditions(op, contact.pressure, mu, unloaded, cg, 1e-6 * scale, 1e-2, &fixed_x,
                                         &fixed_y);
    }
  }
}

// Releases held between set updates (the default, release_period 5) and
// released at every iteration (1, the earlier conjugate gradients) reach
// the same state: both meet the Coulomb conditions by a fresh product and
// agree on the traction, the approach and the stick set, on a step from
// rest and on a reversal, where cells leave the slip set.
TEST(RoughFriction, HeldReleasesGiveTheSameStepAsReleasingEveryIteration) {
  const auto [grid, contact] = rough_contact();
  ASSERT_TRUE(contact.converged());
  TangentialOperator op(grid, ElasticPair::similar(kSteel));
  const double limit = kMu * contact.total_force;
  const TangentialState unloaded = TangentialState::unloaded(grid.size());
  const Eigen::ArrayXd& pressure = contact.pressure;
  const TangentialLoading loadings[] = {TangentialLoading::force(0.5 * limit, 0.2 * limit),
                                        TangentialLoading::force(0.1 * limit, 0.0)};
  TangentialState previous = unloaded;
  for (const TangentialLoading& loading : loadings) {
    const TangentialResult held =
        step(op, solvers::TangentialMethod::conjugate_gradient, pressure, loading, previous, 5);
    const TangentialResult every =
        step(op, solvers::TangentialMethod::conjugate_gradient, pressure, loading, previous, 1);
    ASSERT_TRUE(held.converged()) << held.message;
    ASSERT_TRUE(every.converged()) << every.message;
    const double traction = std::max((held.state.shear_x - every.state.shear_x).abs().maxCoeff(),
                                     (held.state.shear_y - every.state.shear_y).abs().maxCoeff());
    const double scale = std::max((held.state.displacement_x - previous.displacement_x).abs().maxCoeff(),
                                  (held.state.displacement_y - previous.displacement_y).abs().maxCoeff());
    std::printf("rough %zu^2, releases held / every iteration: %d / %d iterations, traction difference %.2e mu p_max\n",
                kCells, held.iterations, every.iterations, traction / (kMu * pressure.maxCoeff()));
    EXPECT_LE(traction, 1e-3 * kMu * pressure.maxCoeff());
    EXPECT_LE(
        std::hypot(held.state.approach_x - every.state.approach_x, held.state.approach_y - every.state.approach_y),
        1e-4 * scale);
    EXPECT_NEAR(held.stick_fraction, every.stick_fraction, 0.01);
    testing::expect_coulomb_conditions(op, pressure, kMu, previous, held, 1e-6 * scale, 1e-2);
    previous = held.state;
  }
}

// The coarse-grid start (TangentialOptions::coarse_start: the step solved
// first on the 32^2 grid, its fraction q / mu p prolonged) and a start from the previous
// traction reach the same state: both meet the Coulomb conditions by a
// fresh product and agree on the traction, the approach and the stick set,
// from rest, on a reversal and under displacement control.
TEST(RoughFriction, CoarseStartGivesTheSameStepAsTheFineStart) {
  const auto [grid, contact] = rough_contact();
  ASSERT_TRUE(contact.converged());
  TangentialOperator op(grid, ElasticPair::similar(kSteel));
  const double limit = kMu * contact.total_force;
  const Eigen::ArrayXd& pressure = contact.pressure;
  TangentialState previous = TangentialState::unloaded(grid.size());
  double first_approach = 0.0;
  for (int k = 0; k < 3; ++k) {
    // As the test above: force from rest, reversed, then 30 % of the way
    // back under displacement control.
    const double further = previous.approach_x + 0.3 * (first_approach - previous.approach_x);
    const TangentialLoading loading = k == 0   ? TangentialLoading::force(0.5 * limit, 0.2 * limit)
                                      : k == 1 ? TangentialLoading::force(0.1 * limit, 0.0)
                                               : TangentialLoading::displacement(further, previous.approach_y);
    const TangentialResult coarse =
        step(op, solvers::TangentialMethod::conjugate_gradient, pressure, loading, previous, 5, true);
    const TangentialResult fine =
        step(op, solvers::TangentialMethod::conjugate_gradient, pressure, loading, previous, 5, false);
    ASSERT_TRUE(coarse.converged()) << coarse.message;
    ASSERT_TRUE(fine.converged()) << fine.message;
    EXPECT_EQ(coarse.coarse.levels, 1);  // 64^2 -> 32^2
    EXPECT_GT(coarse.coarse.iterations, 0);
    EXPECT_GT(coarse.coarse.operator_work, 0.0);
    EXPECT_EQ(fine.coarse.levels, 0);
    const double traction = std::max((coarse.state.shear_x - fine.state.shear_x).abs().maxCoeff(),
                                     (coarse.state.shear_y - fine.state.shear_y).abs().maxCoeff());
    const double scale = std::max((coarse.state.displacement_x - previous.displacement_x).abs().maxCoeff(),
                                  (coarse.state.displacement_y - previous.displacement_y).abs().maxCoeff());
    std::printf(
        "rough %zu^2, step %d, coarse / fine start: %d (+%d coarse) / %d iterations, traction difference %.2e mu "
        "p_max\n",
        kCells, k + 1, coarse.iterations, coarse.coarse.iterations, fine.iterations,
        traction / (kMu * pressure.maxCoeff()));
    EXPECT_LE(traction, 1e-3 * kMu * pressure.maxCoeff());
    EXPECT_LE(
        std::hypot(coarse.state.approach_x - fine.state.approach_x, coarse.state.approach_y - fine.state.approach_y),
        1e-4 * scale);
    EXPECT_NEAR(coarse.stick_fraction, fine.stick_fraction, 0.01);
    EXPECT_GT(coarse.stick_fraction, 0.05);  // partial slip: both sets matter
    EXPECT_LT(coarse.stick_fraction, 0.95);
    testing::expect_coulomb_conditions(op, pressure, kMu, previous, coarse, 1e-6 * scale, 1e-2);
    if (k == 0) first_approach = coarse.state.approach_x;
    previous = coarse.state;
  }
}

// TangentialOptions::precision: the single-precision products C d and M
// (the default on a serial periodic grid) against double ones. The
// operator's single-precision products are within float rounding of the
// double ones and not equal to them (so the single path ran); the step
// solved both ways meets Coulomb's conditions (a fresh double product) and
// gives the same traction within 1e-8 of the largest mu p at the solver
// tolerance 1e-10, with the force met to rounding.
TEST(RoughFriction, SinglePrecisionDirectionsGiveTheDoubleStep) {
  const auto [grid, contact] = rough_contact();
  ASSERT_TRUE(contact.converged());
  TangentialOperator op(grid, ElasticPair::similar(kSteel));
  ASSERT_TRUE(op.single_precision());
  EXPECT_FALSE(TangentialOperator(Grid::plane(16, 16, kSpacing, kSpacing, Boundary::free), ElasticPair::similar(kSteel))
                   .single_precision());
  const std::size_t n = grid.size();
  const Eigen::ArrayXd tx = contact.pressure * 0.3;
  const Eigen::ArrayXd ty = contact.pressure.sqrt() * 1e3;
  Eigen::ArrayXd ux(n), uy(n), sx(n), sy(n);
  for (const bool inverse : {false, true}) {
    if (inverse) {
      op.apply_approximate_inverse({tx.data(), n}, {ty.data(), n}, {ux.data(), n}, {uy.data(), n});
      op.apply_approximate_inverse_in_single_precision({tx.data(), n}, {ty.data(), n}, {sx.data(), n}, {sy.data(), n});
    } else {
      op.apply({tx.data(), n}, {ty.data(), n}, {ux.data(), n}, {uy.data(), n});
      op.apply_in_single_precision({tx.data(), n}, {ty.data(), n}, {sx.data(), n}, {sy.data(), n});
    }
    const double scale = std::max(ux.abs().maxCoeff(), uy.abs().maxCoeff());
    const double error = std::max((sx - ux).abs().maxCoeff(), (sy - uy).abs().maxCoeff());
    EXPECT_LT(error, 1e-5 * scale) << (inverse ? "approximate inverse" : "product");
    EXPECT_GT(error, 0.0) << (inverse ? "approximate inverse" : "product");
  }
  const double limit = kMu * contact.total_force;
  const TangentialState unloaded = TangentialState::unloaded(n);
  const TangentialLoading loading = TangentialLoading::force(0.5 * limit, 0.2 * limit);
  TangentialResult results[2];
  for (const bool single : {false, true}) {
    solvers::TangentialOptions options;
    options.friction_coefficient = kMu;
    options.tolerance = 1e-10;
    options.precision = single ? solvers::Precision::mixed : solvers::Precision::double_precision;
    TangentialSolver solver(op, options);
    results[single ? 1 : 0] = solver.solve({contact.pressure.data(), n}, loading, unloaded);
    const TangentialResult& r = results[single ? 1 : 0];
    ASSERT_TRUE(r.converged()) << r.message;
    const double moved = std::max(r.state.displacement_x.abs().maxCoeff(), r.state.displacement_y.abs().maxCoeff());
    testing::expect_coulomb_conditions(op, contact.pressure, kMu, unloaded, r, 1e-6 * moved, 1e-2);
    EXPECT_NEAR(r.force_x, 0.5 * limit, 1e-9 * limit);
  }
  const double peak = kMu * contact.pressure.maxCoeff();
  EXPECT_LT((results[1].state.shear_x - results[0].state.shear_x).abs().maxCoeff(), 1e-8 * peak);
  EXPECT_LT((results[1].state.shear_y - results[0].state.shear_y).abs().maxCoeff(), 1e-8 * peak);
}

TEST(RoughFriction, CoarseToleranceOutsideTheUnitIntervalIsRefused) {
  solvers::TangentialOptions options;
  options.friction_coefficient = kMu;
  for (const double tolerance : {0.0, 1.0}) {
    options.coarse_tolerance = tolerance;
    try {
      options.validate();
      ADD_FAILURE() << "coarse_tolerance " << tolerance << " accepted";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("coarse_tolerance"), std::string::npos) << error.what();
    }
  }
}

TEST(RoughFriction, ReleasePeriodBelowOneIsRefused) {
  solvers::TangentialOptions options;
  options.friction_coefficient = kMu;
  options.release_period = 0;
  try {
    options.validate();
    ADD_FAILURE() << "release_period 0 accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("release_period"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace halfspace
