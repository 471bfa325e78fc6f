// u = C t by FFT, two traction components in, two displacements out: each
// component transformed once, the 2x2 symbol applied mode by mode,
//   U_x = C_xx T_x + C_xy T_y,   U_y = C_xy T_x + C_yy T_y,
// and both transformed back (four transforms, twice a normal product).
// Periodic grids use the grid's own transform; free grids the pruned padded
// one (DC-FFT, Liu, Wang & Liu 2000), with the coefficients laid out on the
// (2ny, 2nx) wrap-around grid as FftInfluenceOperator lays out Love's. A
// coated body on a free grid splits its symbols as the normal coated kernel
// does (NormalKernel): closed-form cell coefficients (the layer's, plus the
// substrate's less the layer's smoothed to the split height) and the rest
// added to each bin of the padded spectrum (docs/theory.md, "Tangential
// compliance of a coated half-space").
#include "halfspace/operators/tangential_operator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <complex>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>

#include "halfspace/error.hpp"
#include "halfspace/fft/even_symbol.hpp"
#include "halfspace/kernels/cerruti_rectangle.hpp"
#include "halfspace/kernels/coupling_rectangle.hpp"
#include "halfspace/kernels/coupling_strip.hpp"
#include "halfspace/kernels/layered_tangential_fourier.hpp"
#include "halfspace/kernels/normal_kernel.hpp"
#include "halfspace/kernels/periodic_fourier.hpp"
#include "halfspace/kernels/tangential_strip.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::operators {
namespace {

// The signed offset (in cells) of wrap-around index k on a 2n-periodic axis:
// k, then k - 2n for the negative offsets. The middle index n multiplies only
// padding (it never reaches the first n outputs); it gets offset 0 for the
// odd xy part, whose spectrum then stays real, and n for the even parts.
long signed_offset(std::size_t k, std::size_t n) {
  return k < n ? static_cast<long>(k) : k == n ? 0 : static_cast<long>(k) - 2 * static_cast<long>(n);
}

// f(j, k, mode(k)) for every stored entry j of a symbol folded as `layout`
// on `transforms`, k the held entry it stands for (ky <= n/2).
template <class F>
void for_each_stored(const SpectralTransforms& transforms, const EvenSymbol& layout, F&& f) {
  const std::size_t length = transforms.spectrum_length();
  for (std::size_t r = 0; r < layout.stored_rows(); ++r) {
    for (std::size_t c = 0; c < layout.stored_cols(); ++c) {
      const std::size_t k = r * length + c;
      f(r * layout.stored_cols() + c, k, transforms.mode(k));
    }
  }
}

}  // namespace

std::string coated_free_grid_refusal(const Grid& grid, const ElasticPair& pair) {
  if (!pair.coating() || grid.periodic()) return {};
  if (grid.dimension() == 1) {
    return fmt::format(
        "a coated half-space's tangential compliance on the free 1D grid ({}) is not built "
        "(use --boundary periodic)",
        grid.shape_string());
  }
  const LayeredMaterial& coating = *pair.coating();
  if (!kernels::NormalKernel(grid, coating).spectral_remainder()) {
    return fmt::format(
        "a coated half-space's tangential compliance on the free {} grid needs a layer thin against the "
        "domain (split height {:.6g} m <= 1/8 of the shorter side, {:.6g} m; layer t = {:.6g} m): its "
        "remainder is built on the padded spectrum (use --boundary periodic, or a larger domain)",
        grid.shape_string(), kernels::LayeredKernel(coating).split_height(),
        std::min(static_cast<double>(grid.nx()) * grid.dx(), static_cast<double>(grid.ny()) * grid.dy()),
        coating.thickness);
  }
  return {};
}

