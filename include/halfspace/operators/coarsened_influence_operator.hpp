// The influence operator of the grid of twice the spacing, for grid
// sequencing and other coarse-grid work on a solver that only holds a fine
// operator.
#pragma once

#include <memory>
#include <span>

#include "halfspace/fft/even_symbol.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/operators/influence_operator.hpp"
#include "halfspace/operators/spectral_transforms.hpp"

namespace halfspace::operators {

// K on the grid of twice the spacing as seen through a finer operator:
// R K P with P the piecewise-constant prolongation of a coarse pressure
// onto the 2 (1D) or 2 x 2 (2D) fine cells of each coarse cell and R the
// block average of the displacement. Translation invariant and even in
// each axis' offset when K is (as every half-space kernel, free or
// periodic, homogeneous or coated, is), so it is a convolution on the
// coarse grid: its coefficients are read off one fine product (a unit
// pressure on one coarse cell) and each product then costs an FFT of the
// coarse grid (zero-padded on free grids, make_serial_transforms), not of
// the fine one.
class CoarsenedInfluenceOperator final : public InfluenceOperator {
 public:
  // `coarse` must be solvers::coarser_grid(fine.grid(), ...). `fine` is
  // used only here (one product). A distributed `fine` (slabs of rows)
  // takes that product collectively; the coarse operator multiplies on
  // `transforms` of the coarse grid (one transform, fine.transforms_for
  // by default): serial ones (every process then holds the coarse field
  // whole) or slabs of the coarse rows.
  CoarsenedInfluenceOperator(InfluenceOperator& fine, const Grid& coarse);
  CoarsenedInfluenceOperator(InfluenceOperator& fine, const Grid& coarse,
                             std::unique_ptr<SpectralTransforms> transforms);
  ~CoarsenedInfluenceOperator() override;
  CoarsenedInfluenceOperator(const CoarsenedInfluenceOperator&) = delete;
  CoarsenedInfluenceOperator& operator=(const CoarsenedInfluenceOperator&) = delete;

  const Grid& grid() const override { return coarse_; }
  std::size_t local_size() const override { return transforms_->local_size(); }
  const linalg::Communicator& communicator() const override { return transforms_->communicator(); }
  void apply(std::span<const double> pressure, std::span<double> displacement) override;
  double self_influence() const override { return self_influence_; }
  std::unique_ptr<SpectralTransforms> transforms_for(const Grid& grid) const override {
    return transforms_->make_for(grid, {.count = 1});
  }

 private:
  Grid coarse_;
  double self_influence_ = 0.0;
  std::unique_ptr<SpectralTransforms> transforms_;
  EvenSymbol kernel_{0, 0};  // the coefficients' spectrum, FFTW's 1/N folded in
};

}  // namespace halfspace::operators

namespace halfspace {
using operators::CoarsenedInfluenceOperator;
}  // namespace halfspace
