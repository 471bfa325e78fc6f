// u = K p by FFT. Periodic grids: multiply the pressure spectrum by the kernel
// 2/(E* |q|) (Stanley & Kato 1997), or a coated half-space's 2 M(q t)/(E1* |q|). Free grids: linear convolution with
// Love's (2D) or the strip (1D) coefficients by zero padding to 2n per axis (DC-FFT, Liu, Wang & Liu 2000), exact to
// rounding, through the pruned padded transform (PaddedRealFft).
#include "halfspace/operators/fft_influence_operator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/fft/even_symbol.hpp"
#include "halfspace/fft/grid_transform.hpp"
#include "halfspace/fft/padded_real_fft.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/kernels/layered_fourier.hpp"
#include "halfspace/kernels/love_rectangle.hpp"
#include "halfspace/kernels/periodic_fourier.hpp"
#include "halfspace/kernels/plane_strain_strip.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/material.hpp"

namespace halfspace::operators {
namespace {

// A shared transform must be the periodic grid's own: apply() hands it the
// grid's arrays and the kernel follows its spectrum's layout.
std::shared_ptr<RealFft> checked_shared_transform(const Grid& grid, std::shared_ptr<RealFft> transform) {
  if (!grid.periodic()) {
    throw InputError("FftInfluenceOperator: a shared transform needs a periodic grid (free grids pad it)");
  }
  return checked_grid_transform(grid, std::move(transform), "FftInfluenceOperator");
}

// Distance (in cells) of wrap-around index k on a 2n-periodic axis: k, then
// 2n - k for the negative offsets. The middle index n gets distance n: it
// multiplies only padding, never reaching the first n outputs, so any value
// would do.
std::size_t mirrored(std::size_t k, std::size_t n) {
  return k <= n ? k : 2 * n - k;
}

// K and K^-1 as symbols on one transform: the periodic grid's own (shared
// with the operator), or the whole padded grid's of a free one.
class SymbolForm final : public CirculantForm {
 public:
  SymbolForm(bool padded, std::shared_ptr<RealFft> fft, EvenSymbol kernel, EvenSymbol stiffness)
      : CirculantForm(padded), fft_(std::move(fft)), kernel_(std::move(kernel)), stiffness_(std::move(stiffness)) {}
  std::size_t local_size() const override { return fft_->real_size(); }
  std::size_t size() const override { return fft_->real_size(); }
  std::size_t row_stride() const override { return fft_->real_size() / fft_->rows(); }
  void apply(std::span<const double> in, std::span<double> out) override { kernel_.apply(*fft_, in, out); }
  void apply_inverse(std::span<const double> in, std::span<double> out) override { stiffness_.apply(*fft_, in, out); }

 private:
  std::shared_ptr<RealFft> fft_;
  EvenSymbol kernel_;
  EvenSymbol stiffness_;
};

}  // namespace

struct FftInfluenceOperator::Impl {
  // Periodic: `shared` is the grid's transform. Free: a padded one is made.
  // `layered`: a coated half-space's kernel instead of 2/(E* |q|).
  Impl(const Grid& g, double e_star, std::optional<kernels::LayeredKernel> layered_kernel,
       std::shared_ptr<RealFft> shared, FftPlanning planning)
      : grid(g),
        e_star(e_star),
        planning(planning),
        layered(std::move(layered_kernel)),
        transform(std::move(shared)),
        padded(transform ? nullptr
                         : std::make_unique<PaddedRealFft>(g.dimension() == 1 ? 1 : g.ny(), g.nx(), planning)),
        kernel(transform ? transform->rows() : padded->spectrum_rows(),
               transform ? transform->spectrum_cols() : padded->spectrum_cols()) {
    if (grid.periodic()) {
      init_periodic(e_star);
    } else {
      init_free();
    }
  }

  double spectrum(double q, double e_star) const {
    return layered ? layered->spectrum(q) : kernels::periodic_kernel_spectrum(q, e_star);
  }

