// Steps 1-3 of make_self_affine_surface (self_affine.cpp) on the transposed
// slab spectrum of SlabRealFft: column kx = first_column + c, row ky = r at
// [c * ny + r].
#include "halfspace/mpi/slab_self_affine.hpp"

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <span>

#include "../surface/self_affine_modes.hpp"
#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/threads.hpp"

namespace halfspace::mpi {

Eigen::ArrayXd make_self_affine_slab(const Grid& grid, const surface::SelfAffineSpec& requested,
                                     const MpiCommunicator& comm) {
  if (grid.dimension() != 2) {
    throw InputError(fmt::format("make_self_affine_slab: needs a 2D grid, not {}", grid.shape_string()));
  }
  const surface::SelfAffineSpec spec = requested.resolved(grid);
  const surface::detail::ModeGeometry modes(grid, spec);
  // One thread, as the serial synthesis plans.
  const int previous = threads();
  set_threads(1);
  SlabRealFft fft(grid.nx(), grid.ny(), comm, FftPlanning::estimate);
  set_threads(previous);
  const SlabLayout& layout = fft.layout();
  const std::size_t ny = layout.ny;
  const std::size_t modes_here = layout.columns * ny;

  // Step 1: this process's columns of the filtered spectrum.
  const std::span<std::complex<double>> spectrum = fft.spectrum();
  linalg::for_each_row(layout.columns, ny, [&](std::size_t c) {
    for (std::size_t r = 0; r < ny; ++r) {
      spectrum[c * ny + r] = surface::detail::filtered_mode(modes, spec.seed, layout.first_column + c, r);
    }
  });
  // Step 2: the mean square slope, summed over the processes.
  const double slope_sq = linalg::sum(comm, modes_here, [&](std::size_t k) {
    return surface::detail::slope_weight(modes, layout.first_column + k / ny, k % ny) * std::norm(spectrum[k]);
  });
  const double cells = static_cast<double>(grid.size());

  // Step 3: to real space (this process's rows); the mean and the rms height
  // over the whole grid.
  Eigen::ArrayXd heights(static_cast<Eigen::Index>(layout.local_size()));
  fft.backward({heights.data(), layout.local_size()});
  surface::detail::remove_mean_and_scale(heights, spec, slope_sq, cells, comm);
  return heights;
}

}  // namespace halfspace::mpi
