// The half-space's normal kernel on a grid. Periodic: the symbol 2/(E* |q|)
// (Stanley & Kato 1997) or a coated half-space's 2 M(q t)/(E1* |q|). Free:
// Love's (2D) or the plane-strain strip's (1D) cell coefficients, laid out on
// the zero-padded wrap-around grid of the DC-FFT (Liu, Wang & Liu 2000); a
// coated body's closed-form part plus its remainder (docs/theory.md, "Coated
// half-space").
#include "halfspace/kernels/normal_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <variant>

#include "halfspace/kernels/love_rectangle.hpp"
#include "halfspace/kernels/periodic_fourier.hpp"
#include "halfspace/kernels/plane_strain_strip.hpp"
#include "halfspace/material.hpp"

namespace halfspace::kernels {
namespace {

// Free grids, coated half-space: the remainder goes in by DFT unless the
// layer is not thin against the domain (its periodic images would matter).
// The images' share falls like (h / L)^2, h the split height
// (LayeredKernel::split_height: t, or the longer length a stiff layer on a
// soft substrate spreads a load over; docs/theory.md, "Coated half-space").
constexpr double kSpectralRemainderLimit = 0.125;  // h / shorter domain side

}  // namespace

NormalKernel::NormalKernel(const Grid& grid, const HalfSpace& half_space) : grid_(grid) {
  if (const auto* coating = std::get_if<LayeredMaterial>(&half_space)) {
    layered_.emplace(*coating);
  } else {
    e_star_ = checked_composite_modulus(std::get<double>(half_space));
  }
}

double NormalKernel::wavenumber(std::size_t row, std::size_t col) const {
  const double qy = grid_.dimension() == 1 ? 0.0 : dft_wavenumber(row, grid_.ny(), grid_.dy());
  return std::hypot(dft_wavenumber(col, grid_.nx(), grid_.dx()), qy);
}

double NormalKernel::symbol(double q) const {
  return layered_ ? layered_->spectrum(q) : periodic_kernel_spectrum(q, e_star_);
}

double NormalKernel::stiffness(double q) const {
  return layered_ ? 1.0 / layered_->spectrum(q) : 0.5 * e_star_ * q;
}

double NormalKernel::inverse_symbol(double q, double cells) const {
  return layered_ ? 1.0 / (layered_->spectrum(q) * cells) : q * (0.5 * e_star_ / cells);
}

EvenSymbol NormalKernel::preconditioner_symbol(bool transposed) const {
  const std::size_t rows = grid_.dimension() == 1 ? 1 : grid_.ny();
  const std::size_t cols = grid_.nx() / 2 + 1;
  transposed = transposed && rows > 1;
  EvenSymbol inverse = transposed ? EvenSymbol(cols, rows, true) : EvenSymbol(rows, cols);
  for (std::size_t r = 0; r < inverse.stored_rows(); ++r) {
    for (std::size_t c = 0; c < inverse.stored_cols(); ++c) {
      inverse.at(r, c) = transposed ? preconditioner_symbol(c, r) : preconditioner_symbol(r, c);
    }
  }
  return inverse;
}

double NormalKernel::periodic_symbol(std::size_t row, std::size_t col) const {
  return symbol(wavenumber(row, col)) * (1.0 / static_cast<double>(grid_.size()));
}

double NormalKernel::preconditioner_symbol(std::size_t row, std::size_t col) const {
  const double q = wavenumber(row, col);
  return q > 0.0 ? inverse_symbol(q, static_cast<double>(grid_.size())) : preconditioner_at_zero();
}

double NormalKernel::preconditioner_at_zero() const {
  // The smallest non-zero |q| lies on an axis: |q| >= |qx|, |qy|.
  const std::size_t rows = grid_.dimension() == 1 ? 1 : grid_.ny() / 2 + 1;
  double q_min = std::numeric_limits<double>::infinity();
  for (std::size_t c = 1; c < grid_.nx() / 2 + 1; ++c) q_min = std::min(q_min, wavenumber(0, c));
  for (std::size_t r = 1; r < rows; ++r) q_min = std::min(q_min, wavenumber(r, 0));
  return inverse_symbol(q_min, static_cast<double>(grid_.size()));
}

double NormalKernel::self_influence() const {
  if (!grid_.periodic()) return free_quadrant(0, 1)[0];
  const std::size_t rows = grid_.dimension() == 1 ? 1 : grid_.ny();
  double sum = 0.0;
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < grid_.nx(); ++c) sum += symbol(wavenumber(r, c));
  }
  return sum * (1.0 / static_cast<double>(grid_.size()));
}

