// Tests of `halfspace stress` through the real executable: a round trip from a
// solved result to the stress file (layout, units, values against the
// library), and its refusals of bad input.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
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
using testing::kExitInputError;
using testing::kExitOk;
using testing::ProgramRun;
using testing::run_program;

// A small free Hertz solve to take the stresses of.
fs::path solved_sphere(const TempDir& dir) {
  const ProgramRun run =
      run_program({"solve", "--geometry", "sphere", "--radius", "0.01", "--grid", "32x32", "--size", "4e-4", "--E-star",
                   "1e11", "--force", "1", "--threads", "1", "--output", "result.h5", "--quiet"},
                  dir.path());
  EXPECT_EQ(run.exit_code, kExitOk) << run.err;
  return dir / "result.h5";
}

TEST(StressCliTest, WritesTheStressFieldOfAResult) {
  const TempDir dir;
  const fs::path result = solved_sphere(dir);
  const ProgramRun run = run_program({"stress", result.string(), "--depths", "1e-6,5e-6,2e-5", "--nu", "0.3",
                                      "--output", "stress.h5", "--threads", "1"},
                                     dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  EXPECT_NE(run.out.find("max von Mises"), std::string::npos) << run.out;

  const test::H5 file = test::open_file(dir / "stress.h5");
  EXPECT_EQ(test::read_string_attribute(file.get(), "format"), "halfspace-stress");
  EXPECT_EQ(test::read_string_attribute(file.get(), "boundary"), "free");
  EXPECT_EQ(test::dataset_shape(file.get(), "/stress/depths"), (std::vector<hsize_t>{3}));
  const std::vector<double> depths = test::read_dataset<double>(file.get(), "/stress/depths", H5T_NATIVE_DOUBLE);
  EXPECT_EQ(depths, (std::vector<double>{1e-6, 5e-6, 2e-5}));

  // The file holds what the library computes from the result's pressure.
  const io::ResultPressure input = io::read_result_pressure(result);
  const stress::StressVolume expected = stress::compute_stress_volume(input.grid, input.pressure, depths, 0.3);
  const char* names[] = {"sigma_xx", "sigma_yy", "sigma_zz",  "sigma_xy",
                         "sigma_xz", "sigma_yz", "von_mises", "max_shear"};
  for (std::size_t c = 0; c < 8; ++c) {
    const std::string name = std::string("/stress/") + names[c];
    SCOPED_TRACE(name);
    EXPECT_EQ(test::dataset_shape(file.get(), name), (std::vector<hsize_t>{3, 32, 32}));
    const test::H5 dataset(H5Oopen(file.get(), name.c_str(), H5P_DEFAULT), H5Oclose, "open " + name);
    EXPECT_EQ(test::read_string_attribute(dataset.get(), "units"), "Pa");
    const std::vector<double> values = test::read_dataset<double>(file.get(), name, H5T_NATIVE_DOUBLE);
    const std::vector<double>& reference =
        c < 6 ? expected.components[c] : (c == 6 ? expected.von_mises : expected.max_shear);
    EXPECT_EQ(values, reference);
  }
  const std::vector<double> vm = test::read_dataset<double>(file.get(), "/stress/von_mises", H5T_NATIVE_DOUBLE);
  EXPECT_EQ(test::read_double_attribute(file.get(), "max_von_mises"), *std::max_element(vm.begin(), vm.end()));
  EXPECT_EQ(test::read_double_attribute(file.get(), "max_von_mises_x"), expected.max_von_mises.x);
  EXPECT_EQ(test::read_double_attribute(file.get(), "max_von_mises_y"), expected.max_von_mises.y);
  EXPECT_EQ(test::read_double_attribute(file.get(), "max_von_mises_z"), expected.max_von_mises.z);
  // Compression below the contact.
  const std::vector<double> szz = test::read_dataset<double>(file.get(), "/stress/sigma_zz", H5T_NATIVE_DOUBLE);
  EXPECT_LT(*std::min_element(szz.begin(), szz.end()), 0.0);
}

TEST(StressCliTest, DepthRangeIsEvenlySpaced) {
  const TempDir dir;
  const fs::path result = solved_sphere(dir);
  const ProgramRun run = run_program({"stress", result.string(), "--depth-range", "1e-6:4e-6:4", "--nu", "0.25",
                                      "--output", "stress.h5", "--quiet", "--threads", "1"},
                                     dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  EXPECT_EQ(run.out, "");
  const test::H5 file = test::open_file(dir / "stress.h5");
  const std::vector<double> depths = test::read_dataset<double>(file.get(), "/stress/depths", H5T_NATIVE_DOUBLE);
  ASSERT_EQ(depths.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(depths[k], 1e-6 * (k + 1), 1e-20);
}

TEST(StressCliTest, RefusesBadInput) {
  const TempDir dir;
  const fs::path result = solved_sphere(dir);
  const std::string in = result.string();
  const auto run = [&](std::vector<std::string> arguments) {
    arguments.insert(arguments.begin(), "stress");
    return run_program(arguments, dir.path());
  };
  expect_input_error(run({in, "--depths", "1e-6", "--output", "s.h5"}), "E* alone does not fix it");
  expect_input_error(run({in, "--depths", "1e-6", "--nu", "0.6", "--output", "s.h5"}),
                     "--nu 0.6 is invalid: allowed range is -1 < nu <= 0.5");
  expect_input_error(run({in, "--depths", "1e-6,-2e-6", "--nu", "0.3", "--output", "s.h5"}),
                     "every depth must be > 0 m");
  expect_input_error(run({in, "--depths", "1e-6,abc", "--nu", "0.3", "--output", "s.h5"}), "the part 'abc'");
  expect_input_error(run({in, "--nu", "0.3", "--output", "s.h5"}), "no depth given");
  expect_input_error(run({in, "--depths", "1e-6", "--depth-range", "1e-6:2e-6:2", "--nu", "0.3", "--output", "s.h5"}),
                     "were both given");
  expect_input_error(run({in, "--depth-range", "2e-6:1e-6:3", "--nu", "0.3", "--output", "s.h5"}),
                     "need 0 < START < STOP");
  expect_input_error(run({in, "--depth-range", "1e-6:2e-6:100000", "--nu", "0.3", "--output", "s.h5"}),
                     "outside the allowed range 1 to 4096");
  expect_input_error(run({in, "--depths", "1e-6", "--nu", "0.3", "--output", in}), "is the input result file");
  expect_input_error(run({in, "--depths", "1e-6", "--nu", "0.3", "--output", "s.h5", "--max-memory", "1M"}),
                     "needs about");
  expect_input_error(run({"missing.h5", "--depths", "1e-6", "--nu", "0.3", "--output", "s.h5"}), "missing.h5");
  // A height map is not a result: it has no pressure.
  ASSERT_EQ(
      run_program({"generate", "--kind", "flat", "--grid", "8x8", "--size", "8e-6", "--output", "flat.h5", "--quiet"},
                  dir.path())
          .exit_code,
      kExitOk);
  expect_input_error(run({"flat.h5", "--depths", "1e-6", "--nu", "0.3", "--output", "s.h5"}),
                     "cannot read result file 'flat.h5': its pressure cannot be read");
  EXPECT_FALSE(fs::exists(dir / "s.h5"));
  EXPECT_TRUE(fs::exists(result));  // the input is never touched
}

TEST(StressCliTest, SolveWritesTheStressGroupIntoTheResult) {
  const TempDir dir;
  const std::vector<std::string> sphere = {"solve",  "--geometry", "sphere", "--radius", "0.01",
                                           "--grid", "32x32",      "--size", "4e-4",     "--force",
                                           "1",      "--threads",  "1",      "--quiet",  "--output"};
  std::vector<std::string> with_e_star = sphere;
  for (const char* a : {"result.h5", "--E-star", "1e11", "--stress-depths", "2e-6,8e-6", "--stress-nu", "0.3"}) {
    with_e_star.push_back(a);
  }
  const ProgramRun run = run_program(with_e_star, dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  {
    const test::H5 file = test::open_file(dir / "result.h5");
    EXPECT_EQ(test::dataset_shape(file.get(), "/stress/sigma_zz"), (std::vector<hsize_t>{2, 32, 32}));
    EXPECT_EQ(test::dataset_shape(file.get(), "/pressure"), (std::vector<hsize_t>{32, 32}));
    const test::H5 group(H5Oopen(file.get(), "/stress", H5P_DEFAULT), H5Oclose, "open /stress");
    EXPECT_EQ(test::read_double_attribute(group.get(), "poisson_ratio"), 0.3);
    EXPECT_GT(test::read_double_attribute(file.get(), "max_von_mises"), 0.0);
    // The same field as the stress command computes from the result.
    const io::ResultPressure input = io::read_result_pressure(dir / "result.h5");
    const std::vector<double> depths = {2e-6, 8e-6};
    const stress::StressVolume expected = stress::compute_stress_volume(input.grid, input.pressure, depths, 0.3);
    // solve plans its transforms with FFTW_MEASURE: other algorithms, other rounding.
    const std::vector<double> vm = test::read_dataset<double>(file.get(), "/stress/von_mises", H5T_NATIVE_DOUBLE);
    ASSERT_EQ(vm.size(), expected.von_mises.size());
    const double scale = *std::max_element(vm.begin(), vm.end());
    for (std::size_t k = 0; k < vm.size(); ++k) ASSERT_NEAR(vm[k], expected.von_mises[k], 1e-12 * scale) << k;
  }

  // Poisson's ratio from equal --nu1 and --nu2; a range of depths.
  std::vector<std::string> with_bodies = sphere;
  for (const char* a : {"bodies.h5", "--E1", "2e11", "--nu1", "0.3", "--E2", "2e11", "--nu2", "0.3", "--stress-depths",
                        "1e-6:4e-6:3"}) {
    with_bodies.push_back(a);
  }
  ASSERT_EQ(run_program(with_bodies, dir.path()).exit_code, kExitOk);
  {
    const test::H5 file = test::open_file(dir / "bodies.h5");
    EXPECT_EQ(test::dataset_shape(file.get(), "/stress/max_shear"), (std::vector<hsize_t>{3, 32, 32}));
  }

  // Refusals: no Poisson's ratio with E* alone, or with unequal bodies; a sweep.
  std::vector<std::string> no_nu = sphere;
  for (const char* a : {"none.h5", "--E-star", "1e11", "--stress-depths", "1e-6"}) no_nu.push_back(a);
  expect_input_error(run_program(no_nu, dir.path()), "E* alone does not fix it");
  std::vector<std::string> unequal = sphere;
  for (const char* a :
       {"none.h5", "--E1", "2e11", "--nu1", "0.3", "--E2", "1e11", "--nu2", "0.25", "--stress-depths", "1e-6"}) {
    unequal.push_back(a);
  }
  expect_input_error(run_program(unequal, dir.path()), "--stress-nu");
  std::vector<std::string> bad_depth = sphere;
  for (const char* a : {"none.h5", "--E-star", "1e11", "--stress-depths", "0", "--stress-nu", "0.3"}) {
    bad_depth.push_back(a);
  }
  expect_input_error(run_program(bad_depth, dir.path()), "--stress-depths 0 is invalid");
  EXPECT_FALSE(fs::exists(dir / "none.h5"));
}

// A copy of `result` whose root attribute `name` is replaced by `rewrite`
// (which creates the new one on the open file).
template <class Rewrite>
fs::path altered_result(const fs::path& result, const std::string& copy, const char* name, Rewrite rewrite) {
  const fs::path path = result.parent_path() / copy;
  fs::copy_file(result, path, fs::copy_options::overwrite_existing);
  const test::H5 file(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose, "open " + path.string());
  test::check(H5Adelete(file.get(), name), std::string("delete ") + name);
  rewrite(file.get());
  return path;
}

// Depths outside the grid's range, and results whose stresses would not be
// finite, are refused and nothing is written (a depth of 1e154 m wrote
// all-NaN fields and exit 0; dx = 1e300 m was refused without naming the
// file or the attribute).
TEST(StressCliTest, RefusesDepthsAndGridsWhoseStressesAreNotFinite) {
  const TempDir dir;
  const fs::path result = solved_sphere(dir);  // 32x32 cells of 1.25e-5 m
  const auto run = [&](const fs::path& input, const std::string& depths) {
    return run_program({"stress", input.string(), "--depths", depths, "--nu", "0.3", "--output", "s.h5"}, dir.path());
  };
  expect_input_error(run(result, "1e154"),
                     "--depths 1e154: depth = 1e+154 m is outside the allowed range 1.25e-11 to 0.004 m on the free "
                     "32x32 grid");
  expect_input_error(run(result, "1e-6,5e-3"), "depth = 0.005 m is outside the allowed range");
  for (const double dx : {1e150, 1e300}) {
    const fs::path huge =
        altered_result(result, "huge.h5", "dx", [&](hid_t file) { test::add_double_attribute(file, "dx", dx); });
    const ProgramRun refused = run(huge, "1e-6");
    expect_input_error(refused, "result file '" + huge.string() + "'");
    expect_input_error(refused, fmt::format("dx = {:.6g} m", dx));
  }
  EXPECT_FALSE(fs::exists(dir / "s.h5"));
}

// The input must be a result: a stress file (which has a /pressure too) and
// a result whose 'boundary' holds two strings are refused.
TEST(StressCliTest, RefusesFilesThatAreNotAResult) {
  const TempDir dir;
  const fs::path result = solved_sphere(dir);
  const auto run = [&](const fs::path& input) {
    return run_program({"stress", input.string(), "--depths", "1e-6", "--nu", "0.3", "--output", "out.h5"}, dir.path());
  };
  ASSERT_EQ(
      run_program({"stress", result.string(), "--depths", "1e-6", "--nu", "0.3", "--output", "stress.h5", "--quiet"},
                  dir.path())
          .exit_code,
      kExitOk);
  expect_input_error(run(dir / "stress.h5"),
                     "its root attribute format = 'halfspace-stress' is not 'halfspace-result'");
  const fs::path two = altered_result(result, "two.h5", "boundary", [](hid_t file) {
    const test::H5 type(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
    test::check(H5Tset_size(type.get(), 8), "string size");
    const hsize_t count = 2;
    const test::H5 space(H5Screate_simple(1, &count, nullptr), H5Sclose, "space");
    const test::H5 attribute(H5Acreate2(file, "boundary", type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                             "create boundary");
    const char values[17] = "free\0\0\0\0periodic";  // two 8-character strings
    test::check(H5Awrite(attribute.get(), type.get(), values), "write boundary");
  });
  expect_input_error(run(two), "its root attribute 'boundary' holds 2 values; expected one string");
  EXPECT_FALSE(fs::exists(dir / "out.h5"));
}

// solve --stress-depths: a depth beyond the grid's range is refused before the
// solve (it reported converged with a maximum that ignored the NaN depth);
// the messages name the option as given, or the config file's key and file.
TEST(StressCliTest, SolveRefusesStressDepthsOutsideTheGrid) {
  const TempDir dir;
  const std::vector<std::string> sphere = {"solve", "--geometry", "sphere",      "--radius", "0.01",     "--grid",
                                           "32x32", "--size",     "4e-4",        "--force",  "1",        "--E-star",
                                           "1e11",  "--quiet",    "--stress-nu", "0.3",      "--output", "none.h5"};
  std::vector<std::string> deep = sphere;
  for (const char* a : {"--stress-depths", "1e-6,1e200"}) deep.push_back(a);
  expect_input_error(run_program(deep, dir.path()),
                     "--stress-depths 1e-6,1e200: depth = 1e+200 m is outside the allowed range");
  std::vector<std::string> many = sphere;
  for (const char* a : {"--stress-depths", "1e-6:1e-5:4097"}) many.push_back(a);
  const ProgramRun too_many = run_program(many, dir.path());
  expect_input_error(too_many, "--stress-depths 1e-6:1e-5:4097 is invalid: COUNT = 4097");
  EXPECT_EQ(too_many.err.find("depth-range"), std::string::npos) << too_many.err;
  {
    std::ofstream config(dir / "run.toml");
    config << "stress-depths = \"1e-6:1e-5:4097\"\n";
  }
  std::vector<std::string> from_file = sphere;
  for (const char* a : {"--config", "run.toml"}) from_file.push_back(a);
  expect_input_error(run_program(from_file, dir.path()), R"(stress-depths = "1e-6:1e-5:4097" in run.toml is invalid)");
  EXPECT_FALSE(fs::exists(dir / "none.h5"));
}

}  // namespace
}  // namespace halfspace
