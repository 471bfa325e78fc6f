// The stress field of a contact at a list of depths, with the derived fields
// (von Mises, maximum shear) and the location of the largest von Mises stress:
// what the `stress` command and `solve --stress-depths` write.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/stress/fourier_stress.hpp"

namespace halfspace::stress {

// The most depths one request may ask for.
inline constexpr std::size_t kMaxDepthCount = 4096;

struct VonMisesMaximum {
  double value = 0.0;  // Pa
  double x = 0.0;      // m: i dx of its cell, like the grid's coordinates
  double y = 0.0;      // m: j dy (0 on a 1D grid)
  double z = 0.0;      // m: its depth
};

struct StressVolume {
  std::vector<double> depths;  // m, as requested
  // Each depths.size() * cells values, (nz, ny, nx) row-major (1D: (nz, n)), Pa.
  std::array<std::vector<double>, kComponentCount> components;
  std::vector<double> von_mises;
  std::vector<double> max_shear;    // half the largest principal difference
  std::vector<double> hydrostatic;  // (xx + yy + zz) / 3
  // A coated half-space: the body of each depth (true: in the layer, z <= t).
  std::optional<LayeredMaterial> coating;
  std::vector<bool> in_layer;
  VonMisesMaximum max_von_mises;  // the first cell reaching it, in depth then row order
};

// Throws InputError naming the problem unless there are 1 to kMaxDepthCount
// depths, each finite and > 0 (m).
void check_depths(std::span<const double> depths);

// The stress volume of `pressure` (Pa, grid.size() values) on `grid` at
// `depths`, for a body of Poisson's ratio nu. Throws InputError for bad
// depths, nu or pressure.
StressVolume compute_stress_volume(const Grid& grid, std::span<const double> pressure, std::span<const double> depths,
                                   double nu, FftPlanning planning = FftPlanning::estimate);

// The same below a coated half-space (periodic grids only), each depth with
// the constants of its body. Throws InputError for a free grid, bad depths,
// material or pressure.
StressVolume compute_stress_volume(const Grid& grid, std::span<const double> pressure, std::span<const double> depths,
                                   const LayeredMaterial& coating, FftPlanning planning = FftPlanning::estimate);

// Peak bytes of compute_stress_volume on `grid` at `depth_count` depths,
// including the in-memory image of the file that stores it (the 9 stored
// fields, 8 bytes each per cell and depth, three times) and the transforms'
// workspace (more for a coated body's solved modes): an upper bound for the
// memory check of the command line.
double stress_memory_estimate(const Grid& grid, std::size_t depth_count, bool coated = false);

}  // namespace halfspace::stress
