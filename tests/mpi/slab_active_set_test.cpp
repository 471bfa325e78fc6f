// pk-multilevel's primal-dual active-set phase on slabs against the serial
// solve (run by ctest under mpiexec -np 1, 2 and 3 in the MPI build): every
// process makes the same rough surface whole, solves it serially
// (serial_layout) and on its slab of rows (mpi::DistributedLayout) with the
// phase forced on, and the distributed pressure must equal the serial
// pressure's rows within 1e-12 of its largest value, the approach and the
// force within 1e-12 relative, with the same iterations, set updates and
// deflated iterations (the phase's reductions, set updates and the slab
// block deflation follow the serial path; rounding alone differs): periodic
// and free grids, load and displacement control, with and without block
// deflation, on rows that no process count divides. Exits non-zero on a
// mismatch, printing it.
#include <fmt/format.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>

#include "halfspace/mpi/distributed_layout.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/session.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/surface/self_affine.hpp"

namespace {

using namespace halfspace;

// Transforms and sums on slabs round unlike the serial ones; the iterations
// follow the same path (their counts must be equal), so the fields agree to
// rounding. The solves stop at a residual of 1e-10, not at the rounding
// floor: at 1e-12 Polonsky-Keer's last iterations on the free grid under
// displacement control hinge on rounding (one iteration more on 2
// processes, the pressure 9e-12 apart).
constexpr double kTolerance = 1e-12;
constexpr double kEStar = 1.0;

int failures = 0;

void report(bool ok, const std::string& where, const std::string& what, double error, int rank) {
  if (!ok) {
    if (rank == 0) std::printf("FAIL %s: %s differs by %.3g\n", where.c_str(), what.c_str(), error);
    ++failures;
  }
}

void expect_count(const std::string& where, const std::string& what, int got, int want, int rank) {
  if (got != want) {
    if (rank == 0) std::printf("FAIL %s: %s %d, serial %d\n", where.c_str(), what.c_str(), got, want);
    ++failures;
  }
}

// The rough surface of the solver tests: self-affine, H = 0.8, wavelengths
// down to 4 cells, rms slope 0.1.
Eigen::ArrayXd rough_heights(const Grid& grid) {
  surface::SelfAffineSpec spec;
  spec.hurst = 0.8;
  spec.short_cutoff = 4.0 * grid.dx();
  spec.rms_slope = 0.1;
  spec.seed = 3;
  return surface::make_self_affine_surface(grid, spec);
}

void check(const Grid& grid, bool deflated, const mpi::MpiCommunicator& comm) {
  const Eigen::ArrayXd heights = rough_heights(grid);
  solvers::SolverOptions options;
  options.type = solvers::SolverType::pk_multilevel;
  options.tolerance = 1e-10;  // see kTolerance
  options.multilevel.active_set = solvers::MultilevelOptions::ActiveSet::on;
  options.deflation.mode = deflated ? solvers::DeflationOptions::Mode::on : solvers::DeflationOptions::Mode::off;
  const mpi::DistributedLayout layout(comm);
  const mpi::SlabLayout slab = mpi::slab_layout(grid.nx(), grid.ny(), comm);
  const std::size_t begin = slab.first_row * grid.nx();
  const std::span<const double> rows{heights.data() + begin, slab.local_size()};
  // About 8 % contact under load control; displacement control at the
  // approach that load gave.
  const Loading load = Loading::mean_pressure(0.004);
  const SolveResult loaded = solvers::solve_surface(grid, {heights.data(), grid.size()}, kEStar, load, options);
  for (const Loading& loading : {load, Loading::approach(loaded.approach)}) {
    const std::string where = fmt::format(
        "{} {} grid, {}, deflation {}, {} processes", grid.shape_string(), grid.periodic() ? "periodic" : "free",
        loading.load_controlled() ? "load control" : "approach", deflated ? "on" : "off", comm.size());
    const SolveResult want = solvers::solve_surface(grid, {heights.data(), grid.size()}, kEStar, loading, options);
    const SolveResult got = solvers::solve_surface(grid, rows, kEStar, loading, options, {}, layout);
    if (!want.converged() || !got.converged()) {
      report(false, where, fmt::format("convergence (serial: {}; slabs: {})", want.message, got.message), 0.0,
             comm.rank());
      continue;
    }
    // The phase ran in both (forced on) and Polonsky-Keer finished.
    if (want.active_set_outer < 1 || got.active_set_outer < 1) {
      report(false, where,
             fmt::format("the phase ran ({} / {} set updates)", got.active_set_outer, want.active_set_outer), 0.0,
             comm.rank());
    }
    const double scale = want.max_pressure;
    double error = 0.0;
    for (Eigen::Index k = 0; k < got.pressure.size(); ++k) {
      error = std::max(error, std::abs(got.pressure[k] - want.pressure[static_cast<Eigen::Index>(begin) + k]));
    }
    error = comm.max(error);
    report(static_cast<std::size_t>(got.pressure.size()) == slab.local_size() && error <= kTolerance * scale, where,
           "pressure", error / scale, comm.rank());
    report(std::abs(got.approach - want.approach) <= kTolerance * std::abs(want.approach), where, "approach",
           std::abs(got.approach - want.approach) / std::abs(want.approach), comm.rank());
    report(std::abs(got.total_force - want.total_force) <= kTolerance * std::abs(want.total_force), where, "force",
           std::abs(got.total_force - want.total_force) / std::abs(want.total_force), comm.rank());
    expect_count(where, "iterations", got.iterations, want.iterations, comm.rank());
    expect_count(where, "set updates", got.active_set_outer, want.active_set_outer, comm.rank());
    expect_count(where, "phase iterations", got.active_set_inner, want.active_set_inner, comm.rank());
    expect_count(where, "deflated iterations", got.deflation.deflated_iterations, want.deflation.deflated_iterations,
                 comm.rank());
    if (comm.rank() == 0) {
      std::printf("%s: %d iterations (%d in %d set updates, %d deflated), serial %d; max |dp| %.1e of max p\n",
                  where.c_str(), got.iterations, got.active_set_inner, got.active_set_outer,
                  got.deflation.deflated_iterations, want.iterations, error / scale);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  {
    const mpi::MpiCommunicator world(MPI_COMM_WORLD);
    // 160 rows: five deflation blocks of 32, slabs of unequal height on 3
    // processes whose edges cut blocks; the coarse levels distributed and
    // gathered.
    for (const Boundary boundary : {Boundary::periodic, Boundary::free}) {
      const Grid grid = Grid::plane(192, 160, 1.0, 1.0, boundary);
      check(grid, false, world);
      check(grid, true, world);
    }
    int total = failures;
    MPI_Allreduce(&failures, &total, 1, MPI_INT, MPI_SUM, world.get());
    failures = total;
  }
  if (failures > 0 && session.rank() == 0) std::printf("%d mismatch(es)\n", failures);
  return failures == 0 ? 0 : 1;
}