namespace {

// (x, y) = S (x, y) for the symmetric 2x2 block S = {xx, xy, yy} on one
// mode's complex entries, as pairs of reals: through std::complex the
// compiler built each product on the stack and the loads stalled on the
// stores (most of the multiplication's time, docs/development-log.md).
struct Block {
  double xx;
  double xy;
  double yy;
};
template <class Real>
inline void multiply_block(const Block& block, Real* x, Real* y) {
  const auto xx = static_cast<Real>(block.xx);
  const auto xy = static_cast<Real>(block.xy);
  const auto yy = static_cast<Real>(block.yy);
  const Real xr = x[0];
  const Real xi = x[1];
  const Real yr = y[0];
  const Real yi = y[1];
  x[0] = xx * xr + xy * yr;
  x[1] = xx * xi + xy * yi;
  y[0] = xy * xr + yy * yr;
  y[1] = xy * xi + yy * yi;
}

// A spectrum's entries as (real, imaginary) pairs.
template <class Real>
Real* as_reals(std::span<std::complex<Real>> spectrum) {
  return reinterpret_cast<Real*>(spectrum.data());
}

void check_body(const Grid& grid, const ElasticPair& pair) {
  if (const std::string refusal = coated_free_grid_refusal(grid, pair); !refusal.empty()) throw InputError(refusal);
}

}  // namespace

struct TangentialOperator::Impl {
  Impl(const Grid& g, const ElasticPair& p, std::unique_ptr<SpectralTransforms> t)
      : grid(g), pair(p), transforms(std::move(t)) {
    spectrum_rows = transforms->spectrum_blocks();
    spectrum_cols = transforms->spectrum_length();
    const EvenSymbol layout(spectrum_rows, spectrum_cols, transforms->transposed());
    xx = yy = xy = layout;
    coupled = !p.similar();
    if (coupled) coupling_x = coupling_y = layout;
    if (g.periodic()) {
      init_periodic();
    } else {
      if (const auto& coating = p.coating()) {
        coated = ElasticPair::on_rigid(coating->substrate);
        height = kernels::LayeredKernel(*coating).split_height();
      }
      init_free();
      if (coupled) init_free_coupling();
      if (coated) add_coated_remainder();
    }
    // Over the stored entries: a mirrored one has the same eigenvalues.
    const double count = transforms->transform_size();
    for (std::size_t j = 0; j < xx.stored().size(); ++j) {
      const double mean = 0.5 * (xx.stored()[j] + yy.stored()[j]);
      const double spread = std::hypot(0.5 * (xx.stored()[j] - yy.stored()[j]), xy.stored()[j]);
      largest = std::max(largest, count * (mean + spread));
    }
    largest = transforms->communicator().max(largest);
    // The stored symbol carries 1/count; so does the inverse's (count^2 / count).
    largest_stored = largest / count;
    inverse_scale = 1.0 / (count * count);
  }

  // The symbol with FFTW's 1/N folded in, on the modes held here; C_ii is the
  // inverse DFT at zero offset, (1/N) times the sum over the full spectrum
  // (xy sums to zero), summed over every mode in one order on every process.
  void init_periodic() {
    const std::size_t nx = grid.nx();
    const std::size_t rows = transforms->spectrum_rows();
    const double inverse_n = 1.0 / static_cast<double>(grid.size());
    auto wavenumbers = [&](std::size_t r, std::size_t c) {
      return std::pair{kernels::dft_wavenumber(c, nx, grid.dx()),
                       grid.dimension() == 1 ? 0.0 : kernels::dft_wavenumber(r, rows, grid.dy())};
    };
    for_each_stored(*transforms, xx, [&](std::size_t j, std::size_t, SpectrumMode m) {
      const auto [r, c] = m;
      const auto [qx, qy] = wavenumbers(r, c);
      kernels::TangentialCoefficients s;
      kernels::CouplingCoefficients odd;
      pair.symbols(qx, qy, s, odd);
      xx.stored()[j] = s.xx * inverse_n;
      yy.stored()[j] = s.yy * inverse_n;
      xy.stored()[j] = s.xy * inverse_n;
      if (coupled) {
        // The odd symbol's component along an axis vanishes at that axis's
        // Nyquist frequency (an odd sequence's DFT does), where +q and -q
        // are the same mode: otherwise the product would not be real.
        const bool nyquist_x = 2 * c == nx;
        const bool nyquist_y = grid.dimension() == 2 && 2 * r == rows;
        coupling_x.stored()[j] = nyquist_x ? 0.0 : odd.x * inverse_n;
        coupling_y.stored()[j] = nyquist_y ? 0.0 : odd.y * inverse_n;
      }
    });
    double sum_xx = 0.0;
    double sum_yy = 0.0;
    for (std::size_t r = 0; r < rows; ++r) {
      for (std::size_t c = 0; c <= nx / 2; ++c) {
        const auto [qx, qy] = wavenumbers(r, c);
        const kernels::TangentialCoefficients s = pair.tangential_symbol(qx, qy);
        // Columns other than 0 and nx/2 (even nx) stand for two modes.
        const double weight = c == 0 || 2 * c == nx ? 1.0 : 2.0;
        sum_xx += weight * s.xx;
        sum_yy += weight * s.yy;
      }
    }
    self = {sum_xx * inverse_n, sum_yy * inverse_n, 0.0};
  }

