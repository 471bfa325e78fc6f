// The active-set phase of the tangential step (TangentialOptions::
// active_set_updates: semi-smooth Newton updates of the stick/slip sets and
// slip directions around conjugate gradients on the frozen sets, then the
// default conjugate gradients finish): on the Cattaneo-Mindlin sphere and
// cylinder and on a rough periodic contact it reaches the default solver's
// state (traction, approach, stick set) and the closed forms, meets the
// Coulomb conditions by a fresh product apart from the solver's residual,
// and a step that cannot converge within its iterations is reported so.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "friction/friction_checks.hpp"
#include "halfspace/error.hpp"
#include "halfspace/solvers/friction_options.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/solvers/tangential_solver.hpp"
#include "halfspace/surface/self_affine.hpp"
#include "support/analytic_solutions.hpp"
#include "support/grid_fields.hpp"
#include "support/pk_solvers.hpp"

namespace halfspace {
namespace {

constexpr ElasticBody kSteel{2.1e11, 0.3};
constexpr double kMu = 0.3;
constexpr int kUpdates = 30;

solvers::TangentialOptions options(int active_set_updates, double tolerance = 1e-10) {
  solvers::TangentialOptions o;
  o.friction_coefficient = kMu;
  o.tolerance = tolerance;
  o.max_iterations = 20000;
  o.active_set_updates = active_set_updates;
  return o;
}

struct Pair {
  TangentialResult active;  // with the active-set phase
  TangentialResult plain;   // without (the default)
};

// One step by both; both must converge. Prints the iterations.
Pair solve_both(TangentialOperator& op, const Eigen::ArrayXd& pressure, const TangentialLoading& loading,
                const TangentialState& previous, double tolerance, const char* what) {
  TangentialSolver active(op, options(kUpdates, tolerance));
  TangentialSolver plain(op, options(0, tolerance));
  const std::span<const double> p(pressure.data(), op.local_size());
  Pair r{active.solve(p, loading, previous), plain.solve(p, loading, previous)};
  EXPECT_TRUE(r.active.converged()) << what << ": " << r.active.message;
  EXPECT_TRUE(r.plain.converged()) << what << ": " << r.plain.message;
  EXPECT_GT(r.active.active_set_updates, 0) << what;
  EXPECT_GT(r.active.active_set_iterations, 0) << what;
  EXPECT_EQ(r.plain.active_set_updates, 0) << what;
  std::printf(
      "%s: active set %d updates, %d + %d iterations, %d C + %d M products; default %d iterations, %d C + %d M\n", what,
      r.active.active_set_updates, r.active.active_set_iterations, r.active.iterations - r.active.active_set_iterations,
      r.active.operator_applications, r.active.preconditioner_applications, r.plain.iterations,
      r.plain.operator_applications, r.plain.preconditioner_applications);
  return r;
}

// The two results agree: traction to 1e-3 of mu p_max, approach to 1e-4
// of the step's displacement scale, stick fraction to 0.01.
void expect_same_step(const Pair& r, const Eigen::ArrayXd& pressure, const TangentialState& previous,
                      const char* what) {
  const double limit = kMu * pressure.maxCoeff();
  const double traction = std::max((r.active.state.shear_x - r.plain.state.shear_x).abs().maxCoeff(),
                                   (r.active.state.shear_y - r.plain.state.shear_y).abs().maxCoeff());
  const double scale = std::max((r.plain.state.displacement_x - previous.displacement_x).abs().maxCoeff(),
                                (r.plain.state.displacement_y - previous.displacement_y).abs().maxCoeff());
  const double approach = std::hypot(r.active.state.approach_x - r.plain.state.approach_x,
                                     r.active.state.approach_y - r.plain.state.approach_y);
  std::printf("%s: traction difference %.2e mu p_max, approach %.2e, stick %.4f / %.4f\n", what, traction / limit,
              approach / scale, r.active.stick_fraction, r.plain.stick_fraction);
  EXPECT_LE(traction, 1e-3 * limit) << what;
  EXPECT_LE(approach, 1e-4 * scale) << what;
  EXPECT_NEAR(r.active.stick_fraction, r.plain.stick_fraction, 0.01) << what;
}

// Cattaneo-Mindlin sphere (48^2 free grid, Q = 0.5 mu P from rest), then
// Mindlin-Deresiewicz unloading to 0.25 mu P, where cells leave the slip
// set and the annulus slips backwards.
TEST(TangentialActiveSet, SphereMatchesCattaneoMindlinAndTheDefaultSolver) {
  const ElasticPair pair = ElasticPair::similar(kSteel);
  constexpr double kForce = 10.0;         // N
  constexpr double kSphereRadius = 0.01;  // m
  const auto hertz = testing::hertz_point(kForce, kSphereRadius, pair.composite_modulus());
  const std::size_t n = 48;
  const auto [grid, contact] = testing::hertz_sphere_contact(pair, kForce, kSphereRadius, n);
  ASSERT_TRUE(contact.converged());
  TangentialOperator op(grid, pair);
  const TangentialState unloaded = TangentialState::unloaded(grid.size());
  const double ratio = 0.5;
  const Pair loaded = solve_both(op, contact.pressure, TangentialLoading::force(ratio * kMu * kForce), unloaded, 1e-10,
                                 "sphere, Q = 0.5 mu P");
  expect_same_step(loaded, contact.pressure, unloaded, "sphere, Q = 0.5 mu P");
  const TangentialResult& r = loaded.active;
  EXPECT_NEAR(r.force_x, ratio * kMu * kForce, 1e-10 * kForce);
  EXPECT_NEAR(r.force_y, 0.0, 1e-10 * kForce);
  testing::expect_coulomb_conditions(op, contact.pressure, kMu, unloaded, r, 1e-7 * hertz.approach, 1e-2);
  // The closed form (Johnson 1985, eqs. 7.39-7.42): the stick radius within
  // a cell, the traction within the tolerance of cattaneo_mindlin_test.cpp.
  const double a = hertz.radius;
  const double c = a * std::cbrt(1.0 - ratio);
  const double stick_radius = std::sqrt(r.stick.sum() * grid.cell_area() / std::numbers::pi);
  double worst = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t i = 0; i < n; ++i) {
      const double r2 = std::pow(testing::centred_x(grid, i), 2) + std::pow(testing::centred_y(grid, j), 2);
      const double exact =
          kMu * hertz.peak / a * (std::sqrt(std::max(a * a - r2, 0.0)) - std::sqrt(std::max(c * c - r2, 0.0)));
      worst = std::max(worst, std::abs(r.state.shear_x[static_cast<Eigen::Index>(j * n + i)] - exact));
    }
  }
  std::printf("sphere (active set): c/dx %.2f (exact %.2f), traction error %.2e mu p0\n", stick_radius / grid.dx(),
              c / grid.dx(), worst / (kMu * hertz.peak));
  EXPECT_LE(std::abs(stick_radius - c), grid.dx());
  EXPECT_LE(worst, 0.06 * kMu * hertz.peak);

