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
#include "self_affine_modes.hpp"

namespace halfspace::surface {
namespace {

using detail::kEdge;
using detail::ModeGeometry;

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
      spectrum[r * modes.columns + c] = detail::filtered_mode(modes, spec.seed, c, r);
    }
  });

  // Step 2: the mean square slope of the surface this spectrum makes. The
  // inverse transform is unnormalised, h(x) = sum_k H_k exp(i q_k x), so by
  // Parseval <|grad h|^2> = sum_k |q_k|^2 |H_k|^2 over the full spectrum
  // (no Nyquist modes, so no special case). Computed before the inverse
  // transform overwrites the spectrum.
  const double slope_sq = linalg::sum(fft.spectrum_size(), [&](std::size_t k) {
    return detail::slope_weight(modes, k % modes.columns, k / modes.columns) * std::norm(spectrum[k]);
  });
  const double cells = static_cast<double>(grid.size());

  // Step 3: to real space; remove the rounding-level mean and scale.
  fft.backward();
  Eigen::ArrayXd heights =
      Eigen::Map<const Eigen::ArrayXd>(fft.output().data(), static_cast<Eigen::Index>(grid.size()));
  detail::remove_mean_and_scale(heights, spec, slope_sq, cells, linalg::serial_communicator());
  return heights;
}

}  // namespace halfspace::surface
