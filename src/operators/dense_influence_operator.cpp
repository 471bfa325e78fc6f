// The influence matrix assembled entry by entry from the same kernels as the
// FFT operator, but without FFTW: the periodic kernel comes from a direct DFT
// sum, so the two operators check each other.
#include "halfspace/operators/dense_influence_operator.hpp"

#include <fmt/format.h>

#include <cassert>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/kernels/love_rectangle.hpp"
#include "halfspace/kernels/periodic_fourier.hpp"
#include "halfspace/kernels/plane_strain_strip.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/material.hpp"

namespace halfspace::operators {
namespace {

std::string memory_string(double bytes) {
  constexpr double kMiB = 1024.0 * 1024.0;
  constexpr double kGiB = 1024.0 * kMiB;
  return bytes < kGiB ? fmt::format("{:.0f} MiB", bytes / kMiB) : fmt::format("{:.1f} GiB", bytes / kGiB);
}

void check_dense_size(const Grid& grid) {
  const std::size_t n = grid.size();
  if (n > kMaxDenseCells) {
    const double bytes = static_cast<double>(sizeof(double)) * static_cast<double>(n) * static_cast<double>(n);
    throw InputError(
        fmt::format("dense influence matrix for grid {} ({} cells) would take {}: the limit is {} cells; "
                    "use the FFT solver (Polonsky-Keer) instead",
                    grid.shape_string(), n, memory_string(bytes), kMaxDenseCells));
  }
}

// cos(2 pi m / n) for m in [0, n): the DFT twiddles, indexed by (k * i) mod n
// so that no large arguments are passed to cos. Mirrored (entry n - m is entry
// m) so that offsets d and -d sum identical terms: K is exactly symmetric.
std::vector<double> cos_table(std::size_t n) {
  std::vector<double> table(n);
  for (std::size_t m = 0; m <= n / 2; ++m) {
    table[m] = std::cos(2.0 * std::numbers::pi * static_cast<double>(m) / static_cast<double>(n));
    if (m > 0) table[n - m] = table[m];
  }
  return table;
}

// Real-space periodic kernel k(iy, ix) (m/Pa) at cell offset (ix dx, iy dy):
//   k = (1/N) sum_{ky, kx} S(q) cos(qx ix dx) cos(qy iy dy),
// the inverse DFT of S(q) = 2/(E* |q|) (Stanley & Kato 1997). S is even in qx
// and in qy separately, so the sine terms cancel and the sum separates into
// two passes, O(N (nx + ny)) in all.
Eigen::MatrixXd periodic_kernel_table(const Grid& grid, double e_star) {
  const std::size_t nx = grid.nx();
  const std::size_t ny = grid.ny();
  Eigen::MatrixXd spectrum(static_cast<Eigen::Index>(ny), static_cast<Eigen::Index>(nx));
  for (std::size_t ky = 0; ky < ny; ++ky) {
    const double qy = grid.dimension() == 1 ? 0.0 : kernels::dft_wavenumber(ky, ny, grid.dy());
    for (std::size_t kx = 0; kx < nx; ++kx) {
      const double q = std::hypot(kernels::dft_wavenumber(kx, nx, grid.dx()), qy);
      spectrum(static_cast<Eigen::Index>(ky), static_cast<Eigen::Index>(kx)) =
          kernels::periodic_kernel_spectrum(q, e_star);
    }
  }
  const std::vector<double> cos_x = cos_table(nx);
  const std::vector<double> cos_y = cos_table(ny);

  // Pass 1 over ky: partial(iy, kx) = sum_ky cos(2 pi ky iy / ny) S(ky, kx).
  Eigen::MatrixXd partial = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(ny), static_cast<Eigen::Index>(nx));
  linalg::for_each_index(ny, [&](std::size_t iy) {
    std::size_t m = 0;  // (ky * iy) mod ny
    for (std::size_t ky = 0; ky < ny; ++ky) {
      partial.row(static_cast<Eigen::Index>(iy)) += cos_y[m] * spectrum.row(static_cast<Eigen::Index>(ky));
      m += iy;
      if (m >= ny) m -= ny;
    }
  });
  // Pass 2 over kx: table(iy, ix) = (1/N) sum_kx partial(iy, kx) cos(2 pi kx ix / nx).
  Eigen::MatrixXd table(static_cast<Eigen::Index>(ny), static_cast<Eigen::Index>(nx));
  const double inverse_n = 1.0 / static_cast<double>(grid.size());
  linalg::for_each_index(nx, [&](std::size_t ix) {
    for (std::size_t iy = 0; iy < ny; ++iy) {
      double sum = 0.0;
      std::size_t m = 0;  // (kx * ix) mod nx
      for (std::size_t kx = 0; kx < nx; ++kx) {
        sum += partial(static_cast<Eigen::Index>(iy), static_cast<Eigen::Index>(kx)) * cos_x[m];
        m += ix;
        if (m >= nx) m -= nx;
      }
      table(static_cast<Eigen::Index>(iy), static_cast<Eigen::Index>(ix)) = sum * inverse_n;
    }
  });
  return table;
}

// Free-boundary coefficients k(iy, ix) at offset (ix dx, iy dy), ix, iy >= 0:
// Love's rectangle (2D) or the plane-strain strip (1D).
Eigen::MatrixXd free_kernel_table(const Grid& grid, double e_star) {
  const std::size_t nx = grid.nx();
  const std::size_t ny = grid.ny();
  Eigen::MatrixXd table(static_cast<Eigen::Index>(ny), static_cast<Eigen::Index>(nx));
  linalg::for_each_index(nx, [&](std::size_t ix) {
    const double x = static_cast<double>(ix) * grid.dx();
    for (std::size_t iy = 0; iy < ny; ++iy) {
      table(static_cast<Eigen::Index>(iy), static_cast<Eigen::Index>(ix)) =
          grid.dimension() == 1 ? kernels::plane_strain_strip_displacement(x, grid.dx(), e_star)
                                : kernels::love_rectangle_displacement(x, static_cast<double>(iy) * grid.dy(),
                                                                       0.5 * grid.dx(), 0.5 * grid.dy(), e_star);
    }
  });
  return table;
}

// Table index of the offset from cell `from` to cell `to` along an axis of n
// cells: wrapped into [0, n) when periodic, |to - from| when free.
std::size_t offset_index(std::size_t to, std::size_t from, std::size_t n, bool periodic) {
  if (periodic) return to >= from ? to - from : to + n - from;
  return to >= from ? to - from : from - to;
}

}  // namespace

