// K p on a periodic grid through a single-precision transform: the inner
// products of a mixed-precision solve (solver_options.hpp's Precision). The
// pressure is rounded to float, transformed, multiplied by the kernel's
// symbol (kernels/normal_kernel.hpp) and transformed back: the product
// carries a relative error of about 1e-7 (float's 6e-8 times the
// transform's few passes), which the solver's products in double correct
// (polonsky_keer.hpp, "Mixed precision").
#pragma once

#include <memory>
#include <span>

#include "halfspace/fft/even_symbol.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/operators/influence_operator.hpp"

namespace halfspace::operators {

class SinglePrecisionFftOperator final : public InfluenceOperator {
 public:
  // The products of `exact` (which must outlive this operator: its symbol
  // is shared, not copied) on `transform`, the periodic grid's own
  // single-precision transform (make_single_grid_transform). Throws
  // InputError if the grid is free (its products need the padded
  // transform) or the transform's shape is not the grid's.
  SinglePrecisionFftOperator(const FftInfluenceOperator& exact, std::shared_ptr<SingleRealFft> transform);

  const Grid& grid() const override { return grid_; }
  // Allocates nothing; `pressure` and `displacement` may be the same array.
  void apply(std::span<const double> pressure, std::span<double> displacement) override;
  // The same on single-precision arrays, transformed directly where FFTW
  // allows it.
  void apply(std::span<const float> pressure, std::span<float> displacement);
  // K_ii in double (the operator's diagonal, not a product).
  double self_influence() const override { return self_influence_; }

 private:
  Grid grid_;
  std::shared_ptr<SingleRealFft> transform_;
  const EvenSymbol& kernel_;  // exact's: symbol / N, rows folded
  double self_influence_;
};

}  // namespace halfspace::operators

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using operators::SinglePrecisionFftOperator;
}  // namespace halfspace
