// `halfspace stress` on a friction result: the shear tractions /shear_x and
// /shear_y beside the pressure are applied (the file holds what the library
// computes from all three), and the refusals of shear it cannot take.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "halfspace/io/result_pressure_reader.hpp"
#include "halfspace/stress/sliding_traction.hpp"
#include "halfspace/stress/stress_volume.hpp"
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

constexpr double kFriction = 0.3;

// A small free Hertz solve, to which a friction solve's fields are added by
// hand: `datasets` of gross sliding along x, q = mu p (and a zero q_y).
fs::path sliding_sphere(const TempDir& dir, const std::vector<std::string>& datasets = {"shear_x", "shear_y"}) {
  const ProgramRun run =
      run_program({"solve", "--geometry", "sphere", "--radius", "0.01", "--grid", "32x32", "--size", "4e-4", "--E-star",
                   "1e11", "--force", "1", "--threads", "1", "--output", "result.h5", "--quiet"},
                  dir.path());
  EXPECT_EQ(run.exit_code, kExitOk) << run.err;
  const fs::path path = dir / "result.h5";
  const io::ResultPressure result = io::read_result_pressure(path);
  const stress::SlidingShear q = stress::gross_sliding_shear(result.pressure, kFriction, 1.0);
  const test::H5 file(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose, "open for writing");
  for (const std::string& name : datasets) {
    test::add_double_dataset(file.get(), name, {32, 32}, name == "shear_x" ? q.x : q.y);
  }
  return path;
}

TEST(StressShearCliTest, AppliesTheShearTractionsOfAFrictionResult) {
  const TempDir dir;
  const fs::path result = sliding_sphere(dir);
  const ProgramRun run = run_program(
      {"stress", result.string(), "--depths", "1e-6,5e-6", "--nu", "0.3", "--output", "stress.h5", "--threads", "1"},
      dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  EXPECT_NE(run.out.find("pressure and shear (/shear_x, /shear_y)"), std::string::npos) << run.out;

  const io::ResultPressure input = io::read_result_pressure(result);
  ASSERT_TRUE(input.has_shear());
  const std::vector<double> depths = {1e-6, 5e-6};
  const stress::StressVolume with_shear = stress::compute_stress_volume(
      input.grid, stress::SurfaceTractions{input.pressure, input.shear_x, input.shear_y}, depths, 0.3);
  const stress::StressVolume without = stress::compute_stress_volume(input.grid, input.pressure, depths, 0.3);
  const test::H5 file = test::open_file(dir / "stress.h5");
  EXPECT_EQ(test::read_dataset<double>(file.get(), "/shear_x", H5T_NATIVE_DOUBLE), input.shear_x);
  EXPECT_EQ(test::read_dataset<double>(file.get(), "/shear_y", H5T_NATIVE_DOUBLE), input.shear_y);
  const test::H5 group(H5Gopen2(file.get(), "/stress", H5P_DEFAULT), H5Gclose, "open /stress");
  EXPECT_EQ(test::read_string_attribute(group.get(), "tractions"), "pressure and shear");
  for (std::size_t c = 0; c < stress::kComponentCount; ++c) {
    const std::string name = std::string("/stress/") + stress::kComponentNames[c];
    SCOPED_TRACE(name);
    EXPECT_EQ(test::read_dataset<double>(file.get(), name, H5T_NATIVE_DOUBLE), with_shear.components[c]);
  }
  // The shear changes the field: sigma_xz no longer vanishes at the surface
  // of the contact, and the largest von Mises stress grows.
  EXPECT_NE(with_shear.components[4], without.components[4]);
  EXPECT_GT(test::read_double_attribute(file.get(), "max_von_mises"), without.max_von_mises.value);
}

TEST(StressShearCliTest, RefusesShearItCannotTake) {
  {
    const TempDir dir;
    const fs::path result = sliding_sphere(dir, {"shear_x"});
    expect_input_error(
        run_program({"stress", result.string(), "--depths", "1e-6", "--nu", "0.3", "--output", "s.h5"}, dir.path()),
        "it has /shear_x but not /shear_y");
  }
  {
    const TempDir dir;
    const fs::path result = sliding_sphere(dir, {});
    {
      const test::H5 file(H5Fopen(result.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose, "open for writing");
      test::add_double_dataset(file.get(), "shear_x", {16, 64}, std::vector<double>(1024, 0.0));
      test::add_double_dataset(file.get(), "shear_y", {16, 64}, std::vector<double>(1024, 0.0));
    }
    expect_input_error(
        run_program({"stress", result.string(), "--depths", "1e-6", "--nu", "0.3", "--output", "s.h5"}, dir.path()),
        "its /shear_x has 16 x 64 values but /pressure has 32 x 32");
  }
  {
    // A coated half-space's result with shear on a free grid whose layer
    // is thick against the domain: refused as the pressure alone is,
    // naming the file and the bound (a thin one is computed:
    // layered_subsurface_shear_stress_test.cpp).
    const TempDir dir;
    const fs::path result = sliding_sphere(dir);
    {
      const test::H5 file(H5Fopen(result.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose, "open for writing");
      test::add_double_attribute(file.get(), "layer_thickness", 1e-3);
      test::add_double_attribute(file.get(), "layer_E", 2e11);
      test::add_double_attribute(file.get(), "layer_nu", 0.3);
      test::add_double_attribute(file.get(), "substrate_E", 1e11);
      test::add_double_attribute(file.get(), "substrate_nu", 0.25);
    }
    expect_input_error(run_program({"stress", result.string(), "--depths", "1e-6", "--output", "s.h5"}, dir.path()),
                       "result.h5 is a coated half-space's result: subsurface stresses in a coated half-space on a "
                       "free grid need a layer thickness t <= L/8");
  }
}

}  // namespace
}  // namespace halfspace
