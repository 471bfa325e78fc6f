// The Fourier preconditioner: on a periodic grid it inverts K except on the
// mean mode, and it can share one transform (and its buffers) with the
// FFT operator (its transforms, or their idle buffer), interleaved as Polonsky-Keer applies them, with the
// same bits as separate transforms.
#include "halfspace/solvers/fourier_preconditioner.hpp"

#include <gtest/gtest.h>

#include <complex>
#include <functional>
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
    const std::shared_ptr<operators::SpectralTransforms> transforms =
        operators::make_serial_transforms(grid, FftPlanning::estimate, {.count = 1});
    FftInfluenceOperator shared_op(grid, kEStar, transforms);
    FourierPreconditioner shared_preconditioner(grid, kEStar, transforms);
    FftInfluenceOperator own_op(grid, kEStar);
    FourierPreconditioner own_preconditioner(grid, kEStar);

    expect_same_products(grid, shared_op, shared_preconditioner, own_op, own_preconditioner);
  }
}

// Free grids: the preconditioner's transform in the operator's padded
// buffer (the layout's arrangement) gives the bits of separate buffers.
TEST(FourierPreconditionerTest, TransformInTheOperatorsWorkspaceGivesTheSameBits) {
  for (const Grid& grid : {Grid::plane(24, 18, 1e-6, 2e-6, Boundary::free), Grid::line(40, 1e-6, Boundary::free),
                           Grid::line(41, 1e-6, Boundary::free), Grid::plane(9, 7, 1e-6, 1e-6, Boundary::free)}) {
    FftInfluenceOperator shared_op(grid, kEStar);
    FourierPreconditioner shared_preconditioner(
        grid, kEStar,
        operators::make_serial_transforms(
            grid, FftPlanning::estimate,
            {.count = 1, .unpadded = true, .workspace = shared_op.transforms()->workspace()}));
    FftInfluenceOperator own_op(grid, kEStar);
    FourierPreconditioner own_preconditioner(grid, kEStar);

    expect_same_products(grid, shared_op, shared_preconditioner, own_op, own_preconditioner);
  }
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
      FftInfluenceOperator op(grid, half_space);
      FourierPreconditioner inverted(grid, half_space, op.symbol(), op.transforms());
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
      FourierPreconditioner single_inverted(grid, half_space, op.symbol(),
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

// Transforms of another grid, or padded where the grid's own are needed
// (or the reverse), are refused with a message naming the shapes.
TEST(FourierPreconditionerTest, TransformsMustBeTheGrids) {
  const Grid periodic = Grid::plane(16, 12, 1e-6, 1e-6, Boundary::periodic);
  const Grid free = Grid::plane(16, 12, 1e-6, 1e-6, Boundary::free);
  const auto expect_refused = [](const std::function<void()>& make, const std::string& wanted) {
    try {
      make();
      ADD_FAILURE() << "expected InputError with " << wanted;
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find(wanted), std::string::npos) << error.what();
    }
  };
  expect_refused(
      [&] { FourierPreconditioner(free, kEStar, operators::make_serial_transforms(free, FftPlanning::estimate)); },
      "not the 16x12 grid's own (unpadded)");
  expect_refused(
      [&] {
        FftInfluenceOperator(free, kEStar,
                             operators::make_serial_transforms(free, FftPlanning::estimate, {.unpadded = true}));
      },
      "not the 16x12 free grid's (zero-padded)");
  expect_refused(
      [&] {
        FftInfluenceOperator(periodic, kEStar,
                             operators::make_serial_transforms(Grid::plane(16, 16, 1e-6, 1e-6, Boundary::periodic),
                                                               FftPlanning::estimate));
      },
      "not the 16x12 periodic grid's (its own)");
  std::vector<std::complex<double>> workspace(RealFft::workspace_size(16, 16));
  expect_refused(
      [&] {
        FourierPreconditioner(periodic, kEStar,
                              make_single_grid_transform(Grid::plane(16, 16, 1e-6, 1e-6, Boundary::periodic),
                                                         FftPlanning::estimate, workspace));
      },
      "16x16 but the grid needs 12x16");
}

}  // namespace
}  // namespace halfspace::solvers
