// The assembled influence matrix: entries from the kernels, symmetry,
// definiteness, zero-mean periodic columns, apply (also in place), and the
// size limit.
#include "halfspace/operators/dense_influence_operator.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/kernels/love_rectangle.hpp"
#include "halfspace/kernels/plane_strain_strip.hpp"
#include "operators/operator_test_support.hpp"

namespace halfspace {
namespace {

constexpr double kEStar = 1.1e11;  // Pa
// Eigenvalues of a symmetric matrix are found to ~eps * ||K|| (LAPACK-style
// backward stability); the periodic mean mode's zero eigenvalue sits there.
constexpr double kEigenvalueTolerance = 1e-13;
// Periodic column sums: N terms of both signs cancelling to zero.
constexpr double kColumnSumTolerance = 1e-13;
// Matrix-vector product against a plain loop: different summation order.
constexpr double kProductTolerance = 1e-14;

std::vector<Grid> small_grids(Boundary boundary) {
  // Free 1D: the logarithmic kernel is positive definite only while the
  // domain (here 32 um) is small against the 1 m datum length.
  return {Grid::line(16, 2e-6, boundary), Grid::line(15, 2e-6, boundary), Grid::plane(7, 6, 1e-6, 1.7e-6, boundary),
          Grid::plane(8, 8, 1e-6, 1e-6, boundary)};
}

TEST(DenseInfluenceOperatorTest, FreeEntriesAreKernelValues) {
  const Grid plane = Grid::plane(5, 4, 1e-6, 2e-6, Boundary::free);
  const Eigen::MatrixXd k2 = assemble_influence_matrix(plane, kEStar);
  // Cell (i, j) = (1, 3) under pressure on cell (4, 0): offset (-3 dx, 3 dy).
  EXPECT_EQ(k2(3 * 5 + 1, 0 * 5 + 4), kernels::love_rectangle_displacement(-3e-6, 6e-6, 0.5e-6, 1e-6, kEStar));
  const Grid line = Grid::line(6, 2e-6, Boundary::free);
  const Eigen::MatrixXd k1 = assemble_influence_matrix(line, kEStar);
  EXPECT_EQ(k1(1, 5), kernels::plane_strain_strip_displacement(-8e-6, 2e-6, kEStar));
}

TEST(DenseInfluenceOperatorTest, MatrixIsSymmetric) {
  for (const Boundary boundary : {Boundary::periodic, Boundary::free}) {
    for (const Grid& grid : small_grids(boundary)) {
      const Eigen::MatrixXd k = assemble_influence_matrix(grid, kEStar);
      EXPECT_EQ((k - k.transpose()).cwiseAbs().maxCoeff(), 0.0) << to_string(boundary) << " " << grid.shape_string();
    }
  }
}

TEST(DenseInfluenceOperatorTest, FreeMatrixIsPositiveDefinite) {
  for (const Grid& grid : small_grids(Boundary::free)) {
    const Eigen::MatrixXd k = assemble_influence_matrix(grid, kEStar);
    const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(k).eigenvalues();
    std::printf("free %s: eigenvalues in [%.3e, %.3e]\n", grid.shape_string().c_str(), eigenvalues.minCoeff(),
                eigenvalues.maxCoeff());
    EXPECT_GT(eigenvalues.minCoeff(), kEigenvalueTolerance * eigenvalues.maxCoeff()) << grid.shape_string();
  }
}

TEST(DenseInfluenceOperatorTest, PeriodicMatrixIsPositiveSemidefinite) {
  for (const Grid& grid : small_grids(Boundary::periodic)) {
    const Eigen::MatrixXd k = assemble_influence_matrix(grid, kEStar);
    const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(k).eigenvalues();
    const double largest = eigenvalues.maxCoeff();
    // One zero eigenvalue (the mean mode), the rest positive.
    EXPECT_GE(eigenvalues(0), -kEigenvalueTolerance * largest) << grid.shape_string();
    EXPECT_LE(eigenvalues(0), kEigenvalueTolerance * largest) << grid.shape_string();
    EXPECT_GT(eigenvalues(1), kEigenvalueTolerance * largest) << grid.shape_string();
  }
}

TEST(DenseInfluenceOperatorTest, PeriodicColumnsHaveZeroMean) {
  for (const Grid& grid : small_grids(Boundary::periodic)) {
    const Eigen::MatrixXd k = assemble_influence_matrix(grid, kEStar);
    const double worst = k.colwise().sum().cwiseAbs().maxCoeff();
    EXPECT_LE(worst, kColumnSumTolerance * k.cwiseAbs().maxCoeff()) << grid.shape_string();
  }
}

TEST(DenseInfluenceOperatorTest, ApplyIsMatrixVectorProduct) {
  const Grid grid = Grid::plane(6, 5, 1e-6, 1e-6, Boundary::free);
  DenseInfluenceOperator op(grid, kEStar);
  const std::vector<double> pressure = testing::random_field(grid.size(), 3);
  std::vector<double> displacement(grid.size());
  op.apply(pressure, displacement);
  std::vector<double> expected(grid.size(), 0.0);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    for (std::size_t j = 0; j < grid.size(); ++j) {
      expected[i] += op.matrix()(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) * pressure[j];
    }
  }
  const auto error = testing::max_error(displacement, expected);
  EXPECT_LE(error.relative, kProductTolerance) << "at cell " << error.index;
  EXPECT_EQ(op.self_influence(), op.matrix()(0, 0));
}

TEST(DenseInfluenceOperatorTest, InPlaceApplyGivesTheSameResult) {
  // The product goes through the operator's own vector: written straight
  // into the input, later rows would read already overwritten pressures.
  const Grid grid = Grid::plane(6, 5, 1e-6, 1e-6, Boundary::periodic);
  DenseInfluenceOperator op(grid, kEStar);
  std::vector<double> field = testing::random_field(grid.size(), 4);
  std::vector<double> expected(grid.size());
  op.apply(field, expected);
  op.apply(field, field);
  EXPECT_EQ(field, expected);
}

TEST(DenseInfluenceOperatorTest, RefusesTooLargeGrid) {
  const Grid grid = Grid::plane(100, 100, 1e-6, 1e-6, Boundary::periodic);
  try {
    assemble_influence_matrix(grid, kEStar);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("100x100"), std::string::npos) << message;
    EXPECT_NE(message.find("10000 cells"), std::string::npos) << message;
    EXPECT_NE(message.find("763 MiB"), std::string::npos) << message;
    EXPECT_NE(message.find("Polonsky-Keer"), std::string::npos) << message;
  }
  EXPECT_THROW(DenseInfluenceOperator(Grid::line(kMaxDenseCells + 1, 1e-6, Boundary::free), kEStar), InputError);
}

}  // namespace
}  // namespace halfspace
