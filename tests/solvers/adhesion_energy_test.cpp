// The adhesive solver on periodic and free grids, 1D and 2D: exact uniform
// states of flat surfaces, the energy balance along a loading branch (the
// work of the force equals the change of the total energy), warm starts,
// and its refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/solvers/adhesive_contact_solver.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace {
namespace {

using solvers::AdhesiveContactSolver;
using solvers::AdhesiveSolverOptions;

constexpr double kPi = std::numbers::pi;

// A flat surface feels the law's traction everywhere and does not deform:
// exact up to the solver's tolerance (1e-6 relative) in the pressure.
constexpr double kUniformTolerance = 1e-5;

// Total energy (J, J/m in 1D): elastic 1/2 sum p u A plus the interaction sum phi(g) A.
double total_energy(const Grid& grid, const SolveResult& result, const AdhesionLaw& law) {
  double energy = 0.0;
  for (Eigen::Index i = 0; i < result.pressure.size(); ++i) {
    energy += 0.5 * result.pressure[i] * result.displacement[i] + law.energy(result.gap[i]);
  }
  return energy * grid.cell_area();
}

AdhesiveContactSolver make_solver(const Grid& grid, const AdhesionLaw& law, double tolerance = 1e-6,
                                  bool precondition = false, double e_star = 1.0) {
  AdhesiveSolverOptions options;
  options.law = law;
  options.tolerance = tolerance;
  options.precondition = precondition;
  return AdhesiveContactSolver(grid, e_star, options);
}

// E* = 1 GPa: the laws' cohesive zones (pi E* w / (4 sigma0^2), 8 nm) are
// then resolved by the 10 nm cells, as the solver requires.
void expect_uniform_traction(const Grid& grid, const AdhesionLaw& law, double separation) {
  AdhesiveContactSolver solver = make_solver(grid, law, 1e-6, false, 1e9);
  const std::vector<double> gap(grid.size(), 0.0);
  const SolveResult result = solver.solve(gap, Loading::approach(-separation));
  ASSERT_TRUE(result.converged()) << result.message;
  const double expected = law.traction(separation);
  for (Eigen::Index i = 0; i < result.pressure.size(); ++i) {
    ASSERT_NEAR(result.pressure[i], expected, kUniformTolerance * law.stress()) << "cell " << i;
    ASSERT_NEAR(result.gap[i], separation, kUniformTolerance * separation) << "cell " << i;
  }
  EXPECT_NEAR(result.total_force, expected * grid.domain_area(), kUniformTolerance * law.stress() * grid.domain_area());
  EXPECT_NEAR(result.adhesion.adhesive_force, result.total_force, 1e-12 * std::abs(result.total_force) + 1e-300);
  EXPECT_EQ(result.contact_fraction, 0.0);
  EXPECT_EQ(result.adhesion.law, std::string(to_string(law.type)));
}

TEST(AdhesionEnergyTest, FlatPeriodicSurfaceFeelsTheLawUniformly) {
  const AdhesionLaw md = AdhesionLaw::maugis_dugdale(0.1, 1e-9);
  const AdhesionLaw exponential = AdhesionLaw::exponential(0.1, 1e-9);
  for (const Grid& grid :
       {Grid::plane(16, 8, 1e-8, 1e-8, Boundary::periodic), Grid::line(32, 1e-8, Boundary::periodic)}) {
    expect_uniform_traction(grid, md, 0.5e-9);
    expect_uniform_traction(grid, exponential, 1e-9);
  }
}

// A paraboloid (1D: a parabolic cylinder) of radius R = 1 m in its cell,
// on E* = 1 Pa, with the exponential law (w = 1e-4 J/m^2, rho = ell^2 / R).
struct BumpCase {
  Grid grid;
  std::vector<double> gap;
  AdhesionLaw law;
};

BumpCase bump(int dimension, Boundary boundary) {
  const double ell = std::cbrt(kPi * 1e-4 / (4.0 / 3.0));
  // 1D: a wider cell, so that the approach stays below the periodic mean gap.
  const std::size_t n = dimension == 2 ? 48 : 256;
  const double dx = (dimension == 2 ? 4.0 : 8.0) * ell / static_cast<double>(n);
  Grid grid = dimension == 2 ? Grid::plane(n, n, dx, dx, boundary) : Grid::line(n, dx, boundary);
  std::vector<double> gap(grid.size());
  for (std::size_t j = 0; j < grid.ny(); ++j) {
    for (std::size_t i = 0; i < grid.nx(); ++i) {
      const double x = (static_cast<double>(i) + 0.5 - 0.5 * static_cast<double>(n)) * dx;
      const double y = dimension == 2 ? (static_cast<double>(j) + 0.5 - 0.5 * static_cast<double>(n)) * dx : 0.0;
      gap[j * grid.nx() + i] = (x * x + y * y) / 2.0;
    }
  }
  return {grid, gap, AdhesionLaw::exponential(1e-4, ell * ell)};
}

// Along a branch without jumps dPi/d(delta) = F (the wall's and the law's
// forces are the derivative of the minimised energy), so Simpson's integral
// of F over the approaches equals the energy difference; the quadrature
// error of 20 steps and the solver's tolerance bound the mismatch (relative
// to the integral of |F|; measured: below 2e-4 with the trapezoidal rule).
constexpr double kEnergyBalanceTolerance = 1e-3;

void expect_energy_balance(const BumpCase& c, bool precondition = false) {
  AdhesiveContactSolver solver = make_solver(c.grid, c.law, 1e-7, precondition);
  const double unit = c.law.range;  // ell^2 / R
  std::vector<SolveResult> results;
  Eigen::ArrayXd start;
  for (int k = 0; k <= 20; ++k) {
    const double approach = (0.2 + 0.04 * k) * unit;
    std::span<const double> warm;
    if (start.size() > 0) warm = {start.data(), c.grid.size()};
    results.push_back(solver.solve(c.gap, Loading::approach(approach), warm));
    ASSERT_TRUE(results.back().converged()) << "step " << k << ": " << results.back().message;
    start = results.back().pressure;
  }
  const double step = results[1].approach - results[0].approach;
  double work = 0.0;
  double scale = 0.0;
  for (std::size_t k = 0; k < results.size(); ++k) {
    const double weight = (k == 0 || k + 1 == results.size()) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    work += weight * results[k].total_force * step / 3.0;
    scale += weight * std::abs(results[k].total_force) * step / 3.0;
  }
  const double change = total_energy(c.grid, results.back(), c.law) - total_energy(c.grid, results.front(), c.law);
  EXPECT_NEAR(work, change, kEnergyBalanceTolerance * scale) << "work " << work << ", energy change " << change;
  // The attraction is felt on the way: some pressure is negative.
  EXPECT_LT(results.front().adhesion.adhesive_force, 0.0);
  EXPECT_GT(results.front().adhesion.interaction_fraction, results.front().contact_fraction);
}

TEST(AdhesionEnergyTest, WorkEqualsEnergyChangePeriodic2D) {
  expect_energy_balance(bump(2, Boundary::periodic));
}
TEST(AdhesionEnergyTest, WorkEqualsEnergyChangeFree2D) {
  expect_energy_balance(bump(2, Boundary::free));
}
TEST(AdhesionEnergyTest, WorkEqualsEnergyChangePeriodic1D) {
  expect_energy_balance(bump(1, Boundary::periodic));
}
TEST(AdhesionEnergyTest, WorkEqualsEnergyChangeFree1D) {
  expect_energy_balance(bump(1, Boundary::free));
}

// The same with the preconditioned conjugate gradients.
TEST(AdhesionEnergyTest, WorkEqualsEnergyChangePeriodic2DConjugateGradients) {
  expect_energy_balance(bump(2, Boundary::periodic), true);
}
TEST(AdhesionEnergyTest, WorkEqualsEnergyChangeFree2DConjugateGradients) {
  expect_energy_balance(bump(2, Boundary::free), true);
}
TEST(AdhesionEnergyTest, WorkEqualsEnergyChangePeriodic1DConjugateGradients) {
  expect_energy_balance(bump(1, Boundary::periodic), true);
}
TEST(AdhesionEnergyTest, WorkEqualsEnergyChangeFree1DConjugateGradients) {
  expect_energy_balance(bump(1, Boundary::free), true);
}

TEST(AdhesionEnergyTest, WarmStartFromTheSolutionNeedsNoIteration) {
  const BumpCase c = bump(2, Boundary::free);
  AdhesiveContactSolver solver = make_solver(c.grid, c.law);
  const SolveResult first = solver.solve(c.gap, Loading::approach(0.5 * c.law.range));
  ASSERT_TRUE(first.converged());
  const SolveResult again =
      solver.solve(c.gap, Loading::approach(0.5 * c.law.range), {first.pressure.data(), c.grid.size()});
  ASSERT_TRUE(again.converged());
  EXPECT_LE(again.iterations, first.iterations / 4) << "cold " << first.iterations << ", warm " << again.iterations;
  EXPECT_NEAR(again.total_force, first.total_force, 1e-4 * std::abs(first.total_force));
}

TEST(AdhesionEnergyTest, ReportsTheIterationLimitAsStatus) {
  const BumpCase c = bump(2, Boundary::periodic);
  AdhesiveSolverOptions options;
  options.law = c.law;
  options.max_iterations = 3;
  AdhesiveContactSolver solver(c.grid, 1.0, options);
  const SolveResult result = solver.solve(c.gap, Loading::approach(0.5 * c.law.range));
  EXPECT_EQ(result.status, SolveStatus::iteration_limit);
  EXPECT_NE(result.message.find("no convergence after 3 iterations"), std::string::npos) << result.message;
}

TEST(AdhesionEnergyTest, RefusesBadInput) {
  const BumpCase c = bump(2, Boundary::periodic);
  AdhesiveContactSolver solver = make_solver(c.grid, c.law);
  // Periodic: the approach must stay below the mean gap.
  try {
    solver.solve(c.gap, Loading::approach(1.0));
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("below the mean initial gap"), std::string::npos) << error.what();
  }
  EXPECT_THROW(solver.solve(c.gap, Loading::approach(NAN)), InputError);
  EXPECT_THROW(solver.solve(std::vector<double>(3, 0.0), Loading::approach(0.0)), InputError);
  AdhesiveSolverOptions options;
  options.law = AdhesionLaw::exponential(0.0, 1e-9);
  EXPECT_THROW(AdhesiveContactSolver(c.grid, 1.0, options), InputError);
}

