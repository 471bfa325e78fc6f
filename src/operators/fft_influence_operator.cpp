// u = K p by FFT. Periodic grids: multiply the pressure spectrum by the kernel
// 2/(E* |q|) (Stanley & Kato 1997). Free grids: linear convolution with Love's
// (2D) or the strip (1D) coefficients by zero padding to 2n per axis (DC-FFT,
// Liu, Wang & Liu 2000), exact to rounding.
#include "halfspace/operators/fft_influence_operator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <complex>
#include <memory>
#include <utility>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/fft/even_symbol.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/kernels/love_rectangle.hpp"
#include "halfspace/kernels/periodic_fourier.hpp"
#include "halfspace/kernels/plane_strain_strip.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/material.hpp"

namespace halfspace {
namespace {

// Transform shape: the grid itself (periodic) or twice it per axis (free). A
// 1D grid is one row.
std::size_t transform_rows(const Grid& grid) {
  if (grid.dimension() == 1) return 1;
  return grid.periodic() ? grid.ny() : 2 * grid.ny();
}
std::size_t transform_cols(const Grid& grid) {
  return grid.periodic() ? grid.nx() : 2 * grid.nx();
}

// Padded transforms from this many points up work in place: below it FFTW's
// ESTIMATE plans for in-place transforms were up to 1.3x slower than the
// out-of-place ones (512^2 transform), above it faster, and that is where
// the memory matters (docs/performance.md).
constexpr std::size_t kInPlaceMinPoints = std::size_t{1} << 20;

// Periodic transforms have no padding to keep, so the inverse transform may
// overwrite the input: one real array less. Large padded free transforms work
// in place, in one buffer a third the size of three, and rewrite the zero
// padding before every forward transform; small ones keep the padding in
// their own input buffer.
RealFft make_fft(const Grid& grid, FftPlanning planning) {
  const bool large = transform_rows(grid) * transform_cols(grid) >= kInPlaceMinPoints;
  const FftOutput output =
      grid.periodic() ? FftOutput::overwrite_input : (large ? FftOutput::in_place : FftOutput::separate);
  if (grid.dimension() == 1) return RealFft(transform_cols(grid), planning, output);
  return RealFft(transform_rows(grid), transform_cols(grid), planning, output);
}

// A shared transform must be the periodic grid's own: apply() reads rows at
// stride fft.real_stride() and the kernel follows the spectrum's layout.
std::shared_ptr<RealFft> checked_shared_transform(const Grid& grid, std::shared_ptr<RealFft> transform) {
  if (!grid.periodic()) {
    throw InputError("FftInfluenceOperator: a shared transform needs a periodic grid (free grids pad it)");
  }
  if (!transform || transform->rows() != transform_rows(grid) || transform->cols() != transform_cols(grid)) {
    throw InputError(fmt::format("FftInfluenceOperator: the shared transform is {}x{} but the grid needs {}x{}",
                                 transform ? transform->rows() : 0, transform ? transform->cols() : 0,
                                 transform_rows(grid), transform_cols(grid)));
  }
  return transform;
}

// Distance (in cells) of wrap-around index k on a 2n-periodic axis: k, then
// 2n - k for the negative offsets. The middle index n gets distance n: it
// multiplies only padding, never reaching the first n outputs, so any value
// would do.
std::size_t mirrored(std::size_t k, std::size_t n) {
  return k <= n ? k : 2 * n - k;
}

// Calls copy(j, i) over an (ny, nx) block, in parallel over rows, or over the
// cells of a 1D grid's single row.
template <class Copy>
void copy_block(std::size_t ny, std::size_t nx, Copy&& copy) {
  if (ny == 1) {
    linalg::for_each_index(nx, [&](std::size_t i) { copy(0, i); });
  } else {
    linalg::for_each_row(ny, nx, [&](std::size_t j) {
      for (std::size_t i = 0; i < nx; ++i) copy(j, i);
    });
  }
}

// Writes the (ny, nx) block of `values` into the top-left corner of the
// (rows, stride) buffer and zero everywhere else, in parallel over rows.
void copy_padded(std::size_t ny, std::size_t nx, std::size_t rows, std::size_t stride, std::span<const double> values,
                 std::span<double> buffer) {
  if (rows == 1) {  // a 1D grid: one long row
    linalg::for_each_index(stride, [&](std::size_t i) { buffer[i] = i < nx ? values[i] : 0.0; });
    return;
  }
  linalg::for_each_row(rows, stride, [&](std::size_t j) {
    double* row = buffer.data() + j * stride;
    if (j < ny) {
      std::copy_n(values.data() + j * nx, nx, row);
      std::fill(row + nx, row + stride, 0.0);
    } else {
      std::fill(row, row + stride, 0.0);
    }
  });
}

}  // namespace

struct FftInfluenceOperator::Impl {
  Impl(const Grid& g, double e_star, std::shared_ptr<RealFft> shared)
      : grid(g), transform(std::move(shared)), fft(*transform), kernel(fft.rows(), fft.spectrum_cols()) {
    if (grid.periodic()) {
      init_periodic(e_star);
    } else {
      init_free(e_star);
    }
  }

