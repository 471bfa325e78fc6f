// Stresses below a coated half-space under shear tractions
// (SubsurfaceStress with a LayeredMaterial and SurfaceTractions): one Fourier
// mode of each traction against the per-mode solutions
// (layered_fourier_shear_stress_test.cpp checks those), a layer equal to its
// substrate against the homogeneous Cerruti field; and on free grids (the
// remainder per shear) the same limit and a periodic grid four times wider.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/stress/layered_fourier_shear_stress.hpp"
#include "halfspace/stress/layered_fourier_stress.hpp"
#include "halfspace/stress/stress_volume.hpp"
#include "halfspace/stress/subsurface_stress.hpp"
#include "stress/coated_hertz_reference.hpp"

namespace halfspace::stress {
namespace {

using testing::hertz_pressure;
using testing::kHardCoating;
using testing::largest_difference;

// A mean plus one mode: mean + a cos(phase) + b sin(phase).
struct ModeField {
  double mean, a, b;
};

TEST(LayeredSubsurfaceShearStressTest, PeriodicFourierModesMatchThePerModeSolution) {
  // Exact algebra through the FFTs: a few eps of the largest amplitude.
  constexpr double kRoundoff = 1e-12;
  const LayeredMaterial& material = kHardCoating;
  const LayeredFourierStress layered(material);
  const LayeredAntiplane antiplane(material);
  const ModeField pressure_mode{1e6, 0.7e6, -0.4e6};
  const ModeField shear_x_mode{0.2e6, -0.3e6, 0.25e6};
  const ModeField shear_y_mode{-0.1e6, 0.15e6, 0.35e6};
  for (const bool line : {false, true}) {
    const Grid grid =
        line ? Grid::line(40, 0.5e-6, Boundary::periodic) : Grid::plane(32, 24, 1e-6, 1.5e-6, Boundary::periodic);
    const double kx = 2.0 * std::numbers::pi * 3.0 / (static_cast<double>(grid.nx()) * grid.dx());
    const double ky = line ? 0.0 : 2.0 * std::numbers::pi * -2.0 / (static_cast<double>(grid.ny()) * grid.dy());
    const double q = std::hypot(kx, ky);
    const auto phase_of = [&](std::size_t k) {
      return kx * static_cast<double>(k % grid.nx()) * grid.dx() +
             (line ? 0.0 : ky * static_cast<double>(k / grid.nx()) * grid.dy());
    };
    const auto sampled = [&](const ModeField& m) {
      std::vector<double> field(grid.size());
      for (std::size_t k = 0; k < grid.size(); ++k) {
        field[k] = m.mean + m.a * std::cos(phase_of(k)) + m.b * std::sin(phase_of(k));
      }
      return field;
    };
    const std::vector<double> pressure = sampled(pressure_mode);
    const std::vector<double> shear_x = sampled(shear_x_mode);
    const std::vector<double> shear_y = sampled(shear_y_mode);
    SubsurfaceStress stress(grid, material);
    stress.set_tractions({pressure, shear_x, shear_y});
    const LayeredMode normal = layered.solve(q);
    const LayeredMode sheared = layered.solve_shear(q);
    const LayeredMode uniform = layered.solve(0.0);
    // Each traction is constant on a cell: the mode's amplitude times the
    // cell's transform.
    const double cell = std::sin(0.5 * kx * grid.dx()) / (0.5 * kx * grid.dx()) *
                        (line ? 1.0 : std::sin(0.5 * ky * grid.dy()) / (0.5 * ky * grid.dy()));
    for (const double z : {0.3e-6, 4.0e-6, 5e-6, 9.0e-6}) {
      std::array<std::vector<double>, kComponentCount> values;
      std::array<std::span<double>, kComponentCount> fields;
      for (std::size_t c = 0; c < kComponentCount; ++c) {
        values[c].resize(grid.size());
        fields[c] = values[c];
      }
      stress.compute(z, fields);
      const Body body = layered.body_at(z);
      const double nu = body == Body::layer ? material.layer.poissons_ratio : material.substrate.poissons_ratio;
      const auto normal_wave = layered.stress(kx, ky, layered.profile(normal, z, body), body);
      const auto normal_mean = layered.stress(0.0, 0.0, layered.profile(uniform, z, body), body);
      const AiryProfile longitudinal = layered.profile(sheared, z, body);
      const AntiplaneProfile transverse = antiplane.profile(q, z, body);
      const auto x_wave = layered_shear_stress(Traction::shear_x, kx, ky, longitudinal, transverse, nu);
      const auto y_wave = layered_shear_stress(Traction::shear_y, kx, ky, longitudinal, transverse, nu);
      double worst = 0.0;
      for (std::size_t k = 0; k < grid.size(); ++k) {
        const std::complex<double> phase = std::polar(1.0, phase_of(k));
        for (std::size_t c = 0; c < kComponentCount; ++c) {
          const auto kind = static_cast<Component>(c);
          // A uniform shear: sigma_xz = -mean q_x, sigma_yz = -mean q_y.
          const double mean = pressure_mode.mean * normal_mean[c].real() -
                              (kind == Component::xz ? shear_x_mode.mean : 0.0) -
                              (kind == Component::yz ? shear_y_mode.mean : 0.0);
          const std::complex<double> wave = normal_wave[c] * std::complex<double>(pressure_mode.a, -pressure_mode.b) +
                                            x_wave[c] * std::complex<double>(shear_x_mode.a, -shear_x_mode.b) +
                                            y_wave[c] * std::complex<double>(shear_y_mode.a, -shear_y_mode.b);
          const double expected = mean + cell * (wave * phase).real();
          worst = std::max(worst, std::abs(values[c][k] - expected));
          ASSERT_NEAR(values[c][k], expected, kRoundoff * pressure_mode.a)
              << kComponentNames[c] << " at cell " << k << ", z = " << z << (line ? " (1D)" : " (2D)");
        }
      }
      std::printf("coated shear mode on the %s grid at z = %.2g m: largest difference %.2e Pa\n", line ? "1D" : "2D", z,
                  worst);
    }
  }
}

// A partial-slip-like shear beside a Hertz pressure of radius a: mu p along
// x less a concentric part, and a smaller one along y.
SurfaceTractions partial_slip(const Grid& grid, double a, double p0, std::vector<double>& pressure,
                              std::vector<double>& shear_x, std::vector<double>& shear_y) {
  pressure = hertz_pressure(grid, a, p0);
  const std::vector<double> inner = hertz_pressure(grid, 0.5 * a, 0.5 * p0);
  shear_x.resize(grid.size());
  shear_y.resize(grid.size());
  for (std::size_t k = 0; k < grid.size(); ++k) {
    shear_x[k] = 0.3 * (pressure[k] - inner[k]);
    shear_y[k] = -0.1 * pressure[k];
  }
  return {pressure, shear_x, shear_y};
}

// Periodic grids: the same multipliers up to round-off
// (layered_fourier_shear_stress_test) through the same transforms. Free
// grids: Cerruti's rectangle plus each shear's layered remainder, here the
// difference of equal multipliers. Either way a few eps of the peak pressure.
TEST(LayeredSubsurfaceShearStressTest, LayerEqualToSubstrateGivesCerrutisStresses) {
  constexpr double kRoundoff = 1e-12;
  const double p0 = 1e9;
  for (const Boundary boundary : {Boundary::periodic, Boundary::free}) {
    for (const bool line : {false, true}) {
      const Grid grid = line ? Grid::line(96, 0.5e-6, boundary) : Grid::plane(48, 48, 1e-6, 1e-6, boundary);
      std::vector<double> pressure, shear_x, shear_y;
      const SurfaceTractions tractions = partial_slip(grid, 10e-6, p0, pressure, shear_x, shear_y);
      const std::vector<double> depths = {1e-6, 4.9e-6, 5e-6, 5.1e-6, 12e-6};
      const double nu = 0.28;
      const LayeredMaterial same{5e-6, ElasticBody{210e9, nu}, ElasticBody{210e9, nu}};
      const StressVolume coated = compute_stress_volume(grid, tractions, depths, same);
      const StressVolume homogeneous = compute_stress_volume(grid, tractions, depths, nu);
      const double difference = largest_difference(coated, homogeneous);
      std::printf("coated (layer = substrate) vs homogeneous under shear, %s %s: %.2e of p0\n",
                  std::string(to_string(boundary)).c_str(), line ? "1D" : "2D", difference / p0);
      EXPECT_LT(difference, kRoundoff * p0);
      EXPECT_EQ(coated.in_layer, (std::vector<bool>{true, true, true, false, false}));
    }
  }
}

TEST(LayeredSubsurfaceShearStressTest, ShearChangesTheCoatedFieldAndBothBodiesDiffer) {
  // A stiff coating's shear field is not the substrate's nor the layer's
  // homogeneous one (a guard against the shear being dropped or taken with
  // the wrong body): near the surface it approaches the layer's, deep below
  // the interface it differs from both by more than round-off.
  const double p0 = 1e9;
  const Grid grid = Grid::plane(48, 40, 1e-6, 1e-6, Boundary::periodic);
  const std::vector<double> pressure = hertz_pressure(grid, 10e-6, p0);
  std::vector<double> shear_x(grid.size());
  for (std::size_t k = 0; k < grid.size(); ++k) shear_x[k] = 0.4 * pressure[k];
  const std::vector<double> depths = {2e-6, 12e-6};
  const SurfaceTractions with_shear{pressure, shear_x, {}};
  const SurfaceTractions without_shear{pressure, {}, {}};
  const StressVolume coated = compute_stress_volume(grid, with_shear, depths, kHardCoating);
  const StressVolume pressure_only = compute_stress_volume(grid, without_shear, depths, kHardCoating);
  const StressVolume layer = compute_stress_volume(grid, with_shear, depths, kHardCoating.layer.poissons_ratio);
  const StressVolume substrate = compute_stress_volume(grid, with_shear, depths, kHardCoating.substrate.poissons_ratio);
  EXPECT_GT(largest_difference(coated, pressure_only), 0.05 * p0);
  EXPECT_GT(largest_difference(coated, layer), 1e-3 * p0);
  EXPECT_GT(largest_difference(coated, substrate), 1e-3 * p0);
}

// The coating's effect under shear (coated minus homogeneous stresses, the
// same Poisson's ratio in both bodies so that the periodic mean modes
// cancel) on a free 64^2 grid and, embedded in its middle, on a periodic
// grid of four times the period: all six components over the free domain,
// at depths in the layer, at the interface and below. The pressure's
// version of this test (free_layered_stress_test.cpp) meets 4.4e-3 p0 with
// its tolerance 8e-3 p0: the periodic grid's images and the free
// remainder's folded tail, both falling like 1/r^2.
TEST(LayeredSubsurfaceShearStressTest, FreeMatchesPeriodicFarFromTheBoundaries) {
  constexpr double kTolerance = 8e-3;
  const double p0 = 1e9;
  const LayeredMaterial coating{3e-6, ElasticBody{600e9, 0.3}, ElasticBody{200e9, 0.3}};
  const Grid free = Grid::plane(64, 64, 1e-6, 1e-6, Boundary::free);
  const Grid periodic = Grid::plane(256, 256, 1e-6, 1e-6, Boundary::periodic);
  std::vector<double> pressure, shear_x, shear_y;
  const SurfaceTractions tractions = partial_slip(free, 8e-6, p0, pressure, shear_x, shear_y);
  std::vector<double> embedded_p(periodic.size(), 0.0);
  std::vector<double> embedded_x(periodic.size(), 0.0);
  std::vector<double> embedded_y(periodic.size(), 0.0);
  for (std::size_t j = 0; j < 64; ++j) {
    for (std::size_t i = 0; i < 64; ++i) {
      embedded_p[(j + 96) * 256 + i + 96] = pressure[j * 64 + i];
      embedded_x[(j + 96) * 256 + i + 96] = shear_x[j * 64 + i];
      embedded_y[(j + 96) * 256 + i + 96] = shear_y[j * 64 + i];
    }
  }
  const SurfaceTractions embedded{embedded_p, embedded_x, embedded_y};
  const std::vector<double> depths = {1e-6, 2.9e-6, 3.1e-6, 6e-6, 12e-6};
  const StressVolume free_coated = compute_stress_volume(free, tractions, depths, coating);
  const StressVolume free_plain = compute_stress_volume(free, tractions, depths, 0.3);
  const StressVolume periodic_coated = compute_stress_volume(periodic, embedded, depths, coating);
  const StressVolume periodic_plain = compute_stress_volume(periodic, embedded, depths, 0.3);
  // The shear's own share of the effect, to show that it is compared.
  const StressVolume free_pressure_only =
      compute_stress_volume(free, SurfaceTractions{pressure, {}, {}}, depths, coating);
  const StressVolume free_plain_pressure = compute_stress_volume(free, SurfaceTractions{pressure, {}, {}}, depths, 0.3);
  double worst = 0.0;
  double effect = 0.0;
  double shear_effect = 0.0;
  for (std::size_t c = 0; c < kComponentCount; ++c) {
    for (std::size_t d = 0; d < depths.size(); ++d) {
      for (std::size_t j = 0; j < 64; ++j) {
        for (std::size_t i = 0; i < 64; ++i) {
          const std::size_t f = d * free.size() + j * 64 + i;
          const std::size_t p = d * periodic.size() + (j + 96) * 256 + i + 96;
          const double free_effect = free_coated.components[c][f] - free_plain.components[c][f];
          const double periodic_effect = periodic_coated.components[c][p] - periodic_plain.components[c][p];
          const double pressure_effect = free_pressure_only.components[c][f] - free_plain_pressure.components[c][f];
          effect = std::max(effect, std::abs(periodic_effect));
          shear_effect = std::max(shear_effect, std::abs(free_effect - pressure_effect));
          worst = std::max(worst, std::abs(free_effect - periodic_effect));
        }
      }
    }
  }
  std::printf(
      "free against periodic under shear: the coating's effect (up to %.3g p0, the shear's share %.3g p0) agrees "
      "within %.3g p0\n",
      effect / p0, shear_effect / p0, worst / p0);
  EXPECT_GT(shear_effect, 0.02 * p0);  // the shear's remainder is compared, not only the pressure's
  EXPECT_LT(worst, kTolerance * p0);
}

}  // namespace
}  // namespace halfspace::stress
