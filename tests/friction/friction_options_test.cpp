// FrictionOptions' rules (friction_options.hpp): each broken one a
// SolverOptionError naming the option the front ends map to their flags.
#include "halfspace/solvers/friction_options.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace halfspace {
namespace {

std::string refused_option(const std::function<void()>& check) {
  try {
    check();
  } catch (const solvers::SolverOptionError& error) {
    return error.option();
  }
  return "accepted";
}

FrictionOptions history(double mu, std::vector<TangentialLoading> steps) {
  FrictionOptions options;
  options.tangential.friction_coefficient = mu;
  options.history = std::move(steps);
  return options;
}

TEST(FrictionOptions, ValidateNamesTheOption) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(refused_option([] { history(0.3, {TangentialLoading::force(1.0)}).validate(); }), "accepted");
  EXPECT_EQ(refused_option([] { history(-0.1, {TangentialLoading::force(1.0)}).validate(); }), "friction");
  EXPECT_EQ(refused_option([&] { history(inf, {TangentialLoading::force(1.0)}).validate(); }), "friction");
  EXPECT_EQ(refused_option([] { history(0.3, {}).validate(); }), "friction");
  EXPECT_EQ(refused_option([&] { history(0.3, {TangentialLoading::force(inf)}).validate(); }), "tangential_load");
  FrictionOptions sliding = history(0.3, {});
  sliding.sliding_direction = {{1.0, 0.0}};
  EXPECT_EQ(refused_option([&] { sliding.validate(); }), "accepted");
  EXPECT_EQ(sliding.steps(), 1u);
  sliding.sliding_direction = {{0.0, 0.0}};
  EXPECT_EQ(refused_option([&] { sliding.validate(); }), "sliding");
  sliding.sliding_direction = {{1.0, 0.0}};
  sliding.tangential.friction_coefficient = 0.0;
  EXPECT_EQ(refused_option([&] { sliding.validate(); }), "friction");
  sliding.tangential.friction_coefficient = 0.3;
  sliding.history = {TangentialLoading::force(1.0)};
  EXPECT_EQ(refused_option([&] { sliding.validate(); }), "sliding");
  FrictionOptions loose = history(0.3, {TangentialLoading::force(1.0)});
  loose.tangential.tolerance = 1.0;
  EXPECT_EQ(refused_option([&] { loose.validate(); }), "tolerance");
  FrictionOptions eager = history(0.3, {TangentialLoading::force(1.0)});
  eager.tangential.release_period = 0;
  EXPECT_EQ(refused_option([&] { eager.validate(); }), "release_period");
}

TEST(FrictionOptions, RulesOfTheSolve) {
  const Grid plane = Grid::plane(8, 8, 1e-5, 1e-5, Boundary::free);
  const Grid line = Grid::line(8, 1e-5, Boundary::free);
  const solvers::SolverOptions normal;
  const Loading ten = Loading::force(10.0);
  EXPECT_EQ(refused_option([&] { history(0.3, {TangentialLoading::force(3.0)}).validate(plane, normal, ten); }),
            "accepted");
  // Beyond mu P under load control.
  EXPECT_EQ(refused_option([&] { history(0.3, {TangentialLoading::force(3.1)}).validate(plane, normal, ten); }),
            "tangential_load");
  // Under approach control P is not known before the solve.
  EXPECT_EQ(refused_option([&] {
              history(0.3, {TangentialLoading::force(3.1)}).validate(plane, normal, Loading::approach(1e-6));
            }),
            "accepted");
  // Mean pressure: P = p times the domain area (6.4e-9 m^2 here).
  EXPECT_EQ(refused_option([&] {
              history(0.3, {TangentialLoading::force(1.0)}).validate(plane, normal, Loading::mean_pressure(1e6));
            }),
            "tangential_load");
  EXPECT_EQ(refused_option([&] { history(0.3, {TangentialLoading::force(1.0, 0.5)}).validate(line, normal, ten); }),
            "tangential_load");
  solvers::FrictionOptions ramp = history(0.3, {TangentialLoading::force(1.0)});
  ramp.normal_load_steps = 0;
  EXPECT_EQ(refused_option([&] { ramp.validate(); }), "normal_load_steps");
  ramp.normal_load_steps = 4;
  ramp.coupled_step.tolerance = 0.0;
  EXPECT_EQ(refused_option([&] { ramp.validate(); }), "coupling_tolerance");
  ramp.coupled_step.tolerance = 1e-6;
  ramp.coupled_step.max_alternations = 0;
  EXPECT_EQ(refused_option([&] { ramp.validate(); }), "max_alternations");
  solvers::SolverOptions adhesive;
  adhesive.adhesion = solvers::SolverOptions::Adhesion{};
  adhesive.adhesion->law = AdhesionLaw{AdhesionLawType::maugis_dugdale, 0.1, 1e-8};
  EXPECT_EQ(refused_option([&] { history(0.3, {TangentialLoading::force(1.0)}).validate(plane, adhesive, ten); }),
            "adhesion");
  EXPECT_EQ(refused_option([&] { history(0.3, {TangentialLoading::force(1.0)}).validate(adhesive); }), "adhesion");
  // A coated body: refused on free grids less than 8 split heights across
  // (its remainder goes in by DFT only there) and on free lines.
  const ElasticPair coated = ElasticPair::coated({2e-6, {2e11, 0.3}, {7e10, 0.33}});
  const Grid free = Grid::plane(8, 8, 1e-6, 1e-6, Boundary::free);
  const Grid periodic = Grid::plane(8, 8, 1e-6, 1e-6, Boundary::periodic);
  EXPECT_EQ(refused_option([&] { FrictionOptions::check_body(free, coated); }), "coating");
  EXPECT_EQ(refused_option([&] { FrictionOptions::check_body(Grid::line(256, 1e-6, Boundary::free), coated); }),
            "coating");
  EXPECT_EQ(
      refused_option([&] { FrictionOptions::check_body(Grid::plane(64, 64, 1e-6, 1e-6, Boundary::free), coated); }),
      "accepted");
  EXPECT_EQ(refused_option([&] { FrictionOptions::check_body(periodic, coated); }), "accepted");
  EXPECT_EQ(refused_option([&] { FrictionOptions::check_body(free, ElasticPair::on_rigid({2e11, 0.3})); }), "accepted");
  EXPECT_EQ(refused_option([] { FrictionOptions::refuse_composite_modulus_only(); }), "pair");
}

// The coarse start's automatic rule: on (the default), whatever the size
// since the short stall window after it (it won at 2048^2 too); off forces
// the fine start; a value outside the enum is refused.
TEST(FrictionOptions, CoarseStartAutomaticIsOn) {
  solvers::TangentialOptions options;
  EXPECT_EQ(options.coarse_start, TangentialCoarseStart::automatic);
  EXPECT_TRUE(options.coarse_start_wanted());
  options.coarse_start = TangentialCoarseStart::on;
  EXPECT_TRUE(options.coarse_start_wanted());
  options.coarse_start = TangentialCoarseStart::off;
  EXPECT_FALSE(options.coarse_start_wanted());
  options.coarse_start = static_cast<TangentialCoarseStart>(7);
  EXPECT_EQ(refused_option([&] { options.validate(); }), "coarse_start");
}

}  // namespace
}  // namespace halfspace
