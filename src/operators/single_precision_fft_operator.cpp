#include "halfspace/operators/single_precision_fft_operator.hpp"

#include <cassert>
#include <utility>

#include "halfspace/error.hpp"
#include "halfspace/fft/grid_transform.hpp"
#include "halfspace/kernels/normal_kernel.hpp"

namespace halfspace::operators {
namespace {

const Grid& checked_periodic(const Grid& grid) {
  if (!grid.periodic()) {
    throw InputError(
        "SinglePrecisionFftOperator: a free grid's product needs its zero-padded transform; periodic grids only");
  }
  return grid;
}

}  // namespace

SinglePrecisionFftOperator::SinglePrecisionFftOperator(const Grid& grid, const HalfSpace& half_space,
                                                       std::shared_ptr<SingleRealFft> transform)
    : grid_(checked_periodic(grid)),
      transform_(checked_grid_transform(grid, std::move(transform), "SinglePrecisionFftOperator")),
      kernel_(1, 1),
      self_influence_(0.0) {
  const kernels::NormalKernel normal(grid, half_space);
  kernel_ = normal.periodic_symbol();
  self_influence_ = normal.self_influence();
}

void SinglePrecisionFftOperator::apply(std::span<const double> pressure, std::span<double> displacement) {
  assert(pressure.size() == grid_.size() && displacement.size() == grid_.size());
  kernel_.apply(*transform_, pressure, displacement);
}

void SinglePrecisionFftOperator::apply(std::span<const float> pressure, std::span<float> displacement) {
  assert(pressure.size() == grid_.size() && displacement.size() == grid_.size());
  kernel_.apply(*transform_, pressure, displacement);
}

}  // namespace halfspace::operators
