// `mpirun -np N halfspace generate ...` (processes.hpp's
// generate_distributed): every process makes its rows of the surface (a
// self-affine one from its spectrum columns, mpi::make_self_affine_slab; a
// built-in shape from its rows' coordinates, geometry::make_surface_rows)
// and writes them into one height-map file at once (the parallel HDF5), so
// no process holds the whole map.
#include <Eigen/Core>
#include <span>
#include <variant>

#include "halfspace/mpi/agreement.hpp"
#include "halfspace/mpi/parallel_result_writer.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/mpi/slab_self_affine.hpp"
#include "halfspace/mpi/slab_surface_statistics.hpp"
#include "mpi_program.hpp"

namespace halfspace::app {

surface::SurfaceStatistics generate_distributed(const Grid& grid, const SurfaceSource& source,
                                                io::HeightMapMetadata& metadata, const std::filesystem::path& output) {
  const mpi::MpiCommunicator world = mpi_world();
  const mpi::SlabLayout layout = mpi::slab_layout(grid.nx(), grid.ny(), world);
  // The spec was checked by every process alike: the synthesis fails on all
  // or none.
  Eigen::ArrayXd heights;
  mpi::run_agreed(world, [&] {
    if (const auto* self_affine = std::get_if<surface::SelfAffineSpec>(&source)) {
      heights = mpi::make_self_affine_slab(grid, *self_affine, world);
    } else {
      heights =
          geometry::make_surface_rows(grid, std::get<geometry::SurfaceSpec>(source), layout.first_row, layout.rows);
    }
  });
  const std::span<const double> rows(heights.data(), layout.local_size());
  const surface::SurfaceStatistics statistics = mpi::slab_surface_statistics(grid, layout, rows, world);
  metadata.numbers.emplace_back("rms_height", statistics.rms_height);
  metadata.numbers.emplace_back("rms_slope", statistics.rms_slope);
  mpi::write_height_map_slabs(world, output, grid, layout, rows, metadata);
  return statistics;
}

}  // namespace halfspace::app