  // Kernel spectrum 2/(E* |q|) with FFTW's 1/N folded in; K_ii is the inverse
  // DFT at zero offset, (1/N) sum over all q (full, not half, spectrum).
  void init_periodic(double e_star) {
    const std::size_t nx = grid.nx();
    const std::size_t ny = grid.ny();
    const std::size_t cols = kernel.cols();
    const double inverse_n = 1.0 / static_cast<double>(grid.size());
    auto wavenumber_y = [&](std::size_t r) {
      return grid.dimension() == 1 ? 0.0 : kernels::dft_wavenumber(r, ny, grid.dy());
    };
    for (std::size_t r = 0; r < kernel.stored_rows(); ++r) {
      const double qy = wavenumber_y(r);
      for (std::size_t c = 0; c < cols; ++c) {
        const double q = std::hypot(kernels::dft_wavenumber(c, nx, grid.dx()), qy);
        kernel.at(r, c) = spectrum(q, e_star) * inverse_n;
      }
    }
    double sum = 0.0;
    for (std::size_t r = 0; r < kernel.rows(); ++r) {
      const double qy = wavenumber_y(r);
      for (std::size_t c = 0; c < nx; ++c) {
        sum += spectrum(std::hypot(kernels::dft_wavenumber(c, nx, grid.dx()), qy), e_star);
      }
    }
    self = sum * inverse_n;
  }

  // Coefficients on the (2ny, 2nx) wrap-around grid, transformed once. They
  // depend on |offset| only (the kernels fold the sign), so the quadrant of
  // non-negative offsets ((ny + 1, nx + 1), or nx + 1 in 1D) is evaluated
  // once and mirrored.
  std::vector<double> free_quadrant() const {
    const std::size_t nx = grid.nx();
    const bool line = grid.dimension() == 1;
    const double dx = grid.dx();
    const double dy = grid.dy();
    const std::size_t quadrant_cols = nx + 1;
    const std::size_t quadrant_rows = line ? 1 : grid.ny() + 1;
    std::vector<double> quadrant(quadrant_rows * quadrant_cols);
    linalg::for_each_row(quadrant_rows, quadrant_cols, [&](std::size_t dj) {
      for (std::size_t di = 0; di < quadrant_cols; ++di) {
        const double x = static_cast<double>(di) * dx;
        const double y = static_cast<double>(dj) * dy;
        quadrant[dj * quadrant_cols + di] =
            line      ? (layered ? layered->near_strip_displacement(x, 0.5 * dx)
                                 : kernels::plane_strain_strip_displacement(x, dx, e_star))
            : layered ? layered->near_rectangle_displacement(x, y, 0.5 * dx, 0.5 * dy)
                      : kernels::love_rectangle_displacement(x, y, 0.5 * dx, 0.5 * dy, e_star);
      }
    });
    if (layered && !spectral_remainder()) add_layered_remainder_in_real_space(quadrant, quadrant_rows, quadrant_cols);
    return quadrant;
  }

  // The padded coefficients written into the rows `row(r)` (2nx values each)
  // of a transform of the padded grid.
  template <class Row>
  void write_padded(const std::vector<double>& quadrant, std::size_t rows, Row&& row) const {
    const std::size_t nx = grid.nx();
    linalg::for_each_row(rows, 2 * nx, [&](std::size_t r) {
      const std::size_t dj = grid.dimension() == 1 ? 0 : mirrored(r, grid.ny());
      std::span<double> values = row(r);
      for (std::size_t c = 0; c < values.size(); ++c) values[c] = quadrant[dj * (nx + 1) + mirrored(c, nx)];
    });
  }

