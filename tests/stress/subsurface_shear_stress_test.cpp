// The stresses of shear tractions on periodic and free grids: Cerruti's
// Fourier-mode field against the equations it must satisfy, the periodic
// field against a sum over periodic images of the closed-form cell
// coefficients, periodic against free for an isolated load, a loaded cell
// far away against Cerruti's point force, and the refusals (coated bodies:
// layered_subsurface_shear_stress_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/stress/fourier_shear_stress.hpp"
#include "halfspace/stress/rectangle_shear_stress.hpp"
#include "halfspace/stress/stress_volume.hpp"
#include "halfspace/stress/subsurface_stress.hpp"
#include "support/cerruti_point_force.hpp"
#include "support/grid_fields.hpp"

namespace halfspace::stress {
namespace {

using halfspace::testing::centred_x;
using halfspace::testing::centred_y;

double component(const StressTensor& s, std::size_t c) {
  const double v[] = {s.xx, s.yy, s.zz, s.xy, s.xz, s.yz};
  return v[c];
}

std::size_t index(Component c) {
  return static_cast<std::size_t>(c);
}

// The 3x3 tensor of a mode's multipliers (row i, column j).
using Tensor = std::array<std::array<std::complex<double>, 3>, 3>;
Tensor tensor_of(const std::array<std::complex<double>, kComponentCount>& m) {
  using C = Component;
  return {{{m[index(C::xx)], m[index(C::xy)], m[index(C::xz)]},
           {m[index(C::xy)], m[index(C::yy)], m[index(C::yz)]},
           {m[index(C::xz)], m[index(C::yz)], m[index(C::zz)]}}};
}

// Per Fourier mode exp(i k.x), the field must satisfy equilibrium
// (i k_a s_aj + d s_zj/dz = 0), Beltrami-Michell compatibility
// (lap s_ij + d_i d_j tr(s) / (1 + nu) = 0, lap = d^2/dz^2 - q^2) and the
// surface tractions (s_xz, s_yz, s_zz) = (-q_x, -q_y, 0); together they fix
// the elastic field. Derivatives in z by central differences.
TEST(FourierShearStressTest, SatisfiesEquilibriumCompatibilityAndSurfaceTractions) {
  constexpr double kDifferenceError = 1e-6;  // O(h^2) of the second differences, h = 1e-3 / q
  constexpr double kSurface = 1e-9;          // at z = 1e-12 / q
  const double nu = 0.3;
  struct Mode {
    double kx, ky, z;
  };
  const Mode modes[] = {{1.0, 0.0, 0.7}, {0.6, -0.8, 0.3}, {-2.0, 1.5, 0.4}, {0.0, 3.0, 0.2}, {5e5, 2e5, 3e-6}};
  for (const Traction direction : {Traction::shear_x, Traction::shear_y}) {
    for (const Mode& m : modes) {
      SCOPED_TRACE(::testing::Message() << "shear " << (direction == Traction::shear_x ? "x" : "y") << ", k = (" << m.kx
                                        << ", " << m.ky << "), z = " << m.z);
      const double q = std::hypot(m.kx, m.ky);
      const double h = 1e-3 / q;
      const Tensor s = tensor_of(fourier_shear_stress(direction, m.kx, m.ky, m.z, nu));
      const Tensor up = tensor_of(fourier_shear_stress(direction, m.kx, m.ky, m.z - h, nu));
      const Tensor down = tensor_of(fourier_shear_stress(direction, m.kx, m.ky, m.z + h, nu));
      const std::array<std::complex<double>, 3> ik = {{{0.0, m.kx}, {0.0, m.ky}, {0.0, 0.0}}};
      double scale = 0.0;
      for (const auto& row : s) {
        for (const std::complex<double> v : row) scale += std::abs(v);
      }
      // Equilibrium.
      for (int j = 0; j < 3; ++j) {
        const std::complex<double> divergence = ik[0] * s[0][j] + ik[1] * s[1][j] + (down[2][j] - up[2][j]) / (2.0 * h);
        EXPECT_LT(std::abs(divergence), kDifferenceError * q * scale) << "equilibrium, row " << j;
      }
      // Compatibility: d_i d_j tr with d_z as the second difference.
      const auto trace = [](const Tensor& t) { return t[0][0] + t[1][1] + t[2][2]; };
      const std::complex<double> tr = trace(s);
      const std::complex<double> tr_z = (trace(down) - trace(up)) / (2.0 * h);
      const std::complex<double> tr_zz = (trace(down) - 2.0 * tr + trace(up)) / (h * h);
      for (int i = 0; i < 3; ++i) {
        for (int j = i; j < 3; ++j) {
          const std::complex<double> laplacian = (down[i][j] - 2.0 * s[i][j] + up[i][j]) / (h * h) - q * q * s[i][j];
          std::complex<double> hessian;
          if (i < 2 && j < 2) hessian = ik[i] * ik[j] * tr;
          if (i < 2 && j == 2) hessian = ik[i] * tr_z;
          if (i == 2) hessian = tr_zz;
          EXPECT_LT(std::abs(laplacian + hessian / (1.0 + nu)), kDifferenceError * q * q * scale)
              << "compatibility " << i << j;
        }
      }
      // Surface tractions.
      const auto at_surface = fourier_shear_stress(direction, m.kx, m.ky, 1e-12 / q, nu);
      const bool along_x = direction == Traction::shear_x;
      EXPECT_LT(std::abs(at_surface[index(Component::xz)] - (along_x ? -1.0 : 0.0)), kSurface);
      EXPECT_LT(std::abs(at_surface[index(Component::yz)] - (along_x ? 0.0 : -1.0)), kSurface);
      EXPECT_LT(std::abs(at_surface[index(Component::zz)]), kSurface);
    }
  }
}

// A shear of no net force, centred on an odd n x n grid: a Hertz-like
// profile of radius a less that of radius a/2 scaled to the same force, so
// that neither the mean mode nor the images' far field enters.
std::vector<double> forceless_shear(const Grid& grid, double a, double& peak) {
  const auto profile = [&](double radius) {
    std::vector<double> field(grid.size());
    for (std::size_t j = 0; j < grid.ny(); ++j) {
      for (std::size_t i = 0; i < grid.nx(); ++i) {
        const double r2 = std::pow(centred_x(grid, i), 2) + std::pow(centred_y(grid, j), 2);
        field[j * grid.nx() + i] = r2 < radius * radius ? std::sqrt(1.0 - r2 / (radius * radius)) : 0.0;
      }
    }
    return field;
  };
  const std::vector<double> outer = profile(a);
  const std::vector<double> inner = profile(0.5 * a);
  double outer_sum = 0.0;
  double inner_sum = 0.0;
  for (std::size_t k = 0; k < outer.size(); ++k) {
    outer_sum += outer[k];
    inner_sum += inner[k];
  }
  std::vector<double> shear(outer.size());
  peak = 0.0;
  for (std::size_t k = 0; k < outer.size(); ++k) {
    shear[k] = 1e8 * (outer[k] - outer_sum / inner_sum * inner[k]);
    peak = std::max(peak, std::abs(shear[k]));
  }
  return shear;
}

// The periodic stresses of a shear along x and of another (a quarter of it,
// offset) along y against an independent sum: Cerruti's rectangle
// (rectangle_shear_stress.hpp, checked against the integral of Cerruti's
// point force) over every loaded cell and its images up to kImages periods
// away, at 3, 5 and 10 cells depth on every fourth cell of the centre row.
TEST(SubsurfaceShearStressTest, PeriodicMatchesASumOverPeriodicImages) {
  // As for the pressure (subsurface_stress_test.cpp): at 3 cells the content
  // of the cell-constant field above the Nyquist wavenumber, deeper the
  // images left out.
  constexpr double kAtThreeCells = 5e-5;  // measured 1.4e-5; deeper 2.9e-7 with 8 periods of images
  constexpr double kDeeper = 1e-6;
  constexpr int kImages = 8;
  const double dx = 1e-6;
  const std::size_t n = 33;
  const double a = 8.0 * dx;
  const Grid grid = Grid::plane(n, n, dx, dx, Boundary::periodic);
  double peak = 0.0;
  const std::vector<double> shear_x = forceless_shear(grid, a, peak);
  std::vector<double> shear_y(grid.size());
  for (std::size_t k = 0; k < grid.size(); ++k) shear_y[k] = 0.25 * shear_x[(k + 3 * n + 2) % grid.size()];
  const std::vector<double> pressure(grid.size(), 0.0);
  const std::vector<double> depths = {3.0 * dx, 5.0 * dx, 10.0 * dx};
  const double nu = 0.3;
  const StressVolume volume = compute_stress_volume(grid, {pressure, shear_x, shear_y}, depths, nu);
  const double period = static_cast<double>(n) * dx;
  const std::size_t row = n / 2;
  const double bounds[] = {kAtThreeCells, kDeeper, kDeeper};
  for (std::size_t d = 0; d < depths.size(); ++d) {
    double worst = 0.0;
    std::size_t worst_cell = 0;
    for (std::size_t i = 0; i < n; i += 4) {
      std::array<double, kComponentCount> sum{};
      for (std::size_t k = 0; k < grid.size(); ++k) {
        if (shear_x[k] == 0.0 && shear_y[k] == 0.0) continue;
        const double x = static_cast<double>(i) * dx - static_cast<double>(k % n) * dx;
        const double y = static_cast<double>(row) * dx - static_cast<double>(k / n) * dx;
        for (int my = -kImages; my <= kImages; ++my) {
          for (int mx = -kImages; mx <= kImages; ++mx) {
            const double xi = x + mx * period;
            const double yi = y + my * period;
            const StressTensor sx =
                rectangle_shear_stress(Traction::shear_x, xi, yi, depths[d], 0.5 * dx, 0.5 * dx, nu);
            const StressTensor sy =
                rectangle_shear_stress(Traction::shear_y, xi, yi, depths[d], 0.5 * dx, 0.5 * dx, nu);
            for (std::size_t c = 0; c < kComponentCount; ++c) {
              sum[c] += shear_x[k] * component(sx, c) + shear_y[k] * component(sy, c);
            }
          }
        }
      }
      for (std::size_t c = 0; c < kComponentCount; ++c) {
        const double difference = std::abs(volume.components[c][d * grid.size() + row * n + i] - sum[c]) / peak;
        if (difference > worst) {
          worst = difference;
          worst_cell = i;
        }
      }
    }
    std::printf(
        "shear, periodic vs image sum at %.0f cells depth: largest difference %.3g of the peak shear "
        "(column %zu)\n",
        depths[d] / dx, worst, worst_cell);
    EXPECT_LT(worst, bounds[d]) << "depth " << depths[d];
  }
}

// Largest |periodic - free| of the forceless shear within 2a of its centre
// at depths a/4, a/2 and a, over the peak shear; a line contact (plane
// strain and antiplane) when `line`.
double periodic_free_difference(std::size_t cells_per_radius, bool line) {
  const double dx = 1e-6;
  const double a = static_cast<double>(cells_per_radius) * dx;
  const std::size_t n = line ? 40 * cells_per_radius + 1 : 6 * cells_per_radius + 17;
  const Grid periodic = line ? Grid::line(n, dx, Boundary::periodic) : Grid::plane(n, n, dx, dx, Boundary::periodic);
  const Grid free = line ? Grid::line(n, dx, Boundary::free) : Grid::plane(n, n, dx, dx, Boundary::free);
  double peak = 0.0;
  const std::vector<double> shear = forceless_shear(periodic, a, peak);
  std::vector<double> half(shear.size());
  for (std::size_t k = 0; k < shear.size(); ++k) half[k] = -0.5 * shear[k];
  const std::vector<double> pressure(shear.size(), 0.0);
  const std::vector<double> depths = {0.25 * a, 0.5 * a, a};
  const StressVolume p = compute_stress_volume(periodic, {pressure, shear, half}, depths, 0.3);
  const StressVolume f = compute_stress_volume(free, {pressure, shear, half}, depths, 0.3);
  double worst = 0.0;
  for (std::size_t d = 0; d < depths.size(); ++d) {
    for (std::size_t k = 0; k < free.size(); ++k) {
      const double y = line ? 0.0 : centred_y(free, k / n);
      if (std::hypot(centred_x(free, k % n), y) > 2.0 * a) continue;
      for (std::size_t c = 0; c < kComponentCount; ++c) {
        worst = std::max(worst, std::abs(p.components[c][d * free.size() + k] - f.components[c][d * free.size() + k]));
      }
    }
  }
  return worst / peak;
}

TEST(SubsurfaceShearStressTest, PeriodicMatchesFreeForAnIsolatedShear) {
  constexpr double kSameQuestion = 3e-4;  // the periodic images' near field and the content above Nyquist
  for (const bool line : {false, true}) {
    const double coarse = periodic_free_difference(12, line);
    const double fine = periodic_free_difference(24, line);
    std::printf(
        "shear, periodic vs free (%s): largest difference %.3g (12 cells per radius), %.3g (24) of the "
        "peak shear\n",
        line ? "line" : "plane", coarse, fine);
    EXPECT_LT(coarse, kSameQuestion);
    EXPECT_LT(fine, kSameQuestion);
  }
}

TEST(SubsurfaceShearStressTest, UniformShearOnAPeriodicGridIsSimpleShear) {
  constexpr double kRounding = 1e-9;  // of 1 MPa
  const Grid grid = Grid::plane(16, 12, 1e-6, 1e-6, Boundary::periodic);
  const std::vector<double> pressure(grid.size(), 0.0);
  const std::vector<double> qx(grid.size(), 1e6);
  const std::vector<double> qy(grid.size(), -0.5e6);
  const StressVolume v = compute_stress_volume(grid, {pressure, qx, qy}, std::vector<double>{2e-6}, 0.3);
  for (std::size_t k = 0; k < grid.size(); ++k) {
    EXPECT_NEAR(v.components[index(Component::xz)][k], -1e6, kRounding * 1e6);
    EXPECT_NEAR(v.components[index(Component::yz)][k], 0.5e6, kRounding * 1e6);
    for (const Component c : {Component::xx, Component::yy, Component::zz, Component::xy}) {
      EXPECT_NEAR(v.components[index(c)][k], 0.0, kRounding * 1e6);
    }
  }
}

// One loaded cell of a free grid seen from far away is Cerruti's point
// force of the cell's total: the stresses at 6 to 16 cells' distance against
// Johnson's (1985) eq. 3.87, to O((dx / rho)^2).
TEST(SubsurfaceShearStressTest, SingleCellFarAwayIsCerrutisPointForce) {
  const double dx = 1e-6;
  const std::size_t n = 41;
  const Grid grid = Grid::plane(n, n, dx, dx, Boundary::free);
  const std::size_t centre = (n / 2) * n + n / 2;
  std::vector<double> shear(grid.size(), 0.0);
  shear[centre] = 1e6;  // Pa over one cell
  const std::vector<double> pressure(grid.size(), 0.0);
  const double force = 1e6 * dx * dx;
  const double nu = 0.28;
  const std::vector<double> depths = {6.0 * dx, 10.0 * dx, 16.0 * dx};
  const StressVolume v = compute_stress_volume(grid, {pressure, shear, {}}, depths, nu);
  for (std::size_t d = 0; d < depths.size(); ++d) {
    const double z = depths[d];
    const double scale = force / (z * z);  // the point force's stress magnitude at that depth
    double worst_here = 0.0;
    for (std::size_t k = 0; k < grid.size(); ++k) {
      const double x = centred_x(grid, k % n);
      const double y = centred_y(grid, k / n);
      const StressTensor expected = halfspace::testing::cerruti_point_force_stress(x, y, z, nu);
      for (std::size_t c = 0; c < kComponentCount; ++c) {
        const double e = std::abs(v.components[c][d * grid.size() + k] - force * component(expected, c)) / scale;
        worst_here = std::max(worst_here, e);
      }
    }
    std::printf("single cell vs Cerruti's point force at %.0f cells depth: largest difference %.3g of F/z^2\n", z / dx,
                worst_here);
    // The cell's second moments, dx^2 / 12 about its centre, times the
    // field's second derivatives: O((dx / z)^2); measured 0.075 (dx / z)^2
    // at each depth.
    EXPECT_LT(worst_here, 0.15 * (dx / z) * (dx / z)) << "depth " << z;
  }
}

TEST(SubsurfaceShearStressTest, RefusesBadShearFields) {
  const Grid grid = Grid::plane(8, 8, 1e-6, 1e-6, Boundary::periodic);
  const std::vector<double> pressure(grid.size(), 1.0);
  const std::vector<double> shear(grid.size(), 0.1);
  SubsurfaceStress stress(grid, 0.3);
  EXPECT_THROW(stress.set_tractions({pressure, std::vector<double>(5, 0.0), {}}), InputError);
  std::vector<double> bad = shear;
  bad[2] = std::nan("");
  try {
    stress.set_tractions({pressure, shear, bad});
    FAIL() << "a NaN shear was accepted";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "subsurface stress: shear traction along y value nan at index 2 is not finite");
  }
}

}  // namespace
}  // namespace halfspace::stress
