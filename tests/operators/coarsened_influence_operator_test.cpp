// The coarse-grid operator R K P as a convolution on the coarse grid
// (CoarsenedInfluenceOperator) against R K P applied through the fine
// operator (constant prolongation, the fine product, block average), on
// free and periodic, 1D and 2D, homogeneous and coated half-spaces.
#include "halfspace/operators/coarsened_influence_operator.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <optional>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/solvers/grid_transfer.hpp"
#include "operator_test_support.hpp"

namespace halfspace::operators {
namespace {

// Both are sums of the same coefficients through FFTs of different sizes:
// equal to rounding, far inside 1e-12 of the largest displacement.
constexpr double kRounding = 1e-12;

void expect_equals_fine_product(const Grid& fine_grid, const HalfSpace& half_space) {
  FftInfluenceOperator fine(fine_grid, half_space);
  const std::optional<Grid> coarse = solvers::coarser_grid(fine_grid, 4);
  ASSERT_TRUE(coarse.has_value());
  CoarsenedInfluenceOperator coarsened(fine, *coarse);
  EXPECT_EQ(coarsened.grid().size(), coarse->size());
  const std::vector<double> pressure = testing::random_field(coarse->size(), 7);
  std::vector<double> fine_pressure(fine_grid.size()), fine_displacement(fine_grid.size());
  std::vector<double> expected(coarse->size()), actual(coarse->size());
  solvers::prolong_constant(fine_grid, pressure, fine_pressure);
  fine.apply(fine_pressure, fine_displacement);
  solvers::restrict_by_average(fine_grid, fine_displacement, expected);
  coarsened.apply(pressure, actual);
  const testing::MaxError error = testing::max_error(actual, expected);
  EXPECT_LT(error.relative, kRounding) << fine_grid.shape_string() << " at coarse cell " << error.index;
  // K_ii: a unit pressure on one coarse cell, read at that cell.
  std::vector<double> unit(coarse->size(), 0.0), column(coarse->size());
  unit[coarse->size() / 2 + 3] = 1.0;
  coarsened.apply(unit, column);
  EXPECT_NEAR(column[coarse->size() / 2 + 3] / coarsened.self_influence(), 1.0, kRounding);
  // In place.
  std::vector<double> in_place = pressure;
  coarsened.apply(in_place, in_place);
  EXPECT_LT(testing::max_error(in_place, expected).relative, kRounding);
}

const HalfSpace kSteel{1.1e11};

TEST(CoarsenedInfluenceOperatorTest, FreePlaneEqualsProductThroughFineGrid) {
  expect_equals_fine_product(Grid::plane(64, 48, 1e-6, 1.5e-6, Boundary::free), kSteel);
}

TEST(CoarsenedInfluenceOperatorTest, PeriodicPlaneEqualsProductThroughFineGrid) {
  expect_equals_fine_product(Grid::plane(64, 32, 1e-6, 1e-6, Boundary::periodic), kSteel);
}

TEST(CoarsenedInfluenceOperatorTest, LinesEqualProductThroughFineGrid) {
  expect_equals_fine_product(Grid::line(256, 1e-6, Boundary::free), kSteel);
  expect_equals_fine_product(Grid::line(256, 1e-6, Boundary::periodic), kSteel);
}

TEST(CoarsenedInfluenceOperatorTest, CoatedEqualsProductThroughFineGrid) {
  const LayeredMaterial coating{4e-6, ElasticBody{3e9, 0.35}, ElasticBody{2.1e11, 0.29}};
  expect_equals_fine_product(Grid::plane(64, 64, 1e-6, 1e-6, Boundary::free), coating);
  expect_equals_fine_product(Grid::plane(64, 64, 1e-6, 1e-6, Boundary::periodic), coating);
}

}  // namespace
}  // namespace halfspace::operators