  // The coefficients' spectrum through the pruned transform. Being even in
  // each axis, it is real up to rounding: only its real part is kept.
  void init_free() {
    const std::vector<double> quadrant = free_quadrant();
    self = quadrant[0];
    write_padded(quadrant, padded->spectrum_rows(), [&](std::size_t r) { return padded->padded_row(r); });
    padded->forward_all_rows();
    const double inverse_n = 1.0 / static_cast<double>(padded->padded_size());
    std::span<const std::complex<double>> spectrum = padded->spectrum();
    for (std::size_t r = 0; r < kernel.stored_rows(); ++r) {
      for (std::size_t c = 0; c < kernel.cols(); ++c)
        kernel.at(r, c) = spectrum[r * kernel.cols() + c].real() * inverse_n;
    }
    if (layered && spectral_remainder()) {
      add_layered_remainder(kernel, inverse_n);
      self = self_of_padded_kernel();
    }
  }

  // Free grids, coated half-space: the kernel's remainder R (layered_fourier.hpp),
  // smooth and decaying in q, added to the spectrum of the closed-form part's
  // coefficients. Its coefficients are 2n-periodic, as the DC-FFT's
  // wrap-around grid is, so it enters each bin exactly; their periodic images,
  // which the isolated contact has not, decay like t^2 / r^3 (the |q| term of
  // R at q = 0): docs/theory.md, "Coated half-space".
  // (`target`: a padded spectrum, scaled by `scale`.)
  void add_layered_remainder(EvenSymbol& target, double scale) const {
    const std::size_t rows = target.rows();
    const std::size_t padded_cols = 2 * grid.nx();
    const double dx = grid.dx();
    const double dy = grid.dy();
    const bool line = grid.dimension() == 1;
    linalg::for_each_row(target.stored_rows(), target.cols(), [&](std::size_t r) {
      const double qy = kernels::dft_wavenumber(r, rows, dy);
      for (std::size_t c = 0; c < target.cols(); ++c) {
        const double qx = kernels::dft_wavenumber(c, padded_cols, dx);
        target.at(r, c) +=
            (line ? layered->remainder_strip_spectrum(qx, dx) : layered->remainder_cell_spectrum(qx, qy, dx, dy)) *
            scale;
      }
    });
  }

  // K_ii: the padded kernel's coefficient at offset 0, the inverse DFT's sum
  // over the full spectrum (columns other than 0 and nx stand for two).
  double self_of_padded_kernel() const {
    const std::size_t rows = kernel.rows();
    double sum = 0.0;
    for (std::size_t r = 0; r < rows; ++r) {
      const std::size_t stored = kernel.folded(r);
      for (std::size_t c = 0; c < kernel.cols(); ++c) {
        sum += (c == 0 || c == grid.nx() ? 1.0 : 2.0) * kernel.at(stored, c);
      }
    }
    return sum;
  }

  // Free grids, coated half-space: whether the remainder goes in by DFT, or,
  // when the layer is not thin against the domain (its periodic images would
  // matter), in real space. The images' share falls like (h / L)^2, h the
  // split height (LayeredKernel::split_height: t, or the longer length a
  // stiff layer on a soft substrate spreads a load over; docs/theory.md,
  // "Coated half-space").
  static constexpr double kSpectralRemainderLimit = 0.125;  // h / shorter domain side
  bool spectral_remainder() const {
    const double length = static_cast<double>(grid.nx()) * grid.dx();
    const double side = grid.dimension() == 1 ? length : std::min(length, static_cast<double>(grid.ny()) * grid.dy());
    return layered->split_height() <= kSpectralRemainderLimit * side;
  }

