// Tests of the sweep writer on hand-made steps: group names, the summary
// table's values and units, the CSV's exact round trip, and the errors that
// leave nothing behind.
#include "halfspace/io/sweep_writer.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/io/result_attributes.hpp"
#include "io/hdf5_test_support.hpp"

namespace halfspace::io {
namespace {

using test::TempDir;

std::vector<analysis::SweepStep> make_steps(const Grid& grid, std::size_t count) {
  std::vector<analysis::SweepStep> steps(count);
  for (std::size_t k = 0; k < count; ++k) {
    analysis::SweepStep& s = steps[k];
    s.loading = Loading::force(0.1 * static_cast<double>(k + 1));
    s.result.status = k == 1 ? SolveStatus::iteration_limit : SolveStatus::converged;
    s.result.solver = "test";
    s.result.pressure = Eigen::ArrayXd::LinSpaced(static_cast<Eigen::Index>(grid.size()), 0.0, 1.0);
    s.result.gap = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(grid.size()));
    s.result.displacement = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(grid.size()));
    s.result.mean_pressure = 1.0 / 3.0 * static_cast<double>(k);  // not a short decimal
    s.result.iterations = static_cast<int>(k) + 5;
    s.statistics.cluster_sizes = {7, 2};
    s.statistics.free_volume = 1e-13 * static_cast<double>(k);
  }
  return steps;
}

TEST(SweepWriterTest, WritesGroupsTableAndExactCsv) {
  const TempDir dir;
  const Grid grid = Grid::line(6, 1e-6, Boundary::free);
  const std::vector<double> height(6, 0.0);
  const std::vector<analysis::SweepStep> steps = make_steps(grid, 3);
  ResultMetadata metadata;
  metadata.load_mode = "force";
  write_sweep_result(dir / "s.h5", grid, height, steps, metadata);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"s.csv", "s.h5", "s.xdmf"}))
      << "the pair, its sidecar, and no temporary file left";

  const test::H5 file = test::open_file(dir / "s.h5");
  EXPECT_EQ(test::dataset_shape(file.get(), "/steps/002/pressure"), (std::vector<hsize_t>{6}));
  EXPECT_EQ(test::read_dataset<std::int64_t>(file.get(), "/steps/000/cluster_sizes", H5T_NATIVE_INT64),
            (std::vector<std::int64_t>{7, 2}));
  EXPECT_EQ(test::read_dataset<double>(file.get(), "/sweep/converged", H5T_NATIVE_DOUBLE),
            (std::vector<double>{1, 0, 1}));
  // Units follow the dimension: a 1D force is N/m, a free volume m^2.
  const test::H5 load(H5Dopen2(file.get(), "/sweep/load", H5P_DEFAULT), H5Dclose, "open /sweep/load");
  EXPECT_EQ(test::read_string_attribute(load.get(), "units"), "N/m");
  const test::H5 volume(H5Dopen2(file.get(), "/sweep/free_volume", H5P_DEFAULT), H5Dclose, "open free_volume");
  EXPECT_EQ(test::read_string_attribute(volume.get(), "units"), "m^2");
  EXPECT_EQ(test::read_int64_attribute(file.get(), "sweep_steps"), 3);
  EXPECT_EQ(test::read_int64_attribute(file.get(), "iterations"), 7) << "the root describes the last step";

  // Every CSV number reads back to the same double.
  std::ifstream csv(dir / "s.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("load,mean_pressure,total_force,", 0), 0u) << header;
  const auto mean_pressure = test::read_dataset<double>(file.get(), "/sweep/mean_pressure", H5T_NATIVE_DOUBLE);
  for (std::size_t k = 0; std::getline(csv, line); ++k) {
    const std::size_t first = line.find(',');
    const std::size_t second = line.find(',', first + 1);
    EXPECT_EQ(std::strtod(line.substr(first + 1, second - first - 1).c_str(), nullptr), mean_pressure[k]) << line;
  }
}

// The .h5 records the MD5 of the .csv written with it; a previous sweep's
// .csv is replaced by the new one (write_sweep_csv writes the same bytes).
TEST(SweepWriterTest, TheCsvBesideTheFileIsTheOneItRecords) {
  const TempDir dir;
  const Grid grid = Grid::line(6, 1e-6, Boundary::free);
  const std::vector<double> height(6, 0.0);
  std::ofstream(dir / "s.csv") << "load\n1\n";  // a previous sweep's
  const std::vector<analysis::SweepStep> steps = make_steps(grid, 3);
  write_sweep_result(dir / "s.h5", grid, height, steps, ResultMetadata{});
  const std::string recorded = test::read_string_attribute(test::open_file(dir / "s.h5").get(), "summary_csv_md5");
  EXPECT_EQ(recorded.size(), 32u);
  const auto md5_of = [&](const std::string& name) {
    const std::string command = fmt::format("md5sum {} > {}", (dir / name).string(), (dir / "sum.txt").string());
    EXPECT_EQ(std::system(command.c_str()), 0);
    std::ifstream sum(dir / "sum.txt");
    std::string digest;
    sum >> digest;
    return digest;
  };
  EXPECT_EQ(md5_of("s.csv"), recorded);
  write_sweep_csv(dir / "apart.csv", steps);
  EXPECT_EQ(md5_of("apart.csv"), recorded);
  // Another sweep's table has another digest.
  write_sweep_csv(dir / "other.csv", make_steps(grid, 2));
  EXPECT_NE(md5_of("other.csv"), recorded);
}

