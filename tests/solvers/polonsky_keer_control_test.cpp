// Load control and displacement control describe the same contact; the solver
// reports non-convergence as a status; bad loading is refused up front.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "halfspace/error.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "support/contact_checks.hpp"
#include "support/grid_fields.hpp"
#include "support/pk_solvers.hpp"

namespace halfspace {
namespace {

using solvers::SolverType;
using testing::expect_contact_conditions;
using testing::test_options;

class PolonskyKeerControlTest : public ::testing::TestWithParam<SolverType> {};
using testing::field_from;

constexpr double kEStar = 1e11;
// The approach found under load, imposed back, must return the load to this.
constexpr double kRoundTripTolerance = 1e-8;

// A smooth random periodic surface: a few dozen Fourier modes, fixed seed.
Eigen::ArrayXd random_periodic_gap(const Grid& grid, double rms_scale) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  const double lx = grid.dx() * static_cast<double>(grid.nx());
  const double ly = grid.dy() * static_cast<double>(grid.ny());
  Eigen::ArrayXd h = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(grid.size()));
  for (int kx = -4; kx <= 4; ++kx) {
    for (int ky = 0; ky <= 4; ++ky) {
      if (kx == 0 && ky == 0) continue;
      const double amplitude = rms_scale / std::pow(kx * kx + ky * ky, 0.9);
      const double ph = phase(rng);
      h += field_from(grid, [&](double x, double y) {
        return amplitude * std::cos(2 * std::numbers::pi * (kx * x / lx + ky * y / ly) + ph);
      });
    }
  }
  return h.maxCoeff() - h;
}

void expect_round_trip(const Grid& grid, const Eigen::ArrayXd& gap0, const Loading& loading, double gap_tolerance,
                       SolverType type) {
  const auto solver = solvers::make_solver(grid, kEStar, test_options(type, 1e-12));
  const SolveResult loaded = solver->solve({gap0.data(), grid.size()}, loading);
  ASSERT_TRUE(loaded.converged()) << loaded.message;
  expect_contact_conditions(loaded, gap_tolerance);

  const SolveResult displaced = solver->solve({gap0.data(), grid.size()}, Loading::approach(loaded.approach));
  ASSERT_TRUE(displaced.converged()) << displaced.message;
  expect_contact_conditions(displaced, gap_tolerance);
  const double force_error = std::abs(displaced.total_force - loaded.total_force) / loaded.total_force;
  const double pressure_error = (displaced.pressure - loaded.pressure).abs().maxCoeff() / loaded.max_pressure;
  std::printf("round trip %s: force error %.2e, pressure error %.2e, iterations %d / %d\n",
              std::string(to_string(grid.boundary())).c_str(), force_error, pressure_error, loaded.iterations,
              displaced.iterations);
  EXPECT_LE(force_error, kRoundTripTolerance);
  EXPECT_LE(pressure_error, kRoundTripTolerance);
}

TEST_P(PolonskyKeerControlTest, ApproachUnderLoadImposedBackReturnsTheLoadFree2D) {
  const Grid grid = Grid::plane(48, 40, 2e-6, 2.5e-6, Boundary::free);
  const double radius = 0.01;
  const Eigen::ArrayXd gap0 = field_from(grid, [&](double x, double y) { return (x * x + y * y) / (2 * radius); });
  expect_round_trip(grid, gap0, Loading::force(2.0), 1e-9 * gap0.maxCoeff(), GetParam());
}

TEST_P(PolonskyKeerControlTest, ApproachUnderLoadImposedBackReturnsTheLoadPeriodicRough) {
  const Grid grid = Grid::plane(64, 64, 1e-6, 1e-6, Boundary::periodic);
  const Eigen::ArrayXd gap0 = random_periodic_gap(grid, 1e-7);
  expect_round_trip(grid, gap0, Loading::mean_pressure(5e7), 1e-9 * gap0.maxCoeff(), GetParam());
}

TEST_P(PolonskyKeerControlTest, ApproachUnderLoadImposedBackReturnsTheLoadFree1D) {
  const Grid grid = Grid::line(257, 1e-6, Boundary::free);
  const Eigen::ArrayXd gap0 = field_from(grid, [](double x, double) { return x * x / (2 * 0.01); });
  expect_round_trip(grid, gap0, Loading::force(5e4), 1e-9 * gap0.maxCoeff(), GetParam());
}

