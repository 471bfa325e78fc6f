// `halfspace lubricate --time-step`: the program's steps are the library's
// (lubricate_transient), each in its group with the history as CSV beside
// the file, and bad transient input names the option.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "halfspace/io/height_map_reader.hpp"
#include "halfspace/lubrication/transient_film.hpp"
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

std::vector<std::string> lubricate(std::vector<std::string> extra) {
  std::vector<std::string> args{
      "lubricate", "--height-map", "cylinder.h5", "--viscosity", "0.1", "--entrainment-velocity",
      "1",         "--output",     "t.h5",        "--quiet"};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

TEST(LubricateTransientCliTest, StepsAreTheLibrarysWithAHistory) {
  const TempDir dir;
  ASSERT_EQ(run_program({"generate", "--kind", "cylinder", "--grid", "101", "--size", "6e-4", "--radius", "0.01",
                         "--output", "cylinder.h5", "--quiet"},
                        dir.path())
                .exit_code,
            kExitOk);
  const ProgramRun run = run_program(lubricate({"--separation", "1e-5", "--time-step", "1e-4", "--separation-history",
                                                "9e-6,1.2e-5,1e-5", "--time-scheme", "backward-euler"}),
                                     dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;

  const HeightMap map = io::read_height_map(dir / "cylinder.h5");
  lubrication::FlowConditions conditions;
  conditions.viscosity = 0.1;
  conditions.entrainment_velocity = {1.0, 0.0};
  lubrication::TransientFilmOptions options;
  options.time_step = 1e-4;
  options.steps = 3;
  options.initial_separation = 1e-5;
  options.separation_history = std::vector<double>{9e-6, 1.2e-5, 1e-5};
  options.scheme = lubrication::TimeScheme::backward_euler;
  std::vector<lubrication::TransientStep> expected;
  const lubrication::TransientOutcome outcome =
      lubrication::lubricate_transient(Grid::line(map.nx, map.dx, Boundary::free), map.heights, conditions, options, {},
                                       [&](const lubrication::TransientStep& s) { expected.push_back(s); });
  ASSERT_EQ(outcome.status, lubrication::FilmStatus::converged) << outcome.message;
  ASSERT_EQ(expected.size(), 4u);

  const test::H5 file = test::open_file(dir / "t.h5");
  EXPECT_EQ(test::read_int64_attribute(file.get(), "history_steps"), 4);
  EXPECT_EQ(test::read_string_attribute(file.get(), "time_scheme"), "backward-euler");
  const std::vector<double> loads = test::read_dataset<double>(file.get(), "/history/load", H5T_NATIVE_DOUBLE);
  ASSERT_EQ(loads.size(), 4u);
  for (std::size_t k = 0; k < expected.size(); ++k) {
    // The same solves in the same order: equal to the last bit.
    EXPECT_EQ(loads[k], expected[k].film.forces.load) << k;
    const std::vector<double> p =
        test::read_dataset<double>(file.get(), "/steps/00" + std::to_string(k) + "/pressure", H5T_NATIVE_DOUBLE);
    ASSERT_EQ(p.size(), map.nx);
    for (std::size_t i = 0; i < p.size(); ++i) ASSERT_EQ(p[i], expected[k].film.solution.pressure[i]) << k << " " << i;
  }
  EXPECT_EQ(test::read_double_attribute(file.get(), "load"), expected.back().film.forces.load);
  std::ifstream csv(dir / "t.csv");
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  EXPECT_EQ(line.rfind("step,time,separation,load,minimum_film_thickness", 0), 0u) << line;
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 4);
}

TEST(LubricateTransientCliTest, RejectsBadTransientInputNamingTheOption) {
  const TempDir dir;
  ASSERT_EQ(run_program({"generate", "--kind", "cylinder", "--grid", "33", "--size", "6e-4", "--radius", "0.01",
                         "--output", "cylinder.h5", "--quiet"},
                        dir.path())
                .exit_code,
            kExitOk);
  const auto rejects = [&](std::vector<std::string> extra, std::string expected) {
    expect_input_error(run_program(lubricate(std::move(extra)), dir.path()), {expected}, dir.path() / "t.h5");
  };
  rejects({"--separation", "1e-5", "--time-step", "0", "--steps", "2", "--approach-velocity", "1e-3"},
          "--time-step 0 s is invalid");
  rejects({"--separation", "1e-5", "--time-step", "1e-4", "--steps", "0", "--approach-velocity", "1e-3"},
          "--steps 0 is invalid");
  rejects({"--separation", "1e-5", "--time-step", "1e-4", "--steps", "3", "--approach-velocity", "1"},
          "--approach-velocity 1 m/s is invalid");
  rejects({"--time-step", "1e-4", "--steps", "3", "--force", "10"}, "pass --separation");
  rejects({"--separation", "1e-5", "--time-step", "1e-4", "--steps", "3"}, "exactly one of --approach-velocity");
  rejects({"--separation", "1e-5", "--time-step", "1e-4", "--steps", "2", "--separation-history", "1e-5"},
          "--separation-history has 1 separations but --steps 2");
  rejects({"--separation", "1e-5", "--time-step", "1e-4", "--separation-history", "1e-5,-1e-6"},
          "--separation-history -1e-06 m is invalid");
  rejects({"--separation", "1e-5", "--approach-velocity", "1e-3"}, "add --time-step");
  rejects({"--separation", "1e-5", "--time-step", "1e-4", "--steps", "2", "--approach-velocity", "1e-3",
           "--time-scheme", "euler"},
          "--time-scheme 'euler'");
  rejects({"--separation", "1e-5", "--force", "10", "--E-star", "1e11", "--time-step", "1e-4", "--steps", "2"},
          "rigid film only");
}

}  // namespace
}  // namespace halfspace
