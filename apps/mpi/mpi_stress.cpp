// `mpirun -np N halfspace stress RESULT ...` (processes.hpp's
// run_stress_everywhere): the first process reads the result whole (the
// stress command's reader) and scatters the rows of its fields; the grid,
// the coating and whether there is shear go to every process, so that every
// process checks the options against the same result and fails alike; every
// process computes the stresses of its rows of a 2D result
// (mpi::DistributedLayout) and all write their rows of the stress file at
// once (the parallel HDF5), as the solve command's --stress-depths does.
#include <algorithm>
#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "halfspace/io/xdmf_writer.hpp"
#include "halfspace/mpi/agreement.hpp"
#include "halfspace/mpi/distributed_layout.hpp"
#include "halfspace/mpi/parallel_result_writer.hpp"
#include "halfspace/mpi/row_exchange.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "mpi_program.hpp"

namespace halfspace::app {
namespace {

// The coating, both bodies and whether the result has shear, from the first
// process to every process.
void broadcast_details(const mpi::MpiCommunicator& world, std::optional<io::ResultPressure>& whole,
                       std::optional<LayeredMaterial>& coating, std::optional<std::array<ElasticBody, 2>>& bodies,
                       bool& shear) {
  // has coating, t, E1, nu1, E2, nu2, has shear, has bodies, E1, nu1, E2, nu2
  std::array<double, 12> details{};
  if (whole) {
    if (whole->bodies) {
      const std::array<ElasticBody, 2>& b = *whole->bodies;
      details[7] = 1.0;
      details[8] = b[0].youngs_modulus;
      details[9] = b[0].poissons_ratio;
      details[10] = b[1].youngs_modulus;
      details[11] = b[1].poissons_ratio;
    }
    if (whole->coating) {
      const LayeredMaterial& c = *whole->coating;
      const std::array<double, 6> constants{1.0,
                                            c.thickness,
                                            c.layer.youngs_modulus,
                                            c.layer.poissons_ratio,
                                            c.substrate.youngs_modulus,
                                            c.substrate.poissons_ratio};
      std::copy(constants.begin(), constants.end(), details.begin());
    }
    details[6] = whole->has_shear() ? 1.0 : 0.0;
  }
  mpi::check(MPI_Bcast(details.data(), static_cast<int>(details.size()), MPI_DOUBLE, 0, world.get()), "MPI_Bcast");
  if (details[0] == 1.0) {
    coating = LayeredMaterial{details[1], {details[2], details[3]}, {details[4], details[5]}};
  }
  shear = details[6] == 1.0;
  if (details[7] == 1.0) {
    bodies = std::array<ElasticBody, 2>{ElasticBody{details[8], details[9]}, ElasticBody{details[10], details[11]}};
  }
}

// This process's rows of the first process's `whole` field.
std::vector<double> rows_of(const mpi::MpiCommunicator& world, const mpi::SlabLayout& slab,
                            const std::vector<double>* whole) {
  std::vector<double> local(slab.local_size());
  mpi::scatter_rows(world, slab.nx, whole ? std::span<const double>(*whole) : std::span<const double>(), slab.first_row,
                    local);
  return local;
}

}  // namespace

int run_stress_everywhere(const std::filesystem::path& path, const std::function<int(StressPlace& place)>& run) {
  const mpi::MpiCommunicator world = mpi_world();
  const bool root = world.rank() == 0;
  std::optional<io::ResultPressure> whole;
  mpi::run_agreed(world, [&] {
    if (root) whole.emplace(read_stress_input(path));
  });
  if (world.size() == 1) {
    StressPlace place = whole_stress_place(std::move(*whole));
    return run(place);
  }
  const Grid grid = broadcast_grid(world, whole ? std::optional<Grid>(whole->grid) : std::nullopt);
  if (grid.dimension() == 1) {
    // The first process, which holds the result, runs the command as one
    // process does.
    return run_on_first_process([&] {
      StressPlace place = whole_stress_place(std::move(*whole));
      return run(place);
    });
  }
  std::optional<LayeredMaterial> coating;
  std::optional<std::array<ElasticBody, 2>> bodies;
  bool shear = false;
  broadcast_details(world, whole, coating, bodies, shear);
  const mpi::SlabLayout slab = mpi::slab_layout(grid.nx(), grid.ny(), world);
  io::ResultPressure local{grid, rows_of(world, slab, whole ? &whole->pressure : nullptr), coating, bodies, {}, {}};
  if (shear) {
    local.shear_x = rows_of(world, slab, whole ? &whole->shear_x : nullptr);
    local.shear_y = rows_of(world, slab, whole ? &whole->shear_y : nullptr);
  }
  whole.reset();  // the first process too keeps only its rows

  const mpi::DistributedLayout layout(world);
  StressPlace place{.layout = layout, .input = std::move(local), .first = root};
  place.write_file = [&world, &grid](const std::filesystem::path& output, stress::SubsurfaceStress& stresses,
                                     const stress::SurfaceTractions& tractions, std::span<const double> depths,
                                     const io::StressFileMetadata& metadata) {
    stresses.check_tractions(tractions);  // refused before the file is made
    stress::VonMisesMaximum maximum;
    mpi::write_file_slabs(world, output, io::stress_file_bound(grid, stresses.has_shear(tractions), depths.size()),
                          [&](const io::Hdf5Node& root_node) {
                            maximum = io::write_stress_file_contents(root_node, stresses, tractions, depths, metadata);
                          });
    // The sidecar of the complete file (for ParaView), by the first process.
    mpi::run_agreed(world, [&] {
      if (world.rank() == 0) io::write_xdmf_sidecar(output, grid);
    });
    return maximum;
  };
  place.agree = [&world](const std::function<void()>& step) { mpi::run_agreed(world, step); };
  return run(place);
}

}  // namespace halfspace::app
