// The Fourier preconditioner: on a periodic grid it inverts K except on the
// mean mode, and it can share one transform (and its buffers) with the
// periodic FFT operator, interleaved as Polonsky-Keer applies them, with the
// same bits as separate transforms.
#include "halfspace/solvers/fourier_preconditioner.hpp"

#include <gtest/gtest.h>

#include <complex>
#include <memory>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/fft/grid_transform.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "operators/operator_test_support.hpp"

namespace halfspace::solvers {
namespace {

using testing::max_error;
using testing::random_field;

constexpr double kEStar = 2e9;  // Pa
// M^-1 K p against p: two FFT round trips of O(1) data, rounding only.
constexpr double kInverseTolerance = 1e-12;

std::vector<double> mean_free(std::vector<double> values) {
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
  for (double& v : values) v -= mean;
  return values;
}

TEST(FourierPreconditionerTest, InvertsThePeriodicOperatorOnMeanFreeFields) {
  const Grid grid = Grid::plane(24, 18, 1e-6, 2e-6, Boundary::periodic);
  FftInfluenceOperator op(grid, kEStar);
  FourierPreconditioner preconditioner(grid, kEStar);
  const std::vector<double> pressure = mean_free(random_field(grid.size(), 3));
  std::vector<double> field(grid.size());
  op.apply(pressure, field);
  preconditioner.apply(field, field);  // in place
  const auto error = max_error(field, pressure);
  EXPECT_LE(error.relative, kInverseTolerance) << "at cell " << error.index;
}

// An operator and preconditioner that share buffers against a pair with
// buffers of their own: the same bits, interleaved as in an iteration (K t,
// then M^-1 g, then K t again).
void expect_same_products(const Grid& grid, FftInfluenceOperator& shared_op,
                          FourierPreconditioner& shared_preconditioner, FftInfluenceOperator& own_op,
                          FourierPreconditioner& own_preconditioner) {
  std::vector<double> shared(grid.size());
  std::vector<double> own(grid.size());
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const std::vector<double> field = random_field(grid.size(), seed);
    shared_op.apply(field, shared);
    own_op.apply(field, own);
    EXPECT_EQ(shared, own) << "K, seed " << seed << ", grid " << grid.shape_string();
    shared_preconditioner.apply(field, shared);
    own_preconditioner.apply(field, own);
    EXPECT_EQ(shared, own) << "M^-1, seed " << seed << ", grid " << grid.shape_string();
  }
}

TEST(FourierPreconditionerTest, SharedTransformGivesTheSameBits) {
  for (const Grid& grid :
       {Grid::plane(24, 18, 1e-6, 2e-6, Boundary::periodic), Grid::line(40, 1e-6, Boundary::periodic)}) {
    const auto transform = make_grid_transform(grid, FftPlanning::estimate);
    FftInfluenceOperator shared_op(grid, kEStar, transform);
    FourierPreconditioner shared_preconditioner(grid, kEStar, transform);
    FftInfluenceOperator own_op(grid, kEStar);
    FourierPreconditioner own_preconditioner(grid, kEStar);

    expect_same_products(grid, shared_op, shared_preconditioner, own_op, own_preconditioner);
  }
}

// Free grids: the preconditioner's transform in the operator's padded
// buffer (the factory's arrangement) gives the bits of separate buffers.
TEST(FourierPreconditionerTest, TransformInTheOperatorsScratchGivesTheSameBits) {
  for (const Grid& grid : {Grid::plane(24, 18, 1e-6, 2e-6, Boundary::free), Grid::line(40, 1e-6, Boundary::free),
                           Grid::line(41, 1e-6, Boundary::free), Grid::plane(9, 7, 1e-6, 1e-6, Boundary::free)}) {
    FftInfluenceOperator shared_op(grid, kEStar);
    ASSERT_FALSE(shared_op.scratch().empty());
    FourierPreconditioner shared_preconditioner(grid, kEStar,
                                                make_grid_transform(grid, FftPlanning::estimate, shared_op.scratch()));
    FftInfluenceOperator own_op(grid, kEStar);
    FourierPreconditioner own_preconditioner(grid, kEStar);

    expect_same_products(grid, shared_op, shared_preconditioner, own_op, own_preconditioner);
  }
  EXPECT_TRUE(FftInfluenceOperator(Grid::plane(8, 8, 1e-6, 1e-6, Boundary::periodic), kEStar).scratch().empty());
}

// Periodic grids: M^-1 formed from the operator's own symbol, 1/(N^2 K),
// as it is applied (the factory's arrangement, no symbol stored) is the
// stored symbol's to rounding, in double and in single precision, for a
// homogeneous and a coated half-space.
TEST(FourierPreconditionerTest, InverseOfTheOperatorsSymbolIsTheStoredOneToRounding) {
  const LayeredMaterial coating{3e-6, ElasticBody{5e9, 0.3}, ElasticBody{1e9, 0.25}};
  for (const HalfSpace& half_space : {HalfSpace(kEStar), HalfSpace(coating)}) {
    for (const Grid& grid :
         {Grid::plane(24, 18, 1e-6, 2e-6, Boundary::periodic), Grid::line(40, 1e-6, Boundary::periodic)}) {
      const auto transform = make_grid_transform(grid, FftPlanning::estimate);
      FftInfluenceOperator op(grid, half_space, transform);
      FourierPreconditioner inverted(grid, half_space, op.periodic_symbol(), transform);
      FourierPreconditioner stored(grid, half_space);
      const std::vector<double> field = random_field(grid.size(), 5);
      std::vector<double> got(grid.size());
      std::vector<double> want(grid.size());
      inverted.apply(field, got);
      stored.apply(field, want);
      const auto error = max_error(got, want);
      EXPECT_LE(error.relative, 1e-13) << grid.shape_string() << ", at cell " << error.index;

      std::vector<std::complex<double>> workspace(
          RealFft::workspace_size(grid.dimension() == 1 ? 1 : grid.ny(), grid.nx()));
      std::vector<std::complex<double>> own_workspace(workspace.size());
      FourierPreconditioner single_inverted(grid, half_space, op.periodic_symbol(),
                                            make_single_grid_transform(grid, FftPlanning::estimate, workspace));
      FourierPreconditioner single_stored(grid, half_space,
                                          make_single_grid_transform(grid, FftPlanning::estimate, own_workspace));
      std::vector<float> single_field(field.begin(), field.end());
      std::vector<float> single_got(grid.size());
      std::vector<float> single_want(grid.size());
      single_inverted.apply(std::span<const float>(single_field), std::span<float>(single_got));
      single_stored.apply(std::span<const float>(single_field), std::span<float>(single_want));
      const std::vector<double> got_wide(single_got.begin(), single_got.end());
      const std::vector<double> want_wide(single_want.begin(), single_want.end());
      EXPECT_LE(max_error(got_wide, want_wide).relative, 1e-5) << grid.shape_string() << ", single precision";
    }
  }
}

TEST(FourierPreconditionerTest, SharedTransformMustMatchTheGrid) {
  const Grid periodic = Grid::plane(16, 12, 1e-6, 1e-6, Boundary::periodic);
  const auto wrong = std::make_shared<RealFft>(16, 16, FftPlanning::estimate);
  try {
    FourierPreconditioner preconditioner(periodic, kEStar, wrong);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("16x16 but the grid needs 12x16"), std::string::npos) << error.what();
  }
  try {
    FftInfluenceOperator op(periodic, kEStar, wrong);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("16x16 but the grid needs 12x16"), std::string::npos) << error.what();
  }
  const Grid free = Grid::plane(16, 16, 1e-6, 1e-6, Boundary::free);
  try {
    FftInfluenceOperator op(free, kEStar, wrong);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("periodic grid"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace halfspace::solvers
