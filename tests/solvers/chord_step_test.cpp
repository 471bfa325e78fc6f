// Polonsky-Keer's chord steps (polonsky_keer.hpp): the preconditioned
// solve of a rough contact, whose steps clip cells in most iterations of
// its moving phase, reaches the solution the paper's form (no chord steps,
// no preconditioner) reaches, under load and displacement control, and
// spends no correction product on a clipped chord.
#include <gtest/gtest.h>

#include <cstdio>

#include "halfspace/solvers/solver_factory.hpp"
#include "support/contact_checks.hpp"
#include "support/pk_solvers.hpp"
#include "support/rough_gap.hpp"

namespace halfspace::solvers {
namespace {

using testing::expect_contact_conditions;
using testing::self_affine_gap;

constexpr double kEStar = 1.0;
// Two solutions converged to residual 1e-12 differ by rounding-level amounts
// relative to the largest pressure.
constexpr double kSameSolution = 1e-8;

TEST(ChordStepTest, ReachesThePaperFormsSolutionWithAboutOneProductPerIteration) {
  const Grid grid = Grid::plane(128, 128, 1.0, 1.0, Boundary::periodic);
  const Eigen::ArrayXd gap = self_affine_gap(grid, 2);
  const Loading load = Loading::mean_pressure(0.004);  // about 8 % contact
  const SolveResult reference =
      make_solver(grid, kEStar, testing::test_options(SolverType::pk, 1e-12))->solve({gap.data(), grid.size()}, load);
  ASSERT_TRUE(reference.converged()) << reference.message;
  for (const Loading& loading : {load, Loading::approach(reference.approach)}) {
    SolverOptions options = testing::test_options(SolverType::pk_fourier, 1e-12);
    options.deflation.mode = DeflationOptions::Mode::off;
    const SolveResult chord = make_solver(grid, kEStar, options)->solve({gap.data(), grid.size()}, loading);
    ASSERT_TRUE(chord.converged()) << chord.message;
    expect_contact_conditions(chord, 1e-9 * gap.maxCoeff());
    const double difference = (chord.pressure - reference.pressure).abs().maxCoeff() / reference.max_pressure;
    std::printf("%s control: %d iterations, %d K, %d M^-1 (paper form: %d iterations, %d K), max |dp| %.1e\n",
                loading.load_controlled() ? "load" : "displacement", chord.iterations, chord.operator_applications,
                chord.preconditioner_applications, reference.iterations, reference.operator_applications, difference);
    EXPECT_LE(difference, kSameSolution);
    EXPECT_EQ(chord.preconditioner_applications, chord.iterations);
    // One K d per step, the start's K p, the exact product that confirms
    // the end and the independent check's, and a correction only where a
    // step overshoots the end of an unclipped chord (rare). Polonsky-Keer's
    // clipped steps cost a correction each: about half the steps of this
    // solve's moving phase.
    EXPECT_LE(chord.operator_applications, chord.iterations + 3 + chord.iterations / 10);
  }
}

}  // namespace
}  // namespace halfspace::solvers
