// Whose stresses a friction result gives: on a rigid body 2 the elastic body
// 1 by default, under -q and with its own Poisson's ratio, in `solve
// --stress-depths` and `halfspace stress` alike (the result records both
// bodies); --stress-body / --body choose, and ambiguity is refused.
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
using testing::expect_input_error;
using testing::kExitOk;
using testing::ProgramRun;
using testing::run_program;

// An incompressible sphere (body 1) sliding on a rigid body 2 (Dundurs'
// beta = 0: uncoupled), on a free 24 x 24 grid.
std::vector<std::string> sliding_on_rigid(const std::string& output, const std::string& e2,
                                          const std::vector<std::string>& extra) {
  std::vector<std::string> a{"solve",     "--geometry", "sphere",   "--radius", "0.01",      "--grid",     "24x24",
                             "--size",    "4e-4",       "--E1",     "1e9",      "--nu1",     "0.5",        "--E2",
                             e2,          "--nu2",      "0.5",      "--force",  "10",        "--friction", "0.3",
                             "--sliding", "1,0",        "--output", output,     "--threads", "1",          "--quiet"};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

std::vector<double> field(const fs::path& path, const std::string& name) {
  const test::H5 file = test::open_file(path);
  return test::read_dataset<double>(file.get(), name, H5T_NATIVE_DOUBLE);
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

double largest(const std::vector<double>& a) {
  double m = 0.0;
  for (const double v : a) m = std::max(m, std::abs(v));
  return m;
}

TEST(StressedBodyCliTest, ARigidBodyTwoGivesBodyOnesStressesUnderMinusQ) {
  const TempDir dir;
  const std::vector<double> depths{2e-6, 1e-5};
  ProgramRun run = run_program(sliding_on_rigid("s.h5", "inf", {"--stress-depths", "2e-6,1e-5"}), dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;

  const io::ResultPressure input = io::read_result_pressure(dir / "s.h5");
  ASSERT_TRUE(input.bodies.has_value());
  EXPECT_TRUE(std::isinf((*input.bodies)[1].youngs_modulus));
  EXPECT_EQ((*input.bodies)[0].poissons_ratio, 0.5);
  std::vector<double> minus_x = input.shear_x, minus_y = input.shear_y;
  for (double& q : minus_x) q = -q;
  for (double& q : minus_y) q = -q;
  const stress::StressVolume body1 = stress::compute_stress_volume(
      input.grid, stress::SurfaceTractions{input.pressure, minus_x, minus_y}, depths, 0.5);
  const stress::StressVolume body2 = stress::compute_stress_volume(
      input.grid, stress::SurfaceTractions{input.pressure, input.shear_x, input.shear_y}, depths, 0.5);
  {
    const test::H5 file = test::open_file(dir / "s.h5");
    const test::H5 group(H5Gopen2(file.get(), "/stress", H5P_DEFAULT), H5Gclose, "open /stress");
    EXPECT_EQ(test::read_int64_attribute(group.get(), "body"), 1);
    EXPECT_EQ(test::read_double_attribute(group.get(), "poisson_ratio"), 0.5);
  }
  const std::vector<double> xz = field(dir / "s.h5", "/stress/sigma_xz");
  EXPECT_LE(largest_difference(xz, body1.components[4]), 1e-12 * largest(body1.components[4]));
  // The two bodies' fields differ by much more than rounding.
  EXPECT_GT(largest_difference(body1.components[4], body2.components[4]), 0.1 * largest(body1.components[4]));

  // `halfspace stress` needs no --nu: the file records both bodies; its
  // default is the solve's, and --body 2 gives body 2's field.
  run = run_program({"stress", "s.h5", "--depths", "2e-6,1e-5", "--output", "one.h5", "--threads", "1"}, dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  EXPECT_NE(run.out.find("body 1, Poisson's ratio 0.5"), std::string::npos) << run.out;
  EXPECT_LE(largest_difference(field(dir / "one.h5", "/stress/sigma_xz"), xz), 1e-12 * largest(xz));
  run = run_program({"stress", "s.h5", "--depths", "2e-6,1e-5", "--body", "2", "--output", "two.h5", "--threads", "1"},
                    dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  EXPECT_LE(largest_difference(field(dir / "two.h5", "/stress/sigma_xz"), body2.components[4]),
            1e-12 * largest(body2.components[4]));

  // --stress-body 2 in the solve: body 2's field.
  run =
      run_program(sliding_on_rigid("b2.h5", "inf", {"--stress-depths", "2e-6,1e-5", "--stress-body", "2"}), dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  EXPECT_LE(largest_difference(field(dir / "b2.h5", "/stress/sigma_xz"), body2.components[4]),
            1e-12 * largest(body2.components[4]));
}

TEST(StressedBodyCliTest, SimilarBodiesGiveBodyTwoWithTheirRatio) {
  const TempDir dir;
  const ProgramRun run = run_program(sliding_on_rigid("s.h5", "1e9", {"--stress-depths", "1e-5"}), dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  const test::H5 file = test::open_file(dir / "s.h5");
  const test::H5 group(H5Gopen2(file.get(), "/stress", H5P_DEFAULT), H5Gclose, "open /stress");
  EXPECT_EQ(test::read_int64_attribute(group.get(), "body"), 2);
  EXPECT_EQ(test::read_double_attribute(group.get(), "poisson_ratio"), 0.5);
}

TEST(StressedBodyCliTest, RefusalsNameTheOptions) {
  const TempDir dir;
  // Two elastic bodies of different Poisson's ratios: which is meant?
  std::vector<std::string> dissimilar = {
      "solve", "--geometry", "sphere", "--radius",        "0.01", "--grid",   "16x16", "--size",
      "4e-4",  "--E1",       "1e9",    "--nu1",           "0.3",  "--E2",     "2e9",   "--nu2",
      "0.25",  "--force",    "10",     "--stress-depths", "1e-5", "--output", "bad.h5"};
  expect_input_error(run_program(dissimilar, dir.path()), "pass --stress-body 1 or 2, or --stress-nu NU",
                     dir / "bad.h5");
  dissimilar.insert(dissimilar.end(), {"--stress-body", "3"});
  expect_input_error(run_program(dissimilar, dir.path()), "--stress-body 3 is invalid", dir / "bad.h5");
  expect_input_error(run_program(sliding_on_rigid("bad.h5", "inf", {"--stress-body", "1"}), dir.path()),
                     "needs --stress-depths", dir / "bad.h5");
  // A coated result has no body 2 to give.
  const std::vector<std::string> coated = {
      "solve", "--geometry",    "sphere",   "--radius",          "0.01",  "--grid",    "16x16", "--size",
      "4e-4",  "--boundary",    "periodic", "--layer-thickness", "2e-5",  "--layer-E", "1e9",   "--layer-nu",
      "0.3",   "--substrate-E", "2e9",      "--substrate-nu",    "0.3",   "--force",   "1",     "--stress-depths",
      "1e-5",  "--stress-body", "2",        "--output",          "bad.h5"};
  expect_input_error(run_program(coated, dir.path()), "--stress-body 2 is not available for a coated half-space",
                     dir / "bad.h5");
}

TEST(StressedBodyCliTest, AResultWithSomeOfTheBodiesAttributesIsRefused) {
  const TempDir dir;
  ProgramRun run = run_program(sliding_on_rigid("s.h5", "inf", {}), dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  {
    const test::H5 file(H5Fopen((dir / "s.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose, "open for writing");
    ASSERT_GE(H5Adelete(file.get(), "body2_nu"), 0);
  }
  run = run_program({"stress", "s.h5", "--depths", "1e-5", "--output", "t.h5"}, dir.path());
  EXPECT_NE(run.exit_code, kExitOk);
  EXPECT_NE(run.err.find("some but not all of both bodies' attributes (body1_E, body1_nu, body2_E, body2_nu)"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(dir / "t.h5"));
}

}  // namespace
}  // namespace halfspace
