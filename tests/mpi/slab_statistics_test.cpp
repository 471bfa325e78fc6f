// The statistics of slabs against the serial ones on the whole field (run
// by ctest under mpiexec -np 1, 2, 3 and 5 in the MPI build): every process
// makes the same random fields whole, keeps its rows, and the slab
// statistics must equal analysis::contact_statistics (cluster sizes exactly,
// sums within kTolerance) and surface::surface_statistics, on periodic and
// free grids, with more processes than rows too. Exits non-zero on a
// mismatch, printing it.
#include <fmt/format.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <random>
#include <span>
#include <vector>

#include "halfspace/analysis/contact_statistics.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/session.hpp"
#include "halfspace/mpi/slab_contact_statistics.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/mpi/slab_surface_statistics.hpp"
#include "halfspace/surface/statistics.hpp"

namespace {

using namespace halfspace;

// Sums are added per process and then in rank order: equal to rounding.
constexpr double kTolerance = 1e-12;

int failures = 0;

void expect_close(const std::string& where, const char* what, double got, double want, int rank) {
  if (std::abs(got - want) > kTolerance * std::max(std::abs(want), 1e-300)) {
    if (rank == 0) std::printf("FAIL %s: %s = %.17g, serial %.17g\n", where.c_str(), what, got, want);
    ++failures;
  }
}

void check_grid(const Grid& grid, double contact_share, unsigned seed, const mpi::MpiCommunicator& comm) {
  const std::string where = fmt::format("{} {} grid, {:.0f} % contact, {} processes", grid.shape_string(),
                                        grid.periodic() ? "periodic" : "free", 100.0 * contact_share, comm.size());
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  Eigen::ArrayXd pressure(static_cast<Eigen::Index>(grid.size())), gap(pressure.size()), heights(pressure.size());
  for (Eigen::Index k = 0; k < pressure.size(); ++k) {
    const bool touching = uniform(random) < contact_share;
    pressure[k] = touching ? 1e6 * uniform(random) : 0.0;
    // Contact cells keep rounding-level gaps of either sign, as solves leave them.
    gap[k] = touching ? 1e-20 * (uniform(random) - 0.5) : 1e-6 * uniform(random);
    heights[k] = 1e-6 * (uniform(random) - 0.5) + 1e-7 * std::sin(0.3 * static_cast<double>(k % grid.nx()));
  }
  const analysis::ContactStatistics want =
      analysis::contact_statistics(grid, {pressure.data(), grid.size()}, {gap.data(), grid.size()});
  const surface::SurfaceStatistics want_surface = surface::surface_statistics(grid, {heights.data(), grid.size()});

  const mpi::SlabLayout layout = mpi::slab_layout(grid.nx(), grid.ny(), comm);
  const std::size_t begin = layout.first_row * grid.nx();
  const auto rows = [&](const Eigen::ArrayXd& field) {
    return std::span<const double>(field.data() + begin, layout.local_size());
  };
  const analysis::ContactStatistics got = mpi::slab_contact_statistics(grid, layout, rows(pressure), rows(gap), comm);
  const surface::SurfaceStatistics got_surface = mpi::slab_surface_statistics(grid, layout, rows(heights), comm);

  expect_close(where, "contact fraction", got.contact_fraction, want.contact_fraction, comm.rank());
  expect_close(where, "mean gap", got.mean_gap, want.mean_gap, comm.rank());
  expect_close(where, "rms gap", got.rms_gap, want.rms_gap, comm.rank());
  expect_close(where, "free volume", got.free_volume, want.free_volume, comm.rank());
  expect_close(where, "rms height", got_surface.rms_height, want_surface.rms_height, comm.rank());
  expect_close(where, "rms slope", got_surface.rms_slope, want_surface.rms_slope, comm.rank());
  if (got.cluster_sizes != want.cluster_sizes) {
    if (comm.rank() == 0) {
      std::printf("FAIL %s: %lld clusters, serial %lld (largest %lld, serial %lld)\n", where.c_str(),
                  static_cast<long long>(got.clusters()), static_cast<long long>(want.clusters()),
                  static_cast<long long>(got.cluster_sizes.empty() ? 0 : got.cluster_sizes[0]),
                  static_cast<long long>(want.cluster_sizes.empty() ? 0 : want.cluster_sizes[0]));
    }
    ++failures;
  }
  if (comm.rank() == 0) std::printf("%s: %lld clusters\n", where.c_str(), static_cast<long long>(want.clusters()));
}

}  // namespace

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  {
    const mpi::MpiCommunicator world(MPI_COMM_WORLD);
    for (const Boundary boundary : {Boundary::periodic, Boundary::free}) {
      // Near the percolation threshold (about 59 % on a square lattice) the
      // clusters are large and cross slab boundaries and edges; at 20 %
      // they are many and small.
      check_grid(Grid::plane(48, 31, 1e-6, 2e-6, boundary), 0.55, 1, world);
      check_grid(Grid::plane(37, 24, 1e-6, 1e-6, boundary), 0.2, 2, world);
      check_grid(Grid::plane(16, 2, 1e-6, 1e-6, boundary), 0.6, 3, world);   // fewer rows than processes
      check_grid(Grid::plane(20, 20, 1e-6, 1e-6, boundary), 1.0, 4, world);  // one cluster, everything
      check_grid(Grid::plane(20, 20, 1e-6, 1e-6, boundary), 0.0, 5, world);  // none
    }
    // Everything agreed on the first process's count of failures.
    int total = failures;
    MPI_Allreduce(&failures, &total, 1, MPI_INT, MPI_SUM, world.get());
    failures = total;
  }
  if (failures > 0 && session.rank() == 0) std::printf("%d mismatch(es)\n", failures);
  return failures == 0 ? 0 : 1;
}
