// The problem builder (problem.hpp): the rules the program and Python share,
// each message naming the option as the front end spells it.
#include "halfspace/problem.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/material.hpp"
#include "support/flag_spelling.hpp"

namespace halfspace {
namespace {

using Flags = testing::FlagSpelling;  // a program's spelling ("--name value")
using testing::refusal;

ProblemOptions sphere_problem() {
  ProblemOptions options;
  options.e_star = 1e9;
  options.force = std::vector<double>{0.1};
  return options;
}

bool starts_with(const std::string& text, const std::string& start) {
  return text.rfind(start, 0) == 0;
}

TEST(ProblemTest, BodyIsECompositeOrBothBodiesOrACoating) {
  EXPECT_EQ(make_problem(sphere_problem()).e_star, 1e9);
  ProblemOptions pair = sphere_problem();
  pair.e_star.reset();
  pair.e1 = 2e11;
  pair.nu1 = 0.3;
  pair.e2 = std::numeric_limits<double>::infinity();  // rigid body 2: E* = E1 / (1 - nu1^2)
  pair.nu2 = 0.3;
  EXPECT_DOUBLE_EQ(make_problem(pair).e_star, 2e11 / (1.0 - 0.09));
  pair.nu2.reset();
  EXPECT_TRUE(starts_with(refusal([&] { make_problem(pair, Flags{}); }),
                          "incomplete material: missing --nu2 (give all of --E1, --nu1, --E2, --nu2, or --e_star)"));
  pair.e_star = 1e9;
  EXPECT_TRUE(
      starts_with(refusal([&] { make_problem(pair, Flags{}); }), "--e_star cannot be combined with --E1, --nu1, --E2"));

  ProblemOptions coated = sphere_problem();
  coated.e_star.reset();
  coated.layer_thickness = 1e-6;
  coated.layer_e = 3e9;
  coated.layer_nu = 0.35;
  coated.substrate_e = 2e11;
  coated.substrate_nu = 0.3;
  const Problem problem = make_problem(coated);
  ASSERT_TRUE(problem.coating.has_value());
  EXPECT_DOUBLE_EQ(problem.e_star, 3e9 / (1.0 - 0.35 * 0.35));  // the layer's plane-strain modulus
  coated.layer_thickness = -1.0;
  EXPECT_EQ(refusal([&] { make_problem(coated, Flags{}); }), "--layer_thickness -1 is invalid: must be positive (m)");
}

TEST(ProblemTest, AdhesionMakesItsLawAndSignsTheLoads) {
  ProblemOptions options = sphere_problem();
  options.force = std::vector<double>{-1e-3, 2e-3};
  EXPECT_EQ(refusal([&] { make_problem(options); }),
            "force=-0.001,0.002 is invalid: every value must be positive (N in 2D, N/m in 1D); value 1 is -0.001");
  options.adhesion = "md";
  options.work_of_adhesion = 0.05;
  EXPECT_EQ(refusal([&] { make_problem(options, Flags{}); }),
            "--adhesion md needs --adhesion_range H0 (m) or --adhesion_stress SIGMA0 (Pa)");
  options.adhesion_stress = 1e6;  // h0 = w / sigma0 = 5e-8 m
  const Problem problem = make_problem(options);
  ASSERT_TRUE(problem.solver.adhesion.has_value());
  EXPECT_DOUBLE_EQ(problem.solver.adhesion->law.range, 0.05 / 1e6);
  EXPECT_EQ(problem.load_values, (std::vector<double>{-1e-3, 2e-3}));  // a pull is a load
  options.adhesion_stress = 1e13;                                      // h0 = 5e-15 m: below the range of lengths
  EXPECT_TRUE(starts_with(refusal([&] { make_problem(options, Flags{}); }),
                          "--adhesion_stress 1e+13 Pa is invalid with the work of adhesion 0.05 J/m^2"));
  options.adhesion_stress.reset();
  ProblemOptions unused = sphere_problem();
  unused.work_of_adhesion = 0.05;
  EXPECT_EQ(refusal([&] { make_problem(unused); }), "work_of_adhesion needs adhesion md|exponential");
}

TEST(ProblemTest, SolverRulesAreNamedByTheProblemsOption) {
  ProblemOptions options = sphere_problem();
  options.tol = 2.0;  // SolverOptions' "tolerance"
  EXPECT_EQ(refusal([&] { make_problem(options); }), "tol=2 is invalid: the tolerance must be in (0, 1)");
  options.tol.reset();
  options.deflation_block = -1;
  EXPECT_EQ(refusal([&] { make_problem(options); }), "deflation_block=-1 is invalid: give 0 (off) or a block size");
  options.deflation_block.reset();
  options.threads = 0;
  EXPECT_TRUE(starts_with(refusal([&] { make_problem(options); }), "threads=0 is invalid: allowed range is 1 to"));
}

TEST(ProblemTest, ActiveSetIsOnOffOrAutomatic) {
  using Mode = solvers::MultilevelOptions::ActiveSet;
  ProblemOptions options = sphere_problem();
  EXPECT_EQ(make_problem(options).solver.multilevel.active_set, Mode::automatic);
  for (const auto& [name, mode] : std::array<std::pair<const char*, Mode>, 3>{
           {{"on", Mode::on}, {"off", Mode::off}, {"automatic", Mode::automatic}}}) {
    options.active_set = name;
    EXPECT_EQ(make_problem(options).solver.multilevel.active_set, mode) << name;
  }
  options.active_set = "yes";
  EXPECT_EQ(refusal([&] { make_problem(options); }),
            "active_set=yes is invalid: allowed values are on, off, automatic");
  EXPECT_EQ(refusal([&] { make_problem(options, Flags{}); }),
            "--active_set yes is invalid: allowed values are on, off, automatic");
}

TEST(ProblemTest, EachLoadIsCheckedOnTheGridAgainstTheHardnessCap) {
  const Grid grid = Grid::plane(16, 16, 1e-6, 1e-6, Boundary::periodic);  // 2.56e-10 m^2
  ProblemOptions options = sphere_problem();
  options.hardness = 1e9;  // carries at most 0.256 N on this grid
  options.force = std::vector<double>{0.1, 0.3};
  const Problem problem = make_problem(options, Flags{});
  const std::string message = refusal([&] { problem.check_grid(grid, Flags{}); });
  EXPECT_TRUE(starts_with(message, "--force 0.1,0.3 (value 2: 0.3): the load is infeasible with hardness = 1e+09 Pa"))
      << message;
  options.force = std::vector<double>{1e300};  // a mean pressure beyond the range of pressures
  EXPECT_NE(refusal([&] {
              make_problem(options).check_grid(grid);
            }).find("the mean pressure force / area = inf Pa is invalid"),
            std::string::npos);
}

TEST(ProblemTest, PeriodicApproachesStayBelowTheMeanGap) {
  const Grid grid = Grid::line(4, 1e-6, Boundary::periodic);
  const std::vector<double> heights{0.0, 1e-6, 0.0, 1e-6};  // mean initial gap 5e-7 m
  ProblemOptions options = sphere_problem();
  options.force.reset();
  options.approach = std::vector<double>{1e-7, 6e-7};
  const Problem problem = make_problem(options);
  EXPECT_TRUE(starts_with(refusal([&] { problem.check_heights(grid, heights); }),
                          "approach=1e-07,6e-07 (value 2: 6e-07 m) is invalid for a periodic surface"));
}

// A padded map spreads a mean pressure over the padding too: refused with a
// mean-pressure load, taken with a force.
TEST(ProblemTest, APaddedMapTakesAForceButNoMeanPressure) {
  EXPECT_NO_THROW(make_problem(sphere_problem()).check_padding(2.0));
  ProblemOptions options = sphere_problem();
  options.force.reset();
  options.mean_pressure = std::vector<double>{1e5};
  const Problem problem = make_problem(options);
  EXPECT_NO_THROW(problem.check_padding(1.0));
  EXPECT_TRUE(starts_with(refusal([&] { problem.check_padding(2.0); }),
                          "pad=2 cannot be combined with mean_pressure: the mean pressure would be taken over the "
                          "padded area; give force instead"));
}

// Both steel bodies, a force and friction with one tangential force step.
ProblemOptions friction_problem() {
  ProblemOptions options;
  options.e1 = 2.1e11;
  options.nu1 = 0.3;
  options.e2 = 2.1e11;
  options.nu2 = 0.3;
  options.force = std::vector<double>{10.0};
  options.friction = 0.3;
  options.tangential_force = std::vector<std::array<double, 2>>{{1.0, 0.0}, {2.0, 0.5}};
  return options;
}

TEST(ProblemTest, FrictionIsMadeFromItsOptions) {
  ProblemOptions options = friction_problem();
  options.tangential_tol = 1e-8;
  options.tangential_max_iter = 50;
  options.tangential_release_period = 3;
  options.tangential_coarse_start = "on";
  options.coupling = "off";
  options.normal_load_steps = 3;
  const Problem problem = make_problem(options);
  ASSERT_TRUE(problem.friction.has_value() && problem.pair.has_value());
  EXPECT_EQ(problem.friction->tangential.friction_coefficient, 0.3);
  ASSERT_EQ(problem.friction->history.size(), 2u);
  EXPECT_EQ(problem.friction->history[1].control, TangentialControl::force);
  EXPECT_EQ(problem.friction->history[1].x, 2.0);
  EXPECT_EQ(problem.friction->history[1].y, 0.5);
  EXPECT_EQ(problem.friction->tangential.tolerance, 1e-8);
  EXPECT_EQ(problem.friction->tangential.max_iterations, 50);
  EXPECT_EQ(problem.friction->tangential.release_period, 3);
  EXPECT_EQ(problem.friction->tangential.coarse_start, TangentialCoarseStart::on);
  EXPECT_FALSE(problem.friction->coupling);
  EXPECT_EQ(problem.friction->normal_load_steps, 3);
  EXPECT_TRUE(problem.pair->similar());
  options.tangential_force.reset();
  options.sliding = std::vector<double>{1.0, -1.0};
  const Problem sliding = make_problem(options);
  ASSERT_TRUE(sliding.friction->sliding_direction.has_value());
  EXPECT_EQ((*sliding.friction->sliding_direction)[1], -1.0);
  EXPECT_FALSE(make_problem(sphere_problem()).friction.has_value());
}

// A coated half-space with friction: the pair is the coated body against the
// rigid surface; periodic grids are accepted, free ones refused by check_grid.
TEST(ProblemTest, FrictionOnACoatingNeedsALayerThinAgainstAFreeGrid) {
  ProblemOptions options = friction_problem();
  options.e1.reset();
  options.nu1.reset();
  options.e2.reset();
  options.nu2.reset();
  options.layer_thickness = 1e-6;
  options.layer_e = 4.2e11;
  options.layer_nu = 0.22;
  options.substrate_e = 2.1e11;
  options.substrate_nu = 0.3;
  const Problem problem = make_problem(options, Flags{});
  ASSERT_TRUE(problem.pair.has_value() && problem.pair->coating().has_value());
  EXPECT_EQ(problem.pair->coating()->thickness, 1e-6);
  EXPECT_EQ(std::get<LayeredMaterial>(problem.pair->half_space()).layer.youngs_modulus, 4.2e11);
  EXPECT_FALSE(problem.pair->similar());
  problem.check_grid(Grid::plane(32, 32, 1e-5, 1e-5, Boundary::periodic), Flags{});
  problem.check_grid(Grid::plane(32, 32, 1e-5, 1e-5, Boundary::free), Flags{});
  EXPECT_TRUE(starts_with(
      refusal([&] { problem.check_grid(Grid::plane(32, 32, 1e-7, 1e-7, Boundary::free), Flags{}); }),
      "the coated half-space (--layer_thickness, --layer_E, --layer_nu, --substrate_E, --substrate_nu) cannot be "
      "combined with friction here: a coated half-space's tangential compliance on the free 32x32 grid needs a layer "
      "thin against the domain"));
}

TEST(ProblemTest, FrictionRulesNameTheOption) {
  const auto refused = [](const ProblemOptions& options) { return refusal([&] { make_problem(options, Flags{}); }); };
  ProblemOptions options = friction_problem();
  options.friction.reset();
  EXPECT_EQ(refused(options), "--tangential_force 1,0;2,0.5 needs --friction MU (the Coulomb friction coefficient)");
  options.tangential_force.reset();
  options.tangential_max_iter = 5;
  EXPECT_EQ(refused(options), "--tangential_max_iter 5 needs --friction MU (the Coulomb friction coefficient)");
  options.tangential_max_iter.reset();
  options.tangential_release_period = 2;
  EXPECT_EQ(refused(options), "--tangential_release_period 2 needs --friction MU (the Coulomb friction coefficient)");
  EXPECT_EQ(refusal([&] { make_problem(options); }),
            "tangential_release_period=2 needs friction=MU (the Coulomb friction coefficient)");
  options = friction_problem();
  options.tangential_release_period = 0;
  EXPECT_EQ(refused(options), "--tangential_release_period 0 is invalid: must be at least 1");
  EXPECT_EQ(refusal([&] { make_problem(options); }), "tangential_release_period=0 is invalid: must be at least 1");
  options = friction_problem();
  options.tangential_coarse_start = "maybe";
  EXPECT_EQ(refused(options), "--tangential_coarse_start maybe is invalid: allowed values are on, off and automatic");
  options = friction_problem();
  EXPECT_EQ(make_problem(options).friction->tangential.coarse_start, TangentialCoarseStart::automatic);
  options = friction_problem();
  options.friction = -0.1;
  EXPECT_TRUE(starts_with(refused(options), "--friction -0.1 is invalid: the friction coefficient mu must be finite"));
  options = friction_problem();
  options.tangential_force.reset();
  EXPECT_EQ(refused(options),
            "--friction 0.3 needs a tangential load: --tangential_force QX[,QY], --tangential_displacement DX[,DY] "
            "or --sliding X,Y");
  options.tangential_displacement = std::vector<std::array<double, 2>>{{1e-6, 0.0}};
  options.sliding = std::vector<double>{1.0, 0.0};
  EXPECT_EQ(refused(options),
            "--tangential_displacement 1e-06,0 and --sliding 1,0 cannot be combined: give one of --tangential_force, "
            "--tangential_displacement, --sliding");
  options.tangential_displacement = std::vector<std::array<double, 2>>{};
  options.sliding.reset();
  EXPECT_EQ(refused(options), "--tangential_displacement  is invalid: give at least one step");
  options = friction_problem();
  options.tangential_force.reset();
  options.sliding = std::vector<double>{1.0};
  EXPECT_EQ(refused(options), "--sliding 1 is invalid: expected a direction X,Y");
  options.sliding = std::vector<double>{0.0, 0.0};
  EXPECT_EQ(refused(options), "--sliding 0,0 is invalid: the direction must be finite and not zero");
  options = friction_problem();
  options.tangential_tol = 2.0;  // FrictionOptions' "tolerance"
  EXPECT_EQ(refused(options), "--tangential_tol 2 is invalid: allowed range is (0, 1)");
  options.tangential_tol.reset();
  options.coupling = "maybe";
  EXPECT_EQ(refused(options), "--coupling maybe is invalid: allowed values are on and off");
  options.coupling.reset();
  options.force = std::vector<double>{5.0, 10.0};
  EXPECT_TRUE(starts_with(refused(options), "--friction 0.3 takes one normal load, not a load sweep"));
  options = friction_problem();
  options.adhesion = "md";
  options.work_of_adhesion = 0.1;
  options.adhesion_range = 1e-8;
  EXPECT_TRUE(starts_with(refused(options), "--adhesion md cannot be combined with friction"));
  options = friction_problem();
  options.e1.reset();
  options.nu1.reset();
  options.e2.reset();
  options.nu2.reset();
  options.e_star = 1e11;
  EXPECT_TRUE(starts_with(refused(options),
                          "--friction 0.3 with --e_star 1e+11: E* only does not fix the tangential compliance"));
}

TEST(ProblemTest, FrictionIsCheckedOnTheGrid) {
  const Grid plane = Grid::plane(8, 8, 1e-5, 1e-5, Boundary::free);
  const Grid line = Grid::line(8, 1e-5, Boundary::free);
  ProblemOptions options = friction_problem();
  EXPECT_NO_THROW(make_problem(options).check_grid(plane));
  // The second step has y = 0.5: not on a line contact.
  EXPECT_TRUE(starts_with(refusal([&] { make_problem(options).check_grid(line, Flags{}); }),
                          "--tangential_force 2,0.5 is invalid on a 1D grid"));
  options.tangential_force = std::vector<std::array<double, 2>>{{3.5, 0.0}};  // beyond mu P = 3 N
  EXPECT_TRUE(starts_with(refusal([&] { make_problem(options).check_grid(plane, Flags{}); }),
                          "--tangential_force 3.5,0 is invalid: step 1 asks for |Q| = 3.5 N beyond mu P = 3 N"));
}

}  // namespace
}  // namespace halfspace
