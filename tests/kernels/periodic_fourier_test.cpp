// DFT wavenumbers in FFTW order and the periodic kernel spectrum 2/(E* |q|).
#include "halfspace/kernels/periodic_fourier.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace halfspace {
namespace {

using kernels::dft_wavenumber;
using kernels::periodic_kernel_spectrum;

constexpr double kPi = std::numbers::pi;
// Two roundings apart at most.
constexpr double kRoundingTolerance = 4e-16;

TEST(PeriodicFourierTest, WavenumbersFollowDftOrdering) {
  const double h = 2e-6;
  // Even n: 0, 1, ..., n/2 (Nyquist, positive), then -(n/2 - 1), ..., -1.
  const std::size_t n = 8;
  const double dq = 2.0 * kPi / (static_cast<double>(n) * h);
  const double expected_even[] = {0, 1, 2, 3, 4, -3, -2, -1};
  for (std::size_t k = 0; k < n; ++k) {
    EXPECT_NEAR(dft_wavenumber(k, n, h), expected_even[k] * dq, kRoundingTolerance * 4.0 * dq) << "k = " << k;
  }
  // Odd n: 0, 1, ..., (n-1)/2, then -(n-1)/2, ..., -1.
  const std::size_t m = 7;
  const double dq7 = 2.0 * kPi / (static_cast<double>(m) * h);
  const double expected_odd[] = {0, 1, 2, 3, -3, -2, -1};
  for (std::size_t k = 0; k < m; ++k) {
    EXPECT_NEAR(dft_wavenumber(k, m, h), expected_odd[k] * dq7, kRoundingTolerance * 3.0 * dq7) << "k = " << k;
  }
}

TEST(PeriodicFourierTest, KernelSpectrumIsTwoOverEStarQ) {
  const double e_star = 1.5e11;
  for (const double q : {1.0, 3.7e5, -2.0e6}) {
    const double expected = 2.0 / (e_star * std::abs(q));
    EXPECT_NEAR(periodic_kernel_spectrum(q, e_star), expected, kRoundingTolerance * expected) << "q = " << q;
  }
  EXPECT_EQ(periodic_kernel_spectrum(0.0, e_star), 0.0);
}

}  // namespace
}  // namespace halfspace