  const Pair unloading = solve_both(op, contact.pressure, TangentialLoading::force(0.25 * kMu * kForce), r.state, 1e-10,
                                    "sphere, unloaded to 0.25 mu P");
  expect_same_step(unloading, contact.pressure, r.state, "sphere, unloaded to 0.25 mu P");
  testing::expect_coulomb_conditions(op, contact.pressure, kMu, r.state, unloading.active, 1e-7 * hertz.approach, 1e-2);
}

// A tangential displacement three times the onset of sliding: no cell
// sticks (the phase's stick set empties), the force is mu P to within
// the sideways turn of the slips, as the default solver finds.
TEST(TangentialActiveSet, SphereSlidesUnderALargeDisplacement) {
  const ElasticPair pair = ElasticPair::similar(kSteel);
  constexpr double kForce = 10.0;         // N
  constexpr double kSphereRadius = 0.01;  // m
  const auto hertz = testing::hertz_point(kForce, kSphereRadius, pair.composite_modulus());
  const auto [grid, contact] = testing::hertz_sphere_contact(pair, kForce, kSphereRadius, 32);
  ASSERT_TRUE(contact.converged());
  TangentialOperator op(grid, pair);
  const double g = kSteel.youngs_modulus / (2.0 * (1.0 + kSteel.poissons_ratio));
  const double onset = 3.0 * kMu * kForce / (16.0 * hertz.radius) * 2.0 * (2.0 - kSteel.poissons_ratio) / g;
  const TangentialState unloaded = TangentialState::unloaded(grid.size());
  const Pair r = solve_both(op, contact.pressure, TangentialLoading::displacement(3.0 * onset), unloaded, 1e-8,
                            "sphere, sliding by displacement");
  expect_same_step(r, contact.pressure, unloaded, "sphere, sliding by displacement");
  EXPECT_EQ(r.active.stick_fraction, 0.0);
  EXPECT_TRUE(r.active.gross_sliding);
  EXPECT_LE(r.active.force_x, kMu * contact.total_force * (1.0 + 1e-12));
  EXPECT_GE(r.active.force_x, 0.999 * kMu * contact.total_force);
}

