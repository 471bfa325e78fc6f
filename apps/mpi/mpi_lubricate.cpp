// `mpirun -np N halfspace lubricate ...` (processes.hpp's
// run_film_everywhere): the first process reads and prepares the height
// map whole (the serial command's reader) and hands every process its slab
// of rows; the rigid film is solved on the slabs (mpi::SlabFilmRows, the
// serial solver's iterates), the EHL film on an influence operator of slab
// transforms (lubrication/elastic_film.hpp), and all write their rows of
// the result file at once (the parallel HDF5). A profile, one row, and the
// films whose solvers do not run on rows (mixed, transient) are run by the
// first process as the serial program runs them; a Stribeck sweep's speeds
// are shared out, every process holding the whole map.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "halfspace/mpi/agreement.hpp"
#include "halfspace/mpi/parallel_result_writer.hpp"
#include "halfspace/mpi/row_exchange.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/mpi/slab_film_rows.hpp"
#include "halfspace/mpi/slab_spectral_transforms.hpp"
#include "mpi_program.hpp"

namespace halfspace::app {
namespace {

// The map's shape, spacing, source and preparation (not its heights), from
// the first process (which holds `whole`) to every process.
HeightMap broadcast_map_description(const mpi::MpiCommunicator& world, const std::optional<HeightMap>& whole) {
  std::uint64_t shape[3] = {0, 0, 0};  // dimension, nx, ny
  double spacing[2] = {0.0, 0.0};
  std::string source, steps;
  if (whole) {
    shape[0] = static_cast<std::uint64_t>(whole->dimension);
    shape[1] = whole->nx;
    shape[2] = whole->ny;
    spacing[0] = whole->dx;
    spacing[1] = whole->dy;
    source = whole->source;
    for (const std::string& step : whole->preparation) steps += step + '\n';
  }
  mpi::check(MPI_Bcast(shape, 3, MPI_UINT64_T, 0, world.get()), "MPI_Bcast");
  mpi::check(MPI_Bcast(spacing, 2, MPI_DOUBLE, 0, world.get()), "MPI_Bcast");
  mpi::broadcast(world, source);
  mpi::broadcast(world, steps);
  HeightMap map;
  map.dimension = static_cast<int>(shape[0]);
  map.nx = shape[1];
  map.ny = shape[2];
  map.dx = spacing[0];
  map.dy = spacing[1];
  map.source = std::move(source);
  for (std::size_t begin = 0, end; (end = steps.find('\n', begin)) != std::string::npos; begin = end + 1) {
    map.preparation.push_back(steps.substr(begin, end - begin));
  }
  return map;
}

}  // namespace

int run_film_everywhere(const std::function<HeightMap()>& read,
                        const std::function<int(HeightMap& map, const FilmPlace& place)>& run, FilmSpread spread) {
  const mpi::MpiCommunicator world = mpi_world();
  if (world.size() == 1) {
    HeightMap map = read();
    return run(map, FilmPlace{});
  }
  const bool root = world.rank() == 0;
  std::optional<HeightMap> whole;
  mpi::run_agreed(world, [&] {
    if (root) whole.emplace(read());
  });
  HeightMap map = broadcast_map_description(world, whole);
  if (spread == FilmSpread::sweep_speeds) {
    // Every process solves its run of the speeds on the whole map.
    if (root) {
      map.heights = std::move(whole->heights);
    } else {
      map.heights.resize(static_cast<Eigen::Index>(map.nx * map.ny));
    }
    constexpr Eigen::Index kChunk = Eigen::Index{1} << 28;  // MPI counts are ints
    for (Eigen::Index at = 0; at < map.heights.size(); at += kChunk) {
      const auto count = static_cast<int>(std::min(kChunk, map.heights.size() - at));
      mpi::check(MPI_Bcast(map.heights.data() + at, count, MPI_DOUBLE, 0, world.get()), "MPI_Bcast");
    }
    whole.reset();
    const FilmPlace place{.first = root, .sweep_processes = &world};
    return run_on_slabs(world, [&] { return run(map, place); });
  }
  if (map.dimension == 1 || spread != FilmSpread::row_slabs) {
    return run_on_first_process([&] { return run(*whole, FilmPlace{}); });
  }

  const mpi::SlabLayout slab = mpi::slab_layout(map.nx, map.ny, world);
  map.heights.resize(static_cast<Eigen::Index>(slab.local_size()));
  mpi::scatter_rows(world, map.nx,
                    root ? std::span<const double>(whole->heights.data(), whole->size()) : std::span<const double>(),
                    slab.first_row, {map.heights.data(), slab.local_size()});
  whole.reset();  // the first process too keeps only its rows
  FilmPlace place{.whole = false, .first = root, .first_row = slab.first_row};
  place.film_rows = [&world, slab](const Grid& grid, const lubrication::FlowConditions& conditions) {
    return std::unique_ptr<lubrication::FilmRows>(std::make_unique<mpi::SlabFilmRows>(grid, conditions, slab, world));
  };
  place.transforms = [&world](const Grid& grid, FftPlanning planning) {
    return std::shared_ptr<operators::SpectralTransforms>(
        mpi::make_slab_transforms(grid, world, planning, {.count = 1}));
  };
  place.write_file = [&world](const std::filesystem::path& path, std::uint64_t bound,
                              const std::function<void(const io::Hdf5Node& root)>& fill) {
    mpi::write_file_slabs(world, path, bound, fill);
  };
  return run_on_slabs(world, [&] { return run(map, place); });
}

}  // namespace halfspace::app
