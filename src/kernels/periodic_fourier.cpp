// Fourier kernel of the periodic half-space (Stanley & Kato 1997) and the
// wavenumbers of FFTW's (unshifted) DFT ordering.
#include "halfspace/kernels/periodic_fourier.hpp"

#include <cassert>
#include <cmath>
#include <numbers>

namespace halfspace::kernels {

double dft_wavenumber(std::size_t k, std::size_t n, double h) {
  assert(k < n && h > 0.0);
  // Indices above n/2 are the negative frequencies k - n; for even n the
  // Nyquist index n/2 is taken as positive (its sign does not matter: |q|).
  const double signed_index = k <= n / 2 ? static_cast<double>(k) : -static_cast<double>(n - k);
  return 2.0 * std::numbers::pi * signed_index / (static_cast<double>(n) * h);
}

double periodic_kernel_spectrum(double q, double e_star) {
  // The q = 0 (mean) mode is a rigid-body translation, not set by the kernel.
  return q == 0.0 ? 0.0 : 2.0 / (e_star * std::abs(q));
}

}  // namespace halfspace::kernels
