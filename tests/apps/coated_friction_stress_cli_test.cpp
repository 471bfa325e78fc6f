// Subsurface stresses of a coated half-space under friction through the real
// executable: --stress-depths on a coated frictional solve (periodic) and
// `halfspace stress` on its result give the coated body's field under the
// traction on it (-q, the coated body being body 1), equal to the library's
// and with the surface traction it must have.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "halfspace/io/result_pressure_reader.hpp"
#include "halfspace/stress/stress_volume.hpp"
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

// A hard coating (t = 20 um, 400 GPa on 200 GPa steel).
const LayeredMaterial kCoating{2e-5, ElasticBody{4e11, 0.22}, ElasticBody{2e11, 0.3}};

// A 10 mm sphere under 10 N on the coating, sliding along x (mu = 0.3), on a
// periodic 32 x 32 grid 0.4 mm wide, with `extra` options.
std::vector<std::string> sliding_coated_sphere(const std::string& output, const std::vector<std::string>& extra) {
  std::vector<std::string> arguments = {"solve",
                                        "--geometry",
                                        "sphere",
                                        "--radius",
                                        "0.01",
                                        "--grid",
                                        "32x32",
                                        "--size",
                                        "4e-4",
                                        "--boundary",
                                        "periodic",
                                        "--layer-thickness",
                                        fmt::format("{}", kCoating.thickness),
                                        "--layer-E",
                                        fmt::format("{}", kCoating.layer.youngs_modulus),
                                        "--layer-nu",
                                        fmt::format("{}", kCoating.layer.poissons_ratio),
                                        "--substrate-E",
                                        fmt::format("{}", kCoating.substrate.youngs_modulus),
                                        "--substrate-nu",
                                        fmt::format("{}", kCoating.substrate.poissons_ratio),
                                        "--force",
                                        "10",
                                        "--friction",
                                        "0.3",
                                        "--sliding",
                                        "1,0",
                                        "--threads",
                                        "1",
                                        "--quiet",
                                        "--output",
                                        output};
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  return arguments;
}

std::vector<double> dataset(const test::H5& file, const std::string& name) {
  return test::read_dataset<double>(file.get(), name, H5T_NATIVE_DOUBLE);
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

TEST(CoatedFrictionStressCliTest, StressDepthsAndTheStressCommandTakeTheCoatedBodysShear) {
  const TempDir dir;
  // A depth in the layer close to the surface (0.01 of a cell), one in the
  // layer and one in the substrate.
  const std::vector<double> depths = {1.25e-7, 1e-5, 3e-5};
  const std::string depth_list = "1.25e-7,1e-5,3e-5";
  ProgramRun run = run_program(sliding_coated_sphere("s.h5", {"--stress-depths", depth_list}), dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  run = run_program({"stress", "s.h5", "--depths", depth_list, "--output", "alone.h5", "--threads", "1"}, dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  EXPECT_NE(run.out.find("pressure and shear"), std::string::npos) << run.out;

  const io::ResultPressure input = io::read_result_pressure(dir / "s.h5");
  ASSERT_TRUE(input.has_shear());
  ASSERT_TRUE(input.coating.has_value());
  // The coated body carries -q: the library's field under it.
  std::vector<double> on_body1_x = input.shear_x;
  std::vector<double> on_body1_y = input.shear_y;
  for (double& q : on_body1_x) q = -q;
  for (double& q : on_body1_y) q = -q;
  const stress::StressVolume expected = stress::compute_stress_volume(
      input.grid, stress::SurfaceTractions{input.pressure, on_body1_x, on_body1_y}, depths, *input.coating);
  const stress::StressVolume pressure_only =
      stress::compute_stress_volume(input.grid, input.pressure, depths, *input.coating);

  const test::H5 solved = test::open_file(dir / "s.h5");
  const test::H5 alone = test::open_file(dir / "alone.h5");
  const test::H5 group(H5Gopen2(solved.get(), "/stress", H5P_DEFAULT), H5Gclose, "open /stress");
  EXPECT_EQ(test::read_string_attribute(group.get(), "tractions"), "pressure and shear");
  EXPECT_EQ(test::read_int64_attribute(group.get(), "body"), 1);
  EXPECT_EQ(test::read_dataset<std::uint8_t>(solved.get(), "/stress/in_layer", H5T_NATIVE_UINT8),
            (std::vector<std::uint8_t>{1, 1, 0}));
  const double p_max = *std::max_element(input.pressure.begin(), input.pressure.end());
  for (std::size_t c = 0; c < stress::kComponentCount; ++c) {
    const std::string name = std::string("/stress/") + stress::kComponentNames[c];
    SCOPED_TRACE(name);
    // The same library call in both programs, the same transforms.
    EXPECT_LE(largest_difference(dataset(solved, name), expected.components[c]), 1e-12 * p_max);
    EXPECT_LE(largest_difference(dataset(alone, name), expected.components[c]), 1e-12 * p_max);
  }
  // At 0.01 of a cell the field is the surface's: sigma_xz = -(traction on
  // the coated body) = +q_x of the result where the contact slides (the
  // wrong sign would be 2 q_x off). Sampled at the cell centres, a
  // cell-constant traction's field there differs from it by its spectrum's
  // cut at the Nyquist wavenumber (docs/theory.md): a homogeneous body of the
  // layer's material, whose field this one equals at the surface to O(q z),
  // differs from q_x as much (measured 7% of the peak inside the contact;
  // 4.8e-3 between the two, O(q z) with q z <= 0.03 up to the Nyquist
  // wavenumber).
  const stress::StressVolume layer_material =
      stress::compute_stress_volume(input.grid, stress::SurfaceTractions{input.pressure, on_body1_x, on_body1_y},
                                    depths, kCoating.layer.poissons_ratio);
  const std::size_t cells = input.grid.size();
  double from_traction = 0.0;
  double from_layer = 0.0;
  double peak = 0.0;
  for (std::size_t k = 0; k < cells; ++k) {
    peak = std::max(peak, std::abs(input.shear_x[k]));
    // Inside the contact, away from its edge, where q_x varies smoothly.
    if (input.pressure[k] > 0.5 * p_max) {
      from_traction = std::max(from_traction, std::abs(expected.components[4][k] - input.shear_x[k]));
      from_layer = std::max(from_layer, std::abs(expected.components[4][k] - layer_material.components[4][k]));
    }
  }
  std::printf(
      "coated sliding sphere, sigma_xz at 0.01 cell depth: %.2e of the peak q_x = %.3g Pa from q_x, %.2e from the "
      "layer material's\n",
      from_traction / peak, peak, from_layer / peak);
  EXPECT_GT(peak, 0.25 * p_max);
  EXPECT_LT(from_traction, 0.1 * peak);
  EXPECT_LT(from_layer, 0.01 * peak);
  EXPECT_GT(largest_difference(expected.components[4], pressure_only.components[4]), 0.25 * p_max);
  EXPECT_GT(test::read_double_attribute(solved.get(), "max_von_mises"), pressure_only.max_von_mises.value);
}

}  // namespace
}  // namespace halfspace
