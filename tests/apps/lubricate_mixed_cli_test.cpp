// `halfspace lubricate --mixed`: the program's mixed film equals the
// library's on the same rough gap, its fields and attributes are written and
// add up, the Stribeck sweep writes its CSV, and bad input names the option.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "halfspace/io/height_map_reader.hpp"
#include "halfspace/lubrication/mixed_film.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
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

// A cylinder (R = 10 mm) with a self-affine roughness of 0.1 um rms on 97
// points over 0.24 mm, as the generate command makes them.
void make_rough_line(const TempDir& dir, std::size_t points = 97) {
  const std::string grid = std::to_string(points);
  ASSERT_EQ(run_program({"generate", "--kind", "cylinder", "--grid", grid, "--size", "2.4e-4", "--radius", "0.01",
                         "--output", "cylinder.h5", "--quiet"},
                        dir.path())
                .exit_code,
            kExitOk);
  ASSERT_EQ(run_program({"generate", "--kind", "self-affine", "--grid", grid, "--size", "2.4e-4", "--rms-height",
                         "1e-7", "--seed", "3", "--output", "rough.h5", "--quiet"},
                        dir.path())
                .exit_code,
            kExitOk);
}

// The rows of a CSV file after its header (into `header`), split at commas.
std::vector<std::vector<std::string>> read_csv(const std::filesystem::path& path, std::string& header) {
  std::ifstream csv(path);
  std::getline(csv, header);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(csv, line);) {
    std::vector<std::string> cells;
    std::size_t from = 0;
    for (std::size_t comma; (comma = line.find(',', from)) != std::string::npos; from = comma + 1) {
      cells.push_back(line.substr(from, comma - from));
    }
    cells.push_back(line.substr(from));
    rows.push_back(cells);
  }
  return rows;
}

const std::vector<std::string> kMixedRun{"lubricate",
                                         "--height-map",
                                         "cylinder.h5",
                                         "--roughness",
                                         "rough.h5",
                                         "--mixed",
                                         "--viscosity",
                                         "0.04",
                                         "--force",
                                         "4.4e4",
                                         "--E-star",
                                         "1.1e11",
                                         "--pressure-viscosity",
                                         "2.27e-8",
                                         "--piezoviscosity",
                                         "roelands",
                                         "--limiting-shear-slope",
                                         "0.05"};