  // The remainder as a point force at each cell's centre, from its radial
  // profile tabulated every t/100 (linear interpolation; the profile varies on
  // the scale t >= L/8, so both the point-force and the interpolation error
  // are below 1e-4 of the remainder).
  void add_layered_remainder_in_real_space(std::vector<double>& quadrant, std::size_t rows, std::size_t cols) const {
    const double dx = grid.dx();
    const double step = 0.01 * layered->material().thickness;
    if (grid.dimension() == 1) {
      // A line load of dx times the pressure at each cell's centre, the
      // profile tabulated at the cells' own offsets (n values: no
      // interpolation, whose kink at 0 would show at the 1e-9 level).
      const std::vector<double> table = layered->remainder_line_table(static_cast<double>(cols - 1) * dx, dx);
      for (std::size_t di = 0; di < cols; ++di) quadrant[di] += dx * table[di];
      return;
    }
    const double dy = grid.dy();
    const double r_max = std::hypot(static_cast<double>(cols - 1) * dx, static_cast<double>(rows - 1) * dy);
    const std::vector<double> table = layered->remainder_point_table(r_max, step);
    const double cell_area = grid.cell_area();
    linalg::for_each_row(rows, cols, [&](std::size_t dj) {
      for (std::size_t di = 0; di < cols; ++di) {
        const double position = std::hypot(static_cast<double>(di) * dx, static_cast<double>(dj) * dy) / step;
        const auto k = std::min(static_cast<std::size_t>(position), table.size() - 2);
        const double f = position - static_cast<double>(k);
        quadrant[dj * cols + di] += cell_area * ((1.0 - f) * table[k] + f * table[k + 1]);
      }
    });
  }

  // The circulant form: periodic grids multiply by the inverse kernel on
  // their own transform; free ones invert the padded kernel's spectrum on a
  // transform of the whole padded grid (its padding carries values here).
  std::unique_ptr<CirculantForm> make_circulant_form() {
    EvenSymbol stiffness(kernel.rows(), kernel.cols());
    if (grid.periodic()) {
      const double inverse_n = 1.0 / static_cast<double>(grid.size());
      for (std::size_t r = 0; r < kernel.stored_rows(); ++r) {
        const double qy = grid.dimension() == 1 ? 0.0 : kernels::dft_wavenumber(r, grid.ny(), grid.dy());
        for (std::size_t c = 0; c < kernel.cols(); ++c) {
          const double q = std::hypot(kernels::dft_wavenumber(c, grid.nx(), grid.dx()), qy);
          // The mean mode has no stiffness: solvers hold it by a constraint.
          if (q > 0.0) stiffness.at(r, c) = (layered ? 1.0 / layered->spectrum(q) : 0.5 * e_star * q) * inverse_n;
        }
      }
      return std::make_unique<SymbolForm>(false, transform, kernel, std::move(stiffness));
    }
    // The same coefficients transformed whole (the padding rows too), the
    // kernel and its inverse from the unnormalised eigenvalues k.
    const bool line = grid.dimension() == 1;
    auto fft = line ? std::make_shared<RealFft>(2 * grid.nx(), planning)
                    : std::make_shared<RealFft>(2 * grid.ny(), 2 * grid.nx(), planning);
    const std::size_t padded_cols = 2 * grid.nx();
    write_padded(free_quadrant(), kernel.rows(),
                 [&](std::size_t r) { return fft->input().subspan(r * padded_cols, padded_cols); });
    fft->forward();
    EvenSymbol eigenvalues(kernel.rows(), kernel.cols());
    const std::span<const std::complex<double>> spectrum = fft->spectrum();
    for (std::size_t r = 0; r < kernel.stored_rows(); ++r) {
      for (std::size_t c = 0; c < kernel.cols(); ++c) eigenvalues.at(r, c) = spectrum[r * kernel.cols() + c].real();
    }
    if (layered && spectral_remainder()) add_layered_remainder(eigenvalues, 1.0);
    const double inverse_m = 1.0 / static_cast<double>(padded->padded_size());
    EvenSymbol whole(kernel.rows(), kernel.cols());
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t r = 0; r < kernel.stored_rows(); ++r) {
      for (std::size_t c = 0; c < kernel.cols(); ++c) {
        const double k = eigenvalues.at(r, c);
        smallest = std::min(smallest, k);
        whole.at(r, c) = k * inverse_m;
        stiffness.at(r, c) = k > 0.0 ? inverse_m / k : 0.0;
      }
    }
    if (!(smallest > 0.0)) {
      throw InputError(fmt::format(
          "the free {} grid's padded influence kernel is not positive definite (smallest eigenvalue {:g} m/Pa), so it "
          "has no inverse (stiffness) to minimise an energy with; use a periodic grid{}",
          grid.shape_string(), smallest, line ? " or a domain shorter than 1 m (the strip kernel's datum)" : ""));
    }
    return std::make_unique<SymbolForm>(true, std::move(fft), std::move(whole), std::move(stiffness));
  }

