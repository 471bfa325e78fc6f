// FFTW-MPI's r2c/c2r pair on slabs of rows, transposed in Fourier space
// (FFTW_MPI_TRANSPOSED_OUT/IN: the all-to-all that would restore the row
// layout of the spectrum is skipped, both ways). FFTW-MPI keeps the in-place
// layout, rows padded to 2 (nx/2 + 1) reals, so the field is copied in and
// out of the buffer.
#include "halfspace/mpi/slab_fft.hpp"

#include <fftw3-mpi.h>
#include <fmt/format.h>

#include <mutex>
#include <new>
#include <stdexcept>

#include "../fft/fftw_planner.hpp"
#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/threads.hpp"

namespace halfspace::mpi {
namespace {

struct LocalSizes {
  SlabLayout layout;
  std::ptrdiff_t allocation = 0;  // complex values
};

LocalSizes local_sizes(std::size_t nx, std::size_t ny, MPI_Comm comm) {
  fft::detail::checked_extent(nx);
  fft::detail::checked_extent(ny);
  ptrdiff_t rows = 0;
  ptrdiff_t first_row = 0;
  ptrdiff_t columns = 0;
  ptrdiff_t first_column = 0;
  const ptrdiff_t allocation = fftw_mpi_local_size_2d_transposed(
      static_cast<ptrdiff_t>(ny), static_cast<ptrdiff_t>(nx / 2 + 1), comm, &rows, &first_row, &columns, &first_column);
  LocalSizes sizes;
  sizes.layout = {nx,
                  ny,
                  static_cast<std::size_t>(rows),
                  static_cast<std::size_t>(first_row),
                  static_cast<std::size_t>(columns),
                  static_cast<std::size_t>(first_column)};
  sizes.allocation = allocation;
  return sizes;
}

}  // namespace

SlabLayout slab_layout(std::size_t nx, std::size_t ny, const MpiCommunicator& comm) {
  return local_sizes(nx, ny, comm.get()).layout;
}

SlabRealFft::SlabRealFft(std::size_t nx, std::size_t ny, const MpiCommunicator& comm, FftPlanning planning,
                         std::span<std::complex<double>> workspace)
    : comm_(comm), padded_cols_(2 * (nx / 2 + 1)) {
  const LocalSizes sizes = local_sizes(nx, ny, comm.get());
  layout_ = sizes.layout;
  // At least one value, so that a process without rows still has a buffer.
  const auto needed = static_cast<std::size_t>(std::max<std::ptrdiff_t>(sizes.allocation, 1));
  if (workspace.size() >= needed) {
    buffer_ = workspace.data();
    owns_buffer_ = false;
  } else {
    buffer_ = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(needed));
  }
  if (buffer_ == nullptr) throw std::bad_alloc();
  double* real = reinterpret_cast<double*>(buffer_);
  fftw_complex* complex = fft::detail::as_fftw(buffer_);
  const auto n0 = static_cast<ptrdiff_t>(ny);
  const auto n1 = static_cast<ptrdiff_t>(nx);
  {
    // Planning is collective: every process reaches it, under its own lock.
    const std::lock_guard<std::mutex> lock(fft::detail::fftw_planner_mutex());
    fft::detail::init_fftw_threads();
    fftw_plan_with_nthreads(threads());
    const unsigned flags = fft::detail::planner_flags(planning);
    forward_plan_ = fftw_mpi_plan_dft_r2c_2d(n0, n1, real, complex, comm.get(), flags | FFTW_MPI_TRANSPOSED_OUT);
    backward_plan_ = fftw_mpi_plan_dft_c2r_2d(n0, n1, complex, real, comm.get(), flags | FFTW_MPI_TRANSPOSED_IN);
  }
  if (forward_plan_ == nullptr || backward_plan_ == nullptr) {
    release();
    throw std::runtime_error(fmt::format("FFTW-MPI could not plan the {}x{} transform", nx, ny));
  }
}

SlabRealFft::~SlabRealFft() {
  release();
}

void SlabRealFft::release() noexcept {
  const std::lock_guard<std::mutex> lock(fft::detail::fftw_planner_mutex());
  if (forward_plan_) fftw_destroy_plan(static_cast<fftw_plan>(forward_plan_));
  if (backward_plan_) fftw_destroy_plan(static_cast<fftw_plan>(backward_plan_));
  forward_plan_ = backward_plan_ = nullptr;
  if (buffer_ && owns_buffer_) fftw_free(buffer_);
  buffer_ = nullptr;
}

void SlabRealFft::forward(std::span<const double> field) {
  const std::size_t nx = layout_.nx;
  double* real = reinterpret_cast<double*>(buffer_);
  linalg::for_each_row(layout_.rows, nx, [&](std::size_t j) {
    for (std::size_t i = 0; i < nx; ++i) real[j * padded_cols_ + i] = field[j * nx + i];
  });
  fftw_execute(static_cast<fftw_plan>(forward_plan_));
}

std::span<std::complex<double>> SlabRealFft::spectrum() {
  return {buffer_, layout_.columns * layout_.ny};
}

void SlabRealFft::backward(std::span<double> field) {
  fftw_execute(static_cast<fftw_plan>(backward_plan_));
  const std::size_t nx = layout_.nx;
  const double* real = reinterpret_cast<const double*>(buffer_);
  linalg::for_each_row(layout_.rows, nx, [&](std::size_t j) {
    for (std::size_t i = 0; i < nx; ++i) field[j * nx + i] = real[j * padded_cols_ + i];
  });
}

}  // namespace halfspace::mpi
