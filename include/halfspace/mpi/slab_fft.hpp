// The real 2D transform of a periodic (ny, nx) grid spread over MPI processes
// in slabs of rows (FFTW-MPI's distribution of the first, slowest axis). The
// spectrum is left transposed, (nx/2 + 1, ny) with this process's columns
// kx in [first_column, first_column + columns): the multipliers of the
// operator and the preconditioner act on it in that order, so no transpose
// back is needed. Compiled only with HALFSPACE_MPI.
#pragma once

#include <complex>
#include <cstddef>
#include <span>

#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"

namespace halfspace::mpi {

// Which rows of the grid (and columns of the transposed spectrum) a process
// holds.
struct SlabLayout {
  std::size_t nx = 0;
  std::size_t ny = 0;
  std::size_t rows = 0;          // rows of the grid held here
  std::size_t first_row = 0;     // the first of them
  std::size_t columns = 0;       // spectrum columns kx held here
  std::size_t first_column = 0;  // the first of them

  std::size_t local_size() const { return rows * nx; }
};

// FFTW-MPI's layout of the (ny, nx) grid over `comm`. Collective.
SlabLayout slab_layout(std::size_t nx, std::size_t ny, const MpiCommunicator& comm);

class SlabRealFft {
 public:
  // Plans the forward (real to transposed spectrum) and backward transforms
  // in one buffer, with the threads in force (set_threads). Collective;
  // throws InputError for sizes FFTW cannot take, std::runtime_error if
  // FFTW cannot plan.
  // With `workspace` (FFTW-aligned, as another transform's buffer is) large
  // enough for this process's part, the transform works in it instead of a
  // buffer of its own: for a transform that runs only while the owner of
  // the workspace is idle (the Fourier preconditioner in a free operator's
  // padded buffer). Whether it is large enough may differ between processes.
  SlabRealFft(std::size_t nx, std::size_t ny, const MpiCommunicator& comm, FftPlanning planning,
              std::span<std::complex<double>> workspace = {});
  ~SlabRealFft();
  SlabRealFft(const SlabRealFft&) = delete;
  SlabRealFft& operator=(const SlabRealFft&) = delete;

  const SlabLayout& layout() const { return layout_; }
  const MpiCommunicator& communicator() const { return comm_; }

  // The spectrum of this process's slab of `field` (layout().local_size()
  // values): copies it in and transforms. Collective.
  void forward(std::span<const double> field);
  // The transposed spectrum, columns x ny, [c * ny + r] for kx = first_column
  // + c and ky = r; valid after forward(), overwritten by backward().
  std::span<std::complex<double>> spectrum();
  // The unnormalised inverse transform of spectrum() into `field` (which may
  // be the one given to forward()). Collective.
  void backward(std::span<double> field);

 private:
  void release() noexcept;

  SlabLayout layout_;
  const MpiCommunicator& comm_;
  std::size_t padded_cols_ = 0;  // 2 (nx/2 + 1): FFTW's in-place row length
  std::complex<double>* buffer_ = nullptr;
  bool owns_buffer_ = true;
  void* forward_plan_ = nullptr;  // fftw_plan
  void* backward_plan_ = nullptr;
};

}  // namespace halfspace::mpi
