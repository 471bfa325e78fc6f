// What the coated half-space's stress tests share: a hard coating, the
// sampled Hertz pressure, the largest difference of two stress volumes, and
// the independent reference for the pressure: sigma_zz on the axis by the
// axisymmetric (Hankel) transform of the per-mode solution.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/stress/layered_fourier_stress.hpp"
#include "halfspace/stress/stress_volume.hpp"
#include "support/grid_fields.hpp"

namespace halfspace::stress::testing {

// 5 um of a stiff layer (400 GPa) on steel.
inline const LayeredMaterial kHardCoating{5e-6, ElasticBody{400e9, 0.22}, ElasticBody{200e9, 0.3}};

// p0 sqrt(1 - r^2/a^2) about the grid's centre, 0 outside r = a.
inline std::vector<double> hertz_pressure(const Grid& grid, double a, double p0) {
  std::vector<double> p(grid.size());
  for (std::size_t j = 0; j < grid.ny(); ++j) {
    for (std::size_t i = 0; i < grid.nx(); ++i) {
      const double r2 =
          (std::pow(halfspace::testing::centred_x(grid, i), 2) + std::pow(halfspace::testing::centred_y(grid, j), 2)) /
          (a * a);
      p[j * grid.nx() + i] = r2 < 1.0 ? p0 * std::sqrt(1.0 - r2) : 0.0;
    }
  }
  return p;
}

// The largest difference of any component anywhere in two volumes.
inline double largest_difference(const StressVolume& a, const StressVolume& b) {
  double worst = 0.0;
  for (std::size_t c = 0; c < kComponentCount; ++c) {
    for (std::size_t k = 0; k < a.components[c].size(); ++k) {
      worst = std::max(worst, std::abs(a.components[c][k] - b.components[c][k]));
    }
  }
  return worst;
}

// sigma_zz on the axis under that pressure: its transform is
// 2 pi p0 a^2 j1(q a)/(q a) (j1 the spherical Bessel function), so
// sigma_zz(0, z) = -p0 int_0^inf j1(x) g(x z/a) dx, by Simpson's rule up to
// x z/a = 40.
inline double hankel_axis_sigma_zz(const LayeredFourierStress& layered, double a, double p0, double z) {
  const double x_max = 40.0 * a / z;
  const auto intervals = static_cast<std::size_t>(2 * std::ceil(x_max / 0.01 / 2));
  const double h = x_max / static_cast<double>(intervals);
  const Body body = layered.body_at(z);
  double sum = 0.0;
  for (std::size_t k = 1; k <= intervals; ++k) {  // the integrand is 0 at x = 0
    const double x = static_cast<double>(k) * h;
    const double j1 = (std::sin(x) - x * std::cos(x)) / (x * x);
    const double g = layered.profile(layered.solve(x / a), z, body).g;
    const double weight = k == intervals ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    sum += weight * j1 * g;
  }
  return -p0 * sum * h / 3.0;
}

}  // namespace halfspace::stress::testing
