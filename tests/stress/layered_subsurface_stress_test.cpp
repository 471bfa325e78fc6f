// Stresses below a coated half-space on periodic grids (free grids:
// free_layered_stress_test.cpp) (SubsurfaceStress with
// a LayeredMaterial): one Fourier mode against the per-mode solution, a layer
// equal to its substrate against the homogeneous field, and a Hertz pressure
// on a hard coating against an axisymmetric Hankel-transform evaluation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/stress/layered_fourier_stress.hpp"
#include "halfspace/stress/stress_volume.hpp"
#include "halfspace/stress/subsurface_stress.hpp"
#include "stress/coated_hertz_reference.hpp"
#include "support/grid_fields.hpp"

namespace halfspace::stress {
namespace {

using testing::hankel_axis_sigma_zz;
using testing::hertz_pressure;
using testing::kHardCoating;
using testing::largest_difference;

TEST(LayeredSubsurfaceStressTest, PeriodicFourierModeMatchesThePerModeSolution) {
  // Exact algebra through two FFTs: a few eps of the pressure amplitude.
  constexpr double kRoundoff = 1e-12;
  const LayeredFourierStress layered(kHardCoating);
  for (const bool line : {false, true}) {
    const Grid grid =
        line ? Grid::line(40, 0.5e-6, Boundary::periodic) : Grid::plane(32, 24, 1e-6, 1.5e-6, Boundary::periodic);
    const double kx = 2.0 * std::numbers::pi * 3.0 / (static_cast<double>(grid.nx()) * grid.dx());
    const double ky = line ? 0.0 : 2.0 * std::numbers::pi * -2.0 / (static_cast<double>(grid.ny()) * grid.dy());
    const double mean = 1e6;
    const double a = 0.7e6;
    const double b = -0.4e6;
    const auto phase_of = [&](std::size_t k) {
      return kx * static_cast<double>(k % grid.nx()) * grid.dx() +
             (line ? 0.0 : ky * static_cast<double>(k / grid.nx()) * grid.dy());
    };
    std::vector<double> pressure(grid.size());
    for (std::size_t k = 0; k < grid.size(); ++k) {
      pressure[k] = mean + a * std::cos(phase_of(k)) + b * std::sin(phase_of(k));
    }
    SubsurfaceStress stress(grid, kHardCoating);
    stress.set_pressure(pressure);
    const LayeredMode mode = layered.solve(std::hypot(kx, ky));
    // The pressure is constant on each cell: the mode's amplitude times the
    // cell's transform.
    const double cell = std::sin(0.5 * kx * grid.dx()) / (0.5 * kx * grid.dx()) *
                        (line ? 1.0 : std::sin(0.5 * ky * grid.dy()) / (0.5 * ky * grid.dy()));
    const LayeredMode uniform_mode = layered.solve(0.0);
    for (const double z : {0.3e-6, 4.0e-6, 5e-6, 9.0e-6}) {
      std::array<std::vector<double>, kComponentCount> values;
      std::array<std::span<double>, kComponentCount> fields;
      for (std::size_t c = 0; c < kComponentCount; ++c) {
        values[c].resize(grid.size());
        fields[c] = values[c];
      }
      stress.compute(z, fields);
      const Body body = layered.body_at(z);
      EXPECT_EQ(stress.in_layer(z), body == Body::layer);
      const auto wave = layered.stress(kx, ky, layered.profile(mode, z, body), body);
      const auto uniform = layered.stress(0.0, 0.0, layered.profile(uniform_mode, z, body), body);
      for (std::size_t k = 0; k < grid.size(); ++k) {
        for (std::size_t c = 0; c < kComponentCount; ++c) {
          const double expected = mean * uniform[c].real() +
                                  cell * (wave[c] * std::complex<double>(a, -b) * std::polar(1.0, phase_of(k))).real();
          ASSERT_NEAR(values[c][k], expected, kRoundoff * a)
              << kComponentNames[c] << " at cell " << k << ", z = " << z << (line ? " (1D)" : " (2D)");
        }
      }
    }
  }
}

TEST(LayeredSubsurfaceStressTest, LayerEqualToSubstrateGivesTheHomogeneousStresses) {
  // The same multipliers up to round-off (layered_fourier_stress_test.cpp),
  // through the same transforms: a few eps of the peak pressure.
  constexpr double kRoundoff = 1e-12;
  const double p0 = 1e9;
  const Grid grid = Grid::plane(48, 40, 1e-6, 1e-6, Boundary::periodic);
  const std::vector<double> pressure = hertz_pressure(grid, 10e-6, p0);
  const std::vector<double> depths = {1e-6, 4.9e-6, 5e-6, 5.1e-6, 12e-6};
  const double nu = 0.28;
  const LayeredMaterial same{5e-6, ElasticBody{210e9, nu}, ElasticBody{210e9, nu}};
  const StressVolume coated = compute_stress_volume(grid, pressure, depths, same);
  const StressVolume homogeneous = compute_stress_volume(grid, pressure, depths, nu);
  EXPECT_LT(largest_difference(coated, homogeneous), kRoundoff * p0);
  EXPECT_EQ(coated.in_layer, (std::vector<bool>{true, true, true, false, false}));
  EXPECT_DOUBLE_EQ(coated.max_von_mises.value, homogeneous.max_von_mises.value);
}

TEST(LayeredSubsurfaceStressTest, HertzPressureOnAHardCoatingMatchesTheHankelTransform) {
  // The sampled Hertz pressure on a grid of 16 cells per radius and the
  // periodic images (a period of 8 radii): measured largest difference
  // 1.1e-3 p0 on the axis for depths up to 2 a.
  constexpr double kDiscretisation = 3e-3;
  const double a = 16e-6;
  const double p0 = 2e9;
  const std::size_t n = 128;
  const Grid grid = Grid::plane(n + 1, n + 1, 1e-6, 1e-6, Boundary::periodic);  // odd: the centre is a cell
  const std::vector<double> pressure = hertz_pressure(grid, a, p0);
  const std::vector<double> depths = {2e-6, 4.99e-6, 5.01e-6, 10e-6, 20e-6, 32e-6};
  const StressVolume volume = compute_stress_volume(grid, pressure, depths, kHardCoating);
  const LayeredFourierStress layered(kHardCoating);
  const std::size_t centre = (n / 2) * grid.nx() + n / 2;
  double worst = 0.0;
  for (std::size_t d = 0; d < depths.size(); ++d) {
    const double expected = hankel_axis_sigma_zz(layered, a, p0, depths[d]);
    const double got = volume.components[2][d * grid.size() + centre];
    worst = std::max(worst, std::abs(got - expected) / p0);
    EXPECT_NEAR(got, expected, kDiscretisation * p0) << "sigma_zz on the axis at z = " << depths[d];
  }
  std::printf("Hertz on a hard coating: sigma_zz on the axis within %.3g p0 of the Hankel transform\n", worst);
}

TEST(LayeredSubsurfaceStressTest, BadMaterialIsRefused) {
  LayeredMaterial bad = kHardCoating;
  bad.thickness = -1.0;
  EXPECT_THROW(SubsurfaceStress(Grid::plane(8, 6, 1e-6, 1e-6, Boundary::periodic), bad), InputError);
}

}  // namespace
}  // namespace halfspace::stress
