// Tests of load sweeps: warm starts from the previous converged step (checked
// with a recording stand-in solver), failed steps kept and followed by a cold
// start, up-front validation, and a real Westergaard sweep that matches cold
// solves step by step with fewer iterations.
#include "halfspace/analysis/load_sweep.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/solvers/fourier_preconditioner.hpp"
#include "halfspace/solvers/polonsky_keer.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "support/analytic_solutions.hpp"
#include "support/grid_fields.hpp"

namespace halfspace::analysis {
namespace {

// A solver that records what it was asked and answers p = load everywhere,
// with the statuses it is given (converged unless told otherwise).
class RecordingSolver final : public ContactSolver {
 public:
  explicit RecordingSolver(std::size_t cells) : cells_(cells) {}

  std::string_view name() const override { return "recording"; }
  SolveResult do_solve(std::span<const double>, const Loading& loading,
                       std::span<const double> initial_pressure) override {
    loads.push_back(loading.value);
    warm.push_back(initial_pressure.empty() ? std::vector<double>{}
                                            : std::vector<double>(initial_pressure.begin(), initial_pressure.end()));
    SolveResult result;
    const std::size_t call = loads.size() - 1;
    result.status = call < statuses.size() ? statuses[call] : SolveStatus::converged;
    result.pressure = Eigen::ArrayXd::Constant(static_cast<Eigen::Index>(cells_), loading.value);
    result.gap = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(cells_));
    result.displacement = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(cells_));
    result.iterations = static_cast<int>(call) + 10;
    result.contact_fraction = 1.0;
    return result;
  }

  std::vector<SolveStatus> statuses;
  std::vector<double> loads;
  std::vector<std::vector<double>> warm;  // empty: cold start

 private:
  std::size_t cells_;
};

TEST(LoadSweepTest, WarmStartsEachStepFromThePreviousOne) {
  const Grid grid = Grid::plane(4, 3, 1.0, 1.0, Boundary::periodic);
  RecordingSolver solver(grid.size());
  const std::vector<double> gap(grid.size(), 0.0);
  const std::vector<double> loads{3.0, 1.0, 2.0};  // any order, kept as given
  std::vector<std::string> events;
  LoadSweepOptions options;
  options.on_step_start = [&](std::size_t k, std::size_t n, const Loading& loading) {
    events.push_back("start " + std::to_string(k) + "/" + std::to_string(n) + " " + std::to_string(loading.value));
  };
  options.on_step_done = [&](std::size_t k, std::size_t, const SweepStep& step) {
    events.push_back("done " + std::to_string(k) + " " + std::to_string(step.result.iterations));
  };
  const std::vector<SweepStep> steps = run_load_sweep(solver, grid, gap, ControlMode::force, loads, options);

  ASSERT_EQ(steps.size(), 3u);
  EXPECT_EQ(solver.loads, loads);
  EXPECT_TRUE(solver.warm[0].empty()) << "the first step starts cold";
  EXPECT_EQ(solver.warm[1], std::vector<double>(grid.size(), 3.0)) << "step 1 starts from step 0's pressure";
  EXPECT_EQ(solver.warm[2], std::vector<double>(grid.size(), 1.0));
  EXPECT_FALSE(steps[0].warm_started);
  EXPECT_TRUE(steps[1].warm_started);
  EXPECT_EQ(steps[2].loading.mode, ControlMode::force);
  EXPECT_EQ(steps[2].loading.value, 2.0);
  EXPECT_EQ(steps[1].statistics.cluster_sizes, (std::vector<std::int64_t>{12})) << "statistics of every step";
  EXPECT_EQ(events, (std::vector<std::string>{"start 0/3 3.000000", "done 0 10", "start 1/3 1.000000", "done 1 11",
                                              "start 2/3 2.000000", "done 2 12"}));
}

TEST(LoadSweepTest, KeepsFailedStepAndColdStartsTheNext) {
  const Grid grid = Grid::line(5, 1.0, Boundary::free);
  RecordingSolver solver(grid.size());
  solver.statuses = {SolveStatus::converged, SolveStatus::iteration_limit, SolveStatus::converged};
  const std::vector<double> gap(grid.size(), 0.0);
  const std::vector<SweepStep> steps =
      run_load_sweep(solver, grid, gap, ControlMode::mean_pressure, std::vector<double>{1.0, 2.0, 3.0});
  ASSERT_EQ(steps.size(), 3u);
  EXPECT_EQ(steps[1].result.status, SolveStatus::iteration_limit);
  EXPECT_TRUE(solver.warm[1].size() == grid.size());
  EXPECT_TRUE(solver.warm[2].empty()) << "no warm start from a step that did not converge";
  EXPECT_FALSE(steps[2].warm_started);

  // Without warm starts every step starts cold.
  RecordingSolver cold(grid.size());
  LoadSweepOptions options;
  options.warm_start = false;
  run_load_sweep(cold, grid, gap, ControlMode::force, std::vector<double>{1.0, 2.0}, options);
  EXPECT_TRUE(cold.warm[1].empty());
}