  // Coefficients on the (2ny, 2nx) wrap-around grid, each part transformed
  // once; their spectra are real up to rounding (xx, yy even in each axis,
  // xy odd in each), so only the real parts are kept.
  void init_free() {
    const std::size_t nx = grid.nx();
    const std::size_t ny = grid.ny();
    const bool line = grid.dimension() == 1;
    const double a = 0.5 * grid.dx();
    const double b = 0.5 * grid.dy();
    const double e_star = pair.composite_modulus();
    const double shear = pair.shear_compliance();
    const double directional = pair.directional_compliance();
    auto coefficient = [&](long di, long dj) {
      const double x = static_cast<double>(di) * grid.dx();
      const double y = static_cast<double>(dj) * grid.dy();
      if (line) return kernels::tangential_strip_displacement(x, grid.dx(), e_star, shear);
      kernels::TangentialCoefficients k = kernels::cerruti_rectangle_displacement(x, y, a, b, shear, directional);
      if (coated) {
        const kernels::TangentialCoefficients far = kernels::cerruti_rectangle_displacement(
            x, y, a, b, coated->shear_compliance() - shear, coated->directional_compliance() - directional, height);
        k = {k.xx + far.xx, k.yy + far.yy, k.xy + far.xy};
      }
      return k;
    };
    self = coefficient(0, 0);
    EvenSymbol* parts[3] = {&xx, &yy, &xy};
    for (int part = 0; part < (line ? 2 : 3); ++part) {
      const bool odd = part == 2;
      const std::span<const std::complex<double>> spectrum =
          transforms->transform_wraparound([&](std::size_t r, std::size_t c) {
            long di = signed_offset(c, nx);
            long dj = line ? 0 : signed_offset(r, ny);
            if (!odd) {
              // The even parts take the mirrored distance n at the middle index.
              if (c == nx) di = static_cast<long>(nx);
              if (!line && r == ny) dj = static_cast<long>(ny);
            } else if (c == nx || (!line && r == ny)) {
              return 0.0;
            }
            const kernels::TangentialCoefficients k = coefficient(di, dj);
            return part == 0 ? k.xx : part == 1 ? k.yy : k.xy;
          });
      const double inverse_n = 1.0 / transforms->transform_size();
      for_each_stored(*transforms, xx, [&](std::size_t j, std::size_t k, SpectrumMode) {
        parts[part]->stored()[j] = spectrum[k].real() * inverse_n;
      });
    }
  }

