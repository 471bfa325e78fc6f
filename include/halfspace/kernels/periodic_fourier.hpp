// Fourier-space kernel of a periodic elastic half-space (Stanley & Kato 1997):
// u(q) = 2 p(q) / (E* |q|) for q != 0; the mean mode is set to zero and fixed
// by the load or approach constraint instead.
#pragma once

#include <cstddef>

namespace halfspace::kernels {

// Angular wavenumber (rad/m) of DFT index k on n points of spacing h:
// 2 pi k' / (n h) with k' = k for k <= n/2 and k - n above (signed frequency).
double dft_wavenumber(std::size_t k, std::size_t n, double h);

// The kernel 2 / (E* |q|) (m/Pa per unit spectral amplitude), 0 at q = 0.
double periodic_kernel_spectrum(double q, double e_star);

}  // namespace halfspace::kernels