  Grid grid;
  double e_star;  // homogeneous half-space (Pa)
  FftPlanning planning;
  std::optional<kernels::LayeredKernel> layered;
  std::shared_ptr<RealFft> transform;     // periodic grids: own, or shared with a preconditioner
  std::unique_ptr<PaddedRealFft> padded;  // free grids
  EvenSymbol kernel;                      // real kernel spectrum, rows folded (even in qy)
  double self = 0.0;
  std::unique_ptr<CirculantForm> circulant;  // made on first use
};

FftInfluenceOperator::FftInfluenceOperator(const Grid& grid, double e_star, FftPlanning planning)
    : impl_(std::make_unique<Impl>(grid, checked_composite_modulus(e_star), std::nullopt,
                                   grid.periodic() ? make_grid_transform(grid, planning) : nullptr, planning)) {}

FftInfluenceOperator::FftInfluenceOperator(const Grid& grid, double e_star, std::shared_ptr<RealFft> transform)
    : impl_(std::make_unique<Impl>(grid, checked_composite_modulus(e_star), std::nullopt,
                                   checked_shared_transform(grid, std::move(transform)), FftPlanning::estimate)) {}

// Coated half-space.

FftInfluenceOperator::FftInfluenceOperator(const Grid& grid, const LayeredMaterial& material, FftPlanning planning)
    : impl_(std::make_unique<Impl>(grid, 1.0, kernels::LayeredKernel(material),
                                   grid.periodic() ? make_grid_transform(grid, planning) : nullptr, planning)) {}

FftInfluenceOperator::FftInfluenceOperator(const Grid& grid, const LayeredMaterial& material,
                                           std::shared_ptr<RealFft> transform)
    : impl_(std::make_unique<Impl>(grid, 1.0, kernels::LayeredKernel(material),
                                   checked_shared_transform(grid, std::move(transform)), FftPlanning::estimate)) {}

FftInfluenceOperator::~FftInfluenceOperator() = default;

const Grid& FftInfluenceOperator::grid() const {
  return impl_->grid;
}

double FftInfluenceOperator::self_influence() const {
  return impl_->self;
}

std::span<std::complex<double>> FftInfluenceOperator::scratch() {
  return impl_->padded ? impl_->padded->spectrum() : std::span<std::complex<double>>{};
}

void FftInfluenceOperator::apply(std::span<const double> pressure, std::span<double> displacement) {
  Impl& m = *impl_;
  assert(pressure.size() == m.grid.size() && displacement.size() == m.grid.size());
  // In place is safe: the forward transform reads all of the input into the
  // spectrum before the backward one writes the output.
  assert(pressure.data() == displacement.data() || pressure.data() + pressure.size() <= displacement.data() ||
         displacement.data() + displacement.size() <= pressure.data());

  if (m.padded) {
    m.padded->forward(pressure);
    m.kernel.multiply(m.padded->spectrum());
    m.padded->backward(displacement);
    return;
  }
  // Periodic grids transform the caller's arrays directly when FFTW allows
  // it, else copy through the transform's own buffers.
  m.kernel.apply(*m.transform, pressure, displacement);
}

CirculantForm& FftInfluenceOperator::circulant_form() {
  Impl& m = *impl_;
  if (!m.circulant) m.circulant = m.make_circulant_form();
  return *m.circulant;
}

}  // namespace halfspace::operators
