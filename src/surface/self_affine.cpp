// Fourier filtering of Gaussian noise into a self-affine surface. Standard
// construction (e.g. Persson et al. 2005, J. Phys.: Condens. Matter 17, R1;
// Jacobs, Junge & Pastewka 2017, Surf. Topogr. 5, 013001): the Fourier
// amplitudes of a Gaussian random field with power spectrum C(q) are
// sqrt(C(q)) times independent complex Gaussians.
#include "halfspace/surface/self_affine.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "halfspace/error.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/threads.hpp"

namespace halfspace::surface {
namespace {

// Modes within this relative distance of a cutoff count as inside the band,
// so that a cutoff placed exactly on a mode keeps it on every machine.
constexpr double kEdge = 1e-9;

// The Fourier modes of a grid: signed indices, wavenumbers, band test.
struct ModeGeometry {
  std::size_t nx, ny;
  std::size_t columns;  // nx / 2 + 1, the r2c half spectrum
  double qx_unit, qy_unit;
  double q_long, q_rolloff, q_short;
  double exponent;  // 2 + 2H in 2D, 1 + 2H in 1D

  ModeGeometry(const Grid& grid, const SelfAffineSpec& spec)
      : nx(grid.nx()),
        ny(grid.ny()),
        columns(grid.nx() / 2 + 1),
        qx_unit(2.0 * std::numbers::pi / (static_cast<double>(grid.nx()) * grid.dx())),
        qy_unit(grid.dimension() == 1 ? 0.0 : 2.0 * std::numbers::pi / (static_cast<double>(grid.ny()) * grid.dy())),
        q_long(2.0 * std::numbers::pi / spec.long_cutoff),
        q_rolloff(2.0 * std::numbers::pi / spec.rolloff),
        q_short(2.0 * std::numbers::pi / spec.short_cutoff),
        exponent((grid.dimension() == 1 ? 1.0 : 2.0) + 2.0 * spec.hurst) {}

