// The typed front door: solver names parse and print back, and validate()
// refuses every broken rule with the option named, so that front ends need
// no rules of their own.
#include "halfspace/solvers/solver_options.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>

#include "halfspace/solvers/adhesive_contact_solver.hpp"
#include "halfspace/solvers/solver_factory.hpp"

namespace halfspace::solvers {
namespace {

// Runs `call`, which must throw SolverOptionError for `option`; returns it.
SolverOptionError refusal(const std::function<void()>& call, const std::string& option) {
  try {
    call();
  } catch (const SolverOptionError& error) {
    EXPECT_EQ(error.option(), option) << error.what();
    EXPECT_EQ(std::string(error.what()).rfind(option + " = ", 0), 0u) << error.what();
    return error;
  }
  ADD_FAILURE() << "expected SolverOptionError for " << option;
  return SolverOptionError(option, "", "");
}

// Options of `type` changed by `change`, refused by validate() naming `option`.
SolverOptionError refused(SolverType type, const std::function<void(SolverOptions&)>& change,
                          const std::string& option) {
  SolverOptions options;
  options.type = type;
  change(options);
  return refusal([&] { options.validate(); }, option);
}

TEST(SolverOptionsTest, NamesRoundTripAndUnknownNamesListTheKnownOnes) {
  ASSERT_EQ(solver_types().size(), 5u);
  for (const SolverType type : solver_types()) EXPECT_EQ(parse_solver_type(to_string(type)), type);
  EXPECT_EQ(to_string(SolverType::pk_multilevel), "pk-multilevel");
  EXPECT_EQ(to_string(SolverType::lcpquad), "lcpquad");
  const SolverOptionError error = refusal([] { parse_solver_type("magic"); }, "solver");
  EXPECT_EQ(error.value(), "magic");
  for (const char* name : {"pk-multilevel", "pk-fourier", "pk", "lemke", "lcpquad"}) {
    EXPECT_NE(error.rule().find(name), std::string::npos) << error.rule();
  }
  refusal([] { parse_solver_type("PK"); }, "solver");
  refusal([] { parse_solver_type(""); }, "solver");
}

TEST(SolverOptionsTest, DefaultsAreValidAndAreTheProgramsDefaults) {
  const SolverOptions options;
  EXPECT_NO_THROW(options.validate());
  EXPECT_EQ(options.type, SolverType::pk_multilevel);
  EXPECT_EQ(options.tolerance, 1e-10);
  EXPECT_EQ(options.iteration_limit(), 10000);
  EXPECT_EQ(options.fft_planning, FftPlanning::measure);
  EXPECT_EQ(options.deflation.mode, DeflationOptions::Mode::automatic);
  EXPECT_EQ(options.deflation.block, 32u);
  for (const SolverType type : solver_types()) {
    SolverOptions typed;
    typed.type = type;
    EXPECT_NO_THROW(typed.validate()) << to_string(type);
  }
}

TEST(SolverOptionsTest, RefusesEachBrokenRuleNamingTheOption) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const double tolerance : {0.0, -1e-3, 1.0, 2.0, nan, std::numeric_limits<double>::infinity()}) {
    refused(
        SolverType::pk, [&](SolverOptions& o) { o.tolerance = tolerance; }, "tolerance");
  }
  for (const int limit : {0, -5}) {
    refused(
        SolverType::pk_fourier, [&](SolverOptions& o) { o.max_iterations = limit; }, "max_iterations");
  }
  const SolverOptionError lcpquad = refused(
      SolverType::lcpquad, [](SolverOptions& o) { o.max_iterations = 5; }, "max_iterations");
  EXPECT_NE(lcpquad.rule().find("does not apply to solver 'lcpquad'"), std::string::npos) << lcpquad.what();
  SolverOptions lemke;
  lemke.type = SolverType::lemke;
  lemke.max_iterations = 5;
  EXPECT_NO_THROW(lemke.validate());

  refused(
      SolverType::pk_multilevel, [](SolverOptions& o) { o.multilevel.coarse_tolerance = 1.0; },
      "multilevel.coarse_tolerance");
  refused(
      SolverType::pk_multilevel, [](SolverOptions& o) { o.multilevel.min_cells_per_axis = 1; },
      "multilevel.min_cells_per_axis");
  refused(
      SolverType::pk_multilevel, [](SolverOptions& o) { o.multilevel.warm_start_max_load_ratio = 0.9; },
      "multilevel.warm_start_max_load_ratio");

  for (const std::size_t block : {std::size_t{0}, std::size_t{257}}) {
    refused(
        SolverType::pk_fourier, [&](SolverOptions& o) { o.deflation.block = block; }, "deflation.block");
  }
  refused(
      SolverType::pk_fourier, [](SolverOptions& o) { o.deflation.max_pair_terms = 0.0; }, "deflation.max_pair_terms");
  refused(
      SolverType::pk_fourier, [](SolverOptions& o) { o.deflation.coarse_tolerance = 0.0; },
      "deflation.coarse_tolerance");
  refused(
      SolverType::pk_fourier, [](SolverOptions& o) { o.deflation.coarse_max_iterations = 0; },
      "deflation.coarse_max_iterations");
}