TEST(SweepWriterTest, ManyStepsGetWiderNamesThatStillSort) {
  const TempDir dir;
  const Grid grid = Grid::line(2, 1.0, Boundary::free);
  write_sweep_result(dir / "many.h5", grid, std::vector<double>(2, 0.0), make_steps(grid, 1001), ResultMetadata{});
  const test::H5 file = test::open_file(dir / "many.h5");
  EXPECT_GT(H5Lexists(file.get(), "/steps/0000", H5P_DEFAULT), 0);
  EXPECT_GT(H5Lexists(file.get(), "/steps/1000", H5P_DEFAULT), 0);
}

TEST(SweepWriterTest, RejectsBadInputWithoutWriting) {
  const TempDir dir;
  const Grid grid = Grid::line(6, 1e-6, Boundary::free);
  std::vector<analysis::SweepStep> steps = make_steps(grid, 2);
  EXPECT_THROW(write_sweep_result(dir / "a.h5", grid, std::vector<double>(6, 0.0), {}, ResultMetadata{}), InputError);
  EXPECT_THROW(write_sweep_result(dir / "a.h5", grid, std::vector<double>(5, 0.0), steps, ResultMetadata{}),
               InputError);
  steps[1].result.gap = Eigen::ArrayXd::Zero(3);
  try {
    write_sweep_result(dir / "a.h5", grid, std::vector<double>(6, 0.0), steps, ResultMetadata{});
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("field 'gap' of step 1 has 3 values but the grid has 6 cells"),
              std::string::npos)
        << error.what();
  }
  try {
    write_sweep_csv(dir / "missing" / "a.csv", make_steps(grid, 1));
    ADD_FAILURE() << "no error";
  } catch (const FileError& error) {
    EXPECT_NE(std::string(error.what()).find("cannot write output"), std::string::npos) << error.what();
  }
  EXPECT_TRUE(dir.entries().empty());
  EXPECT_EQ(sweep_csv_path("run/sweep.h5"), std::filesystem::path("run/sweep.csv"));
  EXPECT_EQ(sweep_csv_path("result"), std::filesystem::path("result.csv"));
}

// The names of every attribute on `location`, read with the HDF5 C API.
std::set<std::string> attribute_names(hid_t location) {
  std::set<std::string> names;
  const auto collect = [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
    static_cast<std::set<std::string>*>(data)->insert(name);
    return 0;
  };
  test::check(H5Aiterate2(location, H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, collect, &names), "iterate attributes");
  return names;
}

// Every attribute of a single result, but those describing the whole file
// (format, grid, material, provenance, the surface), is on each sweep step
// too: the writers take them from one table and cannot drift apart.
TEST(SweepWriterTest, StepGroupsHaveEveryResultAttributeOfASingleSolve) {
  const TempDir dir;
  const Grid grid = Grid::line(6, 1e-6, Boundary::free);
  const std::vector<double> height(6, 0.0);
  std::vector<analysis::SweepStep> steps = make_steps(grid, 2);
  steps[1].result.deflation.block = 8;
  steps[1].result.deflation.deflated_iterations = 3;
  steps[1].result.deflation.fast_rate = 0.25;
  ResultMetadata metadata;
  metadata.load_mode = "force";
  metadata.contact_statistics = steps[1].statistics;
  write_result(dir / "single.h5", grid, height, steps[1].result, metadata);
  write_sweep_result(dir / "sweep.h5", grid, height, steps, metadata);

  const std::set<std::string> file_level{"format",
                                         "format_version",
                                         "units",
                                         "dimension",
                                         "nx",
                                         "ny",
                                         "dx",
                                         "dy",
                                         "boundary",
                                         "E_star",
                                         "load_mode",
                                         "threads",
                                         "halfspace_version",
                                         "command_line",
                                         "config",
                                         "height_source",
                                         "preparation",
                                         "surface_rms_height",
                                         "surface_rms_slope"};
  const test::H5 single = test::open_file(dir / "single.h5");
  std::set<std::string> expected = attribute_names(single.get());
  for (const std::string& name : file_level) expected.erase(name);
  ASSERT_GE(expected.size(), result_attributes().size() + 4) << "result attributes and contact statistics";
  for (const ResultAttribute& attribute : result_attributes()) {
    EXPECT_TRUE(expected.contains(std::string(attribute.name))) << attribute.name;
  }

  const test::H5 sweep = test::open_file(dir / "sweep.h5");
  for (const char* step : {"/steps/000", "/steps/001"}) {
    const test::H5 group(H5Gopen2(sweep.get(), step, H5P_DEFAULT), H5Gclose, step);
    const std::set<std::string> present = attribute_names(group.get());
    for (const std::string& name : expected) EXPECT_TRUE(present.contains(name)) << step << " lacks " << name;
  }
  const test::H5 last(H5Gopen2(sweep.get(), "/steps/001", H5P_DEFAULT), H5Gclose, "/steps/001");
  EXPECT_EQ(test::read_int64_attribute(last.get(), "deflation_block"), 8);
  EXPECT_EQ(test::read_int64_attribute(last.get(), "deflated_iterations"), 3);
  EXPECT_EQ(test::read_double_attribute(last.get(), "undeflated_rate"), 0.25);
  EXPECT_EQ(test::read_string_attribute(last.get(), "solver"), "test");
}

}  // namespace
}  // namespace halfspace::io