  // Row r of the half spectrum is ky = r or r - ny; column c is kx = c >= 0.
  long long ky(std::size_t r) const {
    return r <= ny / 2 ? static_cast<long long>(r) : static_cast<long long>(r) - static_cast<long long>(ny);
  }
  bool nyquist(std::size_t c, std::size_t r) const {
    return (nx % 2 == 0 && c == nx / 2) || (ny > 1 && ny % 2 == 0 && r == ny / 2);
  }
  double q(std::size_t c, std::size_t r) const {
    const double qx = qx_unit * static_cast<double>(c);
    const double qy = qy_unit * static_cast<double>(ky(r));
    return std::sqrt(qx * qx + qy * qy);
  }
  bool in_band(std::size_t c, std::size_t r) const {
    if ((c == 0 && r == 0) || nyquist(c, r)) return false;
    const double wavenumber = q(c, r);
    return wavenumber >= q_long * (1.0 - kEdge) && wavenumber <= q_short * (1.0 + kEdge);
  }
  // sqrt(C(q) / C0).
  double amplitude(std::size_t c, std::size_t r) const {
    const double wavenumber = q(c, r);
    return wavenumber <= q_rolloff ? 1.0 : std::pow(wavenumber / q_rolloff, -0.5 * exponent);
  }
};

// SplitMix64 finaliser (Steele, Lea & Flood 2014): a bijective 64-bit mixer
// whose outputs pass BigCrush, used here as a counter-based generator.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

// A complex standard Gaussian (E|z|^2 = 2) for mode (kx, ky) by Box-Muller
// on two uniforms from the hash of (seed, kx, ky).
std::complex<double> gaussian(std::uint64_t seed, long long kx, long long ky) {
  const std::uint64_t key =
      mix(mix(mix(seed) ^ static_cast<std::uint64_t>(kx)) ^ (static_cast<std::uint64_t>(ky) * 0xD6E8FEB86659FD93ULL));
  constexpr double kUnit = 0x1.0p-53;
  const double u1 = static_cast<double>((key >> 11) + 1) * kUnit;  // (0, 1]: log is finite
  const double u2 = static_cast<double>(mix(key) >> 11) * kUnit;   // [0, 1)
  const double radius = std::sqrt(-2.0 * std::log(u1));
  const double angle = 2.0 * std::numbers::pi * u2;
  return {radius * std::cos(angle), radius * std::sin(angle)};
}

// The synthesis plan is made with one thread: FFTW may pick another algorithm,
// and round differently, for another thread count.
RealFft single_threaded_plan(const Grid& grid) {
  const int previous = threads();
  set_threads(1);
  RealFft fft = grid.dimension() == 1 ? RealFft(grid.nx(), FftPlanning::estimate)
                                      : RealFft(grid.ny(), grid.nx(), FftPlanning::estimate);
  set_threads(previous);
  return fft;
}

std::size_t count_band_modes(const ModeGeometry& modes) {
  std::size_t count = 0;
  for (std::size_t r = 0; r < modes.ny; ++r) {
    for (std::size_t c = 0; c < modes.columns; ++c) count += modes.in_band(c, r) ? 1 : 0;
  }
  return count;
}

void require(bool condition, const std::string& message) {
  if (!condition) throw InputError("self-affine surface: " + message);
}

}  // namespace

SelfAffineSpec SelfAffineSpec::resolved(const Grid& grid) const {
  SelfAffineSpec spec = *this;
  require(std::isfinite(hurst) && hurst > 0.0 && hurst <= 1.0,
          fmt::format("Hurst exponent {} is invalid: allowed range is (0, 1]", hurst));
  require(rms_height.has_value() != rms_slope.has_value(),
          rms_height ? "give either the rms height or the rms slope, not both"
                     : "no amplitude given: give the rms height (m) or the rms slope");
  const double amplitude = rms_height ? *rms_height : *rms_slope;
  require(std::isfinite(amplitude) && amplitude > 0.0,
          fmt::format("{} {} is invalid: must be positive", rms_height ? "rms height" : "rms slope", amplitude));
  for (const auto& [name, value] : {std::pair{"short cutoff", short_cutoff}, std::pair{"rolloff", rolloff},
                                    std::pair{"long cutoff", long_cutoff}}) {
    require(std::isfinite(value) && value >= 0.0,
            fmt::format("{} {} m is invalid: must be positive (or 0 for the default)", name, value));
  }

  const double spacing = grid.dimension() == 1 ? grid.dx() : std::max(grid.dx(), grid.dy());
  const double domain = std::max(static_cast<double>(grid.nx()) * grid.dx(),
                                 grid.dimension() == 1 ? 0.0 : static_cast<double>(grid.ny()) * grid.dy());
  if (spec.short_cutoff == 0.0) spec.short_cutoff = 2.0 * spacing;
  if (spec.long_cutoff == 0.0) spec.long_cutoff = domain;
  if (spec.rolloff == 0.0) spec.rolloff = spec.long_cutoff;
  require(spec.short_cutoff >= 2.0 * spacing * (1.0 - kEdge),
          fmt::format("short cutoff {} m is invalid: must be at least 2 max(dx, dy) = {} m, the shortest wavelength "
                      "the grid resolves",
                      spec.short_cutoff, 2.0 * spacing));
  require(spec.rolloff > spec.short_cutoff,
          fmt::format("rolloff {} m is invalid: must be longer than the short cutoff {} m", spec.rolloff,
                      spec.short_cutoff));
  require(spec.long_cutoff >= spec.rolloff,
          fmt::format("long cutoff {} m is invalid: must be at least the rolloff wavelength {} m", spec.long_cutoff,
                      spec.rolloff));
  require(count_band_modes(ModeGeometry(grid, spec)) > 0,
          fmt::format("no Fourier mode of the {} grid (domain {} m) has a wavelength between the short cutoff {} m "
                      "and the long cutoff {} m",
                      grid.shape_string(), domain, spec.short_cutoff, spec.long_cutoff));
  return spec;
}

Eigen::ArrayXd make_self_affine_surface(const Grid& grid, const SelfAffineSpec& requested) {
  const SelfAffineSpec spec = requested.resolved(grid);
  const ModeGeometry modes(grid, spec);
  RealFft fft = single_threaded_plan(grid);

  // Step 1: the filtered spectrum on the half plane kx >= 0. Column kx = 0
  // holds both ky and -ky: the pair is drawn once, at ky > 0, and conjugated.
  std::complex<double>* spectrum = fft.spectrum().data();
  linalg::for_each_row(modes.ny, modes.columns, [&](std::size_t r) {
    for (std::size_t c = 0; c < modes.columns; ++c) {
      std::complex<double> value(0.0, 0.0);
      if (modes.in_band(c, r)) {
        const long long ky = modes.ky(r);
        const bool mirrored = c == 0 && ky < 0;
        const std::complex<double> z = gaussian(spec.seed, static_cast<long long>(c), mirrored ? -ky : ky);
        value = modes.amplitude(c, r) * (mirrored ? std::conj(z) : z);
      }
      spectrum[r * modes.columns + c] = value;
    }
  });

  // Step 2: the mean square slope of the surface this spectrum makes. The
  // inverse transform is unnormalised, h(x) = sum_k H_k exp(i q_k x), so by
  // Parseval <|grad h|^2> = sum_k |q_k|^2 |H_k|^2 over the full spectrum
  // (no Nyquist modes, so no special case). Computed before the inverse
  // transform overwrites the spectrum.
  const double slope_sq = linalg::sum(fft.spectrum_size(), [&](std::size_t k) {
    const std::size_t r = k / modes.columns;
    const std::size_t c = k % modes.columns;
    const double qx = modes.qx_unit * static_cast<double>(c);
    const double qy = modes.qy_unit * static_cast<double>(modes.ky(r));
    return (c == 0 ? 1.0 : 2.0) * (qx * qx + qy * qy) * std::norm(spectrum[k]);
  });
  const double cells = static_cast<double>(grid.size());

  // Step 3: to real space; remove the rounding-level mean and scale.
  fft.backward();
  Eigen::ArrayXd heights =
      Eigen::Map<const Eigen::ArrayXd>(fft.output().data(), static_cast<Eigen::Index>(grid.size()));
  const double mean =
      linalg::sum(grid.size(), [&](std::size_t i) { return heights[static_cast<Eigen::Index>(i)]; }) / cells;
  heights -= mean;
  double scale = 0.0;
  if (spec.rms_height) {
    const double square = linalg::sum(grid.size(), [&](std::size_t i) {
      const double h = heights[static_cast<Eigen::Index>(i)];
      return h * h;
    });
    scale = *spec.rms_height / std::sqrt(square / cells);
  } else {
    scale = *spec.rms_slope / std::sqrt(slope_sq);
  }
  heights *= scale;
  return heights;
}

}  // namespace halfspace::surface
