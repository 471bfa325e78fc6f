// The DFT of a real (ny, nx) grid zero-padded to (2ny, 2nx), the grid spread
// over MPI processes in slabs of rows, and its inverse restricted back to the
// grid: the transforms of the free-boundary (DC-FFT) convolution on slabs.
// The counterpart of PaddedRealFft, pruned the same way: each process
// transforms its own ny rows along x (padded to 2nx, r2c), FFTW-MPI
// transposes the (ny, nx + 1) half-spectrum to columns, and each process
// transforms its columns along y (padded to 2ny, c2c); the inverse in reverse
// order. The padding rows never exist as rows, so the grid's slabs are the
// transform's input as they are and only the ny data rows are transposed
// (FFTW-MPI's 2D transform of the padded grid would move and transform
// twice as many). The spectrum stays transposed, (nx + 1, 2ny), each process
// holding its columns kx. Compiled only with HALFSPACE_MPI.
#pragma once

#include <complex>
#include <cstddef>
#include <span>

#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/slab_fft.hpp"

namespace halfspace::mpi {

class SlabPaddedRealFft {
 public:
  // Plans the local row and column transforms and the two distributed
  // transposes in one buffer, the size of this process's part of the padded
  // spectrum (or FFTW-MPI's transpose, if larger), with the threads in force.
  // The rows are the grid's slabs (slab_layout). Collective; throws
  // InputError for sizes FFTW cannot take, std::runtime_error if FFTW cannot
  // plan.
  SlabPaddedRealFft(std::size_t nx, std::size_t ny, const MpiCommunicator& comm, FftPlanning planning);
  ~SlabPaddedRealFft();
  SlabPaddedRealFft(const SlabPaddedRealFft&) = delete;
  SlabPaddedRealFft& operator=(const SlabPaddedRealFft&) = delete;

  // Rows: the grid's held here. Columns: the padded spectrum's kx held here,
  // of spectrum_cols().
  const SlabLayout& layout() const { return layout_; }
  const MpiCommunicator& communicator() const { return comm_; }
  std::size_t spectrum_rows() const { return 2 * layout_.ny; }
  std::size_t spectrum_cols() const { return layout_.nx + 1; }
  // The N of backward(forward(x)) = N x.
  double padded_size() const { return 4.0 * static_cast<double>(layout_.nx) * static_cast<double>(layout_.ny); }

  // The padded spectrum of this process's rows of the grid (layout().rows *
  // nx values). Collective.
  void forward(std::span<const double> block);
  // The transposed spectrum, columns x 2ny: [c * 2ny + r] for kx =
  // first_column + c (0 <= kx <= nx) and ky = r (0 <= r < 2ny); valid after
  // forward(), destroyed by backward().
  std::span<std::complex<double>> spectrum();
  // This process's rows of the grid part of the unnormalised inverse
  // transform of spectrum() (`block` may be the array given to forward()).
  // Collective.
  void backward(std::span<double> block);
  // The same for this process's rows of the padded grid's top half, all 2nx
  // values of each (layout().rows * 2nx values; the padding columns need
  // not be zero): the transforms of a field living on the padded grid
  // (the free operator's circulant form on slabs), whose padding rows ny .. 2ny - 1
  // the form transforms as a second top half. Collective.
  void forward_wide(std::span<const double> block);
  void backward_wide(std::span<double> block);
  // The whole buffer (at least spectrum()), FFTW-aligned; its contents
  // matter only from forward() to backward().
  std::span<std::complex<double>> buffer() { return {buffer_, buffer_size_}; }

 private:
  void release() noexcept;
  // forward() and backward() on rows `width` values long (nx or 2nx).
  void forward_rows(const double* block, std::size_t width);
  void backward_rows(double* block, std::size_t width);

  SlabLayout layout_;
  const MpiCommunicator& comm_;
  std::complex<double>* buffer_ = nullptr;
  std::size_t buffer_size_ = 0;   // complex values
  void* rows_forward_ = nullptr;  // fftw_plan: r2c of the local rows, 2nx long
  void* rows_backward_ = nullptr;
  void* to_columns_ = nullptr;       // FFTW-MPI transpose (ny, nx + 1) -> (nx + 1, ny)
  void* to_rows_ = nullptr;          // and back
  void* columns_forward_ = nullptr;  // c2c of the local columns, 2ny long
  void* columns_backward_ = nullptr;
};

}  // namespace halfspace::mpi