  // The coupling coefficients on the wrap-around grid: the x part odd in x
  // and even in y, the y part the reverse, so their spectra are imaginary
  // up to rounding and only the imaginary parts are kept (the symbol c of
  // coupling_fourier.hpp, with the transform's 1/N).
  void init_free_coupling() {
    const std::size_t nx = grid.nx();
    const std::size_t ny = grid.ny();
    const bool line = grid.dimension() == 1;
    const double a = 0.5 * grid.dx();
    const double b = 0.5 * grid.dy();
    const double d = pair.coupling_compliance();
    const double far_d = coated ? coated->coupling_compliance() - d : 0.0;
    EvenSymbol* parts[2] = {&coupling_x, &coupling_y};
    for (int part = 0; part < (line ? 1 : 2); ++part) {
      const std::span<const std::complex<double>> spectrum =
          transforms->transform_wraparound([&](std::size_t r, std::size_t c) {
            // The odd axis takes offset 0 at its middle index (zero there),
            // the even one the mirrored distance n.
            const bool odd_middle = part == 0 ? c == nx : (!line && r == ny);
            if (odd_middle) return 0.0;
            const long di = c == nx ? static_cast<long>(nx) : signed_offset(c, nx);
            const long dj = line ? 0 : r == ny ? static_cast<long>(ny) : signed_offset(r, ny);
            const double x = static_cast<double>(di) * grid.dx();
            const double y = static_cast<double>(dj) * grid.dy();
            if (line) return kernels::coupling_strip_displacement(x, grid.dx(), d).x;
            const kernels::CouplingCoefficients k = kernels::coupling_rectangle_displacement(x, y, a, b, d);
            if (!coated) return part == 0 ? k.x : k.y;
            const kernels::CouplingCoefficients far =
                kernels::coupling_rectangle_displacement(x, y, a, b, far_d, height);
            return part == 0 ? k.x + far.x : k.y + far.y;
          });
      const double inverse_n = 1.0 / transforms->transform_size();
      for_each_stored(*transforms, xx, [&](std::size_t j, std::size_t k, SpectrumMode) {
        parts[part]->stored()[j] = spectrum[k].imag() * inverse_n;
      });
    }
  }

  // A coated body's remainder (LayeredTangentialKernel::
  // remainder_cell_spectrum) added to each bin held here; then K_ii, the
  // inverse DFT at offset 0 of the whole padded symbol (columns other than
  // 0 and nx stand for two modes; xy's vanishes).
  void add_coated_remainder() {
    const kernels::LayeredTangentialKernel layered(*pair.coating());
    const std::size_t nx = grid.nx();
    const std::size_t ny = grid.ny();
    const double inverse_n = 1.0 / transforms->transform_size();
    linalg::for_each_row(xx.stored_rows(), xx.stored_cols(), [&](std::size_t row) {
      for (std::size_t j = row * xx.stored_cols(); j < (row + 1) * xx.stored_cols(); ++j) {
        const auto [r, c] = transforms->mode(row * spectrum_cols + j % xx.stored_cols());
        kernels::TangentialCoefficients s;
        kernels::CouplingCoefficients odd;
        layered.remainder_cell_spectrum(kernels::dft_wavenumber(c, 2 * nx, grid.dx()),
                                        kernels::dft_wavenumber(r, 2 * ny, grid.dy()), grid.dx(), grid.dy(), height, s,
                                        odd);
        // The odd parts vanish on their Nyquist column or row, as the DFT
        // of an odd sequence does there.
        xx.stored()[j] += s.xx * inverse_n;
        yy.stored()[j] += s.yy * inverse_n;
        if (c != nx && r != ny) xy.stored()[j] += s.xy * inverse_n;
        if (coupled && c != nx) coupling_x.stored()[j] += odd.x * inverse_n;
        if (coupled && r != ny) coupling_y.stored()[j] += odd.y * inverse_n;
      }
    });
    double diagonal[2] = {0.0, 0.0};
    for (std::size_t k = 0; k < transforms->held(); ++k) {
      const std::size_t c = transforms->mode(k).col;
      const double weight = c == 0 || c == nx ? 1.0 : 2.0;
      diagonal[0] += weight * xx.value(k / spectrum_cols, k % spectrum_cols);
      diagonal[1] += weight * yy.value(k / spectrum_cols, k % spectrum_cols);
    }
    transforms->communicator().sum(diagonal);
    self = {diagonal[0], diagonal[1], 0.0};
  }