Eigen::MatrixXd assemble_influence_matrix(const Grid& grid, double e_star) {
  checked_composite_modulus(e_star);
  check_dense_size(grid);
  const Eigen::MatrixXd table = grid.periodic() ? periodic_kernel_table(grid, e_star) : free_kernel_table(grid, e_star);

  const std::size_t nx = grid.nx();
  const std::size_t ny = grid.ny();
  const std::size_t n = grid.size();
  const bool periodic = grid.periodic();
  Eigen::MatrixXd matrix(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  // Column `source` holds the displacements of all cells under unit pressure
  // on cell `source`.
  linalg::for_each_index(n, [&](std::size_t source) {
    const std::size_t js = source / nx;
    const std::size_t is = source % nx;
    for (std::size_t target = 0; target < n; ++target) {
      const std::size_t jt = target / nx;
      const std::size_t it = target % nx;
      matrix(static_cast<Eigen::Index>(target), static_cast<Eigen::Index>(source)) =
          table(static_cast<Eigen::Index>(offset_index(jt, js, ny, periodic)),
                static_cast<Eigen::Index>(offset_index(it, is, nx, periodic)));
    }
  });
  return matrix;
}

DenseInfluenceOperator::DenseInfluenceOperator(const Grid& grid, double e_star)
    : grid_(grid), matrix_(assemble_influence_matrix(grid, e_star)), product_(matrix_.rows()) {}

void DenseInfluenceOperator::apply(std::span<const double> pressure, std::span<double> displacement) {
  const auto n = static_cast<Eigen::Index>(grid_.size());
  assert(pressure.size() == grid_.size() && displacement.size() == grid_.size());
  const Eigen::Map<const Eigen::VectorXd> p(pressure.data(), n);
  Eigen::Map<Eigen::VectorXd> u(displacement.data(), n);
  if (pressure.data() == displacement.data()) {
    product_.noalias() = matrix_ * p;
    u = product_;
    return;
  }
  u.noalias() = matrix_ * p;
}

}  // namespace halfspace::operators
