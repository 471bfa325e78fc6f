// The files of the Table 1 reproduction: the CSV and HDF5 hold the same
// columns, values round-trip exactly, and the summary table lists each test.
#include "halfspace/paper/paper_output.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/io/result_attributes.hpp"
#include "io/hdf5_test_support.hpp"

namespace halfspace {
namespace {

using test::TempDir;

// Test 4 has 7 nodes: quick, and enough for the file layout.
paper::TestReproduction small_run() {
  return paper::reproduce(paper::table1_test(4), {});
}

std::vector<std::string> lines_of(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(PaperOutputTest, CsvHoldsTheColumnsToFullPrecision) {
  const TempDir dir;
  const paper::TestReproduction run = small_run();
  paper::write_csv(dir / "test4.csv", run);
  const std::vector<std::string> lines = lines_of(dir / "test4.csv");
  ASSERT_EQ(lines.size(), 8U);
  EXPECT_EQ(lines[0], "x,gap,p_lemke,p_lcpquad,p_pk,p_hertz");
  for (std::size_t i = 0; i < 7; ++i) {
    std::istringstream row(lines[i + 1]);
    std::vector<double> values;
    for (std::string cell; std::getline(row, cell, ',');) values.push_back(std::stod(cell));
    ASSERT_EQ(values.size(), 6U) << lines[i + 1];
    const auto k = static_cast<Eigen::Index>(i);
    EXPECT_EQ(values[0], run.contact.x[i]);
    EXPECT_EQ(values[1], run.contact.initial_gap[k]);
    EXPECT_EQ(values[2], run.lemke.pressure[k]);
    EXPECT_EQ(values[3], run.lcpquad.pressure[k]);
    EXPECT_EQ(values[4], run.pk.pressure[k]);
    EXPECT_EQ(values[5], run.hertz_pressure[k]);
  }
}

TEST(PaperOutputTest, HdfFileHoldsTheSameDataAndTheOutcomes) {
  const TempDir dir;
  const paper::TestReproduction run = small_run();
  paper::write_hdf5(dir / "test4.h5", run, {});
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"test4.h5"});  // no temporary left behind
  const test::H5 file = test::open_file(dir / "test4.h5");
  EXPECT_EQ(test::read_string_attribute(file.get(), "format"), "halfspace-paper-test");
  EXPECT_EQ(test::read_int64_attribute(file.get(), "test"), 4);
  EXPECT_EQ(test::read_double_attribute(file.get(), "hertz_peak"), run.contact.hertz.peak);
  EXPECT_EQ(test::read_int64_attribute(file.get(), "lemke_pivots"), run.lemke_report.iterations);
  EXPECT_EQ(test::read_string_attribute(file.get(), "lemke_status"), "converged");
  const auto lemke = test::read_dataset<double>(file.get(), "p_lemke", H5T_NATIVE_DOUBLE);
  ASSERT_EQ(lemke.size(), 7U);
  for (std::size_t i = 0; i < 7; ++i) EXPECT_EQ(lemke[i], run.lemke.pressure[static_cast<Eigen::Index>(i)]);
  for (const char* name : {"x", "gap", "p_lcpquad", "p_pk", "p_hertz"}) {
    EXPECT_EQ(test::dataset_shape(file.get(), name), std::vector<hsize_t>{7}) << name;
  }
}

// Each method's outcome comes from the one table of result attributes, so
// the paper's files record what a result file records (but `tolerance`,
// whose name the file uses for the options).
TEST(PaperOutputTest, EachMethodHasEveryResultAttribute) {
  const TempDir dir;
  const paper::TestReproduction run = small_run();
  paper::write_hdf5(dir / "test4.h5", run, {});
  const test::H5 file = test::open_file(dir / "test4.h5");
  for (const char* method : {"lemke", "lcpquad", "pk"}) {
    for (const io::ResultAttribute& attribute : io::result_attributes()) {
      // <method>_tolerance is the option given to the method (docs/paper.md).
      if (attribute.name == "tolerance") continue;
      const std::string name = fmt::format("{}_{}", method, attribute.name);
      EXPECT_GT(H5Aexists(file.get(), name.c_str()), 0) << name;
    }
  }
  EXPECT_EQ(test::read_int64_attribute(file.get(), "pk_iterations"), run.pk.iterations);
  EXPECT_EQ(test::read_int64_attribute(file.get(), "pk_operator_applications"), run.pk.operator_applications);
  EXPECT_EQ(test::read_double_attribute(file.get(), "pk_seconds"), run.pk.wall_seconds) << "the name kept";
  EXPECT_EQ(test::read_double_attribute(file.get(), "pk_solve_seconds"), run.pk.wall_seconds);
  EXPECT_EQ(test::read_string_attribute(file.get(), "lemke_solver"), run.lemke.solver);
}

TEST(PaperOutputTest, SummaryTableHasOneRowPerTest) {
  const std::string table = paper::summary_markdown({small_run()}, {});
  EXPECT_NE(table.find("| test | N | E* (GPa)"), std::string::npos) << table;
  EXPECT_NE(table.find("\n| 4 | 7 | 42.66 |"), std::string::npos) << table;
}

TEST(PaperOutputTest, ReportsAnUnwritableDirectory) {
  const paper::TestReproduction run = small_run();
  try {
    paper::write_csv("/nonexistent-halfspace-dir/test4.csv", run);
    FAIL() << "expected FileError";
  } catch (const FileError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent-halfspace-dir/test4.csv"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace halfspace
