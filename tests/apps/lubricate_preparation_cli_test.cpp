// `halfspace lubricate --window --detrend`: the height map prepared as solve
// prepares it (the library's prepare_height_map) before the film is solved,
// the steps recorded; a bad value names its flag.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "halfspace/io/height_map_reader.hpp"
#include "halfspace/lubrication/load_control.hpp"
#include "halfspace/surface/preparation.hpp"
#include "io/hdf5_test_support.hpp"
#include "support/cli_checks.hpp"
#include "support/program_run.hpp"

namespace halfspace {
namespace {

using test::TempDir;
using testing::kExitOk;
using testing::ProgramRun;
using testing::run_program;

const std::string kProfile = std::string(HALFSPACE_TEST_DATA_DIR) + "/dektak-1.csv";

std::vector<std::string> film_of(std::vector<std::string> preparation) {
  std::vector<std::string> args{"lubricate", "--height-map", kProfile};
  args.insert(args.end(), preparation.begin(), preparation.end());
  args.insert(args.end(), {"--viscosity", "0.1", "--entrainment-velocity", "1", "--separation", "2e-8", "--output",
                           "film.h5", "--quiet"});
  return args;
}

TEST(LubricatePreparationCliTest, WindowAndDetrendAreTheLibrarys) {
  const TempDir dir;
  const ProgramRun run = run_program(film_of({"--window", "3000,240", "--detrend", "plane"}), dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  const test::H5 file = test::open_file(dir / "film.h5");
  const std::vector<double> pressure = test::read_dataset<double>(file.get(), "/pressure", H5T_NATIVE_DOUBLE);
  ASSERT_EQ(pressure.size(), 240u);
  const std::string preparation = test::read_string_attribute(file.get(), "preparation");
  EXPECT_NE(preparation.find("window"), std::string::npos) << preparation;
  EXPECT_NE(preparation.find("detrend plane"), std::string::npos) << preparation;

  HeightMap map = io::read_height_map(kProfile);
  surface::PreparationOptions prepare;
  prepare.window = surface::parse_window("3000,240");
  prepare.detrend = surface::Detrend::plane;
  surface::prepare_height_map(map, prepare);
  lubrication::FlowConditions conditions;
  conditions.viscosity = 0.1;
  conditions.entrainment_velocity = {1.0, 0.0};
  const lubrication::LubricatedFilm expected = lubrication::lubricate_at_separation(
      Grid::line(map.nx, map.dx, Boundary::free), map.heights, conditions, 2e-8, {});
  ASSERT_TRUE(expected.solution.converged());
  for (std::size_t k = 0; k < pressure.size(); ++k) {
    EXPECT_EQ(pressure[k], expected.solution.pressure[static_cast<Eigen::Index>(k)]) << k;
  }
}

TEST(LubricatePreparationCliTest, BadPreparationNamesTheFlag) {
  const TempDir dir;
  testing::expect_input_error(run_program(film_of({"--window", "0,x"}), dir.path()), {"--window: window '0,x'"},
                              dir / "film.h5");
  testing::expect_input_error(run_program(film_of({"--detrend", "cubic"}), dir.path()), {"--detrend: detrend 'cubic'"},
                              dir / "film.h5");
  testing::expect_input_error(run_program(film_of({"--invalid", "guess"}), dir.path()), {"--invalid:"},
                              dir / "film.h5");
}

}  // namespace
}  // namespace halfspace
