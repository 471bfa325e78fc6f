// `halfspace lubricate --plot`: the figures of a film (pressure and film along
// the centre line; maps of a 2D film) and of a Stribeck curve are written
// next to the results, and a plotting tool that cannot run is reported before
// the solve, naming --plot. Needs the plotting tool's python (matplotlib,
// h5py, numpy), as the solve --plot tests do.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "io/hdf5_test_support.hpp"
#include "support/cli_checks.hpp"
#include "support/program_run.hpp"

namespace halfspace {
namespace {

namespace fs = std::filesystem;
using test::TempDir;
using testing::kExitOk;
using testing::ProgramRun;
using testing::run_program;

void generate(const TempDir& dir, const std::vector<std::string>& arguments) {
  std::vector<std::string> args{"generate"};
  args.insert(args.end(), arguments.begin(), arguments.end());
  args.insert(args.end(), {"--quiet"});
  ASSERT_EQ(run_program(args, dir.path()).exit_code, kExitOk);
}

// A PNG file of some size (matplotlib wrote a figure, not an empty file).
void expect_figure(const fs::path& path) {
  ASSERT_TRUE(fs::exists(path)) << path;
  EXPECT_GT(fs::file_size(path), 5000u) << path;
}

TEST(LubricatePlotCliTest, RigidMapDrawsCentreLineAndMaps) {
  const TempDir dir;
  generate(dir, {"--kind", "sphere", "--grid", "48x48", "--size", "1e-3", "--radius", "0.01", "--output", "s.h5"});
  const ProgramRun run =
      run_program({"lubricate", "--height-map", "s.h5", "--viscosity", "0.1", "--entrainment-velocity", "1", "--force",
                   "10", "--output", "film.h5", "--plot", "--quiet"},
                  dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  expect_figure(dir / "film_film.png");
  expect_figure(dir / "film_film_maps.png");
}

TEST(LubricatePlotCliTest, MixedStribeckSweepDrawsFilmAndCurve) {
  const TempDir dir;
  generate(dir, {"--kind", "cylinder", "--grid", "65", "--size", "2.4e-4", "--radius", "0.01", "--output", "c.h5"});
  generate(dir, {"--kind", "self-affine", "--grid", "65", "--size", "2.4e-4", "--rms-height", "1e-7", "--seed", "3",
                 "--output", "r.h5"});
  const ProgramRun run = run_program({"lubricate",
                                      "--height-map",
                                      "c.h5",
                                      "--roughness",
                                      "r.h5",
                                      "--mixed",
                                      "--viscosity",
                                      "0.04",
                                      "--force",
                                      "4.4e4",
                                      "--E-star",
                                      "1.1e11",
                                      "--pressure-viscosity",
                                      "2.27e-8",
                                      "--limiting-shear-slope",
                                      "0.05",
                                      "--entrainment-velocity",
                                      "1",
                                      "--sliding-velocity",
                                      "0.5",
                                      "--speeds",
                                      "1,0.001",
                                      "--stribeck",
                                      "curve.csv",
                                      "--output",
                                      "last.h5",
                                      "--plot"},
                                     dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  expect_figure(dir / "last_film.png");
  EXPECT_FALSE(fs::exists(dir / "last_film_maps.png")) << "a profile has no maps";
  expect_figure(dir / "curve_stribeck.png");
  // The tool prints the figures it wrote (its output is kept without --quiet).
  EXPECT_NE(run.out.find("curve_stribeck.png"), std::string::npos) << run.out;
}

TEST(LubricatePlotCliTest, UnusableToolIsRefusedBeforeTheSolve) {
  const TempDir dir;
  generate(dir, {"--kind", "cylinder", "--grid", "65", "--size", "1e-3", "--radius", "0.01", "--output", "c.h5"});
  const std::vector<std::string> film{
      "lubricate", "--height-map", "c.h5", "--viscosity", "0.1",     "--entrainment-velocity",
      "1",         "--force",      "100",  "--output",    "film.h5", "--plot"};
  const ProgramRun python = run_program(film, dir.path(), {{"HALFSPACE_PYTHON", "/nonexistent/python3"}});
  testing::expect_input_error(
      python, {"error: --plot: the plotting tool's interpreter /nonexistent/python3 cannot be run", "drop --plot"},
      dir / "film.h5");
  const ProgramRun packages = run_program(film, dir.path(), {{"HALFSPACE_PYTHON", "/bin/false"}});
  testing::expect_input_error(packages, {"--plot: /bin/false cannot import matplotlib, h5py and numpy"},
                              dir / "film.h5");
  const ProgramRun timeout = run_program(film, dir.path(), {{"HALFSPACE_PLOT_TIMEOUT", "soon"}});
  testing::expect_input_error(timeout, {"--plot: HALFSPACE_PLOT_TIMEOUT=soon is invalid"}, dir / "film.h5");
}

}  // namespace
}  // namespace halfspace
