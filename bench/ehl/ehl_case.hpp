// The EHL benchmarks' smooth contact (ehl_validation.cpp, ehl_scaling.cpp):
// a ball or a cylinder of radius kRadius on a flat of composite modulus
// kEStar in a lubricant of viscosity kViscosity, set by the Hamrock-Dowson
// dimensionless speed U and materials parameter G.
#pragma once

#include <Eigen/Core>
#include <cstddef>

#include "halfspace/grid.hpp"
#include "halfspace/lubrication/elastic_film.hpp"

namespace halfspace::bench {

inline constexpr double kEStar = 1.1e11;    // Pa
inline constexpr double kRadius = 0.01;     // m
inline constexpr double kViscosity = 0.04;  // Pa s

// Roelands' piezoviscosity with alpha = G / E' (E' = 2 E*) and
// Dowson-Higginson's density.
inline lubrication::LubricantLaws roelands_laws(double g) {
  return {.piezoviscosity = lubrication::Piezoviscosity::roelands,
          .pressure_viscosity = g / (2.0 * kEStar),
          .compressibility = lubrication::Compressibility::dowson_higginson};
}

// Pure rolling along x at the speed of U = eta0 u / (E' R).
inline lubrication::FlowConditions rolling(double u) {
  lubrication::FlowConditions conditions;
  conditions.viscosity = kViscosity;
  conditions.entrainment_velocity = {u * 2.0 * kEStar * kRadius / kViscosity, 0.0};
  return conditions;
}

// The parabolic gap (x^2 + y^2) / (2 R) on `grid` (x^2 / (2 R) on a line),
// its vertex at node (upstream, centre_row).
inline Eigen::ArrayXd parabolic_gap(const Grid& grid, std::size_t upstream, std::size_t centre_row) {
  const std::size_t nx = grid.nx();
  const std::size_t ny = grid.dimension() == 1 ? 1 : grid.ny();
  Eigen::ArrayXd gap(static_cast<Eigen::Index>(nx * ny));
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const double x = (static_cast<double>(i) - static_cast<double>(upstream)) * grid.dx();
      const double y =
          grid.dimension() == 1 ? 0.0 : (static_cast<double>(j) - static_cast<double>(centre_row)) * grid.dy();
      gap[static_cast<Eigen::Index>(j * nx + i)] = (x * x + y * y) / (2.0 * kRadius);
    }
  }
  return gap;
}

}  // namespace halfspace::bench