// The two search sets are two paths to the same LCP solution: plain
// Polonsky-Keer on the contact set, and the Fourier-preconditioned one on
// the projected-gradient set, under load and under an imposed approach.
TEST(PolonskyKeerSearchSetTest, BothSearchSetsReachTheSameContact) {
  const Grid grid = Grid::plane(64, 64, 1e-6, 1e-6, Boundary::periodic);
  const Eigen::ArrayXd gap0 = random_periodic_gap(grid, 1e-7);
  const auto on_contact = solvers::make_solver(grid, kEStar, test_options(SolverType::pk, 1e-12));
  const auto projected = solvers::make_solver(grid, kEStar, test_options(SolverType::pk_fourier, 1e-12));
  for (const Loading loading : {Loading::mean_pressure(5e7), Loading::approach(0.7 * gap0.mean())}) {
    const SolveResult a = on_contact->solve({gap0.data(), grid.size()}, loading);
    const SolveResult b = projected->solve({gap0.data(), grid.size()}, loading);
    ASSERT_TRUE(a.converged()) << a.message;
    ASSERT_TRUE(b.converged()) << b.message;
    const double difference = (a.pressure - b.pressure).abs().maxCoeff() / a.max_pressure;
    std::printf("%s: iterations %d (contact) / %d (projected), pressure difference %.2e\n",
                loading.load_controlled() ? "load" : "approach", a.iterations, b.iterations, difference);
    EXPECT_LE(difference, 1e-8);
    EXPECT_NEAR(b.contact_fraction, a.contact_fraction, 1.0 / static_cast<double>(grid.size()));
    EXPECT_NEAR(b.total_force, a.total_force, 1e-8 * a.total_force);
  }
}

// A start handed over (solve_from) iterates exactly like the same start
// passed as a view (solve): same iterates, same bits.
TEST_P(PolonskyKeerControlTest, StartHandedOverSolvesLikeAStartPassedAsAView) {
  const Grid grid = Grid::plane(64, 64, 1e-6, 1e-6, Boundary::periodic);
  const Eigen::ArrayXd gap0 = random_periodic_gap(grid, 2e-8);
  const auto solver = solvers::make_solver(grid, kEStar, test_options(GetParam()));
  const Loading loading = Loading::mean_pressure(2e8);
  const SolveResult cold = solver->solve({gap0.data(), grid.size()}, loading);
  ASSERT_TRUE(cold.converged()) << cold.message;
  const Eigen::ArrayXd start = 0.8 * cold.pressure;
  const SolveResult viewed =
      solver->solve({gap0.data(), grid.size()}, Loading::mean_pressure(2.5e8), {start.data(), grid.size()});
  const SolveResult handed =
      solver->solve_from({gap0.data(), grid.size()}, Loading::mean_pressure(2.5e8), Eigen::ArrayXd(start));
  ASSERT_TRUE(handed.converged()) << handed.message;
  EXPECT_EQ(handed.iterations, viewed.iterations);
  EXPECT_TRUE((handed.pressure == viewed.pressure).all());
  EXPECT_EQ(handed.residual, viewed.residual);
}

TEST_P(PolonskyKeerControlTest, ReportsIterationLimitAsStatus) {
  const Grid grid = Grid::plane(32, 32, 1e-6, 1e-6, Boundary::periodic);
  const Eigen::ArrayXd gap0 = random_periodic_gap(grid, 1e-7);
  solvers::SolverOptions options = test_options(GetParam());
  options.max_iterations = 2;
  const auto solver = solvers::make_solver(grid, kEStar, options);
  const SolveResult result = solver->solve({gap0.data(), grid.size()}, Loading::mean_pressure(1e7));
  EXPECT_EQ(result.status, SolveStatus::iteration_limit);
  EXPECT_EQ(result.iterations, 2);
  EXPECT_GT(result.residual, options.tolerance);
  EXPECT_NE(result.message.find("no convergence"), std::string::npos) << result.message;
  EXPECT_EQ(result.residual_history.size(), 3u);
}

TEST_P(PolonskyKeerControlTest, RefusesInvalidLoadingAndOptions) {
  const Grid grid = Grid::line(16, 1e-6, Boundary::periodic);
  const Eigen::ArrayXd gap0 = field_from(grid, [](double x, double) { return x * x; });
  const auto solver = solvers::make_solver(grid, kEStar, test_options(GetParam()));
  EXPECT_THROW(solver->solve({gap0.data(), grid.size()}, Loading::force(-1.0)), InputError);
  EXPECT_THROW(solver->solve({gap0.data(), grid.size()}, Loading::mean_pressure(0.0)), InputError);
  // Periodic displacement control beyond the mean gap would need infinite pressure.
  try {
    solver->solve({gap0.data(), grid.size()}, Loading::approach(gap0.mean() * 1.01));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mean initial gap"), std::string::npos) << e.what();
  }
  EXPECT_THROW(solver->solve({gap0.data(), 3}, Loading::force(1.0)), InputError);
  solvers::SolverOptions bad = test_options(GetParam());
  bad.tolerance = 0.0;
  EXPECT_THROW(solvers::make_solver(grid, kEStar, bad), InputError);
}

INSTANTIATE_TEST_SUITE_P(Variants, PolonskyKeerControlTest, testing::all_pk_solvers(), testing::solver_type_name);

}  // namespace
}  // namespace halfspace