TEST(LoadSweepTest, ChecksEveryLoadBeforeTheFirstSolve) {
  const Grid grid = Grid::line(8, 1.0, Boundary::periodic);
  RecordingSolver solver(grid.size());
  std::vector<double> gap(grid.size(), 0.0);
  EXPECT_THROW(run_load_sweep(solver, grid, gap, ControlMode::force, std::vector<double>{}), InputError);
  EXPECT_THROW(run_load_sweep(solver, grid, gap, ControlMode::force, std::vector<double>{1.0, -1.0}), InputError);
  EXPECT_THROW(run_load_sweep(solver, grid, std::vector<double>(3, 0.0), ControlMode::force, std::vector<double>{1.0}),
               InputError);
  // A periodic approach at or above the mean initial gap needs infinite
  // pressure; the whole list is checked first.
  gap = {0, 1, 2, 3, 4, 5, 6, 7};  // mean 3.5
  try {
    run_load_sweep(solver, grid, gap, ControlMode::approach, std::vector<double>{1.0, 3.5});
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("approach = 3.5 m is invalid for a periodic surface"), std::string::npos)
        << error.what();
  }
  EXPECT_TRUE(solver.loads.empty()) << "nothing was solved";
}

TEST(LoadSweepTest, WestergaardSweepMatchesColdSolvesWithFewerIterations) {
  // 1D periodic wave at 5 close loads near a third of full contact: each
  // warm-started step must reproduce the cold solve, and the sweep must save
  // iterations (the contact edge moves by a few cells per step).
  const std::size_t n = 1024;
  const double wavelength = 1e-4;
  const double amplitude = 1e-6;
  const double e_star = 2e9;
  const Grid grid = Grid::line(n, wavelength / static_cast<double>(n), Boundary::periodic);
  const testing::Westergaard exact{wavelength, amplitude, e_star};
  const Eigen::ArrayXd gap0 = testing::field_from(
      grid, [&](double x, double) { return amplitude * (1.0 - std::cos(2.0 * std::numbers::pi * x / wavelength)); });
  std::vector<double> loads;
  for (const double fraction : {0.30, 0.32, 0.34, 0.36, 0.38})
    loads.push_back(fraction * exact.full_contact_pressure());

  // Fourier-preconditioned Polonsky-Keer on the single grid, whose cold
  // start is the uniform pressure. Plain PK gains nothing from the warm start
  // on this one-mode surface (its iteration count is set by the
  // conditioning, not by the starting error), and pk-multilevel's cold start
  // from coarser grids is already as good as the previous step. (pk-fourier
  // itself runs without the preconditioner on 1D grids, so it is built here
  // from its parts.)
  FftInfluenceOperator op(grid, e_star);
  solvers::FourierPreconditioner preconditioner(grid, e_star);
  solvers::PolonskyKeerOptions options;
  options.form = solvers::PolonskyKeerForm::projected;
  const std::unique_ptr<ContactSolver> solver =
      std::make_unique<solvers::PolonskyKeer>(op, options, solvers::InterfaceLaw{}, &preconditioner);
  const std::vector<SweepStep> steps =
      run_load_sweep(*solver, grid, {gap0.data(), n}, ControlMode::mean_pressure, loads);

  int warm_iterations = 0;
  int cold_iterations = 0;
  // Both solves meet the residual tolerance 1e-10; their pressures differ by
  // that order relative to the peak.
  constexpr double kAgreement = 1e-6;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const SolveResult cold = solver->solve({gap0.data(), n}, Loading::mean_pressure(loads[k]));
    ASSERT_TRUE(steps[k].result.converged()) << "step " << k << ": " << steps[k].result.message;
    const double difference = (steps[k].result.pressure - cold.pressure).abs().maxCoeff();
    EXPECT_LT(difference, kAgreement * cold.max_pressure) << "step " << k;
    EXPECT_EQ(steps[k].statistics.clusters(), 1) << "one contact per period, step " << k;
    EXPECT_DOUBLE_EQ(steps[k].statistics.contact_fraction, steps[k].result.contact_fraction);
    warm_iterations += steps[k].result.iterations;
    cold_iterations += cold.iterations;
  }
  std::printf("Westergaard sweep: %d iterations warm-started, %d cold\n", warm_iterations, cold_iterations);
  EXPECT_LT(warm_iterations, cold_iterations);
}

}  // namespace
}  // namespace halfspace::analysis
