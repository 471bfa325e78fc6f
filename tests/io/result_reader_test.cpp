// Tests of read_result: a result and a sweep written by the writers read
// back bit for bit, with every attribute, and the errors for files that are
// not results.
#include "halfspace/io/result_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/io/result_metadata.hpp"
#include "halfspace/io/result_writer.hpp"
#include "halfspace/io/sweep_writer.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "io/hdf5_test_support.hpp"

namespace halfspace::io {
namespace {

using test::TempDir;

Eigen::ArrayXd sphere_heights(const Grid& grid, double radius) {
  Eigen::ArrayXd h(static_cast<Eigen::Index>(grid.size()));
  for (std::size_t j = 0; j < grid.ny(); ++j) {
    for (std::size_t i = 0; i < grid.nx(); ++i) {
      const double x = (static_cast<double>(i) - 0.5 * static_cast<double>(grid.nx() - 1)) * grid.dx();
      const double y = (static_cast<double>(j) - 0.5 * static_cast<double>(grid.ny() - 1)) * grid.dy();
      h[static_cast<Eigen::Index>(j * grid.nx() + i)] = -(x * x + y * y) / (2.0 * radius);
    }
  }
  return h;
}

solvers::SolverOptions estimate_options() {
  solvers::SolverOptions options;
  options.fft_planning = FftPlanning::estimate;
  return options;
}

template <class T>
T attribute(const StoredResult& stored, const std::string& name) {
  const AttributeValue* value = stored.find(name);
  EXPECT_NE(value, nullptr) << name;
  return value ? std::get<T>(*value) : T{};
}

TEST(ResultReaderTest, ReadsBackWhatWriteResultWrote) {
  const TempDir dir;
  const Grid grid = Grid::plane(24, 16, 1e-5, 2e-5, Boundary::free);
  const Eigen::ArrayXd heights = sphere_heights(grid, 0.01);
  const std::span<const double> h(heights.data(), grid.size());
  const SolveResult result = solvers::solve_surface(grid, h, 1e9, Loading::force(0.05), estimate_options());
  ASSERT_TRUE(result.converged()) << result.message;
  ResultMetadata metadata = result_metadata({1e9, ControlMode::force, 1, "test", "", "sphere", {"a", "b"}}, grid, h);
  metadata.contact_statistics =
      analysis::contact_statistics(grid, {result.pressure.data(), grid.size()}, {result.gap.data(), grid.size()});
  write_result(dir / "r.h5", grid, h, result, metadata);

  const StoredResult stored = read_result(dir / "r.h5");
  EXPECT_EQ(stored.group, "/");
  EXPECT_EQ(stored.steps, 0);
  EXPECT_EQ(stored.shape, (std::vector<std::size_t>{16, 24}));
  EXPECT_TRUE((stored.height == heights).all());
  EXPECT_TRUE((stored.pressure == result.pressure).all());
  EXPECT_TRUE((stored.gap == result.gap).all());
  EXPECT_TRUE((stored.displacement == result.displacement).all());
  EXPECT_EQ(stored.residual_history, result.residual_history);
  for (std::size_t k = 0; k < grid.size(); ++k) {
    EXPECT_EQ(stored.contact[k], result.pressure[static_cast<Eigen::Index>(k)] > 0.0 ? 1 : 0);
  }
  EXPECT_EQ(attribute<std::string>(stored, "format"), "halfspace-result");
  EXPECT_EQ(attribute<std::int64_t>(stored, "iterations"), result.iterations);
  EXPECT_EQ(attribute<double>(stored, "approach"), result.approach);
  EXPECT_EQ(attribute<std::string>(stored, "preparation"), "a\nb");
  EXPECT_EQ(attribute<std::string>(stored, "load_mode"), "force");
  EXPECT_EQ(attribute<double>(stored, "surface_rms_height"), metadata.surface_statistics->rms_height);
}

TEST(ResultReaderTest, ReadsEachStepOfASweep) {
  const TempDir dir;
  const Grid grid = Grid::plane(16, 16, 1e-5, 1e-5, Boundary::periodic);
  const Eigen::ArrayXd heights = sphere_heights(grid, 0.01);
  const std::span<const double> h(heights.data(), grid.size());
  const std::vector<double> loads{1e5, 2e5, 4e5};
  const std::vector<analysis::SweepStep> steps =
      analysis::sweep_surface(grid, h, 1e9, ControlMode::mean_pressure, loads, estimate_options());
  write_sweep_result(dir / "s.h5", grid, h, steps,
                     result_metadata({1e9, ControlMode::mean_pressure, 1, "", "", "", {}}, grid, h));
  for (int k = 0; k < 3; ++k) {
    const StoredResult stored = read_result(dir / "s.h5", k);
    EXPECT_EQ(stored.steps, 3);
    EXPECT_EQ(stored.group, "/steps/00" + std::to_string(k));
    EXPECT_TRUE((stored.pressure == steps[static_cast<std::size_t>(k)].result.pressure).all()) << k;
    EXPECT_EQ(stored.cluster_sizes, steps[static_cast<std::size_t>(k)].statistics.cluster_sizes);
    EXPECT_EQ(attribute<double>(stored, "mean_pressure"), steps[static_cast<std::size_t>(k)].result.mean_pressure);
  }
  EXPECT_TRUE((read_result(dir / "s.h5").pressure == steps.back().result.pressure).all());
  EXPECT_THROW(read_result(dir / "s.h5", 3), FileError);
}

TEST(ResultReaderTest, RefusesWhatIsNotAResult) {
  const TempDir dir;
  try {
    read_result(dir / "missing.h5");
    ADD_FAILURE() << "no error";
  } catch (const FileError& error) {
    EXPECT_NE(std::string(error.what()).find("missing.h5': no such file"), std::string::npos) << error.what();
  }
  try {
    read_result(std::filesystem::path(HALFSPACE_TEST_DATA_DIR) / "di-5-crop-48x64.h5");
    ADD_FAILURE() << "no error";
  } catch (const FileError& error) {
    EXPECT_NE(std::string(error.what()).find("not a halfspace result"), std::string::npos) << error.what();
  }
}

// A result file that declares datasets it does not hold: the reader must
// refuse before allocating what the shape implies (a few hundred bytes of
// file could ask for any size; the height-map reader had these checks, the
// result reader, which `halfspace stress` uses, had not).
std::string hollow_result_error(const std::filesystem::path& path, std::vector<hsize_t> dims) {
  {
    const auto file = test::create_file(path);
    test::add_string_attribute(file.get(), "format", "halfspace-result");
    const test::H5 space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose, "space");
    const test::H5 creation(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "plist");
    std::vector<hsize_t> chunk(dims.size(), 2);
    H5Pset_chunk(creation.get(), static_cast<int>(chunk.size()), chunk.data());
    const test::H5 dataset(
        H5Dcreate2(file.get(), "height", H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, creation.get(), H5P_DEFAULT),
        H5Dclose, "dataset");
  }
  try {
    read_result(path);
  } catch (const FileError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no error for " << path;
  return {};
}

TEST(ResultReaderTest, RefusesDatasetsItWouldHaveToInvent) {
  const TempDir dir;
  const std::string never_written = hollow_result_error(dir / "never-written.h5", {3, 4});
  EXPECT_NE(never_written.find("dataset 'height': the dataset holds no stored data"), std::string::npos)
      << never_written;
  const std::string huge = hollow_result_error(dir / "huge.h5", {hsize_t{1} << 20, hsize_t{1} << 20});
  EXPECT_NE(huge.find("more than this machine's memory holds"), std::string::npos) << huge;
  const std::string overflowing = hollow_result_error(dir / "overflowing.h5", {hsize_t{1} << 40, hsize_t{1} << 40});
  EXPECT_NE(overflowing.find("whose size overflows"), std::string::npos) << overflowing;
}

}  // namespace
}  // namespace halfspace::io
