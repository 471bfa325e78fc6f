// Mixed precision (SolverOptions::precision): the step's products and the
// preconditioner in single precision; the displacement refreshed in double,
// the residual, contact decisions and the convergence check in double. The
// mixed solve must give the double solve's pressure within 10x the
// tolerance (issue 31) on periodic and free rough surfaces, its contact
// conditions must hold by a product of the pressure it returns taken here,
// apart from the solver's own fields; a tolerance single precision alone
// cannot reach must still be reached (or reported as not), and the inner
// products must really be single precision (else the option would be a
// no-op this suite could not tell from the real thing).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/fft/grid_transform.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/operators/single_precision_fft_operator.hpp"
#include "halfspace/solvers/balancing_preconditioner.hpp"
#include "halfspace/solvers/block_deflation.hpp"
#include "halfspace/solvers/layout.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/solvers/solver_options.hpp"
#include "support/pk_solvers.hpp"
#include "support/rough_gap.hpp"

namespace halfspace::solvers {
namespace {

using testing::self_affine_gap;

constexpr double kEStar = 1.0;

SolverOptions options_for(SolverType type, double tolerance, Precision precision) {
  SolverOptions options = testing::test_options(type, tolerance);
  options.precision = precision;
  return options;
}

struct Pair {
  SolveResult exact;
  SolveResult mixed;
};

Pair solve_both(const Grid& grid, const Eigen::ArrayXd& gap, const Loading& loading, SolverType type,
                double tolerance) {
  Pair pair;
  pair.exact = make_solver(grid, kEStar, options_for(type, tolerance, Precision::double_precision))
                   ->solve({gap.data(), grid.size()}, loading);
  pair.mixed = make_solver(grid, kEStar, options_for(type, tolerance, Precision::mixed))
                   ->solve({gap.data(), grid.size()}, loading);
  return pair;
}

// max |p_mixed - p_double| / max p_double.
double pressure_difference(const Pair& pair) {
  return (pair.mixed.pressure - pair.exact.pressure).abs().maxCoeff() / pair.exact.max_pressure;
}

// The contact conditions of `result`'s pressure and approach, from a gap
// computed here with a double-precision operator of its own: p >= 0, the
// gap within `gap_tolerance` of 0 where p > 0 and not below -gap_tolerance
// elsewhere.
void expect_conditions_hold(const Grid& grid, const Eigen::ArrayXd& initial_gap, const SolveResult& result,
                            double gap_tolerance) {
  FftInfluenceOperator op(grid, kEStar);
  Eigen::ArrayXd displacement(static_cast<Eigen::Index>(grid.size()));
  op.apply({result.pressure.data(), grid.size()}, {displacement.data(), grid.size()});
  const Eigen::ArrayXd gap = initial_gap + displacement - result.approach;
  double open_in_contact = 0.0;
  double overlap = 0.0;
  for (Eigen::Index i = 0; i < gap.size(); ++i) {
    ASSERT_GE(result.pressure[i], 0.0) << i;
    if (result.pressure[i] > 0.0) open_in_contact = std::max(open_in_contact, std::abs(gap[i]));
    overlap = std::max(overlap, -gap[i]);
  }
  EXPECT_LE(open_in_contact, gap_tolerance);
  EXPECT_LE(overlap, gap_tolerance);
}

TEST(MixedPrecisionTest, GivesTheDoublePressureWithinTenTimesTheTolerance) {
  constexpr double kTolerance = 1e-10;
  for (const Boundary boundary : {Boundary::periodic, Boundary::free}) {
    const Grid grid = Grid::plane(128, 128, 1.0, 1.0, boundary);
    const Eigen::ArrayXd gap = self_affine_gap(grid, 11);
    const double gap_range = gap.maxCoeff() - gap.minCoeff();
    for (const SolverType type : {SolverType::pk_fourier, SolverType::pk_multilevel, SolverType::pk}) {
      const Pair pair = solve_both(grid, gap, Loading::mean_pressure(0.004), type, kTolerance);
      ASSERT_TRUE(pair.exact.converged()) << pair.exact.message;
      ASSERT_TRUE(pair.mixed.converged()) << pair.mixed.message;
      EXPECT_LE(pair.mixed.residual, kTolerance);
      expect_conditions_hold(grid, gap, pair.mixed, 1e-8 * gap_range);
      const double difference = pressure_difference(pair);
      std::printf("%s %s: double %d iterations, mixed %d; max |dp| / max p = %.1e\n",
                  std::string(to_string(boundary)).c_str(), std::string(to_string(type)).c_str(), pair.exact.iterations,
                  pair.mixed.iterations, difference);
      EXPECT_LE(difference, 10.0 * kTolerance) << to_string(boundary) << ' ' << to_string(type);
      EXPECT_NEAR(pair.mixed.total_force, pair.exact.total_force, 1e-12 * pair.exact.total_force);
    }
  }
}

// With the block-deflation coarse correction, which runs on the float work
// vectors too (BalancingPreconditioner::apply_single), with and without
// the active-set phase before Polonsky-Keer (the phase applies it in
// double, Polonsky-Keer then in float).
TEST(MixedPrecisionTest, GivesTheDoublePressureWithBlockDeflation) {
  constexpr double kTolerance = 1e-10;
  using ActiveSet = MultilevelOptions::ActiveSet;
  for (const Boundary boundary : {Boundary::periodic, Boundary::free}) {
    for (const ActiveSet phase : {ActiveSet::off, ActiveSet::on}) {
      const Grid grid = Grid::plane(256, 256, 1.0, 1.0, boundary);
      const Eigen::ArrayXd gap = self_affine_gap(grid, 3);
      // pk-multilevel's fine solve, started from the coarse grids, settles
      // slowly enough for the correction to join.
      SolverOptions exact = options_for(SolverType::pk_multilevel, kTolerance, Precision::double_precision);
      exact.deflation.mode = DeflationOptions::Mode::on;
      exact.deflation.block = 32;
      exact.multilevel.active_set = phase;
      SolverOptions mixed = exact;
      mixed.precision = Precision::mixed;
      const Loading loading = Loading::mean_pressure(0.004);
      const Pair pair{make_solver(grid, kEStar, exact)->solve({gap.data(), grid.size()}, loading),
                      make_solver(grid, kEStar, mixed)->solve({gap.data(), grid.size()}, loading)};
      const std::string what = fmt::format("{}, active set {}", to_string(boundary), phase == ActiveSet::on);
      ASSERT_TRUE(pair.exact.converged()) << what << ": " << pair.exact.message;
      ASSERT_TRUE(pair.mixed.converged()) << what << ": " << pair.mixed.message;
      ASSERT_GT(pair.mixed.deflation.deflated_iterations, 0)
          << what << ": the correction must join for this test to mean anything";
      if (phase == ActiveSet::on) {
        ASSERT_GT(pair.mixed.active_set_outer, 0) << what;
      }
      expect_conditions_hold(grid, gap, pair.mixed, 1e-8 * (gap.maxCoeff() - gap.minCoeff()));
      const double difference = pressure_difference(pair);
      std::printf("%s: double %d iterations, mixed %d (%d deflated); max |dp| / max p = %.1e\n", what.c_str(),
                  pair.exact.iterations, pair.mixed.iterations, pair.mixed.deflation.deflated_iterations, difference);
      EXPECT_LE(difference, 10.0 * kTolerance) << what;
    }
  }
}

// The coarse correction on float vectors is the double one to float
// rounding: B r of the same rough contact set through apply_single (float
// fields, single-precision K and M^-1, the coarse solve in double) against
// apply on double operators. Neither equal (the float path would be
// unused) nor off by more than single precision's products allow; and the
// correction must change M^-1 r by far more, or the comparison would not
// see it.
TEST(MixedPrecisionTest, CoarseCorrectionOnFloatVectorsIsTheDoubleOneToFloatRounding) {
  const Grid grid = Grid::plane(128, 128, 1.0, 1.0, Boundary::periodic);
  const auto n = static_cast<Eigen::Index>(grid.size());
  const Eigen::ArrayXd gap = self_affine_gap(grid, 5);
  const double threshold = gap.minCoeff() + 0.2 * (gap.maxCoeff() - gap.minCoeff());
  const Eigen::ArrayXd in_set = (gap < threshold).cast<double>();
  const Eigen::Array<std::uint8_t, Eigen::Dynamic, 1> mask = (gap < threshold).cast<std::uint8_t>();
  const SearchSet set = SearchSet::of_mask(mask.data(), true);
  const Eigen::ArrayXd r = in_set * (gap - gap.mean());
  const std::vector<double> residuals{1.0, 0.9, 0.81};
  BlockDeflationOptions block;
  block.block = 16;

  ElasticOperators exact = serial_layout().make_operators(grid, kEStar, true, FftPlanning::estimate);
  BlockDeflation exact_deflation(grid, block);
  BalancingPreconditioner exact_b(*exact.op, *exact.fourier, exact_deflation);
  ElasticOperators mixed = serial_layout().make_mixed_operators(grid, kEStar, true, FftPlanning::estimate);
  ASSERT_TRUE(mixed.single.precondition);
  BlockDeflation mixed_deflation(grid, block);
  BalancingPreconditioner mixed_b(*mixed.inner, *mixed.fourier, mixed_deflation, mixed.single);
  for (BalancingPreconditioner* b : {&exact_b, &mixed_b}) {
    b->begin_solve();
    b->observe_step({0.0, in_set.sum()});
    b->observe_step({0.0, in_set.sum()});
    ASSERT_TRUE(b->adapt(set, residuals)) << "the correction must apply";
  }
  Eigen::ArrayXd out(n);
  exact_b.apply({r.data(), grid.size()}, {out.data(), grid.size()});
  Eigen::ArrayXf single_out = r.cast<float>();
  mixed_b.apply_single({single_out.data(), grid.size()}, {single_out.data(), grid.size()});
  Eigen::ArrayXd plain(n);
  exact.fourier->apply({r.data(), grid.size()}, {plain.data(), grid.size()});
  // M^-1 alone on the set, mean-free there, for the size of the correction.
  const double plain_mean = (in_set * plain).sum() / in_set.sum();
  plain = in_set * (plain - plain_mean);

  const double scale = out.abs().maxCoeff();
  const double error = (single_out.cast<double>() - out).abs().maxCoeff() / scale;
  const double correction = (out - plain).abs().maxCoeff() / scale;
  std::printf("float against double B r: %.1e of max |B r|; the correction changes M^-1 r by %.2f\n", error,
              correction);
  EXPECT_GT(error, 0.0) << "the float path was not taken";
  EXPECT_LT(error, 1e-4);
  EXPECT_GT(correction, 1e-2);
  // Off the set the correction is zero in both.
  for (Eigen::Index i = 0; i < n; ++i) {
    if (in_set[i] == 0.0) {
      ASSERT_EQ(single_out[i], 0.0F) << i;
    }
  }
  SolveResult report;
  mixed_b.report(report);
  EXPECT_EQ(report.deflation.deflated_iterations, 1);
}

// Displacement control too: the approach is given, the load follows.
TEST(MixedPrecisionTest, GivesTheDoublePressureUnderDisplacementControl) {
  constexpr double kTolerance = 1e-10;
  const Grid grid = Grid::plane(96, 96, 1.0, 1.0, Boundary::periodic);
  const Eigen::ArrayXd gap = self_affine_gap(grid, 7);
  const double approach = gap.minCoeff() + 0.05 * (gap.maxCoeff() - gap.minCoeff());
  const Pair pair = solve_both(grid, gap, Loading::approach(approach), SolverType::pk_fourier, kTolerance);
  ASSERT_TRUE(pair.exact.converged()) << pair.exact.message;
  ASSERT_TRUE(pair.mixed.converged()) << pair.mixed.message;
  expect_conditions_hold(grid, gap, pair.mixed, 1e-8 * (gap.maxCoeff() - gap.minCoeff()));
  EXPECT_LE(pressure_difference(pair), 10.0 * kTolerance);
}

// 1e-13 lies far below what single-precision products resolve (float's
// epsilon is 6e-8): a solve run wholly in float would stall near 1e-7. The
// double products carry the mixed solve there, or it reports that they did
// not; "converged" must hold in double either way.
TEST(MixedPrecisionTest, ReachesAToleranceBeyondSinglePrecisionThroughTheDoubleProducts) {
  constexpr double kTolerance = 1e-13;
  for (const Boundary boundary : {Boundary::periodic, Boundary::free}) {
    const Grid grid = Grid::plane(64, 64, 1.0, 1.0, boundary);
    const Eigen::ArrayXd gap = self_affine_gap(grid, 5);
    const Pair pair = solve_both(grid, gap, Loading::mean_pressure(0.006), SolverType::pk_fourier, kTolerance);
    ASSERT_TRUE(pair.exact.converged()) << pair.exact.message;
    ASSERT_TRUE(pair.mixed.converged()) << pair.mixed.message;
    EXPECT_LE(pair.mixed.residual, kTolerance);
    expect_conditions_hold(grid, gap, pair.mixed, 1e-10 * (gap.maxCoeff() - gap.minCoeff()));
    EXPECT_LE(pressure_difference(pair), 10.0 * kTolerance) << to_string(boundary);
  }
}

// A limit too small to get there: reported as the iteration limit, never as
// converged.
TEST(MixedPrecisionTest, ReportsNonConvergenceInsteadOfHidingIt) {
  const Grid grid = Grid::plane(64, 64, 1.0, 1.0, Boundary::periodic);
  const Eigen::ArrayXd gap = self_affine_gap(grid, 5);
  SolverOptions options = options_for(SolverType::pk_fourier, 1e-13, Precision::mixed);
  options.max_iterations = 3;
  const SolveResult result =
      make_solver(grid, kEStar, options)->solve({gap.data(), grid.size()}, Loading::mean_pressure(0.006));
  EXPECT_FALSE(result.converged());
  EXPECT_EQ(result.status, SolveStatus::iteration_limit);
  EXPECT_GT(result.residual, 1e-13);
}

// The inner product is K in single precision: off the double product by
// float rounding (neither exact, which would make the option a no-op, nor
// wrong by more than the transform's rounding).
TEST(MixedPrecisionTest, InnerProductIsSinglePrecision) {
  const Grid grid = Grid::plane(64, 48, 1.0, 1.0, Boundary::periodic);
  const Eigen::ArrayXd pressure = self_affine_gap(grid, 3) + 1.0;
  FftInfluenceOperator exact(grid, kEStar);
  const std::span<std::complex<double>> workspace = exact.transforms()->workspace();
  SinglePrecisionFftOperator single(exact, make_single_grid_transform(grid, FftPlanning::estimate, workspace));
  Eigen::ArrayXd u_exact(static_cast<Eigen::Index>(grid.size()));
  Eigen::ArrayXd u_single(static_cast<Eigen::Index>(grid.size()));
  exact.apply({pressure.data(), grid.size()}, {u_exact.data(), grid.size()});
  single.apply({pressure.data(), grid.size()}, {u_single.data(), grid.size()});
  const double error = (u_single - u_exact).abs().maxCoeff() / u_exact.abs().maxCoeff();
  EXPECT_GT(error, 1e-12) << "the product is not single precision";
  EXPECT_LT(error, 1e-5);
  EXPECT_DOUBLE_EQ(single.self_influence(), exact.self_influence());
  // Free grids need the padded transform: refused with a message.
  const Grid free = Grid::plane(64, 48, 1.0, 1.0, Boundary::free);
  const FftInfluenceOperator free_exact(free, kEStar);
  EXPECT_THROW(
      SinglePrecisionFftOperator(free_exact, make_single_grid_transform(free, FftPlanning::estimate, workspace)),
      InputError);
}

// The option named in every refusal: an unknown value, the dense solvers,
// adhesion, and a layout without single-precision operators (a solve on
// several processes, tests/mpi for the program).
void expect_refused(const std::function<void()>& action, const std::string& wanted) {
  try {
    action();
    ADD_FAILURE() << "no error; wanted " << wanted;
  } catch (const SolverOptionError& error) {
    EXPECT_EQ(error.option(), "precision");
    EXPECT_NE(std::string(error.what()).find(wanted), std::string::npos) << error.what();
  }
}

// The serial operators in double only, as a layout that has no
// single-precision ones.
class DoubleOnlyLayout final : public Layout {
 public:
  std::unique_ptr<operators::SpectralTransforms> make_transforms(
      const Grid& grid, FftPlanning planning, const operators::TransformsShape& shape) const override {
    return serial_layout().make_transforms(grid, planning, shape);
  }
  RowSlab rows(const Grid& grid) const override { return serial_layout().rows(grid); }
  const linalg::Communicator& communicator() const override { return serial_layout().communicator(); }
};

TEST(MixedPrecisionTest, OptionIsParsedAndRefusedWhereItDoesNotApply) {
  EXPECT_EQ(parse_precision("double"), Precision::double_precision);
  EXPECT_EQ(parse_precision("mixed"), Precision::mixed);
  EXPECT_EQ(to_string(Precision::mixed), "mixed");
  EXPECT_EQ(to_string(Precision::double_precision), "double");
  expect_refused([] { parse_precision("half"); }, "one of double, mixed");
  for (const SolverType dense : {SolverType::lemke, SolverType::lcpquad}) {
    SolverOptions options;
    options.type = dense;
    options.precision = Precision::mixed;
    expect_refused([&] { options.validate(); }, "dense path");
  }
  SolverOptions adhesive;
  adhesive.precision = Precision::mixed;
  adhesive.adhesion = SolverOptions::Adhesion{AdhesionLaw::maugis_dugdale(0.05, 1e-6), 1e-6, true};
  expect_refused([&] { adhesive.validate(); }, "adhesive solver");
  SolverOptions fine;
  fine.precision = Precision::mixed;
  EXPECT_NO_THROW(fine.validate());
  const Grid grid = Grid::plane(32, 32, 1.0, 1.0, Boundary::periodic);
  const DoubleOnlyLayout double_only;
  for (const SolverType type : {SolverType::pk, SolverType::pk_fourier, SolverType::pk_multilevel}) {
    expect_refused([&] { make_solver(grid, kEStar, options_for(type, 1e-8, Precision::mixed), double_only); },
                   "more than one process");
  }
}

}  // namespace
}  // namespace halfspace::solvers
