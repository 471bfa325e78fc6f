// `halfspace lubricate`: the program's film equals the library's, the load it
// was asked for is carried, the flows balance, and bad input names the option.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "halfspace/io/height_map_reader.hpp"
#include "halfspace/lubrication/elastic_film.hpp"
#include "halfspace/lubrication/load_control.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "io/hdf5_test_support.hpp"
#include "support/cli_checks.hpp"
#include "support/program_run.hpp"

namespace halfspace {
namespace {

namespace fs = std::filesystem;
using test::TempDir;
using testing::expect_input_error;
using testing::kExitOk;
using testing::ProgramRun;
using testing::run_program;

// The load control's own tolerance (LoadControlOptions' default, 1e-8) with room.
constexpr double kLoadTolerance = 1e-7;
// The program's film is warm-started from the load search's previous one, the
// library's cold: both converged to 1e-11 of the mass balance.
constexpr double kWarmVersusCold = 1e-6;

// `generate` a cylinder (R = 10 mm) of `grid` points over `size` m into `file`: its exit code.
int generate_cylinder(const TempDir& dir, const std::string& grid, const std::string& size, const std::string& file) {
  return run_program({"generate", "--kind", "cylinder", "--grid", grid, "--size", size, "--radius", "0.01", "--output",
                      file, "--quiet"},
                     dir.path())
      .exit_code;
}

TEST(LubricateCliTest, CarriesTheForceAndWritesTheLibrarysFilm) {
  const TempDir dir;
  ASSERT_EQ(generate_cylinder(dir, "401", "8e-4", "cylinder.h5"), kExitOk);
  const ProgramRun run =
      run_program({"lubricate", "--height-map", "cylinder.h5", "--viscosity", "0.1", "--entrainment-velocity", "1",
                   "--sliding-velocity", "0.2", "--force", "4000", "--output", "film.h5"},
                  dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  const test::H5 file = test::open_file(dir / "film.h5");
  EXPECT_NEAR(test::read_double_attribute(file.get(), "load"), 4000.0, kLoadTolerance * 4000.0);
  const double inflow = test::read_double_attribute(file.get(), "inflow");
  EXPECT_NEAR(test::read_double_attribute(file.get(), "outflow"), inflow, 1e-9 * inflow);
  EXPECT_GT(test::read_double_attribute(file.get(), "cavitated_fraction"), 0.0);
  const double separation = test::read_double_attribute(file.get(), "separation");
  const std::vector<double> pressure = test::read_dataset<double>(file.get(), "/pressure", H5T_NATIVE_DOUBLE);

  const HeightMap map = io::read_height_map(dir / "cylinder.h5");
  lubrication::FlowConditions conditions;
  conditions.viscosity = 0.1;
  conditions.entrainment_velocity = {1.0, 0.0};
  const lubrication::LubricatedFilm film = lubrication::lubricate_at_separation(
      Grid::line(map.nx, map.dx, Boundary::free), map.heights, conditions, separation);
  ASSERT_EQ(pressure.size(), static_cast<std::size_t>(film.solution.pressure.size()));
  double worst = 0.0;
  for (std::size_t i = 0; i < pressure.size(); ++i) {
    worst = std::max(worst, std::abs(pressure[i] - film.solution.pressure[i]));
  }
  EXPECT_LT(worst, kWarmVersusCold * film.solution.pressure.maxCoeff());
}

// The elastic film: the program's is the library's on the same height map
// (one deterministic Newton iteration from the same start), carries the
// force, and the file holds the film, deformation and attributes.
TEST(LubricateCliTest, ElasticFilmIsTheLibrarys) {
  const TempDir dir;
  ASSERT_EQ(generate_cylinder(dir, "129", "7e-4", "cylinder.h5"), kExitOk);
  const ProgramRun run = run_program({"lubricate",   "--height-map",
                                      "cylinder.h5", "--viscosity",
                                      "0.04",        "--entrainment-velocity",
                                      "0.55",        "--force",
                                      "4.4e4",       "--E1",
                                      "2.1e11",      "--nu1",
                                      "0.3",         "--E2",
                                      "2.1e11",      "--nu2",
                                      "0.3",         "--pressure-viscosity",
                                      "2e-8",        "--piezoviscosity",
                                      "roelands",    "--output",
                                      "ehl.h5"},
                                     dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  const test::H5 file = test::open_file(dir / "ehl.h5");
  EXPECT_EQ(test::read_string_attribute(file.get(), "model"), "elastic");
  EXPECT_EQ(test::read_string_attribute(file.get(), "compressibility"), "dowson-higginson");
  EXPECT_NEAR(test::read_double_attribute(file.get(), "load"), 4.4e4, 1e-7 * 4.4e4);
  const double central = test::read_double_attribute(file.get(), "central_film_thickness");
  const double minimum = test::read_double_attribute(file.get(), "minimum_film_thickness");
  EXPECT_LT(minimum, central);
  const std::vector<double> film = test::read_dataset<double>(file.get(), "/film", H5T_NATIVE_DOUBLE);
  const std::vector<double> deformation = test::read_dataset<double>(file.get(), "/deformation", H5T_NATIVE_DOUBLE);
  ASSERT_EQ(film.size(), 129U);
  ASSERT_EQ(deformation.size(), 129U);

  const HeightMap map = io::read_height_map(dir / "cylinder.h5");
  const Grid grid = Grid::line(map.nx, map.dx, Boundary::free);
  lubrication::FlowConditions conditions;
  conditions.viscosity = 0.04;
  conditions.entrainment_velocity = {0.55, 0.0};
  const lubrication::LubricantLaws laws{.piezoviscosity = lubrication::Piezoviscosity::roelands,
                                        .pressure_viscosity = 2e-8,
                                        .compressibility = lubrication::Compressibility::dowson_higginson};
  FftInfluenceOperator op(grid, 2.1e11 / (2.0 * (1.0 - 0.09)));
  const lubrication::ElasticFilm expected =
      lubrication::solve_elastic_film(op, map.heights.maxCoeff() - map.heights, conditions, laws, {.load = 4.4e4});
  ASSERT_TRUE(expected.converged()) << expected.message;
  EXPECT_NEAR(central, expected.central_film_thickness, 1e-9 * central);
  EXPECT_NEAR(minimum, expected.minimum_film_thickness, 1e-9 * minimum);
}

TEST(LubricateCliTest, RejectsBadElasticInputNamingTheOption) {
  const TempDir dir;
  ASSERT_EQ(generate_cylinder(dir, "41", "8e-4", "c.h5"), kExitOk);
  const std::vector<std::string> base{
      "lubricate", "--height-map", "c.h5", "--viscosity", "0.04", "--entrainment-velocity", "1", "--output", "f.h5"};
  const auto with = [&](std::vector<std::string> more) {
    std::vector<std::string> args = base;
    args.insert(args.end(), more.begin(), more.end());
    return run_program(args, dir.path());
  };
  expect_input_error(with({"--separation", "1e-6", "--E-star", "1e11"}), {"--force"}, dir / "f.h5");
  expect_input_error(with({"--force", "1e3", "--E-star", "1e11", "--piezoviscosity", "exponential"}),
                     {"piezoviscosity 'exponential'", "barus, roelands"}, dir / "f.h5");
  expect_input_error(with({"--force", "1e3", "--E-star", "1e11", "--compressibility", "tait"}),
                     {"compressibility 'tait'"}, dir / "f.h5");
  expect_input_error(with({"--force", "1e3", "--pressure-viscosity", "2e-8"}), {"--E-star"}, dir / "f.h5");
  expect_input_error(with({"--force", "1e3", "--E-star", "1e11", "--E1", "2e11"}), {"--E-star", "--E1"}, dir / "f.h5");
  expect_input_error(with({"--force", "1e3", "--E1", "2e11", "--nu1", "0.3"}), {"incomplete material"}, dir / "f.h5");
  expect_input_error(with({"--force", "1e3", "--E-star", "1e11", "--piezoviscosity", "barus"}),
                     {"pressure-viscosity coefficient"}, dir / "f.h5");
  expect_input_error(with({"--force", "1e3", "--E-star", "1e11", "--max-iterations", "0"}), {"--max-iterations 0"},
                     dir / "f.h5");
  expect_input_error(with({"--force", "1e3", "--E-star", "1e11", "--fft-planning", "exhaustive"}),
                     {"--fft-planning 'exhaustive'", "'estimate', 'measure' or 'patient'"}, dir / "f.h5");
  expect_input_error(with({"--separation", "1e-6", "--fft-planning", "estimate"}),
                     {"--fft-planning need an elastic film"}, dir / "f.h5");
}

// A film that does not converge (one Newton step) is written, exits with the
// not-converged code and says what to try, naming the flags.
TEST(LubricateCliTest, UnconvergedElasticFilmSaysWhatToTry) {
  const TempDir dir;
  ASSERT_EQ(generate_cylinder(dir, "41", "8e-4", "c.h5"), kExitOk);
  const ProgramRun run =
      run_program({"lubricate", "--height-map", "c.h5", "--viscosity", "0.04", "--entrainment-velocity", "1", "--force",
                   "1e3", "--E-star", "1e11", "--max-iterations", "1", "--output", "f.h5"},
                  dir.path());
  EXPECT_EQ(run.exit_code, testing::kExitNotConverged) << run.err;
  EXPECT_TRUE(fs::exists(dir / "f.h5"));
  for (const std::string_view part :
       {"to try: a faster --entrainment-velocity or a smaller --force", "more --max-iterations (now 1)",
        "a looser --tolerance (now 1e-08)", "--film-preconditioner sparse-lu"}) {
    EXPECT_NE(run.err.find(part), std::string::npos) << part << " not in: " << run.err;
  }
}

TEST(LubricateCliTest, RejectsBadInputNamingTheOption) {
  const TempDir dir;
  ASSERT_EQ(generate_cylinder(dir, "41", "8e-4", "c.h5"), kExitOk);
  expect_input_error(run_program({"lubricate", "--height-map", "c.h5", "--viscosity", "-1", "--entrainment-velocity",
                                  "1", "--separation", "1e-6", "--output", "f.h5"},
                                 dir.path()),
                     {"--viscosity -1 Pa s is invalid"}, dir / "f.h5");
  expect_input_error(run_program({"lubricate", "--height-map", "c.h5", "--viscosity", "0.1", "--entrainment-velocity",
                                  "1", "--output", "f.h5"},
                                 dir.path()),
                     {"--separation", "--force"}, dir / "f.h5");
  expect_input_error(run_program({"lubricate", "--height-map", "c.h5", "--viscosity", "0.1", "--entrainment-velocity",
                                  "1,2", "--separation", "1e-6", "--output", "f.h5"},
                                 dir.path()),
                     {"--entrainment-velocity 2 m/s (y component) is invalid on a 1D grid"}, dir / "f.h5");
  expect_input_error(run_program({"lubricate", "--height-map", "c.h5", "--viscosity", "0.1", "--entrainment-velocity",
                                  "1", "--separation", "1e-6", "--supply-fluid-fraction", "1.5", "--output", "f.h5"},
                                 dir.path()),
                     {"--supply-fluid-fraction 1.5 is invalid: allowed range is 0 to 1"}, dir / "f.h5");
  expect_input_error(run_program({"lubricate", "--height-map", "c.h5", "--viscosity", "0.1", "--entrainment-velocity",
                                  "1", "--separation", "1e-6", "--periodic-x", "--output", "f.h5"},
                                 dir.path()),
                     {"--periodic-x on a 1D grid: the film is periodic along every axis"}, dir / "f.h5");
}

// No output replaces an input: the result named as the height map, the
// roughness or (mixed) the Stribeck curve named as the height map are
// refused before anything is solved, and the input is left as it was.
TEST(LubricateCliTest, RefusesAnOutputThatWouldReplaceAnInput) {
  const TempDir dir;
  ASSERT_EQ(generate_cylinder(dir, "41", "8e-4", "c.h5"), kExitOk);
  ASSERT_EQ(generate_cylinder(dir, "41", "8e-4", "r.h5"), kExitOk);
  const auto bytes = [&](const char* name) {
    std::ifstream in(dir / name, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string map = bytes("c.h5"), roughness = bytes("r.h5");
  const std::vector<std::string> rigid{
      "lubricate", "--height-map", "c.h5", "--viscosity", "0.1", "--entrainment-velocity", "1", "--separation", "1e-6"};
  const auto with = [&](const std::vector<std::string>& base, std::vector<std::string> more) {
    std::vector<std::string> args = base;
    args.insert(args.end(), more.begin(), more.end());
    return run_program(args, dir.path());
  };
  expect_input_error(with(rigid, {"--output", "./c.h5"}),
                     {"--output ./c.h5 would overwrite the input --height-map c.h5", "choose another output name"});
  const std::vector<std::string> mixed{
      "lubricate", "--height-map", "c.h5",  "--viscosity", "0.04",   "--entrainment-velocity",
      "0.001",     "--force",      "4.4e4", "--E-star",    "1.1e11", "--mixed"};
  expect_input_error(with(mixed, {"--roughness", "r.h5", "--output", "r.h5"}),
                     {"--output r.h5 would overwrite the input --roughness r.h5"});
  expect_input_error(with(mixed, {"--speeds", "0.002,0.001", "--stribeck", "c.h5", "--output", "f.h5"}),
                     {"--stribeck c.h5 would overwrite the input --height-map c.h5"}, dir / "f.h5");
  EXPECT_EQ(bytes("c.h5"), map);
  EXPECT_EQ(bytes("r.h5"), roughness);
}

// A starved supply: the program passes --supply-fluid-fraction to the film
// (the library's film at the same separation, and less lubricant flows in
// than with a full supply).
TEST(LubricateCliTest, StarvedSupplyIsTheLibrarys) {
  const TempDir dir;
  ASSERT_EQ(generate_cylinder(dir, "201", "8e-4", "cylinder.h5"), kExitOk);
  const auto run_with = [&](std::string_view supply, std::string_view output) {
    return run_program(
        {"lubricate", "--height-map", "cylinder.h5", "--viscosity", "0.1", "--entrainment-velocity", "1",
         "--separation", "2e-6", "--supply-fluid-fraction", std::string(supply), "--output", std::string(output)},
        dir.path());
  };
  const ProgramRun starved = run_with("0.3", "starved.h5");
  ASSERT_EQ(starved.exit_code, kExitOk) << starved.err;
  const ProgramRun flooded = run_with("1", "flooded.h5");
  ASSERT_EQ(flooded.exit_code, kExitOk) << flooded.err;
  const test::H5 file = test::open_file(dir / "starved.h5");
  const std::vector<double> pressure = test::read_dataset<double>(file.get(), "/pressure", H5T_NATIVE_DOUBLE);
  const double inflow = test::read_double_attribute(file.get(), "inflow");
  EXPECT_LT(inflow, test::read_double_attribute(test::open_file(dir / "flooded.h5").get(), "inflow"));

  const HeightMap map = io::read_height_map(dir / "cylinder.h5");
  lubrication::FlowConditions conditions;
  conditions.viscosity = 0.1;
  conditions.entrainment_velocity = {1.0, 0.0};
  conditions.boundary.supply_fluid_fraction = 0.3;
  const lubrication::LubricatedFilm film =
      lubrication::lubricate_at_separation(Grid::line(map.nx, map.dx, Boundary::free), map.heights, conditions, 2e-6);
  ASSERT_EQ(pressure.size(), static_cast<std::size_t>(film.solution.pressure.size()));
  double worst = 0.0;
  for (std::size_t i = 0; i < pressure.size(); ++i) {
    worst = std::max(worst, std::abs(pressure[i] - film.solution.pressure[i]));
  }
  EXPECT_GT(film.solution.pressure.maxCoeff(), 0.0);
  EXPECT_LT(worst, 1e-9 * film.solution.pressure.maxCoeff());
}

}  // namespace
}  // namespace halfspace
