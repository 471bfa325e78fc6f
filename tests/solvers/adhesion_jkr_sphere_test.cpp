// The adhesive sphere at a large Tabor parameter against JKR directly: the
// load against contact radius on the loading and unloading branches,
// P = A^3 - sqrt(6 A^3) in Maugis's units (F(a) = 4 E* a^3 / (3R) -
// sqrt(8 pi w E* a^3), Johnson, Kendall & Roberts 1971), and the pull-off
// -3/2 pi w R.
//
// The law is the exponential one: with Maugis-Dugdale at lambda = 5 the
// discrete crack edge stays trapped by the lattice on every grid a unit
// test (or a workstation) can afford, while the smooth exponential law of
// the same largest stress converges once a cell is no wider than the
// nominal cohesive zone d = (pi/4) E* rho^2 / w = (3/4) ell / lambda^2
// (docs/theory.md, "Adhesion"; docs/validation.md, "Adhesion", has the
// measurements and bench/adhesion_jkr_sphere.py the finer grids).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "halfspace/analysis/load_sweep.hpp"
#include "halfspace/solvers/adhesive_contact_solver.hpp"
#include "solvers/adhesive_sphere.hpp"

namespace halfspace {
namespace {

using solvers::AdhesiveContactSolver;
using solvers::AdhesiveSolverOptions;
using testing::AdhesiveSphere;

struct JkrSphereBranches {
  double worst_load_error;  // largest |P - P_JKR(A)| (pi w R) over the steps in contact
  double pull_off;          // the least force of the unloading branch (pi w R), refined by a parabola
  double hysteresis;        // largest |P_loading - P_unloading| (pi w R) at the approaches both visit
};

// A displacement-controlled sweep on a free grid of `cells_per_ell` cells per
// ell spanning 3.5 ell (the contact stays below A = 1.6, its cohesive zone
// below 1.75): loading from first touch (approach 0, where the sphere jumps
// into contact) to 0.5 ell^2 / R in steps of 0.25, unloading to -0.8 in
// steps of 0.05, past the pull-off (JKR: at -0.44, A = 1.145) but short of
// the jump out of contact (-0.91, A = 0.55). A = sqrt(area / pi) / ell of
// the cells at the wall.
JkrSphereBranches sweep(const AdhesiveSphere& sphere, double cells_per_ell) {
  const double dx = sphere.ell() / cells_per_ell;
  const auto n = static_cast<std::size_t>(std::lround(3.5 * cells_per_ell));
  const Grid grid = Grid::plane(n, n, dx, dx, Boundary::free);
  AdhesiveSolverOptions options;
  options.law = sphere.exponential_law();
  AdhesiveContactSolver solver(grid, sphere.e_star, options);
  const std::vector<double> gap = testing::sphere_gap(grid, sphere.radius);
  // Approaches in units of 0.05 ell^2 / R, so that the branches meet exactly.
  std::vector<int> twentieths{0, 5, 10};
  for (int k = 9; k >= -16; --k) twentieths.push_back(k);
  std::vector<double> values;
  for (const int k : twentieths) values.push_back(0.05 * k * sphere.approach_unit());
  analysis::LoadSweepOptions sweep_options;
  sweep_options.signed_loads = true;
  const std::vector<analysis::SweepStep> steps =
      analysis::run_load_sweep(solver, grid, gap, ControlMode::approach, values, sweep_options);

  JkrSphereBranches out{0.0, 0.0, 0.0};
  std::vector<double> loads(steps.size());
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const SolveResult& r = steps[k].result;
    EXPECT_TRUE(r.converged()) << "approach " << 0.05 * twentieths[k] << ": " << r.message;
    const double a = std::sqrt(r.contact_fraction * grid.domain_area() / std::numbers::pi) / sphere.ell();
    loads[k] = r.total_force / sphere.force_unit();
    EXPECT_GT(a, 0.7) << "approach " << 0.05 * twentieths[k] << ": the contact broke early";
    out.worst_load_error = std::max(out.worst_load_error, std::abs(loads[k] - testing::jkr_load(a)));
  }
  const std::size_t deepest = 2;
  for (std::size_t k = deepest + 1; k < steps.size(); ++k) {
    for (std::size_t j = 0; j < deepest; ++j) {
      if (twentieths[j] == twentieths[k]) out.hysteresis = std::max(out.hysteresis, std::abs(loads[k] - loads[j]));
    }
  }
  std::vector<double> at;
  std::vector<double> unloading;
  for (std::size_t k = deepest; k < steps.size(); ++k) {
    at.push_back(0.05 * twentieths[k]);
    unloading.push_back(loads[k]);
  }
  out.pull_off = testing::refined_minimum(at, unloading);
  return out;
}

// lambda = 5: the nominal zone (3/4) ell / lambda^2 = 0.03 ell is half a
// cell at 16 cells per ell and a cell at 32. Measured (adhesive-pcg): the
// largest |P - P_JKR(A)| 0.26 and 0.058 pi w R, the pull-off -1.653 and
// -1.527 pi w R (+10 % and +1.8 %), loading and unloading apart by
// 0.17 and 0.016 pi w R at the same approach (the lattice traps the edge on
// the coarse grid, hardly on the fine one). What remains on the fine grid is
// the law's own finite range, not the grid: 64 cells per ell give 0.065 and
// -1.520, and a shorter range (lambda = 10 on 128 cells per ell) 0.019 and
// -1.506 (bench/adhesion_jkr_sphere.py).
constexpr double kTaborParameter = 5.0;
constexpr double kLoadTolerance = 0.1;         // pi w R, absolute: the fine grid's 0.058 plus margin
constexpr double kPullOffTolerance = 0.03;     // relative to 3/2: the fine grid's 1.8 % plus margin
constexpr double kHysteresisTolerance = 0.03;  // pi w R: the fine grid's 0.016 plus margin
constexpr double kConvergenceRatio = 0.5;      // error(h/2) / error(h): measured 0.22, 0.17 and 0.10

TEST(AdhesionJkrSphereTest, LoadAgainstContactRadiusAndPullOffFollowJkrAtLargeTaborParameter) {
  const AdhesiveSphere sphere{kTaborParameter};
  const JkrSphereBranches coarse = sweep(sphere, 16.0);
  const JkrSphereBranches fine = sweep(sphere, 32.0);
  const auto report = [&] {
    return ::testing::Message() << "largest |P - P_JKR(A)|: coarse " << coarse.worst_load_error << ", fine "
                                << fine.worst_load_error << "; pull-off: coarse " << coarse.pull_off << ", fine "
                                << fine.pull_off << "; hysteresis: coarse " << coarse.hysteresis << ", fine "
                                << fine.hysteresis;
  };
  EXPECT_LT(fine.worst_load_error, kConvergenceRatio * coarse.worst_load_error) << report();
  EXPECT_LT(fine.worst_load_error, kLoadTolerance) << report();
  EXPECT_LT(std::abs(fine.pull_off + 1.5), kConvergenceRatio * std::abs(coarse.pull_off + 1.5)) << report();
  EXPECT_NEAR(fine.pull_off, -1.5, kPullOffTolerance * 1.5) << report();
  EXPECT_LT(fine.hysteresis, kConvergenceRatio * coarse.hysteresis) << report();
  EXPECT_LT(fine.hysteresis, kHysteresisTolerance) << report();
}

}  // namespace
}  // namespace halfspace
