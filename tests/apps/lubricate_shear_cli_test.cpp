// `halfspace lubricate`: the film's shear (/shear_x, /shear_y, the friction
// attributes) for rigid and elastic films, the limiting shear stress flags,
// a coated elastic body (a coating of the substrate's own material is the
// homogeneous body), and bad flags named.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/hdf5_test_support.hpp"
#include "support/cli_checks.hpp"
#include "support/program_run.hpp"

namespace halfspace {
namespace {

using test::TempDir;
using testing::expect_input_error;
using testing::kExitOk;
using testing::ProgramRun;
using testing::run_program;

TEST(LubricateShearCliTest, RigidFilmWritesItsShear) {
  const TempDir dir;
  ASSERT_EQ(run_program({"generate", "--kind", "cylinder", "--grid", "201", "--size", "8e-4", "--radius", "0.01",
                         "--output", "cylinder.h5", "--quiet"},
                        dir.path())
                .exit_code,
            kExitOk);
  const ProgramRun run =
      run_program({"lubricate", "--height-map", "cylinder.h5", "--viscosity", "0.1", "--entrainment-velocity", "1",
                   "--sliding-velocity", "0.2", "--separation", "1e-6", "--output", "film.h5"},
                  dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  const test::H5 file = test::open_file(dir / "film.h5");
  const std::vector<double> shear = test::read_dataset<double>(file.get(), "/shear_x", H5T_NATIVE_DOUBLE);
  const std::vector<double> film = test::read_dataset<double>(file.get(), "/film", H5T_NATIVE_DOUBLE);
  const std::vector<double> theta = test::read_dataset<double>(file.get(), "/fluid_fraction", H5T_NATIVE_DOUBLE);
  ASSERT_EQ(shear.size(), 201U);
  // At the edges (fixed pressures) the one-sided Poiseuille part is small
  // against the Couette part theta eta du / h; the friction is the sum.
  EXPECT_NEAR(shear.back(), theta.back() * 0.1 * 0.2 / film.back(), 0.2 * 0.1 * 0.2 / film.back());
  const double friction = test::read_double_attribute(file.get(), "friction_force_x");
  const double couette = test::read_double_attribute(file.get(), "couette_friction_force_x");
  EXPECT_GT(couette, 0.0);
  EXPECT_NE(friction, couette);
  EXPECT_EQ(test::read_double_attribute(file.get(), "limiting_shear_stress"), 0.0);
  EXPECT_EQ(test::read_double_attribute(file.get(), "limited_fraction"), 0.0);
}

// A point contact on a free 2D grid: the coated body whose layer is the
// substrate's material gives the homogeneous body's film, and a limiting
// shear stress lowers the traction of a piezoviscous film.
TEST(LubricateShearCliTest, CoatingOfTheSubstratesMaterialIsTheHomogeneousBody) {
  const TempDir dir;
  ASSERT_EQ(run_program({"generate", "--kind", "sphere", "--grid", "25x25", "--size", "6e-4", "--radius", "0.01",
                         "--output", "sphere.h5", "--quiet"},
                        dir.path())
                .exit_code,
            kExitOk);
  const std::vector<std::string> base{
      "lubricate", "--height-map",       "sphere.h5", "--viscosity", "0.04", "--entrainment-velocity",
      "0.55",      "--sliding-velocity", "0.3",       "--force",     "6.6",  "--pressure-viscosity",
      "1e-8"};
  const auto with = [&](std::vector<std::string> more) {
    std::vector<std::string> args = base;
    args.insert(args.end(), more.begin(), more.end());
    return run_program(args, dir.path());
  };
  const double e_star = 2.1e11 / (1.0 - 0.3 * 0.3);
  ProgramRun run = with({"--E-star", fmt::format("{:.17g}", e_star), "--output", "plain.h5"});
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  run = with({"--layer-thickness", "2e-5", "--layer-E", "2.1e11", "--layer-nu", "0.3", "--substrate-E", "2.1e11",
              "--substrate-nu", "0.3", "--output", "coated.h5"});
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  run = with({"--E-star", fmt::format("{:.17g}", e_star), "--limiting-shear-stress", "1e6", "--limiting-shear-slope",
              "0.04", "--output", "capped.h5"});
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  const test::H5 plain = test::open_file(dir / "plain.h5");
  const test::H5 coated = test::open_file(dir / "coated.h5");
  const test::H5 capped = test::open_file(dir / "capped.h5");
  EXPECT_EQ(test::read_double_attribute(coated.get(), "layer_thickness"), 2e-5);
  for (const char* name : {"central_film_thickness", "minimum_film_thickness", "max_pressure"}) {
    const double expected = test::read_double_attribute(plain.get(), name);
    EXPECT_NEAR(test::read_double_attribute(coated.get(), name), expected, 1e-6 * expected) << name;
  }
  const double newtonian = test::read_double_attribute(plain.get(), "friction_coefficient");
  const double limited = test::read_double_attribute(capped.get(), "friction_coefficient");
  EXPECT_LT(limited, newtonian);
  EXPECT_GT(limited, 0.0);
  EXPECT_GT(test::read_double_attribute(capped.get(), "limited_fraction"), 0.0);
  EXPECT_EQ(test::read_dataset<double>(capped.get(), "/shear_y", H5T_NATIVE_DOUBLE).size(), 625U);
}

TEST(LubricateShearCliTest, RejectsBadShearAndCoatingFlags) {
  const TempDir dir;
  ASSERT_EQ(run_program({"generate", "--kind", "cylinder", "--grid", "41", "--size", "8e-4", "--radius", "0.01",
                         "--output", "c.h5", "--quiet"},
                        dir.path())
                .exit_code,
            kExitOk);
  const std::vector<std::string> base{
      "lubricate", "--height-map", "c.h5", "--viscosity", "0.04", "--entrainment-velocity", "1", "--output", "f.h5"};
  const auto with = [&](std::vector<std::string> more) {
    std::vector<std::string> args = base;
    args.insert(args.end(), more.begin(), more.end());
    return run_program(args, dir.path());
  };
  expect_input_error(with({"--separation", "1e-6", "--eyring-stress", "-1"}), {"--eyring-stress -1 Pa is invalid"},
                     dir / "f.h5");
  expect_input_error(with({"--separation", "1e-6", "--limiting-shear-slope", "-0.05"}),
                     {"--limiting-shear-slope -0.05 is invalid"}, dir / "f.h5");
  expect_input_error(with({"--force", "1e3", "--layer-thickness", "1e-5"}), {"incomplete coated half-space"},
                     dir / "f.h5");
  expect_input_error(with({"--force", "1e3", "--E-star", "1e11", "--layer-thickness", "1e-5", "--layer-E", "1e11",
                           "--layer-nu", "0.3", "--substrate-E", "1e11", "--substrate-nu", "0.3"}),
                     {"--substrate-nu cannot be combined with --E-star"}, dir / "f.h5");
  expect_input_error(with({"--force", "-1", "--E-star", "1e11"}), {"--force -1 is invalid"}, dir / "f.h5");
  expect_input_error(with({"--separation", "1e-6", "--inlet-pressure", "-5"}), {"--inlet-pressure -5 Pa is invalid"},
                     dir / "f.h5");
}

}  // namespace
}  // namespace halfspace
