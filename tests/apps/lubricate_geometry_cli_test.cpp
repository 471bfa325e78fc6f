// `halfspace lubricate --geometry`: a built-in surface is the height map
// `generate` writes of the same shape (the same film to the last bit), takes
// --roughness on its points, and the surface options that do not apply are
// refused naming them.
#include <gtest/gtest.h>

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

const std::vector<std::string> kFilm = {"--viscosity", "0.1", "--entrainment-velocity", "1", "--force", "2", "--quiet"};

std::vector<std::string> lubricate(std::vector<std::string> surface, const std::string& output) {
  std::vector<std::string> argv = {"lubricate"};
  argv.insert(argv.end(), surface.begin(), surface.end());
  argv.insert(argv.end(), kFilm.begin(), kFilm.end());
  argv.insert(argv.end(), {"--output", output});
  return argv;
}

TEST(LubricateGeometryCliTest, BuiltinSphereIsTheGeneratedHeightMap) {
  const TempDir dir;
  const std::vector<std::string> shape = {"--radius", "0.01", "--grid", "24x20", "--size", "4e-4x3e-4"};
  std::vector<std::string> generate = {"generate", "--kind", "sphere", "--output", "sphere.h5", "--quiet"};
  generate.insert(generate.end(), shape.begin(), shape.end());
  ASSERT_EQ(run_program(generate, dir.path()).exit_code, kExitOk);
  std::vector<std::string> builtin = {"--geometry", "sphere"};
  builtin.insert(builtin.end(), shape.begin(), shape.end());
  const ProgramRun from_shape = run_program(lubricate(builtin, "shape.h5"), dir.path());
  ASSERT_EQ(from_shape.exit_code, kExitOk) << from_shape.err;
  const ProgramRun from_file = run_program(lubricate({"--height-map", "sphere.h5"}, "file.h5"), dir.path());
  ASSERT_EQ(from_file.exit_code, kExitOk) << from_file.err;

  const test::H5 a = test::open_file(dir / "shape.h5");
  const test::H5 b = test::open_file(dir / "file.h5");
  EXPECT_NEAR(test::read_double_attribute(a.get(), "load"), 2.0, 1e-7 * 2.0);
  EXPECT_EQ(test::read_double_attribute(a.get(), "separation"), test::read_double_attribute(b.get(), "separation"));
  for (const char* field : {"/pressure", "/film", "/fluid_fraction"}) {
    EXPECT_EQ(test::read_dataset<double>(a.get(), field, H5T_NATIVE_DOUBLE),
              test::read_dataset<double>(b.get(), field, H5T_NATIVE_DOUBLE))
        << field;
  }
}

TEST(LubricateGeometryCliTest, RoughnessIsAddedToTheBuiltinSurface) {
  // A flat roughness file adds nothing: the same film as without it; a
  // wavy one changes the film.
  const TempDir dir;
  ASSERT_EQ(run_program({"generate", "--kind", "wavy", "--grid", "24x20", "--size", "4e-4x3e-4", "--wavelength", "1e-4",
                         "--amplitude", "2e-8", "--output", "wavy.h5", "--quiet"},
                        dir.path())
                .exit_code,
            kExitOk);
  ASSERT_EQ(run_program({"generate", "--kind", "flat", "--grid", "24x20", "--size", "4e-4x3e-4", "--output", "flat.h5",
                         "--quiet"},
                        dir.path())
                .exit_code,
            kExitOk);
  const std::vector<std::string> builtin = {"--geometry", "sphere", "--radius", "0.01",
                                            "--grid",     "24x20",  "--size",   "4e-4x3e-4"};
  std::vector<std::string> rough = builtin;
  rough.insert(rough.end(), {"--roughness", "flat.h5"});
  ASSERT_EQ(run_program(lubricate(builtin, "smooth.h5"), dir.path()).exit_code, kExitOk);
  const ProgramRun run = run_program(lubricate(rough, "rough.h5"), dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  const test::H5 a = test::open_file(dir / "smooth.h5");
  const test::H5 b = test::open_file(dir / "rough.h5");
  EXPECT_EQ(test::read_dataset<double>(a.get(), "/pressure", H5T_NATIVE_DOUBLE),
            test::read_dataset<double>(b.get(), "/pressure", H5T_NATIVE_DOUBLE));

  std::vector<std::string> wavy = builtin;
  wavy.insert(wavy.end(), {"--roughness", "wavy.h5"});
  const ProgramRun waved = run_program(lubricate(wavy, "wavy_film.h5"), dir.path());
  ASSERT_EQ(waved.exit_code, kExitOk) << waved.err;
  const test::H5 c = test::open_file(dir / "wavy_film.h5");
  EXPECT_NE(test::read_dataset<double>(a.get(), "/pressure", H5T_NATIVE_DOUBLE),
            test::read_dataset<double>(c.get(), "/pressure", H5T_NATIVE_DOUBLE));
}

TEST(LubricateGeometryCliTest, RefusesSurfaceOptionsThatDoNotApply) {
  const TempDir dir;
  ASSERT_EQ(run_program({"generate", "--kind", "cylinder", "--grid", "41", "--size", "8e-4", "--radius", "0.01",
                         "--output", "c.h5", "--quiet"},
                        dir.path())
                .exit_code,
            kExitOk);
  expect_input_error(run_program(lubricate({}, "f.h5"), dir.path()), {"no surface given", "--geometry"}, dir / "f.h5");
  expect_input_error(run_program(lubricate({"--height-map", "c.h5", "--geometry", "sphere"}, "f.h5"), dir.path()),
                     {"--height-map and --geometry"}, dir / "f.h5");
  expect_input_error(run_program(lubricate({"--height-map", "c.h5", "--radius", "0.01"}, "f.h5"), dir.path()),
                     {"--radius", "applies only to --geometry"}, dir / "f.h5");
  expect_input_error(
      run_program(lubricate({"--geometry", "sphere", "--radius", "0.01", "--size", "1e-3"}, "f.h5"), dir.path()),
      {"--geometry needs --grid"}, dir / "f.h5");
  expect_input_error(
      run_program(lubricate({"--geometry", "sphere", "--grid", "16", "--size", "1e-3"}, "f.h5"), dir.path()),
      {"needs --radius"}, dir / "f.h5");
  expect_input_error(
      run_program(lubricate({"--geometry", "cube", "--grid", "16", "--size", "1e-3"}, "f.h5"), dir.path()),
      {"--geometry", "cube"}, dir / "f.h5");
  expect_input_error(run_program(lubricate({"--geometry", "sphere", "--radius", "0.01", "--grid", "16", "--size",
                                            "1e-3", "--detrend", "mean"},
                                           "f.h5"),
                                 dir.path()),
                     {"--detrend", "applies only to --height-map"}, dir / "f.h5");
}

}  // namespace
}  // namespace halfspace
