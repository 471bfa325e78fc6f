// The adhesive sphere of the sphere tests (adhesion_sphere_test.cpp,
// adhesion_jkr_sphere_test.cpp) in Maugis's units: lengths along the surface
// in ell = (pi w R^2 / K)^(1/3) (K = 4E*/3), approaches in ell^2 / R, forces
// in pi w R.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/solvers/adhesion_law.hpp"

namespace halfspace::testing {

// A sphere of radius R = 1 m on E* = 1 Pa with a cohesive law of Tabor
// parameter lambda = 2 sigma0 (R / (pi w K^2))^(1/3): Maugis-Dugdale of
// stress sigma0 (h0 = 2 / (pi lambda) approach units), or the exponential
// law of the same largest stress (rho = w / sigma0).
struct AdhesiveSphere {
  double lambda;
  double radius = 1.0;
  double e_star = 1.0;
  double work = 1e-4;
  double k() const { return 4.0 * e_star / 3.0; }
  double ell() const { return std::cbrt(std::numbers::pi * work * radius * radius / k()); }
  double sigma0() const { return 0.5 * lambda * k() * ell() / radius; }
  double approach_unit() const { return ell() * ell() / radius; }
  double force_unit() const { return std::numbers::pi * work * radius; }
  AdhesionLaw law() const { return AdhesionLaw::maugis_dugdale_from_stress(work, sigma0()); }
  AdhesionLaw exponential_law() const { return AdhesionLaw::exponential(work, work / sigma0()); }
};

// The paraboloid r^2 / (2R), its apex between the four middle cells.
inline std::vector<double> sphere_gap(const Grid& grid, double radius) {
  std::vector<double> gap(grid.size());
  const auto centred = [](std::size_t i, std::size_t n, double h) {
    return (static_cast<double>(i) + 0.5 - 0.5 * static_cast<double>(n)) * h;
  };
  for (std::size_t j = 0; j < grid.ny(); ++j) {
    for (std::size_t i = 0; i < grid.nx(); ++i) {
      const double x = centred(i, grid.nx(), grid.dx());
      const double y = centred(j, grid.ny(), grid.dy());
      gap[j * grid.nx() + i] = (x * x + y * y) / (2.0 * radius);
    }
  }
  return gap;
}

// JKR's load at contact radius A, P = A^3 - sqrt(6 A^3) (Maugis's curve as
// lambda -> infinity; F(a) = 4 E* a^3 / (3R) - sqrt(8 pi w E* a^3)).
inline double jkr_load(double a_bar) {
  return a_bar * a_bar * a_bar - std::sqrt(6.0 * a_bar * a_bar * a_bar);
}

// The least of `values` (one per entry of `at`, in sweep order), refined by
// the parabola through it and its neighbours (a force is smooth at its
// minimum); the least value itself at an end of the sweep or where the three
// do not curve upwards.
inline double refined_minimum(const std::vector<double>& at, const std::vector<double>& values) {
  const auto least = std::min_element(values.begin(), values.end());
  const auto k = static_cast<std::size_t>(least - values.begin());
  if (k == 0 || k + 1 >= values.size()) return *least;
  // Parabola through (x_i, f_i), i = k-1, k, k+1, at its vertex.
  const double x0 = at[k - 1], x1 = at[k], x2 = at[k + 1];
  const double f0 = values[k - 1], f1 = values[k], f2 = values[k + 1];
  const double d01 = (f1 - f0) / (x1 - x0);
  const double d12 = (f2 - f1) / (x2 - x1);
  const double curvature = (d12 - d01) / (x2 - x0);
  if (!(curvature > 0.0)) return f1;
  const double vertex = 0.5 * (x0 + x1) - d01 / (2.0 * curvature);
  return std::min(f1 + d01 * (vertex - x1) + curvature * (vertex - x0) * (vertex - x1), f1);
}

}  // namespace halfspace::testing