// Cattaneo's cylinder (plane strain, 1D free grid): c/b = sqrt(1 - Q/(mu P)).
TEST(TangentialActiveSet, CylinderStickHalfWidth) {
  const ElasticPair pair = ElasticPair::similar(kSteel);
  const double load = 1e5;     // N/m
  const double radius = 0.01;  // m
  const auto hertz = testing::hertz_line(load, radius, pair.composite_modulus());
  const std::size_t n = 240;
  const double h = 2.4 * hertz.half_width / static_cast<double>(n);
  const Grid grid = Grid::line(n, h, Boundary::free);
  const Eigen::ArrayXd gap0 = testing::field_from(grid, [&](double x, double) { return x * x / (2 * radius); });
  const auto normal =
      solvers::make_solver(grid, pair.composite_modulus(), testing::test_options(solvers::SolverType::pk_fourier));
  const SolveResult contact = normal->solve({gap0.data(), grid.size()}, Loading::force(load));
  ASSERT_TRUE(contact.converged());
  TangentialOperator op(grid, pair);
  const TangentialState unloaded = TangentialState::unloaded(n);
  const double ratio = 0.5;
  const Pair r =
      solve_both(op, contact.pressure, TangentialLoading::force(ratio * kMu * load), unloaded, 1e-8, "cylinder");
  expect_same_step(r, contact.pressure, unloaded, "cylinder");
  const double scale = r.active.state.slip_x.abs().maxCoeff();
  testing::expect_coulomb_conditions(op, contact.pressure, kMu, unloaded, r.active, 1e-3 * scale, 1e-2);
  const double b = hertz.half_width;
  const double stick_half_width = 0.5 * r.active.stick.sum() * h;
  EXPECT_LE(std::abs(stick_half_width - b * std::sqrt(1.0 - ratio)), h);
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

// Force from rest (oblique), reversed, then displacement control: many
// spots, some sticking, some slipping, directions not along the load.
TEST(TangentialActiveSet, RoughContactGivesTheDefaultSolversStep) {
  const Grid grid = Grid::plane(64, 64, 1e-6, 1e-6, Boundary::periodic);
  const SolveResult contact = rough_contact(grid);
  ASSERT_TRUE(contact.converged());
  TangentialOperator op(grid, ElasticPair::similar(kSteel));
  const double limit = kMu * contact.total_force;
  TangentialState previous = TangentialState::unloaded(grid.size());
  double first_approach = 0.0;
  const char* names[] = {"rough, oblique force", "rough, reversed", "rough, displacement"};
  for (int k = 0; k < 3; ++k) {
    const double further = previous.approach_x + 0.3 * (first_approach - previous.approach_x);
    const TangentialLoading loading = k == 0   ? TangentialLoading::force(0.5 * limit, 0.2 * limit)
                                      : k == 1 ? TangentialLoading::force(0.1 * limit, 0.0)
                                               : TangentialLoading::displacement(further, previous.approach_y);
    const Pair r = solve_both(op, contact.pressure, loading, previous, 1e-10, names[k]);
    expect_same_step(r, contact.pressure, previous, names[k]);
    EXPECT_GT(r.active.stick_fraction, 0.05);  // partial slip: both sets matter
    EXPECT_LT(r.active.stick_fraction, 0.95);
    const double scale = std::max((r.active.state.displacement_x - previous.displacement_x).abs().maxCoeff(),
                                  (r.active.state.displacement_y - previous.displacement_y).abs().maxCoeff());
    testing::expect_coulomb_conditions(op, contact.pressure, kMu, previous, r.active, 1e-6 * scale, 1e-2);
    if (loading.control == TangentialControl::force) {
      EXPECT_NEAR(r.active.force_x, loading.x, 1e-9 * limit);
      EXPECT_NEAR(r.active.force_y, loading.y, 1e-9 * limit);
    }
    if (k == 0) first_approach = r.active.state.approach_x;
    previous = r.active.state;
  }
}

// Too few iterations: the phase stops at the limit and the step is
// reported as not converged (the limit counts the phase's iterations).
TEST(TangentialActiveSet, StepShortOfItsIterationsIsReported) {
  const Grid grid = Grid::plane(64, 64, 1e-6, 1e-6, Boundary::periodic);
  const SolveResult contact = rough_contact(grid);
  ASSERT_TRUE(contact.converged());
  TangentialOperator op(grid, ElasticPair::similar(kSteel));
  solvers::TangentialOptions o = options(kUpdates);
  o.max_iterations = 4;
  TangentialSolver solver(op, o);
  const TangentialResult r =
      solver.solve({contact.pressure.data(), grid.size()}, TangentialLoading::force(0.5 * kMu * contact.total_force),
                   TangentialState::unloaded(grid.size()));
  EXPECT_FALSE(r.converged());
  EXPECT_EQ(r.status, SolveStatus::iteration_limit);
  EXPECT_EQ(r.iterations, 4);
  EXPECT_LE(r.active_set_iterations, 4);
  EXPECT_GT(r.residual, o.tolerance);
  EXPECT_NE(r.message.find("no convergence"), std::string::npos) << r.message;
}

TEST(TangentialActiveSet, NegativeUpdatesAreRefusedByName) {
  solvers::TangentialOptions o = options(-1);
  try {
    o.validate();
    ADD_FAILURE() << "active_set_updates -1 accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("active_set_updates"), std::string::npos) << error.what();
  }
  solvers::FrictionOptions friction;
  friction.tangential.friction_coefficient = kMu;
  friction.history = {TangentialLoading::force(1.0)};
  friction.tangential.active_set_updates = -2;
  try {
    friction.validate();
    ADD_FAILURE() << "active_set_updates -2 accepted";
  } catch (const solvers::SolverOptionError& error) {
    EXPECT_EQ(error.option(), "active_set_updates");
  }
  friction.tangential.active_set_updates = 7;
  const std::size_t step = 0;
  EXPECT_EQ(friction.tangential_options(step).active_set_updates, 7);
}

}  // namespace
}  // namespace halfspace
