// The pruned padded transform on slabs, in place in one buffer. Forward: the
// local rows as real rows at stride 2 (nx + 1), zero-padded to 2nx and
// transformed (r2c); FFTW-MPI's transpose of the (ny, nx + 1) complex half
// spectrum (pairs of doubles) leaves each process its columns, ny values
// each, which are spread in place to stride 2ny with zeros below and
// transformed (c2c, 2ny long). Backward: the columns back, their first ny
// values gathered to stride ny, the transpose back, the rows back (c2r),
// the first nx values of each row out. The wide forms take and give all 2nx
// values of each row.
#include "halfspace/mpi/slab_padded_fft.hpp"

#include <fftw3-mpi.h>
#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <mutex>
#include <new>
#include <stdexcept>

#include "../fft/fftw_planner.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/threads.hpp"

namespace halfspace::mpi {
namespace {

struct PaddedSizes {
  SlabLayout layout;
  std::size_t allocation = 0;  // doubles, for FFTW-MPI's transposes
};

// The transpose of the (ny, nx + 1) half spectrum with FFTW-MPI's default
// blocks: rows as the grid's slabs (checked against slab_layout), columns
// as the padded spectrum's.
PaddedSizes padded_sizes(std::size_t nx, std::size_t ny, const MpiCommunicator& comm) {
  fft::detail::checked_extent(2 * nx);
  fft::detail::checked_extent(2 * ny);
  const ptrdiff_t n[2] = {static_cast<ptrdiff_t>(ny), static_cast<ptrdiff_t>(nx + 1)};
  ptrdiff_t rows = 0;
  ptrdiff_t first_row = 0;
  ptrdiff_t columns = 0;
  ptrdiff_t first_column = 0;
  const ptrdiff_t allocation = fftw_mpi_local_size_many_transposed(
      2, n, 2, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK, comm.get(), &rows, &first_row, &columns, &first_column);
  const SlabLayout grid = slab_layout(nx, ny, comm);
  if (static_cast<std::size_t>(rows) != grid.rows || static_cast<std::size_t>(first_row) != grid.first_row) {
    // Both are FFTW-MPI's default block of ny rows; a different FFTW would
    // need the rows redistributed, which is not done.
    throw std::logic_error(
        fmt::format("FFTW-MPI distributes the {}x{} grid's rows differently for its padded transform", nx, ny));
  }
  PaddedSizes sizes;
  sizes.layout = {
      nx, ny, grid.rows, grid.first_row, static_cast<std::size_t>(columns), static_cast<std::size_t>(first_column)};
  sizes.allocation = static_cast<std::size_t>(allocation);
  return sizes;
}

}  // namespace

SlabPaddedRealFft::SlabPaddedRealFft(std::size_t nx, std::size_t ny, const MpiCommunicator& comm, FftPlanning planning)
    : comm_(comm) {
  const PaddedSizes sizes = padded_sizes(nx, ny, comm);
  layout_ = sizes.layout;
  // At least one value, so that a process without rows or columns still has
  // a buffer.
  const std::size_t complex_values =
      std::max({(sizes.allocation + 1) / 2, layout_.columns * spectrum_rows(), std::size_t{1}});
  buffer_ = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(complex_values));
  if (buffer_ == nullptr) throw std::bad_alloc();
  buffer_size_ = complex_values;
  double* real = reinterpret_cast<double*>(buffer_);
  fftw_complex* complex = fft::detail::as_fftw(buffer_);
  const int padded_x[1] = {fft::detail::checked_extent(2 * nx)};
  const int padded_y[1] = {fft::detail::checked_extent(2 * ny)};
  const int rows = static_cast<int>(layout_.rows);
  const int columns = static_cast<int>(layout_.columns);
  const int real_stride = static_cast<int>(2 * (nx + 1));
  const int row_spectrum = static_cast<int>(nx + 1);
  bool planned = true;
  {
    // The transposes are collective: every process plans them, in the same
    // order, under its own lock.
    const std::lock_guard<std::mutex> lock(fft::detail::fftw_planner_mutex());
    fft::detail::init_fftw_threads();
    fftw_plan_with_nthreads(threads());
    const unsigned flags = fft::detail::planner_flags(planning);
    const unsigned local = flags | FFTW_DESTROY_INPUT;
    to_columns_ =
        fftw_mpi_plan_many_transpose(static_cast<ptrdiff_t>(ny), static_cast<ptrdiff_t>(nx + 1), 2,
                                     FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK, real, real, comm.get(), flags);
    to_rows_ =
        fftw_mpi_plan_many_transpose(static_cast<ptrdiff_t>(nx + 1), static_cast<ptrdiff_t>(ny), 2,
                                     FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK, real, real, comm.get(), flags);
    planned = to_columns_ != nullptr && to_rows_ != nullptr;
    if (rows > 0) {
      rows_forward_ = fftw_plan_many_dft_r2c(1, padded_x, rows, real, nullptr, 1, real_stride, complex, nullptr, 1,
                                             row_spectrum, local);
      rows_backward_ = fftw_plan_many_dft_c2r(1, padded_x, rows, complex, nullptr, 1, row_spectrum, real, nullptr, 1,
                                              real_stride, local);
      planned = planned && rows_forward_ != nullptr && rows_backward_ != nullptr;
    }
    if (columns > 0) {
      columns_forward_ = fftw_plan_many_dft(1, padded_y, columns, complex, nullptr, 1, padded_y[0], complex, nullptr, 1,
                                            padded_y[0], FFTW_FORWARD, local);
      columns_backward_ = fftw_plan_many_dft(1, padded_y, columns, complex, nullptr, 1, padded_y[0], complex, nullptr,
                                             1, padded_y[0], FFTW_BACKWARD, local);
      planned = planned && columns_forward_ != nullptr && columns_backward_ != nullptr;
    }
  }
  if (!planned) {
    release();
    throw std::runtime_error(fmt::format("FFTW-MPI could not plan the padded transform of the {}x{} grid", nx, ny));
  }
}