std::vector<std::string> mixed_run(std::vector<std::string> more) {
  std::vector<std::string> args = kMixedRun;
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST(LubricateMixedCliTest, MixedFilmIsTheLibrarys) {
  const TempDir dir;
  make_rough_line(dir);
  // Planned as the library's operator below is (estimate): the same
  // transforms, so the same film to the bit.
  const ProgramRun run =
      run_program(mixed_run({"--entrainment-velocity", "0.001", "--sliding-velocity", "0.0005", "--contact-friction",
                             "0.12", "--fft-planning", "estimate", "--output", "m.h5"}),
                  dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  const test::H5 file = test::open_file(dir / "m.h5");
  const auto field = [&](const std::string& name) {
    return test::read_dataset<double>(file.get(), name, H5T_NATIVE_DOUBLE);
  };
  const std::vector<double> fluid = field("/fluid_pressure");
  const std::vector<double> contact = field("/contact_pressure");
  const std::vector<double> total = field("/pressure");
  const std::vector<double> film = field("/film");
  ASSERT_EQ(fluid.size(), 97u);
  double contact_sum = 0.0, total_sum = 0.0;
  for (std::size_t k = 0; k < fluid.size(); ++k) {
    EXPECT_EQ(total[k], fluid[k] + contact[k]);
    if (contact[k] > 0.0) {
      EXPECT_EQ(film[k], 0.0);
    }
    contact_sum += contact[k];
    total_sum += total[k];
  }
  EXPECT_EQ(test::read_string_attribute(file.get(), "model"), "mixed");
  const double share = test::read_double_attribute(file.get(), "contact_load_fraction");
  EXPECT_NEAR(share, contact_sum / total_sum, 1e-12);
  EXPECT_GT(share, 0.01);
  EXPECT_LT(share, 0.99);
  EXPECT_GT(test::read_double_attribute(file.get(), "contact_area_fraction"), 0.0);
  EXPECT_EQ(test::read_double_attribute(file.get(), "contact_friction"), 0.12);

  // The library on the same gap.
  HeightMap map = io::read_height_map(dir / "cylinder.h5");
  map.heights += io::read_height_map(dir / "rough.h5").heights;
  const Grid grid = Grid::line(map.nx, map.dx, Boundary::free);
  FftInfluenceOperator op(grid, 1.1e11);
  lubrication::FlowConditions conditions;
  conditions.viscosity = 0.04;
  conditions.entrainment_velocity = {0.001, 0.0};
  conditions.sliding_velocity = {0.0005, 0.0};
  lubrication::LubricantLaws laws;
  laws.piezoviscosity = lubrication::Piezoviscosity::roelands;
  laws.pressure_viscosity = 2.27e-8;
  laws.compressibility = lubrication::Compressibility::dowson_higginson;
  lubrication::MixedFilmOptions options;
  options.load = 4.4e4;
  options.friction.contact_friction = 0.12;
  options.friction.shear.limiting_shear_slope = 0.05;
  const lubrication::MixedFilm expected =
      lubrication::solve_mixed_film(op, map.heights.maxCoeff() - map.heights, conditions, laws, options);
  ASSERT_TRUE(expected.converged()) << expected.message;
  for (std::size_t k = 0; k < fluid.size(); ++k) {
    EXPECT_EQ(contact[k], expected.contact_pressure[static_cast<Eigen::Index>(k)]) << k;
    EXPECT_EQ(fluid[k], expected.fluid_pressure[static_cast<Eigen::Index>(k)]) << k;
  }
  EXPECT_EQ(test::read_double_attribute(file.get(), "friction_coefficient"), expected.friction_coefficient);
}

// A rough point contact (a 2D map: the GMRES path): the program converges
// and writes both pressures, which add up, with the film 0 where the
// asperities touch and a share of the load on contact (measured 0.50 at
// 33 x 33 with 0.05 um rms; 17 x 17 here).
TEST(LubricateMixedCliTest, RoughPointContactMapRuns) {
  const TempDir dir;
  for (const std::vector<std::string>& generate :
       {std::vector<std::string>{"--kind", "sphere", "--radius", "0.01", "--output", "ball.h5"},
        std::vector<std::string>{"--kind", "self-affine", "--rms-height", "5e-8", "--seed", "3", "--output",
                                 "rough.h5"}}) {
    std::vector<std::string> args{"generate", "--grid", "17x17", "--size", "3.1e-4x3.1e-4", "--quiet"};
    args.insert(args.end(), generate.begin(), generate.end());
    ASSERT_EQ(run_program(args, dir.path()).exit_code, kExitOk);
  }
  const ProgramRun run = run_program({"lubricate",
                                      "--height-map",
                                      "ball.h5",
                                      "--roughness",
                                      "rough.h5",
                                      "--mixed",
                                      "--viscosity",
                                      "0.04",
                                      "--entrainment-velocity",
                                      "0.005",
                                      "--sliding-velocity",
                                      "0.0025",
                                      "--force",
                                      "6.6",
                                      "--E-star",
                                      "1.1e11",
                                      "--pressure-viscosity",
                                      "2.27e-8",
                                      "--piezoviscosity",
                                      "roelands",
                                      "--output",
                                      "m.h5"},
                                     dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err << run.out;
  const test::H5 file = test::open_file(dir / "m.h5");
  const auto field = [&](const std::string& name) {
    return test::read_dataset<double>(file.get(), name, H5T_NATIVE_DOUBLE);
  };
  const std::vector<double> fluid = field("/fluid_pressure");
  const std::vector<double> contact = field("/contact_pressure");
  const std::vector<double> total = field("/pressure");
  const std::vector<double> film = field("/film");
  ASSERT_EQ(fluid.size(), 17u * 17u);
  double contact_sum = 0.0, total_sum = 0.0;
  for (std::size_t k = 0; k < fluid.size(); ++k) {
    EXPECT_EQ(total[k], fluid[k] + contact[k]);
    EXPECT_GE(film[k], 0.0);
    if (contact[k] > 0.0) {
      EXPECT_EQ(film[k], 0.0);
    }
    contact_sum += contact[k];
    total_sum += total[k];
  }
  const double share = test::read_double_attribute(file.get(), "contact_load_fraction");
  EXPECT_NEAR(share, contact_sum / total_sum, 1e-12);
  EXPECT_GT(share, 0.01);
  EXPECT_LT(share, 0.99);
  EXPECT_NEAR(total_sum * (3.1e-4 / 17.0) * (3.1e-4 / 17.0) / 6.6, 1.0, 1e-8);
}

TEST(LubricateMixedCliTest, StribeckSweepWritesItsCurve) {
  const TempDir dir;
  make_rough_line(dir);
  const ProgramRun run =
      run_program(mixed_run({"--entrainment-velocity", "1", "--sliding-velocity", "0.5", "--speeds", "1,0.001,0.0001",
                             "--stribeck", "s.csv", "--trace", "t.csv", "--output", "m.h5", "--quiet"}),
                  dir.path());
  ASSERT_EQ(run.exit_code, kExitOk) << run.err;
  std::string header;
  const std::vector<std::vector<std::string>> rows = read_csv(dir / "s.csv", header);
  EXPECT_EQ(header.rfind("entrainment_speed,hersey_number,friction_coefficient,", 0), 0u) << header;
  ASSERT_EQ(rows.size(), 3u);
  // The trace: one line per Newton solve, whose steps add up to the sweep's
  // (column 10 of the curve), the last one the slowest speed's answer.
  std::string trace_header;
  const std::vector<std::vector<std::string>> solves = read_csv(dir / "t.csv", trace_header);
  EXPECT_EQ(trace_header.rfind("solve,nx,ny,entrainment_speed,smoothing,start,checked_step_branches,status,"
                               "newton_steps,gmres_iterations,",
                               0),
            0u)
      << trace_header;
  ASSERT_GE(solves.size(), 3u);
  long long traced_steps = 0, swept_steps = 0;
  for (std::size_t k = 0; k < solves.size(); ++k) {
    ASSERT_EQ(solves[k].size(), 16u);
    EXPECT_EQ(std::stoul(solves[k][0]), k + 1);
    EXPECT_EQ(solves[k][1], "97");
    traced_steps += std::stoll(solves[k][8]);
  }
  for (const auto& row : rows) swept_steps += std::stoll(row[10]);
  EXPECT_EQ(traced_steps, swept_steps);
  EXPECT_EQ(std::stod(solves.back()[3]), 0.0001);
  EXPECT_EQ(solves.back()[7], "converged");
  // speed, Hersey number, friction coefficient, ..., contact share (column 5), status (column 9).
  EXPECT_EQ(std::stod(rows[0][5]), 0.0);
  EXPECT_GT(std::stod(rows[2][5]), std::stod(rows[1][5]));
  EXPECT_GT(std::stod(rows[2][5]), 0.5);
  EXPECT_NEAR(std::stod(rows[1][1]) / (0.04 * 0.001 / 4.4e4), 1.0, 1e-8);  // 9 digits in the CSV
  for (const auto& row : rows) EXPECT_EQ(row[9], "converged");
  // The HDF5 file holds the last speed's film.
  const test::H5 file = test::open_file(dir / "m.h5");
  EXPECT_EQ(test::read_double_attribute(file.get(), "entrainment_speed"), 0.0001);
  EXPECT_NEAR(test::read_double_attribute(file.get(), "contact_load_fraction"), std::stod(rows[2][5]), 1e-8);
}

TEST(LubricateMixedCliTest, RejectsBadMixedInputNamingTheOption) {
  const TempDir dir;
  make_rough_line(dir);
  const auto with = [&](std::vector<std::string> more) {
    more.insert(more.end(), {"--entrainment-velocity", "1", "--output", "f.h5"});
    return run_program(mixed_run(more), dir.path());
  };
  expect_input_error(with({"--contact-friction", "-1"}), {"--contact-friction -1 is invalid"}, dir / "f.h5");
  expect_input_error(with({"--boundary-film", "0"}), {"--boundary-film 0 m is invalid"}, dir / "f.h5");
  expect_input_error(with({"--speeds", "1,0.1"}), {"--speeds and --stribeck"}, dir / "f.h5");
  expect_input_error(with({"--speeds", "1,-0.1", "--stribeck", "s.csv"}), {"--speeds -0.1 m/s is invalid"},
                     dir / "f.h5");
  const std::vector<std::string> rigid{
      "lubricate", "--height-map", "cylinder.h5", "--viscosity", "0.04", "--entrainment-velocity",
      "1",         "--force",      "1e3",         "--output",    "f.h5"};
  const auto rigid_with = [&](std::vector<std::string> more) {
    std::vector<std::string> args = rigid;
    args.insert(args.end(), more.begin(), more.end());
    return run_program(args, dir.path());
  };
  expect_input_error(rigid_with({"--contact-friction", "0.1"}), {"--mixed"}, dir / "f.h5");
  expect_input_error(rigid_with({"--mixed"}), {"--mixed needs an elastic body"}, dir / "f.h5");
  expect_input_error(rigid_with({"--trace", "t.csv"}), {"--trace t.csv", "needs --mixed"}, dir / "f.h5");
  expect_input_error(with({"--trace", "./f.h5"}), {"--trace ./f.h5 is the same file as f.h5"}, dir / "f.h5");
  EXPECT_FALSE(std::filesystem::exists(dir / "t.csv"));
  // A roughness of another size (a profile beyond the dense path's 2048
  // points is no longer refused: it takes the GMRES path).
  ASSERT_EQ(
      run_program({"generate", "--kind", "flat", "--grid", "50", "--size", "2.4e-4", "--output", "small.h5", "--quiet"},
                  dir.path())
          .exit_code,
      kExitOk);
  expect_input_error(rigid_with({"--roughness", "small.h5"}), {"--roughness small.h5 has 50"}, dir / "f.h5");
}

}  // namespace
}  // namespace halfspace
