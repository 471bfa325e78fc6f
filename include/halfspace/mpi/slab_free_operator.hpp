// The free (non-periodic) half-space's influence operator on a 2D grid
// spread over MPI processes in slabs of rows: the distributed counterpart of
// FftInfluenceOperator on a free grid, the linear convolution with Love's
// rectangle coefficients (a coated body's: kernels::NormalKernel) by zero padding to (2ny, 2nx) (DC-FFT, Liu, Wang &
// Liu 2000) through SlabPaddedRealFft. Fields hold this process's rows only.
// Compiled only with HALFSPACE_MPI.
#pragma once

#include <complex>
#include <memory>
#include <span>
#include <vector>

#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/half_space.hpp"
#include "halfspace/mpi/slab_padded_fft.hpp"
#include "halfspace/operators/influence_operator.hpp"

namespace halfspace::mpi {

class SlabFreeOperator final : public InfluenceOperator {
 public:
  // u = K p on the free 2D `grid` for the half-space (a composite modulus
  // E* in Pa, or a coated body), over `comm` (which must outlive the
  // operator). Each process computes the coefficients' spectrum of its own
  // columns only. Collective; throws InputError unless the grid is 2D and
  // free.
  SlabFreeOperator(const Grid& grid, const HalfSpace& half_space, const MpiCommunicator& comm,
                   FftPlanning planning = FftPlanning::estimate);
  ~SlabFreeOperator() override;

  const Grid& grid() const override { return grid_; }
  std::size_t local_size() const override { return fft_->layout().local_size(); }
  const linalg::Communicator& communicator() const override { return fft_->communicator(); }
  // Collective: every process applies the operator together.
  void apply(std::span<const double> pressure, std::span<double> displacement) override;
  double self_influence() const override { return self_; }
  // The whole (2ny, 2nx) wrap-around grid, as FftInfluenceOperator's free
  // form: this process holds its rows j and the padding rows ny + j, each
  // 2nx wide, as [rows j | rows ny + j] (row_stride() 2nx), so its grid
  // cells come first, at (k / nx) 2nx + k % nx. Made on first use, with a
  // second padded transform. Collective; throws InputError (on every
  // process) if the padded kernel is not positive definite.
  CirculantForm& circulant_form() override;
  // The padded transform's buffer, whose contents matter only inside
  // apply(): a workspace for a transform that runs only between products
  // (the Fourier preconditioner's SlabRealFft), as FftInfluenceOperator's
  // scratch() is serially. Lives as long as the operator.
  std::span<std::complex<double>> scratch() { return fft_->buffer(); }

 private:
  Grid grid_;
  FftPlanning planning_;
  std::unique_ptr<SlabPaddedRealFft> fft_;
  // The coefficients' (real) spectrum over the padded size on this
  // process's columns, [c * (ny + 1) + r]: even in ky, so ky = 0 .. ny only.
  std::vector<double> symbol_;
  double self_ = 0.0;
  std::unique_ptr<CirculantForm> circulant_;  // made on first use
};

}  // namespace halfspace::mpi