  // Kernel spectrum 2/(E* |q|) with FFTW's 1/N folded in; K_ii is the inverse
  // DFT at zero offset, (1/N) sum over all q (full, not half, spectrum).
  void init_periodic(double e_star) {
    const std::size_t nx = grid.nx();
    const std::size_t ny = grid.ny();
    const std::size_t cols = fft.spectrum_cols();
    const double inverse_n = 1.0 / static_cast<double>(grid.size());
    auto wavenumber_y = [&](std::size_t r) {
      return grid.dimension() == 1 ? 0.0 : kernels::dft_wavenumber(r, ny, grid.dy());
    };
    for (std::size_t r = 0; r < kernel.stored_rows(); ++r) {
      const double qy = wavenumber_y(r);
      for (std::size_t c = 0; c < cols; ++c) {
        const double q = std::hypot(kernels::dft_wavenumber(c, nx, grid.dx()), qy);
        kernel.at(r, c) = kernels::periodic_kernel_spectrum(q, e_star) * inverse_n;
      }
    }
    double sum = 0.0;
    for (std::size_t r = 0; r < fft.rows(); ++r) {
      const double qy = wavenumber_y(r);
      for (std::size_t c = 0; c < nx; ++c) {
        sum += kernels::periodic_kernel_spectrum(std::hypot(kernels::dft_wavenumber(c, nx, grid.dx()), qy), e_star);
      }
    }
    self = sum * inverse_n;
  }

  // Coefficients on the (2ny, 2nx) wrap-around grid, transformed once. They
  // depend on |offset| only (the kernels fold the sign), so the quadrant of
  // non-negative offsets is evaluated once and mirrored. Being even in each
  // axis, they have a real spectrum up to rounding: only its real part is kept.
  void init_free(double e_star) {
    const std::size_t nx = grid.nx();
    const std::size_t ny = grid.ny();
    const bool line = grid.dimension() == 1;
    const double dx = grid.dx();
    const double dy = grid.dy();
    const std::size_t quadrant_cols = nx + 1;
    const std::size_t quadrant_rows = line ? 1 : ny + 1;
    std::vector<double> quadrant(quadrant_rows * quadrant_cols);
    linalg::for_each_row(quadrant_rows, quadrant_cols, [&](std::size_t dj) {
      for (std::size_t di = 0; di < quadrant_cols; ++di) {
        const double x = static_cast<double>(di) * dx;
        quadrant[dj * quadrant_cols + di] =
            line ? kernels::plane_strain_strip_displacement(x, dx, e_star)
                 : kernels::love_rectangle_displacement(x, static_cast<double>(dj) * dy, 0.5 * dx, 0.5 * dy, e_star);
      }
    });
    self = quadrant[0];

    const std::size_t rows = fft.rows();
    const std::size_t cols = fft.cols();
    const std::size_t stride = fft.real_stride();
    std::span<double> coefficients = fft.input();
    linalg::for_each_row(rows, cols, [&](std::size_t r) {
      const std::size_t dj = line ? 0 : mirrored(r, ny);
      for (std::size_t c = 0; c < cols; ++c)
        coefficients[r * stride + c] = quadrant[dj * quadrant_cols + mirrored(c, nx)];
    });
    fft.forward();
    const double inverse_n = 1.0 / static_cast<double>(fft.real_size());
    std::span<const std::complex<double>> spectrum = fft.spectrum();
    for (std::size_t r = 0; r < kernel.stored_rows(); ++r) {
      for (std::size_t c = 0; c < kernel.cols(); ++c)
        kernel.at(r, c) = spectrum[r * kernel.cols() + c].real() * inverse_n;
    }
    // apply() relies on the padding of a separate input buffer being zero.
    if (!fft.in_place()) std::fill(coefficients.begin(), coefficients.end(), 0.0);
  }

  Grid grid;
  std::shared_ptr<RealFft> transform;  // own, or shared with a preconditioner (periodic grids)
  RealFft& fft;
  EvenSymbol kernel;  // real kernel spectrum, rows folded (even in qy)
  double self = 0.0;
};

FftInfluenceOperator::FftInfluenceOperator(const Grid& grid, double e_star, FftPlanning planning)
    : impl_(std::make_unique<Impl>(grid, checked_composite_modulus(e_star),
                                   std::make_shared<RealFft>(make_fft(grid, planning)))) {}

FftInfluenceOperator::FftInfluenceOperator(const Grid& grid, double e_star, std::shared_ptr<RealFft> transform)
    : impl_(std::make_unique<Impl>(grid, checked_composite_modulus(e_star),
                                   checked_shared_transform(grid, std::move(transform)))) {}

FftInfluenceOperator::~FftInfluenceOperator() = default;

const Grid& FftInfluenceOperator::grid() const {
  return impl_->grid;
}

double FftInfluenceOperator::self_influence() const {
  return impl_->self;
}

void FftInfluenceOperator::apply(std::span<const double> pressure, std::span<double> displacement) {
  Impl& m = *impl_;
  const std::size_t nx = m.grid.nx();
  const std::size_t ny = m.grid.ny();
  assert(pressure.size() == m.grid.size() && displacement.size() == m.grid.size());
  assert(pressure.data() + pressure.size() <= displacement.data() ||
         displacement.data() + displacement.size() <= pressure.data());

  // Periodic grids transform the caller's arrays directly when FFTW allows
  // it. Otherwise rows of the grid sit at stride fft.real_stride(); a free
  // grid's transform (in place) gets its zero padding rewritten around them.
  const std::size_t stride = m.fft.real_stride();
  const bool direct = m.grid.periodic();
  if (!(direct && m.fft.forward_from(pressure))) {
    std::span<double> input = m.fft.input();
    if (m.fft.in_place()) {
      copy_padded(ny, nx, m.fft.rows(), stride, pressure, input);
    } else {  // any padding of a separate input buffer stays zero
      copy_block(ny, nx, [&](std::size_t j, std::size_t i) { input[j * stride + i] = pressure[j * nx + i]; });
    }
    m.fft.forward();
  }
  m.kernel.multiply(m.fft.spectrum());
  if (!(direct && m.fft.backward_into(displacement))) {
    m.fft.backward();
    std::span<const double> output = m.fft.output();
    copy_block(ny, nx, [&](std::size_t j, std::size_t i) { displacement[j * nx + i] = output[j * stride + i]; });
  }
}

}  // namespace halfspace
