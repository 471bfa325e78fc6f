// Random self-affine (fractal) surfaces by Fourier filtering: Gaussian random
// Fourier amplitudes shaped by a power-law spectrum between two cutoffs,
// periodic on the grid, normalised to a given rms height or rms slope.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>

#include "halfspace/grid.hpp"

namespace halfspace::surface {

// The isotropic power spectrum, with wavenumber q = 2 pi / wavelength,
// q_s = 2 pi / short_cutoff, q_r = 2 pi / rolloff, q_L = 2 pi / long_cutoff:
//
//   C(q) = 0                          for q < q_L or q > q_s,
//   C(q) = C0                         for q_L <= q < q_r (the rolloff plateau),
//   C(q) = C0 (q / q_r)^-(2 + 2H)     for q_r <= q <= q_s        (2D),
//   C(q) = C0 (q / q_r)^-(1 + 2H)     for q_r <= q <= q_s        (1D profile),
//
// with C0 fixed by the rms height or the rms slope. Lengths in m; 0 selects
// the default.
struct SelfAffineSpec {
  double hurst = 0.8;                // Hurst exponent H, in (0, 1]
  double short_cutoff = 0.0;         // shortest wavelength [2 max(dx, dy), the grid's limit]
  double rolloff = 0.0;              // the power law holds below this wavelength [long_cutoff]
  double long_cutoff = 0.0;          // longest wavelength [the domain's longer side]
  std::optional<double> rms_height;  // m, sqrt(<(h - <h>)^2>); exactly one of the two
  std::optional<double> rms_slope;   // sqrt(<|grad h|^2>) as defined by surface::rms_slope (periodic)
  std::uint64_t seed = 0;

  // The spec with every default replaced by its value on `grid`, checked:
  // throws InputError naming the parameter, its value and the allowed range
  // unless 0 < H <= 1, exactly one of rms_height and rms_slope is given and
  // positive, 2 max(dx, dy) <= short_cutoff < rolloff <= long_cutoff, and at
  // least one Fourier mode of the grid lies between the cutoffs.
  SelfAffineSpec resolved(const Grid& grid) const;
};

// Heights (m) on `grid`, (ny, nx) row-major, zero mean. The surface is
// periodic with the domain (nx dx, ny dy) whatever grid.boundary() says.
//
// Every Fourier mode k = (kx, ky) of the grid inside the band gets amplitude
// sqrt(C(|q|)) times a complex standard Gaussian drawn from a hash of
// (seed, kx, ky) alone, with H(-k) = conj(H(k)) so that the surface is real;
// the Nyquist modes of even axes are left out, so the discrete surface is
// exactly band-limited and its slope unambiguous. Hence the same seed gives
// the same bits for any thread count (the synthesis FFT is planned with one
// thread; FFTW wisdom loaded by earlier measured plans in the same process
// could still change the plan, and the last bits), and a mode's random
// number does not depend on the cutoffs.
// Finally the heights are scaled so that the requested rms height (about the
// mean) or rms slope (surface::rms_slope's periodic definition, evaluated on
// the spectrum) holds to rounding. Throws InputError as resolved() does.
Eigen::ArrayXd make_self_affine_surface(const Grid& grid, const SelfAffineSpec& spec);

}  // namespace halfspace::surface
