// Grids and moduli at the edges of what the library accepts: cell counts
// whose products overflow, denormal spacings and moduli (which pass "positive
// and finite" but make areas of 0 and infinite compliances).
#include <gtest/gtest.h>

#include <cstddef>
#include <limits>
#include <string>

#include "halfspace/checked_size.hpp"
#include "halfspace/error.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/material.hpp"

namespace halfspace {
namespace {

template <class Function>
std::string input_error_of(Function&& function) {
  try {
    function();
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(InputLimitsTest, CheckedArithmeticDetectsOverflow) {
  constexpr std::size_t kMax = std::numeric_limits<std::size_t>::max();
  EXPECT_EQ(checked_multiply(std::size_t{1} << 32, std::size_t{1} << 31), std::size_t{1} << 63);
  EXPECT_FALSE(checked_multiply(std::size_t{1} << 32, std::size_t{1} << 32));
  EXPECT_FALSE(checked_multiply(kMax, 2));
  EXPECT_EQ(checked_multiply(kMax, 1), kMax);
  EXPECT_EQ(checked_add(kMax - 1, 1), kMax);
  EXPECT_FALSE(checked_add(kMax, 1));
}

TEST(InputLimitsTest, GridsBeyondTheCellLimitAreRefused) {
  // 2^32 x 2^32 wraps to 0 cells when multiplied unchecked.
  EXPECT_NE(input_error_of([] {
              Grid::plane(std::size_t{1} << 32, std::size_t{1} << 32, 1.0, 1.0, Boundary::free);
            }).find("grid 4294967296x4294967296 is too large: nx * ny = 1.845e+19 cells"),
            std::string::npos);
  EXPECT_NE(input_error_of([] { Grid::line(kMaxGridCells + 1, 1.0, Boundary::free); }).find("is too large"),
            std::string::npos);
  // At the limit: accepted (a Grid allocates nothing).
  EXPECT_EQ(Grid::line(kMaxGridCells, 1e-6, Boundary::periodic).size(), kMaxGridCells);
}

TEST(InputLimitsTest, DenormalSpacingsAndAreasAreRefused) {
  EXPECT_NE(input_error_of([] {
              Grid::line(8, 4.9e-324, Boundary::free);
            }).find("grid spacing dx = 5e-324 m is invalid: must be positive, finite and not denormal"),
            std::string::npos);
  // Each spacing is normal, their product is not.
  EXPECT_NE(input_error_of([] {
              Grid::plane(8, 8, 1e-200, 1e-200, Boundary::free);
            }).find("grid cell area dx * dy = 0 m^2 is invalid"),
            std::string::npos);
  EXPECT_NE(input_error_of([] { Grid::plane(8, 8, 1e200, 1e200, Boundary::free); }).find("is invalid"),
            std::string::npos);
}

TEST(InputLimitsTest, DenormalModuliAreRefused) {
  EXPECT_NE(input_error_of([] {
              checked_composite_modulus(4.9e-324);
            }).find("composite modulus E* = 5e-324 Pa is invalid: must be positive, finite and not denormal"),
            std::string::npos);
  EXPECT_NE(input_error_of([] {
              composite_modulus({1e-310, 0.3}, {2e11, 0.3});
            }).find("Young's modulus E1 = 1e-310 Pa is invalid"),
            std::string::npos);
  // Each body valid, but with nu near -1 their compliances are denormal and
  // E* = 1 / their sum overflows.
  EXPECT_NE(input_error_of([] {
              composite_modulus({1e308, -0.9999999999}, {1e308, -0.9999999999});
            }).find("composite modulus E* = inf Pa of E1 = 1e+308 Pa"),
            std::string::npos);
  EXPECT_DOUBLE_EQ(checked_composite_modulus(1.0), 1.0);  // tests work in units of E*
}

}  // namespace
}  // namespace halfspace