TEST(SolverOptionsTest, DeflationIsOnOnlyWhereItApplies) {
  for (const SolverType type : {SolverType::pk, SolverType::lemke, SolverType::lcpquad}) {
    const SolverOptionError error = refused(
        type, [](SolverOptions& o) { o.deflation.mode = DeflationOptions::Mode::on; }, "deflation.mode");
    EXPECT_NE(error.rule().find("deflation needs pk-fourier or pk-multilevel"), std::string::npos) << error.what();
    // Off or automatic is no request, so nothing to refuse.
    SolverOptions quiet;
    quiet.type = type;
    quiet.deflation.mode = DeflationOptions::Mode::off;
    EXPECT_NO_THROW(quiet.validate());
  }
  SolverOptions on;
  on.type = SolverType::pk_fourier;
  on.deflation.mode = DeflationOptions::Mode::on;
  EXPECT_NO_THROW(on.validate(Grid::plane(96, 128, 1.0, 1.0, Boundary::periodic)));
  const SolverOptionError error =
      refusal([&] { on.validate(Grid::plane(96, 80, 1.0, 1.0, Boundary::free)); }, "deflation.block");
  EXPECT_NE(error.rule().find("must divide nx and ny"), std::string::npos) << error.what();
  refusal([&] { on.validate(Grid::plane(128, 64, 1.0, 1.0, Boundary::free)); }, "deflation.block");  // 2 blocks
  EXPECT_THROW(on.validate(Grid::line(1024, 1.0, Boundary::periodic)), InputError);
  // The grid rule concerns deflation that is on only.
  on.deflation.mode = DeflationOptions::Mode::automatic;
  EXPECT_NO_THROW(on.validate(Grid::line(1024, 1.0, Boundary::periodic)));
}

TEST(SolverOptionsTest, TheFactoryRefusesWhatValidateRefuses) {
  const Grid grid = Grid::plane(64, 64, 1e-6, 1e-6, Boundary::periodic);
  SolverOptions options;
  options.fft_planning = FftPlanning::estimate;
  options.tolerance = 0.0;
  refusal([&] { make_solver(grid, 1e9, options); }, "tolerance");
  options.tolerance = 1e-8;
  options.type = SolverType::lcpquad;
  options.max_iterations = 3;
  refusal([&] { make_solver(grid, 1e9, options); }, "max_iterations");
  options.max_iterations.reset();
  options.type = SolverType::pk_fourier;
  options.deflation.mode = DeflationOptions::Mode::on;
  options.deflation.block = 48;
  refusal([&] { make_solver(grid, 1e9, options); }, "deflation.block");
}

// The progress line estimates how far a solve has come from its residual
// against the tolerance of the solver that runs (apps/progress.cpp): with
// adhesion that is the adhesive solver's own (default 1e-6, a relative
// pressure error), not the elastic 1e-10, and make_solver builds the
// adhesive solver with it.
TEST(SolverOptionsTest, SolverToleranceIsTheAdhesiveSolversWithAdhesion) {
  const Grid grid = Grid::plane(16, 16, 1e-6, 1e-6, Boundary::periodic);
  SolverOptions options;
  EXPECT_EQ(options.solver_tolerance(), options.tolerance);
  options.adhesion = SolverOptions::Adhesion{AdhesionLaw::maugis_dugdale(0.05, 1e-6)};
  EXPECT_EQ(options.solver_tolerance(), 1e-6);
  EXPECT_NE(options.solver_tolerance(), options.tolerance);
  options.adhesion->tolerance = 3e-5;
  EXPECT_EQ(options.solver_tolerance(), 3e-5);
  const std::unique_ptr<ContactSolver> solver = make_solver(grid, 1e9, options);
  const auto* adhesive = dynamic_cast<const AdhesiveContactSolver*>(solver.get());
  ASSERT_NE(adhesive, nullptr) << solver->name();
  EXPECT_EQ(adhesive->options().tolerance, options.solver_tolerance());
  EXPECT_TRUE(adhesive->options().precondition) << "the default minimiser is adhesive-pcg";
  EXPECT_EQ(solver->name(), "adhesive-pcg");
}

// The rules of a coated half-space live in validate(grid, coating), which
// make_solver and the program both call: no dense solver, a grid the coated
// operator supports, no adhesion.
TEST(SolverOptionsTest, CoatedHalfSpaceRefusesTheDenseSolversAndAdhesion) {
  const Grid grid = Grid::plane(16, 16, 1e-6, 1e-6, Boundary::free);
  const LayeredMaterial coating{4e-6, {3e9, 0.35}, {2.1e11, 0.29}};
  for (const SolverType type : {SolverType::pk, SolverType::pk_fourier, SolverType::pk_multilevel}) {
    SolverOptions options;
    options.type = type;
    EXPECT_NO_THROW(options.validate(grid, coating)) << to_string(type);
  }
  for (const SolverType type : {SolverType::lemke, SolverType::lcpquad}) {
    SolverOptions options;
    options.type = type;
    const SolverOptionError error = refusal([&] { options.validate(grid, coating); }, "type");
    EXPECT_EQ(error.value(), to_string(type));
    EXPECT_NE(error.rule().find("allowed are pk, pk-fourier and pk-multilevel"), std::string::npos) << error.rule();
    // Homogeneous: the same options are valid.
    EXPECT_NO_THROW(options.validate(grid)) << to_string(type);
  }
  SolverOptions adhesive;
  adhesive.adhesion = SolverOptions::Adhesion{AdhesionLaw::maugis_dugdale(0.05, 1e-6)};
  EXPECT_NO_THROW(adhesive.validate(grid));
  // Adhesion below a coating: the adhesive solver runs on its operator.
  EXPECT_NO_THROW(adhesive.validate(grid, coating));
  // Every grid is supported below a coating, free 1D ones included.
  const SolverOptions pk;
  EXPECT_NO_THROW(pk.validate(Grid::line(16, 1e-6, Boundary::free), coating));
  EXPECT_NO_THROW(pk.validate(Grid::line(16, 1e-6, Boundary::periodic), coating));
}

}  // namespace
}  // namespace halfspace::solvers
