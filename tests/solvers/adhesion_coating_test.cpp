// Adhesion below a coating: the adhesive solver on the coated half-space's
// operator. A layer of the substrate's own material is the homogeneous
// half-space (the same answer to rounding), and a soft layer moves the
// sphere's pull-off from the stiff (DMT-like) end of Maugis's curve towards
// the soft (JKR) end: a higher Tabor parameter lambda ~ E*^(-2/3) pulls off
// with less force, from -2 pi w R (DMT) towards -3/2 pi w R (JKR).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "halfspace/analysis/adhesion_sweep.hpp"
#include "halfspace/analysis/load_sweep.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "solvers/adhesive_sphere.hpp"

namespace halfspace {
namespace {

using solvers::SolverOptions;

// A layer of the substrate's material: its kernel is the homogeneous one up
// to the rounding of the layered kernel's arithmetic (and, on free grids,
// of splitting it into a closed-form part and a remainder), which the
// iteration carries into the pressures at most a few orders above 1e-16.
constexpr double kSameMaterialTolerance = 1e-10;  // of the largest pressure

constexpr double kModulus = 1e6;  // E* of the substrate (Pa)
constexpr double kNu = 0.3;

// The sphere of adhesive_sphere.hpp at E* = 1 MPa (w scaled with E*, so the
// lengths, approaches in ell^2 / R and forces in pi w R stay the same), at
// Tabor parameter `lambda`, the exponential law.
testing::AdhesiveSphere sphere(double lambda) {
  return testing::AdhesiveSphere{lambda, 1.0, kModulus, 1e-4 * kModulus};
}

SolverOptions adhesive_options(const testing::AdhesiveSphere& s) {
  SolverOptions options;
  options.adhesion = SolverOptions::Adhesion{s.exponential_law()};
  return options;
}

ElasticBody body_of_modulus(double e_star) {
  return {e_star * (1.0 - kNu * kNu), kNu};
}

// 32 x 32 cells over 3.5 ell.
Grid sphere_grid(const testing::AdhesiveSphere& s, Boundary boundary) {
  const double dx = 3.5 * s.ell() / 32.0;
  return Grid::plane(32, 32, dx, dx, boundary);
}

// Approaches (ell^2 / R) loading to 0.5, then unloading past the pull-off.
std::vector<double> loading_and_unloading(const testing::AdhesiveSphere& s) {
  std::vector<double> values;
  for (const double a : {0.0, 0.25, 0.5, 0.3, 0.1, -0.1, -0.2, -0.3, -0.4, -0.5, -0.6, -0.7, -0.8}) {
    values.push_back(a * s.approach_unit());
  }
  return values;
}

void expect_same_material_is_homogeneous(Boundary boundary) {
  const testing::AdhesiveSphere s = sphere(2.0);
  const Grid grid = sphere_grid(s, boundary);
  const std::vector<double> gap = testing::sphere_gap(grid, s.radius);
  const LayeredMaterial same{0.5 * s.ell(), body_of_modulus(kModulus), body_of_modulus(kModulus)};
  const SolverOptions options = adhesive_options(s);
  auto homogeneous = solvers::make_solver(grid, kModulus, options);
  auto coated = solvers::make_solver(grid, same, options);
  const std::vector<double> approaches = loading_and_unloading(s);
  analysis::LoadSweepOptions sweep;
  sweep.signed_loads = true;
  const auto expected = analysis::run_load_sweep(*homogeneous, grid, gap, ControlMode::approach, approaches, sweep);
  const auto got = analysis::run_load_sweep(*coated, grid, gap, ControlMode::approach, approaches, sweep);
  // And load control (the search on the approach), pressing then pulling,
  // on fresh solvers.
  homogeneous = solvers::make_solver(grid, kModulus, options);
  coated = solvers::make_solver(grid, same, options);
  ASSERT_TRUE(homogeneous->solve(gap, Loading::force(0.5 * s.force_unit())).converged());
  ASSERT_TRUE(coated->solve(gap, Loading::force(0.5 * s.force_unit())).converged());
  const SolveResult expected_pulled = homogeneous->solve(gap, Loading::force(-0.5 * s.force_unit()));
  const SolveResult pulled = coated->solve(gap, Loading::force(-0.5 * s.force_unit()));
  ASSERT_TRUE(expected_pulled.converged()) << expected_pulled.message;
  ASSERT_TRUE(pulled.converged()) << pulled.message;
  double worst = 0.0;
  const auto compare = [&](const SolveResult& e, const SolveResult& r, const char* what) {
    ASSERT_TRUE(r.converged()) << what << ": " << r.message;
    const double scale = e.pressure.abs().maxCoeff();
    const double error = (r.pressure - e.pressure).abs().maxCoeff() / scale;
    worst = std::max(worst, error);
    EXPECT_LE(error, kSameMaterialTolerance) << what;
    EXPECT_NEAR(r.total_force, e.total_force, kSameMaterialTolerance * scale * grid.domain_area()) << what;
  };
  for (std::size_t k = 0; k < got.size(); ++k) compare(expected[k].result, got[k].result, "sweep step");
  compare(expected_pulled, pulled, "load control");
  std::printf("largest pressure difference, coating of the substrate's material: %.3g of the largest pressure\n",
              worst);
}

TEST(AdhesionCoatingTest, LayerOfTheSubstratesMaterialIsTheHomogeneousAnswerPeriodic) {
  expect_same_material_is_homogeneous(Boundary::periodic);
}
TEST(AdhesionCoatingTest, LayerOfTheSubstratesMaterialIsTheHomogeneousAnswerFree) {
  expect_same_material_is_homogeneous(Boundary::free);
}

// The sphere's pull-off (pi w R) from a displacement-controlled sweep on a
// free grid of 32 x 32 cells over 6 ell (ell of E* = kModulus): loading to 2
// ell^2 / R, unloading to -4 in steps of 0.2 (a body 10x softer has 2.15x the length and
// 4.6x the approach unit, and pulls off at -0.44 of its unit in JKR's
// limit).
template <class Body>
double pull_off(const testing::AdhesiveSphere& s, const Body& body) {
  const double dx = 6.0 * s.ell() / 32.0;
  const Grid grid = Grid::plane(32, 32, dx, dx, Boundary::free);
  const std::vector<double> gap = testing::sphere_gap(grid, s.radius);
  auto solver = solvers::make_solver(grid, body, adhesive_options(s));
  std::vector<double> approaches{0.0, 1.0, 2.0};
  for (int k = 9; k >= -20; --k) approaches.push_back(0.2 * k);
  for (double& a : approaches) a *= s.approach_unit();
  analysis::LoadSweepOptions sweep;
  sweep.signed_loads = true;
  const auto steps = analysis::run_load_sweep(*solver, grid, gap, ControlMode::approach, approaches, sweep);
  for (const analysis::SweepStep& step : steps) EXPECT_TRUE(step.result.converged()) << step.result.message;
  return analysis::pull_off_force(steps) / s.force_unit();
}

TEST(AdhesionCoatingTest, SoftCoatingMovesThePullOffTowardsJkr) {
  // lambda = 0.5 on the substrate (Maugis: about -1.9); a layer 10x softer,
  // 4 ell thick (twice the soft contact's radius at pull-off), is lambda =
  // 0.5 x 10^(2/3) = 2.3 for the contact (about -1.6). The law is the same.
  const testing::AdhesiveSphere s = sphere(0.5);
  const LayeredMaterial soft{4.0 * s.ell(), body_of_modulus(0.1 * kModulus), body_of_modulus(kModulus)};
  const double stiff_pull_off = pull_off(s, kModulus);
  const double coated_pull_off = pull_off(s, soft);
  const double soft_pull_off = pull_off(s, 0.1 * kModulus);
  std::printf("pull-off (pi w R): substrate %.4f, soft coating %.4f, the layer's material throughout %.4f\n",
              stiff_pull_off, coated_pull_off, soft_pull_off);
  // Less pull than on the substrate (towards JKR), at least as much as on
  // the soft half-space (the stiff substrate below still shows).
  EXPECT_GT(coated_pull_off, stiff_pull_off + 0.05);
  EXPECT_LE(coated_pull_off, soft_pull_off + 0.02);
}

}  // namespace
}  // namespace halfspace
