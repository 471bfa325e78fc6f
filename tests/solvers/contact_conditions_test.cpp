// "Converged means the conditions hold": on random rough surfaces, loads and
// both boundaries, every solver type (with and without a hardness cap where
// it takes one) is checked by check_contact_conditions on an operator of its
// own, apart from the solver's residual; and the check fails on a result
// that breaks a condition.
#include "halfspace/solvers/contact_conditions.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <limits>
#include <optional>
#include <string>

#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "support/pk_solvers.hpp"
#include "support/rough_gap.hpp"

namespace halfspace {
namespace {

using solvers::SolverType;

constexpr double kEStar = 1e11;    // Pa
constexpr double kSpacing = 1e-6;  // m
constexpr double kSolveTolerance = 1e-10;

struct Problem {
  Grid grid;
  Eigen::ArrayXd gap;
  Loading loading;
  std::optional<double> hardness;
};

solvers::ContactConditionReport check(const Problem& run, const SolveResult& result) {
  FftInfluenceOperator op(run.grid, kEStar);
  Eigen::ArrayXd scratch(static_cast<Eigen::Index>(run.grid.size()));
  const solvers::PressureBounds bounds =
      run.hardness ? solvers::PressureBounds::capped_at(*run.hardness) : solvers::PressureBounds{};
  return solvers::check_contact_conditions(op, {run.gap.data(), run.grid.size()}, run.loading, bounds, result,
                                           solvers::ContactConditionTolerances::for_solver_tolerance(kSolveTolerance),
                                           {scratch.data(), run.grid.size()});
}

TEST(ContactConditionsTest, WheneverASolverSaysConvergedTheConditionsHold) {
  int checked = 0;
  for (const Boundary boundary : {Boundary::periodic, Boundary::free}) {
    const Grid grid = Grid::plane(24, 24, kSpacing, kSpacing, boundary);
    for (const std::uint64_t seed : {3u, 29u}) {
      const Eigen::ArrayXd gap = 10.0 * testing::self_affine_gap(grid, seed);
      for (const double mean_pressure : {3e7, 3e8, 1.5e9}) {
        for (const std::optional<double> hardness : {std::optional<double>{}, std::optional<double>{2e9}}) {
          for (const SolverType type : solvers::solver_types()) {
            if (type == SolverType::lemke && hardness) continue;  // Lemke takes no cap (refused)
            solvers::SolverOptions options = testing::test_options(type, kSolveTolerance);
            options.interface_law.hardness = hardness;
            const Problem run{grid, gap, Loading::mean_pressure(mean_pressure), hardness};
            const SolveResult result =
                solvers::make_solver(grid, kEStar, options)->solve({gap.data(), grid.size()}, run.loading);
            if (!result.converged()) {
              std::printf("%s, seed %u, %g Pa: %s (%s)\n", std::string(to_string(type)).c_str(),
                          static_cast<unsigned>(seed), mean_pressure, std::string(to_string(result.status)).c_str(),
                          result.message.c_str());
              continue;
            }
            const solvers::ContactConditionReport report = check(run, result);
            ++checked;
            EXPECT_TRUE(report.holds) << to_string(type) << ", " << (boundary == Boundary::free ? "free" : "periodic")
                                      << ", seed " << seed << ", " << mean_pressure << " Pa"
                                      << (hardness ? ", capped" : "") << ": " << report.violation;
          }
        }
      }
    }
  }
  std::printf("%d converged solves checked\n", checked);
  EXPECT_GT(checked, 100);
}

TEST(ContactConditionsTest, BrokenResultsFailTheCheck) {
  const Grid grid = Grid::plane(24, 24, kSpacing, kSpacing, Boundary::free);
  const Eigen::ArrayXd gap = 10.0 * testing::self_affine_gap(grid, 5);
  const Problem run{grid, gap, Loading::mean_pressure(3e8), std::nullopt};
  const SolveResult good = solvers::make_solver(grid, kEStar, testing::test_options(SolverType::pk, kSolveTolerance))
                               ->solve({gap.data(), grid.size()}, run.loading);
  ASSERT_TRUE(good.converged()) << good.message;
  ASSERT_TRUE(check(run, good).holds) << check(run, good).violation;

  SolveResult moved = good;  // the approach off by a tenth of the gap range
  moved.approach += 0.1 * (gap.maxCoeff() - gap.minCoeff());
  EXPECT_NE(check(run, moved).violation.find("contact conditions fail"), std::string::npos);

  SolveResult light = good;  // a tenth of the pressure: the force and K p both wrong
  light.pressure *= 0.9;
  EXPECT_FALSE(check(run, light).holds);

  SolveResult nan = good;
  nan.pressure[7] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(check(run, nan).violation.find("non-finite"), std::string::npos);
}

}  // namespace
}  // namespace halfspace