  Grid grid;
  ElasticPair pair;
  std::unique_ptr<SpectralTransforms> transforms;
  std::size_t spectrum_rows = 0;  // the entries held here, as blocks x length
  std::size_t spectrum_cols = 0;
  // The real symbol on the entries held here, folded in ky (xx, yy even in
  // ky, xy odd: its mirrored entries are the stored ones' negatives).
  EvenSymbol xx{0, 0}, yy{0, 0}, xy{0, 0};
  bool coupled = false;
  // The coupling's imaginary symbol c (coupling_fourier.hpp), folded the
  // same (c_x even in ky, c_y odd), empty unless coupled.
  EvenSymbol coupling_x{0, 0}, coupling_y{0, 0};
  kernels::TangentialCoefficients self;
  // Free grids, coated: the substrate against the rigid body, whose factors
  // less the layer's (the pair's) weight the smoothed closed forms at the
  // split height (m).
  std::optional<ElasticPair> coated;
  double height = 0.0;
  double largest = 0.0;         // largest_eigenvalue_bound()
  double largest_stored = 0.0;  // the same in the stored symbol's scale
  double inverse_scale = 0.0;   // 1/count^2: the inverse symbol's scale
  // Serial periodic 2D grids: the transforms of the single-precision
  // products, in the memory of the double ones' spectra (idle while these
  // run); empty elsewhere.
  std::unique_ptr<SingleRealFft> single[2];

  void make_single_transforms(FftPlanning planning) {
    if (!grid.periodic() || grid.dimension() != 2) return;
    for (int k = 0; k < 2; ++k) {
      const std::span<std::complex<double>> memory = transforms->spectrum(k);
      const std::span<std::complex<float>> workspace(reinterpret_cast<std::complex<float>*>(memory.data()),
                                                     2 * memory.size());
      if (workspace.size() < SingleRealFft::workspace_size(grid.ny(), grid.nx())) return;
      single[k] = std::make_unique<SingleRealFft>(grid.ny(), grid.nx(), planning, workspace, FftLayout::transposed);
    }
    // The spectra must be laid out as the double ones, where the symbols are.
    if (!single[0]->takes_double_rows() || !single[1]->takes_double_rows() ||
        single[0]->spectrum_blocks() != spectrum_rows || single[0]->spectrum_length() != spectrum_cols) {
      single[0].reset();
      single[1].reset();
    }
  }
  // (out_x, out_y) from (in_x, in_y) through the single-precision
  // transforms, multiply(sx, sy, first, count) working on the spectra's
  // blocks [first, first + count); false, and nothing done, without them.
  template <class Multiply>
  bool single_pair(std::span<const double> in_x, std::span<const double> in_y, std::span<double> out_x,
                   std::span<double> out_y, Multiply&& multiply) {
    const std::size_t n = grid.size();
    if (!single[0] || in_x.size() != n || in_y.size() != n || out_x.size() != n || out_y.size() != n) return false;
    float* const sx = as_reals(single[0]->spectrum());
    float* const sy = as_reals(single[1]->spectrum());
    fft::transform_pair_by_columns(*single[0], *single[1], in_x, in_y, out_x, out_y,
                                   [&](std::size_t first, std::size_t count) { multiply(sx, sy, first, count); });
    return true;
  }

  // (x, y) = S (x, y) on the spectrum blocks [first, first + count) of the
  // two spectra (pairs of reals), S the symbol.
  template <class Real>
  void multiply(Real* sx, Real* sy, std::size_t first, std::size_t count) const {
    const double* const sxx = xx.stored().data();
    const double* const syy = yy.stored().data();
    const double* const sxy = xy.stored().data();
    for (std::size_t r = first; r < first + count; ++r) {
      xx.for_each_entry(r, [&](std::size_t k, std::size_t j, double sign) {
        multiply_block({sxx[j], sign * sxy[j], syy[j]}, sx + 2 * k, sy + 2 * k);
      });
    }
  }

