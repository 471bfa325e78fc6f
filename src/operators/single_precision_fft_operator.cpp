#include "halfspace/operators/single_precision_fft_operator.hpp"

#include <cassert>
#include <utility>

#include "halfspace/error.hpp"
#include "halfspace/fft/grid_transform.hpp"

namespace halfspace::operators {
namespace {

const Grid& checked_periodic(const FftInfluenceOperator& exact) {
  if (!exact.grid().periodic()) {
    throw InputError(
        "SinglePrecisionFftOperator: a free grid's product needs its zero-padded transform; periodic grids only");
  }
  return exact.grid();
}

// The operator's symbol, laid out as the single-precision transform's
// spectrum: a symbol held in slabs (MPI) covers only this process's part.
const EvenSymbol& checked_symbol(const FftInfluenceOperator& exact, const SingleRealFft& transform) {
  const EvenSymbol& symbol = exact.symbol();
  if (symbol.rows() != transform.spectrum_blocks() || symbol.cols() != transform.spectrum_length() ||
      symbol.transposed() != transform.transposed()) {
    throw InputError("SinglePrecisionFftOperator: the operator's symbol is held in slabs; one process only");
  }
  return symbol;
}

}  // namespace

SinglePrecisionFftOperator::SinglePrecisionFftOperator(const FftInfluenceOperator& exact,
                                                       std::shared_ptr<SingleRealFft> transform)
    : grid_(checked_periodic(exact)),
      transform_(checked_grid_transform(grid_, std::move(transform), "SinglePrecisionFftOperator")),
      kernel_(checked_symbol(exact, *transform_)),
      self_influence_(exact.self_influence()) {}

void SinglePrecisionFftOperator::apply(std::span<const double> pressure, std::span<double> displacement) {
  assert(pressure.size() == grid_.size() && displacement.size() == grid_.size());
  kernel_.apply(*transform_, pressure, displacement);
}

void SinglePrecisionFftOperator::apply(std::span<const float> pressure, std::span<float> displacement) {
  assert(pressure.size() == grid_.size() && displacement.size() == grid_.size());
  kernel_.apply(*transform_, pressure, displacement);
}

}  // namespace halfspace::operators