std::vector<double> NormalKernel::free_quadrant(std::size_t first_row, std::size_t rows) const {
  const bool line = grid_.dimension() == 1;
  const std::size_t cols = grid_.nx() + 1;
  const double dx = grid_.dx();
  const double dy = grid_.dy();
  std::vector<double> quadrant(rows * cols);
  linalg::for_each_row(rows, cols, [&](std::size_t j) {
    const double y = static_cast<double>(first_row + j) * dy;
    for (std::size_t i = 0; i < cols; ++i) {
      const double x = static_cast<double>(i) * dx;
      quadrant[j * cols + i] = line       ? (layered_ ? layered_->near_strip_displacement(x, 0.5 * dx)
                                                      : plane_strain_strip_displacement(x, dx, e_star_))
                               : layered_ ? layered_->near_rectangle_displacement(x, y, 0.5 * dx, 0.5 * dy)
                                          : love_rectangle_displacement(x, y, 0.5 * dx, 0.5 * dy, e_star_);
    }
  });
  if (layered_ && !spectral_remainder()) add_real_space_remainder(quadrant, first_row, rows);
  return quadrant;
}

// The remainder as a point force at each cell's centre, from its radial
// profile tabulated every t/100 up to the quadrant's far corner (linear
// interpolation; the profile varies on the scale t >= L/8, so both the
// point-force and the interpolation error are below 1e-4 of the remainder).
void NormalKernel::add_real_space_remainder(std::vector<double>& quadrant, std::size_t first_row,
                                            std::size_t rows) const {
  const std::size_t cols = grid_.nx() + 1;
  const double dx = grid_.dx();
  if (grid_.dimension() == 1) {
    // A line load of dx times the pressure at each cell's centre, the
    // profile tabulated at the cells' own offsets (n values: no
    // interpolation, whose kink at 0 would show at the 1e-9 level).
    const std::vector<double> table = layered_->remainder_line_table(static_cast<double>(cols - 1) * dx, dx);
    for (std::size_t di = 0; di < cols; ++di) quadrant[di] += dx * table[di];
    return;
  }
  const double dy = grid_.dy();
  const double step = 0.01 * layered_->material().thickness;
  const double r_max = std::hypot(static_cast<double>(cols - 1) * dx, static_cast<double>(grid_.ny()) * dy);
  const std::vector<double> table = layered_->remainder_point_table(r_max, step);
  const double cell_area = grid_.cell_area();
  linalg::for_each_row(rows, cols, [&](std::size_t j) {
    const double y = static_cast<double>(first_row + j) * dy;
    for (std::size_t di = 0; di < cols; ++di) {
      const double position = std::hypot(static_cast<double>(di) * dx, y) / step;
      const auto k = std::min(static_cast<std::size_t>(position), table.size() - 2);
      const double f = position - static_cast<double>(k);
      quadrant[j * cols + di] += cell_area * ((1.0 - f) * table[k] + f * table[k + 1]);
    }
  });
}

// The quadrant rows a block of wrap-around rows reads are consecutive
// unless it spans row ny (serially, all of them).
void NormalKernel::write_padded_rows(std::size_t first, std::size_t rows,
                                     const std::function<std::span<double>(std::size_t)>& row) const {
  const std::size_t ny = grid_.dimension() == 1 ? 0 : grid_.ny();
  std::size_t low = ny;
  std::size_t high = 0;
  for (std::size_t r = first; r < first + rows; ++r) {
    low = std::min(low, ny == 0 ? 0 : mirrored(r, ny));
    high = std::max(high, ny == 0 ? 0 : mirrored(r, ny));
  }
  const std::vector<double> quadrant = free_quadrant(low, high - low + 1);
  const std::size_t nx = grid_.nx();
  linalg::for_each_row(rows, 2 * nx, [&](std::size_t i) {
    const std::size_t dj = (ny == 0 ? 0 : mirrored(first + i, ny)) - low;
    const std::span<double> values = row(i);
    for (std::size_t c = 0; c < 2 * nx; ++c) values[c] = quadrant[dj * (nx + 1) + mirrored(c, nx)];
  });
}

bool NormalKernel::spectral_remainder() const {
  if (!layered_) return false;
  const double length = static_cast<double>(grid_.nx()) * grid_.dx();
  const double side = grid_.dimension() == 1 ? length : std::min(length, static_cast<double>(grid_.ny()) * grid_.dy());
  return layered_->split_height() <= kSpectralRemainderLimit * side;
}

// The remainder R (layered_fourier.hpp) is smooth and decays in q. Its
// coefficients are 2n-periodic, as the DC-FFT's wrap-around grid is, so it
// enters each bin exactly; their periodic images, which the isolated contact
// has not, decay like t^2 / r^3 (the |q| term of R at q = 0).
double NormalKernel::padded_remainder(std::size_t row, std::size_t col) const {
  const double dx = grid_.dx();
  const double qx = dft_wavenumber(col, 2 * grid_.nx(), dx);
  if (grid_.dimension() == 1) return layered_->remainder_strip_spectrum(qx, dx);
  const double qy = dft_wavenumber(row, 2 * grid_.ny(), grid_.dy());
  return layered_->remainder_cell_spectrum(qx, qy, dx, grid_.dy());
}

}  // namespace halfspace::kernels