  // (x, y) = S^-1 (x, y) the same way (apply_approximate_inverse): the
  // inverse of the symmetric 2x2 block S = m I + D (D traceless, D^2 = s^2
  // I, eigenvalues m +- s) is f(m + s) P+ + f(m - s) P-, f(x) = 1/x, with
  // the spectral projectors P+- = (I +- D/s)/2.
  template <class Real>
  void invert(Real* sx, Real* sy, std::size_t first, std::size_t count) const {
    const double* const sxx = xx.stored().data();
    const double* const syy = yy.stored().data();
    const double* const sxy = xy.stored().data();
    const double floor = 1e-9 * largest_stored;
    const double scale = inverse_scale;
    auto inverse = [&](double eigenvalue) { return scale / (eigenvalue > floor ? eigenvalue : largest_stored); };
    for (std::size_t r = first; r < first + count; ++r) {
      // On the stored entry j: ixy, odd in xy, takes the mirrored sign.
      xx.for_each_entry(r, [&](std::size_t k, std::size_t j, double sign) {
        double ixx = 0.0;
        double iyy = 0.0;
        double ixy = 0.0;
        // Both eigenvalues above the floor ((xx - f)(yy - f) > xy^2 with
        // xx > f: the smaller one, m - s, exceeds f): the plain inverse, no
        // square root (almost every mode; the hypot per mode cost about a
        // tenth of a tangential step, docs/development-log.md).
        const double shifted_xx = sxx[j] - floor;
        const double shifted_yy = syy[j] - floor;
        if (shifted_xx > 0.0 && shifted_xx * shifted_yy > sxy[j] * sxy[j]) {
          const double f = scale / (sxx[j] * syy[j] - sxy[j] * sxy[j]);
          ixx = f * syy[j];
          iyy = f * sxx[j];
          ixy = -f * sxy[j];
        } else {
          const double mean = 0.5 * (sxx[j] + syy[j]);
          const double half_difference = 0.5 * (sxx[j] - syy[j]);
          const double spread = std::hypot(half_difference, sxy[j]);
          const double upper = inverse(mean + spread);
          const double lower = inverse(mean - spread);
          const double along = 0.5 * (upper + lower);
          // (f(m + s) - f(m - s)) / (2 s), zero when the block is a multiple of I.
          const double across = spread > 0.0 ? 0.5 * (upper - lower) / spread : 0.0;
          ixx = along + across * half_difference;
          iyy = along - across * half_difference;
          ixy = across * sxy[j];
        }
        multiply_block({ixx, sign * ixy, iyy}, sx + 2 * k, sy + 2 * k);
      });
    }
  }
};

TangentialOperator::TangentialOperator(const Grid& grid, const ElasticPair& pair, FftPlanning planning)
    : TangentialOperator(grid, pair, make_serial_transforms(grid, planning)) {
  impl_->make_single_transforms(planning);
}

TangentialOperator::TangentialOperator(const Grid& grid, const ElasticPair& pair,
                                       std::unique_ptr<SpectralTransforms> transforms)
    : impl_((check_body(grid, pair), std::make_unique<Impl>(grid, pair, std::move(transforms)))) {}

std::size_t TangentialOperator::local_size() const {
  return impl_->transforms->local_size();
}

const linalg::Communicator& TangentialOperator::communicator() const {
  return impl_->transforms->communicator();
}

TangentialOperator::~TangentialOperator() = default;

const Grid& TangentialOperator::grid() const {
  return impl_->grid;
}

const ElasticPair& TangentialOperator::pair() const {
  return impl_->pair;
}

kernels::TangentialCoefficients TangentialOperator::self_influence() const {
  return impl_->self;
}

bool TangentialOperator::coupled() const {
  return impl_->coupled;
}

void TangentialOperator::apply_pressure_coupling(std::span<const double> pressure, std::span<double> displacement_x,
                                                 std::span<double> displacement_y) {
  Impl& m = *impl_;
  assert(pressure.size() == local_size());
  assert(displacement_x.size() == local_size() && displacement_y.size() == local_size());
  if (!m.coupled) {
    std::fill(displacement_x.begin(), displacement_x.end(), 0.0);
    std::fill(displacement_y.begin(), displacement_y.end(), 0.0);
    return;
  }
  // U_a = i c_a P: the pressure's spectrum in transform 0, the y part
  // written into transform 1's.
  const std::span<std::complex<double>> sx = m.transforms->forward(0, pressure);
  const std::span<std::complex<double>> sy = m.transforms->spectrum(1);
  const double* cx = m.coupling_x.stored().data();
  const double* cy = m.coupling_y.stored().data();
  const std::complex<double> i(0.0, 1.0);
  linalg::for_each_row(m.spectrum_rows, m.spectrum_cols, [&](std::size_t r) {
    m.xx.for_each_entry(r, [&](std::size_t k, std::size_t j, double sign) {
      const std::complex<double> p = i * sx[k];
      sx[k] = cx[j] * p;
      sy[k] = (sign * cy[j]) * p;
    });
  });
  m.transforms->backward(0, displacement_x);
  m.transforms->backward(1, displacement_y);
}

