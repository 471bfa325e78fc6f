// The stress tensor below a solved contact: from the surface pressure on a
// Grid, the six components at any depth, matrix-free. Periodic grids use the
// closed-form Fourier-space solution (fourier_stress.hpp); free grids convolve
// the pressure with the exact stress coefficients of a loaded cell
// (rectangle_stress.hpp) by zero padding (DC-FFT, Liu, Wang & Liu 2000).
// Shear tractions beside the pressure add Cerruti's solution in the same two
// forms (fourier_shear_stress.hpp, rectangle_shear_stress.hpp); below a
// coating, the layered field of layered_fourier_shear_stress.hpp (periodic).
// Cost and memory per depth: docs/theory.md#subsurface-stresses.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <span>

#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/linalg/communicator.hpp"
#include "halfspace/solvers/layout.hpp"
#include "halfspace/stress/fourier_stress.hpp"
#include "halfspace/stress/surface_traction.hpp"

namespace halfspace::stress {

// Throws InputError unless -1 < nu <= 0.5 (and finite); returns nu.
double checked_poisson_ratio(double nu);

// Coated half-spaces on free grids: the layer's thickness may be at most this
// fraction of the domain's shorter side (the remainder's spectrum folds in
// its periodic images beyond it, docs/theory.md).
inline constexpr double kFreeCoatedStressThicknessRatio = 0.125;

// Throws InputError naming the grid unless the stresses below `coating` can
// be computed on `grid`: periodic grids, and free grids with t <= L/8 (L the
// domain's shorter side, or its length in 1D).
void require_coated_stress_grid(const Grid& grid, const LayeredMaterial& coating);

// Throws InputError unless depth is finite and > 0 (m); returns it.
double checked_depth(double depth);

// The depths (m) at which stresses are computed on a grid: from a millionth
// of the finer cell spacing (shallower, the field is the surface's own
// cell-constant pressure to that resolution) to ten times the domain's longer
// side (deeper, a periodic field is uniform, the non-mean modes having decayed
// by exp(-20 pi), and a free one is a point load's, its cell coefficients lost
// to cancellation as (z/dx)^2 machine epsilon).
struct DepthRange {
  double shallowest = 0.0;
  double deepest = 0.0;
};
inline constexpr double kShallowestDepthPerCell = 1e-6;
inline constexpr double kDeepestDepthPerDomain = 10.0;
DepthRange allowed_depth_range(const Grid& grid);

// Throws InputError naming the depth, the grid and the allowed range unless
// depth lies in allowed_depth_range(grid); returns it.
double checked_depth(const Grid& grid, double depth);

class SubsurfaceStress {
 public:
  // Plans the transforms of `grid` (made once, reused for every depth) for a
  // body of Poisson's ratio nu. Throws InputError for a bad nu.
  SubsurfaceStress(const Grid& grid, double nu, FftPlanning planning = FftPlanning::estimate);
  // A coated half-space (layered_fourier_stress.hpp): depths z <= t are in
  // the layer. Periodic grids solve each mode's layer and substrate
  // coefficients once, for every depth (about 32 bytes per cell); free grids
  // add the remainder of the layered solution over Love's rectangle (the
  // strip in 1D), solved per depth, up to 25 (1D: 5) alias images per bin of
  // the padded grid.
  // Throws InputError for a grid require_coated_stress_grid refuses, or for
  // a bad material.
  SubsurfaceStress(const Grid& grid, const LayeredMaterial& coating, FftPlanning planning = FftPlanning::estimate);
  // The same on `layout`'s transforms (solvers/layout.hpp; the two above are
  // serial_layout()'s): on a distributed layout (mpi::DistributedLayout, 2D
  // grids) every field holds this process's rows() of the grid, the
  // spectra and coefficients its share, and compute() and the checks are
  // collective. `layout` need not outlive the object (its communicator
  // must).
  SubsurfaceStress(const Grid& grid, double nu, const solvers::Layout& layout,
                   FftPlanning planning = FftPlanning::estimate);
  SubsurfaceStress(const Grid& grid, const LayeredMaterial& coating, const solvers::Layout& layout,
                   FftPlanning planning = FftPlanning::estimate);
  ~SubsurfaceStress();
  SubsurfaceStress(const SubsurfaceStress&) = delete;
  SubsurfaceStress& operator=(const SubsurfaceStress&) = delete;

  const Grid& grid() const;
  // The rows of the grid held here (all of them serially; a 1D grid's one
  // row), the cells they hold (the size of every field given or filled),
  // and the processes the fields are spread over.
  solvers::RowSlab rows() const;
  std::size_t local_size() const;
  const linalg::Communicator& communicator() const;
  // The Poisson's ratio of a homogeneous body, or of the body at `depth`.
  double poisson_ratio() const;
  double poisson_ratio(double depth) const;
  // Whether the stresses are those of a coated half-space, and the body of a depth.
  bool coated() const;
  bool in_layer(double depth) const;
  // The coated half-space's layer and substrate; nullopt for a homogeneous body.
  std::optional<LayeredMaterial> coating() const;

  // Takes the surface pressure (Pa, local_size() values, (ny, nx) row-major,
  // positive in compression): one forward FFT, kept for every depth. Throws
  // InputError if the size differs from the grid's or a value is not finite.
  void set_pressure(std::span<const double> pressure);

  // Takes the pressure and the shear tractions beside it (surface_traction.hpp:
  // Pa, the traction on this body, sigma_xz = -q_x and sigma_yz = -q_y at
  // the surface; an empty span is no shear): one forward FFT each, kept for
  // every depth; a later set_pressure drops them. A coated half-space takes
  // the layered shear field (layered_fourier_shear_stress.hpp; its modes
  // solved when a shear is first set, about 60 bytes per cell). Throws
  // InputError as set_pressure does for each field.
  void set_tractions(const SurfaceTractions& tractions);
  // Whether `tractions` hold a shear on any process (SurfaceTractions::
  // has_shear, reduced: a process without rows holds empty spans either
  // way). Collective.
  bool has_shear(const SurfaceTractions& tractions) const;
  // The checks of set_tractions alone (no transform): what a writer calls
  // before it creates a file.
  void check_tractions(const SurfaceTractions& tractions) const;

  // The stress (Pa, compression negative) at depth z (m, > 0) below every
  // cell centre: fields[c] (local_size() values each) receives component c in
  // Component order. One inverse FFT per component (free grids: also one
  // forward FFT of the padded coefficients per component). Throws InputError
  // for a depth outside allowed_depth_range(grid()), a field of the wrong
  // size, or no pressure set.
  void compute(double depth, const std::array<std::span<double>, kComponentCount>& fields);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace halfspace::stress
