// The normal influence of a half-space (homogeneous or coated) on a grid,
// computed here and nowhere else: the Fourier symbol u(q)/p(q) of periodic
// grids and its inverse (the Fourier preconditioner's, the circulant form's
// stiffness), a free grid's cell coefficients on the DC-FFT's wrap-around
// grid, and K_ii. The serial and the distributed operators lay these values
// out on their own transforms.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "halfspace/fft/even_symbol.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/half_space.hpp"
#include "halfspace/kernels/layered_fourier.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::kernels {

class NormalKernel {
 public:
  // Throws InputError for an invalid E* (checked_composite_modulus) or
  // coating (LayeredKernel).
  NormalKernel(const Grid& grid, const HalfSpace& half_space);

  const Grid& grid() const { return grid_; }
  bool coated() const { return layered_.has_value(); }

  // |q| (rad/m) of row `row`, column `col` of the grid's own DFT (1D: qy = 0).
  double wavenumber(std::size_t row, std::size_t col) const;
  // u(q)/p(q) (m/Pa per unit spectral amplitude): 2/(E*|q|) (Stanley & Kato
  // 1997), or the coated 2 M(q t)/(E1*|q|); 0 at q = 0.
  double symbol(double q) const;
  // 1/symbol(q) for q > 0: the stiffness (Pa/m per unit spectral
  // amplitude), E*|q|/2 homogeneous.
  double stiffness(double q) const;
  // The same over `cells` (a transform's 1/N folded in), rounded as the
  // Fourier preconditioner has always formed it.
  double inverse_symbol(double q, double cells) const;
  // At row `row`, column `col` of the spectrum of the grid's own transform
  // ((ny, nx/2 + 1), one row in 1D), FFTW's 1/N folded in: symbol(q) / N, 0
  // at q = 0 (K on a periodic grid); and inverse_symbol(q, N), the mean mode
  // given the smallest non-zero wavenumber's value so that it stays
  // positive definite (the Fourier preconditioner, an approximate K^-1 on
  // any grid). preconditioner_symbol(transposed) is the latter on the whole
  // spectrum in a single-precision grid transform's layout (kx-major if
  // `transposed`, as make_single_grid_transform's in 2D), ky folded.
  double periodic_symbol(std::size_t row, std::size_t col) const;
  EvenSymbol preconditioner_symbol(bool transposed) const;
  double preconditioner_symbol(std::size_t row, std::size_t col) const;
  // preconditioner_symbol()'s mean mode: inverse_symbol(q, N) at the
  // smallest non-zero wavenumber q. Elsewhere it is 1/(N^2 periodic_symbol()),
  // which the preconditioner on an operator's kernel forms as it applies it.
  double preconditioner_at_zero() const;
  // K_ii (m/Pa), the displacement of a cell under unit pressure on itself.
  // Periodic: the inverse DFT at offset 0, (1/N) sum of symbol() over the
  // whole spectrum. Free: free_quadrant's coefficient at offset 0; where a
  // coated body's remainder goes in spectrally, padded_self_influence.
  double self_influence() const;

  // Free grids: rows [first_row, first_row + rows) of the quadrant of
  // non-negative offsets, coefficients k(i dx, j dy) for 0 <= i <= nx,
  // 0 <= j <= ny (one row in 1D), row-major with nx + 1 columns: Love's
  // rectangle (2D) or the plane-strain strip (1D); coated, the closed-form
  // part plus, unless spectral_remainder(), the remainder in real space.
  std::vector<double> free_quadrant(std::size_t first_row, std::size_t rows) const;
  // Rows [first, first + rows) of the padded (2ny, 2nx) wrap-around grid's
  // coefficients, 2nx values each into row(i) (i counted from first), from
  // the quadrant rows they read (all of them once, serially; a block of a
  // distributed transform's rows). They depend on |offset| only, so index k
  // of a 2n-periodic axis reads the quadrant at mirrored(k, n).
  void write_padded_rows(std::size_t first, std::size_t rows,
                         const std::function<std::span<double>(std::size_t)>& row) const;
  // Distance (in cells) of wrap-around index k on a 2n-periodic axis: k,
  // then 2n - k for the negative offsets. The middle index n gets distance
  // n: it multiplies only padding, never reaching the first n outputs.
  static std::size_t mirrored(std::size_t k, std::size_t n) { return k <= n ? k : 2 * n - k; }

  // Coated free grids: whether the remainder goes into the padded spectrum
  // (the layer is thin against the domain) rather than into free_quadrant.
  bool spectral_remainder() const;
  // The remainder's value in bin (row, col) of the padded grid's spectrum
  // (ky and kx indices of the (2ny, 2nx) transform; row 0 in 1D), for a
  // coated body only.
  double padded_remainder(std::size_t row, std::size_t col) const;
  // K_ii of a padded symbol (1/N folded in), its inverse DFT at offset 0,
  // over `count` bins of it, bin(k) giving {value, column kx}
  // (the bins a process holds; the caller sums over the processes).
  template <class Bin>
  double padded_self_influence(std::size_t count, Bin&& bin) const {
    double sum = 0.0;
    for (std::size_t k = 0; k < count; ++k) {
      const auto [value, col] = bin(k);
      // Columns other than kx = 0 and nx stand for two bins.
      sum += (col == 0 || col == grid_.nx() ? 1.0 : 2.0) * value;
    }
    return sum;
  }

 private:
  void add_real_space_remainder(std::vector<double>& quadrant, std::size_t first_row, std::size_t rows) const;

  Grid grid_;
  double e_star_ = 0.0;  // homogeneous (Pa)
  std::optional<LayeredKernel> layered_;
};

}  // namespace halfspace::kernels