void TangentialOperator::apply_traction_coupling(std::span<const double> traction_x, std::span<const double> traction_y,
                                                 std::span<double> normal_displacement) {
  Impl& m = *impl_;
  assert(traction_x.size() == local_size() && traction_y.size() == local_size());
  assert(normal_displacement.size() == local_size());
  if (!m.coupled) {
    std::fill(normal_displacement.begin(), normal_displacement.end(), 0.0);
    return;
  }
  // U_n = -i (c_x T_x + c_y T_y): K^T, the odd kernel's negative.
  const std::span<std::complex<double>> sx = m.transforms->forward(0, traction_x);
  const std::span<std::complex<double>> sy = m.transforms->forward(1, traction_y);
  const double* cx = m.coupling_x.stored().data();
  const double* cy = m.coupling_y.stored().data();
  const std::complex<double> minus_i(0.0, -1.0);
  linalg::for_each_row(m.spectrum_rows, m.spectrum_cols, [&](std::size_t r) {
    m.xx.for_each_entry(r, [&](std::size_t k, std::size_t j, double sign) {
      sx[k] = minus_i * (cx[j] * sx[k] + (sign * cy[j]) * sy[k]);
    });
  });
  m.transforms->backward(0, normal_displacement);
}

double TangentialOperator::largest_eigenvalue_bound() const {
  return impl_->largest;
}

void TangentialOperator::apply(std::span<const double> traction_x, std::span<const double> traction_y,
                               std::span<double> displacement_x, std::span<double> displacement_y) {
  Impl& m = *impl_;
  assert(traction_x.size() == local_size() && traction_y.size() == local_size());
  assert(displacement_x.size() == local_size() && displacement_y.size() == local_size());
  // Both inputs are read into the spectra before either output is written,
  // so in place is safe.
  double* const sx = as_reals(m.transforms->spectrum(0));
  double* const sy = as_reals(m.transforms->spectrum(1));
  m.transforms->apply_pair(traction_x, traction_y, displacement_x, displacement_y,
                           [&](std::size_t first, std::size_t count) { m.multiply(sx, sy, first, count); });
}

void TangentialOperator::apply_in_single_precision(std::span<const double> traction_x,
                                                   std::span<const double> traction_y, std::span<double> displacement_x,
                                                   std::span<double> displacement_y) {
  Impl& m = *impl_;
  const bool done = m.single_pair(
      traction_x, traction_y, displacement_x, displacement_y,
      [&](float* sx, float* sy, std::size_t first, std::size_t count) { m.multiply(sx, sy, first, count); });
  if (!done) apply(traction_x, traction_y, displacement_x, displacement_y);
}

bool TangentialOperator::single_precision() const {
  return static_cast<bool>(impl_->single[0]);
}

void TangentialOperator::apply_approximate_inverse(std::span<const double> displacement_x,
                                                   std::span<const double> displacement_y, std::span<double> traction_x,
                                                   std::span<double> traction_y) {
  Impl& m = *impl_;
  assert(displacement_x.size() == local_size() && displacement_y.size() == local_size());
  assert(traction_x.size() == local_size() && traction_y.size() == local_size());
  double* const sx = as_reals(m.transforms->spectrum(0));
  double* const sy = as_reals(m.transforms->spectrum(1));
  m.transforms->apply_pair(displacement_x, displacement_y, traction_x, traction_y,
                           [&](std::size_t first, std::size_t count) { m.invert(sx, sy, first, count); });
}

void TangentialOperator::apply_approximate_inverse_in_single_precision(std::span<const double> displacement_x,
                                                                       std::span<const double> displacement_y,
                                                                       std::span<double> traction_x,
                                                                       std::span<double> traction_y) {
  Impl& m = *impl_;
  const bool done = m.single_pair(
      displacement_x, displacement_y, traction_x, traction_y,
      [&](float* sx, float* sy, std::size_t first, std::size_t count) { m.invert(sx, sy, first, count); });
  if (!done) apply_approximate_inverse(displacement_x, displacement_y, traction_x, traction_y);
}

}  // namespace halfspace::operators