SlabPaddedRealFft::~SlabPaddedRealFft() {
  release();
}

void SlabPaddedRealFft::release() noexcept {
  const std::lock_guard<std::mutex> lock(fft::detail::fftw_planner_mutex());
  for (void** plan :
       {&rows_forward_, &rows_backward_, &to_columns_, &to_rows_, &columns_forward_, &columns_backward_}) {
    if (*plan != nullptr) fftw_destroy_plan(static_cast<fftw_plan>(*plan));
    *plan = nullptr;
  }
  if (buffer_ != nullptr) fftw_free(buffer_);
  buffer_ = nullptr;
}

void SlabPaddedRealFft::forward(std::span<const double> block) {
  assert(block.size() == layout_.local_size());
  forward_rows(block.data(), layout_.nx);
}

void SlabPaddedRealFft::forward_wide(std::span<const double> block) {
  assert(block.size() == 2 * layout_.local_size());
  forward_rows(block.data(), 2 * layout_.nx);
}

void SlabPaddedRealFft::forward_rows(const double* block, std::size_t width) {
  const std::size_t ny = layout_.ny;
  const std::size_t stride = 2 * (layout_.nx + 1);
  double* real = reinterpret_cast<double*>(buffer_);
  linalg::for_each_row(layout_.rows, stride, [&](std::size_t j) {
    double* row = real + j * stride;
    std::copy_n(block + j * width, width, row);
    std::fill(row + width, row + stride, 0.0);
  });
  if (rows_forward_ != nullptr) fftw_execute(static_cast<fftw_plan>(rows_forward_));
  fftw_execute(static_cast<fftw_plan>(to_columns_));
  // Column c moves from c * ny to c * 2ny, its padding half zeroed. The
  // columns [ceil(hi / 2), hi) land above all of their sources, so they
  // move together (in parallel), the top group first.
  for (std::size_t hi = layout_.columns; hi > 1;) {
    const std::size_t lo = (hi + 1) / 2;
    linalg::for_each_row(hi - lo, 2 * ny, [&](std::size_t k) {
      const std::size_t c = lo + k;
      std::copy_n(buffer_ + c * ny, ny, buffer_ + c * 2 * ny);
      std::fill_n(buffer_ + c * 2 * ny + ny, ny, std::complex<double>(0.0, 0.0));
    });
    hi = lo;
  }
  if (layout_.columns > 0) std::fill_n(buffer_ + ny, ny, std::complex<double>(0.0, 0.0));
  if (columns_forward_ != nullptr) fftw_execute(static_cast<fftw_plan>(columns_forward_));
}

std::span<std::complex<double>> SlabPaddedRealFft::spectrum() {
  return {buffer_, layout_.columns * spectrum_rows()};
}

void SlabPaddedRealFft::backward(std::span<double> block) {
  assert(block.size() == layout_.local_size());
  backward_rows(block.data(), layout_.nx);
}

void SlabPaddedRealFft::backward_wide(std::span<double> block) {
  assert(block.size() == 2 * layout_.local_size());
  backward_rows(block.data(), 2 * layout_.nx);
}

void SlabPaddedRealFft::backward_rows(double* block, std::size_t width) {
  const std::size_t nx = layout_.nx;
  const std::size_t ny = layout_.ny;
  if (columns_backward_ != nullptr) fftw_execute(static_cast<fftw_plan>(columns_backward_));
  // The grid's ny rows of each column back to stride ny: the columns
  // [lo, 2 lo) land below all of their sources, so they move together, the
  // lowest group first.
  for (std::size_t lo = 1; lo < layout_.columns; lo *= 2) {
    const std::size_t hi = std::min(2 * lo, layout_.columns);
    linalg::for_each_row(hi - lo, ny, [&](std::size_t k) {
      const std::size_t c = lo + k;
      std::copy_n(buffer_ + c * 2 * ny, ny, buffer_ + c * ny);
    });
  }
  fftw_execute(static_cast<fftw_plan>(to_rows_));
  if (rows_backward_ != nullptr) fftw_execute(static_cast<fftw_plan>(rows_backward_));
  const std::size_t stride = 2 * (nx + 1);
  const double* real = reinterpret_cast<const double*>(buffer_);
  linalg::for_each_row(layout_.rows, width,
                       [&](std::size_t j) { std::copy_n(real + j * stride, width, block + j * width); });
}

}  // namespace halfspace::mpi