// The options' errors name the option, as SolverOptions' do.
TEST(AdhesionEnergyTest, OptionErrorsNameTheOption) {
  const auto option_of = [](const AdhesiveSolverOptions& options) {
    try {
      options.validate();
    } catch (const solvers::SolverOptionError& error) {
      return error.option();
    }
    return std::string("none");
  };
  AdhesiveSolverOptions options;
  options.law = AdhesionLaw::exponential(0.1, 1e-9);
  EXPECT_EQ(option_of(options), "none");
  AdhesiveSolverOptions bad = options;
  bad.law.work = -1.0;
  EXPECT_EQ(option_of(bad), "law.work");
  bad = options;
  bad.law.range = 0.0;
  EXPECT_EQ(option_of(bad), "law.range");
  bad = options;
  bad.tolerance = 1.0;
  EXPECT_EQ(option_of(bad), "tolerance");
  bad = options;
  bad.force_tolerance = 0.0;
  EXPECT_EQ(option_of(bad), "force_tolerance");
  bad = options;
  bad.max_iterations = 0;
  EXPECT_EQ(option_of(bad), "max_iterations");
  bad = options;
  bad.max_load_steps = 0;
  EXPECT_EQ(option_of(bad), "max_load_steps");
}

}  // namespace
}  // namespace halfspace
