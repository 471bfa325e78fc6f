// The periodic half-space's influence operator and the Fourier preconditioner
// on a grid spread over MPI processes in slabs of rows: the distributed
// counterparts of FftInfluenceOperator (periodic) and FourierPreconditioner,
// with the same kernels (Stanley & Kato 1997; a coated half-space's,
// layered_fourier.hpp) applied to the transposed spectrum of SlabRealFft. Fields hold this process's rows only.
// Compiled only with HALFSPACE_MPI.
#pragma once

#include <memory>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/half_space.hpp"
#include "halfspace/kernels/normal_kernel.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/operators/influence_operator.hpp"
#include "halfspace/solvers/preconditioner.hpp"

namespace halfspace::mpi {

class SlabFourierOperator final : public InfluenceOperator {
 public:
  // u = K p on the periodic 2D `grid` for composite modulus E* (Pa) or a
  // coating (the kernel 2 M(q t)/(E1*|q|)), through `transform` (the grid's, shared with a preconditioner that runs
  // between products). Throws InputError unless the grid is 2D and periodic
  // and the transform is its own, or as checked_composite_modulus and
  // kernels::LayeredKernel for an invalid modulus or coating.
  SlabFourierOperator(const Grid& grid, const HalfSpace& half_space, std::shared_ptr<SlabRealFft> transform);

  const Grid& grid() const override { return grid_; }
  std::size_t local_size() const override { return transform_->layout().local_size(); }
  const linalg::Communicator& communicator() const override { return transform_->communicator(); }
  // Collective: every process applies the operator together.
  void apply(std::span<const double> pressure, std::span<double> displacement) override;
  double self_influence() const override { return self_; }
  // The grid itself, this process's rows: K is apply(), K^-1 the inverse
  // kernel on the same transform (0 at the mean mode). Collective.
  CirculantForm& circulant_form() override;

 private:
  Grid grid_;
  kernels::NormalKernel normal_;
  std::shared_ptr<SlabRealFft> transform_;
  std::unique_ptr<CirculantForm> circulant_;  // made on first use
  std::vector<double> kernel_;                // 2/(E*|q|)/N or its coated form, on this process's spectrum columns
  double self_ = 0.0;
};

class SlabFourierPreconditioner final : public solvers::Preconditioner {
 public:
  // M^-1 = E*|q|/2 (coated: the inverse of the layered kernel), the mean
  // mode at the smallest non-zero |q|, as FourierPreconditioner; `transform` as for the operator. On a free grid
  // too (with a transform of its own), as the serial solvers precondition
  // the padded operator with the unpadded grid's symbol. Throws InputError
  // unless the grid is 2D and the transform its own.
  SlabFourierPreconditioner(const Grid& grid, const HalfSpace& half_space, std::shared_ptr<SlabRealFft> transform);
  // Collective.
  void apply(std::span<const double> in, std::span<double> out) override;

 private:
  std::shared_ptr<SlabRealFft> transform_;
  std::vector<double> symbol_;  // E*|q|/(2N) or its coated form, on this process's spectrum columns
};

}  // namespace halfspace::mpi
