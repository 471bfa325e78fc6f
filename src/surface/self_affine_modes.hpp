// The self-affine surface's filtered spectrum, mode by mode: shared by the
// serial synthesis (self_affine.cpp) and the slab one (MPI builds), which
// fill the same modes with the same values, each its own part.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <numbers>

#include "halfspace/grid.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/surface/self_affine.hpp"

namespace halfspace::surface::detail {

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
inline std::uint64_t mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

// A complex standard Gaussian (E|z|^2 = 2) for mode (kx, ky) by Box-Muller
// on two uniforms from the hash of (seed, kx, ky).
inline std::complex<double> gaussian(std::uint64_t seed, long long kx, long long ky) {
  const std::uint64_t key =
      mix(mix(mix(seed) ^ static_cast<std::uint64_t>(kx)) ^ (static_cast<std::uint64_t>(ky) * 0xD6E8FEB86659FD93ULL));
  constexpr double kUnit = 0x1.0p-53;
  const double u1 = static_cast<double>((key >> 11) + 1) * kUnit;  // (0, 1]: log is finite
  const double u2 = static_cast<double>(mix(key) >> 11) * kUnit;   // [0, 1)
  const double radius = std::sqrt(-2.0 * std::log(u1));
  const double angle = 2.0 * std::numbers::pi * u2;
  return {radius * std::cos(angle), radius * std::sin(angle)};
}

// The filtered spectrum's value at column c (kx = c >= 0) and row r of the
// r2c half spectrum (Step 1 of make_self_affine_surface): zero outside the
// band; column kx = 0 holds both ky and -ky, the pair drawn once, at
// ky > 0, and conjugated.
inline std::complex<double> filtered_mode(const ModeGeometry& modes, std::uint64_t seed, std::size_t c, std::size_t r) {
  if (!modes.in_band(c, r)) return {0.0, 0.0};
  const long long ky = modes.ky(r);
  const bool mirrored = c == 0 && ky < 0;
  const std::complex<double> z = gaussian(seed, static_cast<long long>(c), mirrored ? -ky : ky);
  return modes.amplitude(c, r) * (mirrored ? std::conj(z) : z);
}

// The mode's weight in the mean square slope (Step 2): |q|^2, counted twice
// for kx > 0 (its conjugate kx < 0 is not stored).
inline double slope_weight(const ModeGeometry& modes, std::size_t c, std::size_t r) {
  const double qx = modes.qx_unit * static_cast<double>(c);
  const double qy = modes.qy_unit * static_cast<double>(modes.ky(r));
  return (c == 0 ? 1.0 : 2.0) * (qx * qx + qy * qy);
}

// Step 3's end, on the whole grid or a process's rows of it: the
// rounding-level mean removed and the heights scaled to the requested rms
// height, or to the rms slope whose square the spectrum gave
// (`slope_squared`); the sums run over `comm`'s processes.
inline void remove_mean_and_scale(Eigen::ArrayXd& heights, const SelfAffineSpec& spec, double slope_squared,
                                  double cells, const linalg::Communicator& comm) {
  const auto n = static_cast<std::size_t>(heights.size());
  const double mean =
      linalg::sum(comm, n, [&](std::size_t i) { return heights[static_cast<Eigen::Index>(i)]; }) / cells;
  heights -= mean;
  double scale = 0.0;
  if (spec.rms_height) {
    const double square = linalg::sum(comm, n, [&](std::size_t i) {
      const double h = heights[static_cast<Eigen::Index>(i)];
      return h * h;
    });
    scale = *spec.rms_height / std::sqrt(square / cells);
  } else {
    scale = *spec.rms_slope / std::sqrt(slope_squared);
  }
  heights *= scale;
}

}  // namespace halfspace::surface::detail
