// The rough surface of the solver tests: a self-affine height map (H = 0.8,
// wavelengths down to 4 cells, rms slope 0.1) turned into an initial gap.
#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "halfspace/grid.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/surface/self_affine.hpp"

namespace halfspace::testing {

inline Eigen::ArrayXd self_affine_gap(const Grid& grid, std::uint64_t seed) {
  surface::SelfAffineSpec spec;
  spec.hurst = 0.8;
  spec.short_cutoff = 4.0 * grid.dx();
  spec.rms_slope = 0.1;
  spec.seed = seed;
  const Eigen::ArrayXd heights = surface::make_self_affine_surface(grid, spec);
  return solvers::initial_gap(grid, {heights.data(), grid.size()});
}

}  // namespace halfspace::testing
