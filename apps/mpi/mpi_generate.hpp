// `mpirun -np N halfspace generate ...`: every process makes its rows of the
// surface (a self-affine one from its spectrum columns,
// mpi::make_self_affine_slab; a built-in shape from its rows' coordinates,
// geometry::make_surface_rows) and writes them into one height-map file at
// once (the parallel HDF5), so no process holds the whole map.
// HALFSPACE_MPI builds only.
#pragma once

#include <filesystem>
#include <functional>

#include "../processes.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/io/height_map_writer.hpp"
#include "halfspace/surface/statistics.hpp"

namespace halfspace::app {

// processes.hpp's agree_everywhere.
void run_agreed_everywhere(const std::function<void()>& step);

// processes.hpp's generate_distributed.
surface::SurfaceStatistics generate_on_slabs(const Grid& grid, const SurfaceSource& source,
                                             io::HeightMapMetadata& metadata, const std::filesystem::path& output);

}  // namespace halfspace::app
