// A coupled (dissimilar bodies) tangential history written to its file: each
// step's group holds the step's own normal solution (its pressure under its
// shear), read back equal to the one in memory, and the steps' pressures
// differ (docs/file-format.md#friction-histories).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "halfspace/io/friction_history_writer.hpp"
#include "halfspace/io/result_writer.hpp"
#include "halfspace/solvers/frictional_solve.hpp"
#include "io/hdf5_test_support.hpp"
#include "support/analytic_solutions.hpp"
#include "support/grid_fields.hpp"
#include "support/pk_solvers.hpp"

namespace halfspace {
namespace {

// A rigid sphere pressed into steel (Dundurs' beta = 0.29) and sheared by
// two growing forces: the coupling shifts the pressure with the shear.
struct CoupledHistory {
  Grid grid;
  Eigen::ArrayXd heights;
  solvers::FrictionalSolveResult result;
};

CoupledHistory coupled_history() {
  const ElasticPair pair = ElasticPair::on_rigid({2.1e11, 0.3});
  const double radius = 0.01;
  const double force = 10.0;
  const std::size_t n = 24;
  const double a = testing::hertz_point(force, radius, pair.composite_modulus()).radius;
  const double h = 2.4 * a / static_cast<double>(n);
  CoupledHistory out{Grid::plane(n, n, h, h, Boundary::free), {}, {}};
  out.heights = testing::field_from(out.grid, [&](double x, double y) { return -(x * x + y * y) / (2 * radius); });
  solvers::FrictionOptions friction;
  friction.tangential.friction_coefficient = 0.3;
  friction.history = {TangentialLoading::force(0.5), TangentialLoading::force(2.0)};
  out.result =
      solvers::solve_frictional_surface(out.grid, {out.heights.data(), out.grid.size()}, pair, Loading::force(force),
                                        testing::test_options(solvers::SolverType::pk_fourier, 1e-12), friction);
  return out;
}

TEST(CoupledHistoryFile, EachStepHoldsItsOwnPressure) {
  const CoupledHistory history = coupled_history();
  const solvers::FrictionalSolveResult& r = history.result;
  ASSERT_TRUE(r.converged()) << r.failure();
  ASSERT_TRUE(r.coupled);
  ASSERT_EQ(r.step_normals.size(), 2u);
  const test::TempDir dir;
  const std::filesystem::path path = dir / "coupled.h5";
  io::ResultMetadata metadata;
  metadata.e_star = 1.0;
  metadata.load_mode = "force";
  for (const SolveResult& normal : r.step_normals) metadata.step_normals.push_back(&normal);
  const std::vector<TangentialLoading> loads{TangentialLoading::force(0.5), TangentialLoading::force(2.0)};
  io::write_friction_history(path, history.grid, {history.heights.data(), history.grid.size()}, r.normal, r.steps,
                             loads, metadata);

  const test::H5 file = test::open_file(path);
  std::vector<std::vector<double>> stored;
  for (std::size_t k = 0; k < 2; ++k) {
    const std::string step = "/steps/00" + std::to_string(k);
    stored.push_back(test::read_dataset<double>(file.get(), step + "/pressure", H5T_NATIVE_DOUBLE));
    const Eigen::ArrayXd& memory = r.step_normals[k].pressure;
    ASSERT_EQ(stored[k].size(), static_cast<std::size_t>(memory.size()));
    // The file holds the double written, bit for bit.
    for (std::size_t i = 0; i < stored[k].size(); ++i) {
      ASSERT_EQ(stored[k][i], memory[static_cast<Eigen::Index>(i)]) << step << " cell " << i;
    }
    const std::vector<double> gap = test::read_dataset<double>(file.get(), step + "/gap", H5T_NATIVE_DOUBLE);
    EXPECT_EQ(gap[gap.size() / 2], r.step_normals[k].gap[static_cast<Eigen::Index>(gap.size() / 2)]);
    const hid_t group = H5Gopen2(file.get(), step.c_str(), H5P_DEFAULT);
    ASSERT_GE(group, 0);
    EXPECT_EQ(test::read_double_attribute(group, "total_force"), r.step_normals[k].total_force);
    EXPECT_EQ(test::read_double_attribute(group, "approach"), r.step_normals[k].approach);
    H5Gclose(group);
  }
  // The steps' pressures differ by more than the solver's tolerance: the
  // larger shear moves the pressure (coupled_contact_test.cpp measures how).
  const double peak = *std::max_element(stored[1].begin(), stored[1].end());
  double change = 0.0;
  for (std::size_t i = 0; i < stored[0].size(); ++i) change = std::max(change, std::abs(stored[1][i] - stored[0][i]));
  EXPECT_GT(change, 1e-4 * peak) << "largest change " << change << " Pa of a peak " << peak << " Pa";
  // The root keeps the normal loading's pressure.
  const std::vector<double> root = test::read_dataset<double>(file.get(), "/pressure", H5T_NATIVE_DOUBLE);
  EXPECT_EQ(root[root.size() / 2], r.normal.pressure[static_cast<Eigen::Index>(root.size() / 2)]);
}

TEST(CoupledHistoryFile, StepNormalsMustMatchTheSteps) {
  const CoupledHistory history = coupled_history();
  const solvers::FrictionalSolveResult& r = history.result;
  const test::TempDir dir;
  io::ResultMetadata metadata;
  metadata.step_normals = {&r.step_normals.front()};  // one for two steps
  const std::vector<TangentialLoading> loads{TangentialLoading::force(0.5), TangentialLoading::force(2.0)};
  try {
    io::write_friction_history(dir / "bad.h5", history.grid, {history.heights.data(), history.grid.size()}, r.normal,
                               r.steps, loads, metadata);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("1 step normal solutions for 2 steps"), std::string::npos) << error.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.h5"));
}

}  // namespace
}  // namespace halfspace
