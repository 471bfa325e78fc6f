// The stress field of a contact at a list of depths, with the derived fields
// (von Mises, maximum shear) and the location of the largest von Mises stress:
// what the `stress` command and `solve --stress-depths` write.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/stress/fourier_stress.hpp"
#include "halfspace/stress/subsurface_stress.hpp"
#include "halfspace/stress/surface_traction.hpp"

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

// The fields at one depth: what stresses_by_depth hands over, depth after
// depth, in the same arrays.
struct StressSlice {
  std::size_t index = 0;  // of the depth in the request
  double depth = 0.0;     // m
  bool in_layer = false;  // a coated half-space: the depth is in the layer (z <= t)
  // SubsurfaceStress::local_size() values each (all of the grid serially,
  // this process's rows on a distributed layout), (ny, nx) row-major, Pa.
  std::array<std::vector<double>, kComponentCount> components;
  std::vector<double> von_mises;
  std::vector<double> max_shear;
  std::vector<double> hydrostatic;
};

// Throws InputError naming the problem unless there are 1 to kMaxDepthCount
// depths, each finite and > 0 (m).
void check_depths(std::span<const double> depths);
// The same, and each depth in allowed_depth_range(grid).
void check_depths(const Grid& grid, std::span<const double> depths);

// The stresses of `pressure` (Pa, stresses.local_size() values) below
// `stresses`' grid at each of `depths` in turn: `consume` receives each
// depth's fields before the next depth is computed, so that only one depth is
// ever held (the streaming writer, io/stress_writer.hpp). Returns the largest
// von Mises stress and its position, reduced over the processes of a
// distributed layout (the same on every process; collective there). Throws InputError for bad depths (check_depths on
// the grid) or pressure, and for a field that is not finite (a pressure or
// grid whose stresses overflow) before that depth is handed over.
VonMisesMaximum stresses_by_depth(SubsurfaceStress& stresses, std::span<const double> pressure,
                                  std::span<const double> depths,
                                  const std::function<void(const StressSlice& slice)>& consume);
// The same for the pressure and the shear tractions beside it
// (surface_traction.hpp; SubsurfaceStress::set_tractions); also throws
// InputError for a shear on a coated half-space.
VonMisesMaximum stresses_by_depth(SubsurfaceStress& stresses, const SurfaceTractions& tractions,
                                  std::span<const double> depths,
                                  const std::function<void(const StressSlice& slice)>& consume);

// The stress volume of `pressure` (Pa, grid.size() values) on `grid` at
// `depths`, for a body of Poisson's ratio nu. Throws InputError for bad
// depths, nu or pressure.
StressVolume compute_stress_volume(const Grid& grid, std::span<const double> pressure, std::span<const double> depths,
                                   double nu, FftPlanning planning = FftPlanning::estimate);
// The same under the pressure and shear tractions (surface_traction.hpp).
StressVolume compute_stress_volume(const Grid& grid, const SurfaceTractions& tractions, std::span<const double> depths,
                                   double nu, FftPlanning planning = FftPlanning::estimate);

// The same below a coated half-space (require_coated_stress_grid), each depth with
// the constants of its body. Throws InputError for a grid it refuses, bad depths,
// material or pressure.
StressVolume compute_stress_volume(const Grid& grid, std::span<const double> pressure, std::span<const double> depths,
                                   const LayeredMaterial& coating, FftPlanning planning = FftPlanning::estimate);
// The same under the pressure and shear tractions.
StressVolume compute_stress_volume(const Grid& grid, const SurfaceTractions& tractions, std::span<const double> depths,
                                   const LayeredMaterial& coating, FftPlanning planning = FftPlanning::estimate);

// Peak bytes of stresses_by_depth on `grid`: the transforms' workspace (more
// for a coated body's solved modes) and one depth's nine fields, whatever the
// number of depths; an upper bound for the memory check of the command line.
// compute_stress_volume holds the whole volume besides: nine fields of 8
// bytes per cell and depth. With `shear`, the two shear tractions' spectra
// and (free grids) coefficients as well.
double stress_memory_estimate(const Grid& grid, bool coated = false, bool shear = false);

}  // namespace halfspace::stress
