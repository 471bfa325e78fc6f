// The frictional solve on slabs against the serial one (run by ctest under
// mpiexec -np 1, 2 and 3 in the MPI build): every process makes the same
// surface whole, solves it serially (serial_layout) and on its slab of rows
// (mpi::DistributedLayout), and each field of the distributed solve (the
// pressure; per step of a loading history the shear, stick map, slip and
// tangential displacement) must equal the serial field's rows within 1e-12
// of the serial field's largest magnitude, the step's integrals (force,
// approach, stick fraction, dissipated energy) within 1e-12 relative: on
// periodic and free grids, for similar bodies (the pressure solved once)
// and dissimilar ones (the coupled normal-tangential alternation), with a
// gross sliding step too, and a coated body on periodic and free grids (the
// free grid's layered remainder added per mode of the padded spectrum held
// on each slab). Exits non-zero on a mismatch, printing it.
#include <fmt/format.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "halfspace/mpi/distributed_layout.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/session.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/mpi/slab_spectral_transforms.hpp"
#include "halfspace/operators/tangential_operator.hpp"
#include "halfspace/solvers/frictional_solve.hpp"

namespace {

using namespace halfspace;

// Transforms and sums on slabs round unlike the serial ones; the iterations
// follow the same path, so the fields agree to rounding.
constexpr double kTolerance = 1e-12;
// The coated free grid: its operators agree to rounding (checked apart, to
// kOperatorTolerance), but its coupled alternation amplifies the rounding
// over a history: 0.4-2.2e-8 of the largest shear, 2-6e-10 of the largest
// pressure at 1-3 processes, the spread set by which FFTW plans were chosen
// (the same run with and without other plans made first). A wrong slab,
// mode or remainder shows at 1e-3 or more.
constexpr double kAmplifiedTolerance = 1e-7;
constexpr double kOperatorTolerance = 1e-13;
double tolerance = kTolerance;

int failures = 0;

void report(bool ok, const std::string& where, const std::string& what, double error, int rank) {
  if (!ok) {
    if (rank == 0) std::printf("FAIL %s: %s differs by %.3g\n", where.c_str(), what.c_str(), error);
    ++failures;
  }
}

// got: this process's rows; want: the whole serial field.
void expect_field(const std::string& where, const std::string& what, const Eigen::ArrayXd& got,
                  const Eigen::ArrayXd& want, std::size_t begin, const mpi::MpiCommunicator& comm) {
  const double scale = want.abs().maxCoeff();
  double error = 0.0;
  if (static_cast<std::size_t>(got.size()) + begin > static_cast<std::size_t>(want.size())) {
    error = INFINITY;
  } else {
    for (Eigen::Index k = 0; k < got.size(); ++k) {
      error = std::max(error, std::abs(got[k] - want[static_cast<Eigen::Index>(begin) + k]));
    }
  }
  error = comm.max(error);
  report(error <= tolerance * std::max(scale, 1e-300), where, what, error / std::max(scale, 1e-300), comm.rank());
}

void expect_value(const std::string& where, const std::string& what, double got, double want, double scale,
                  const mpi::MpiCommunicator& comm) {
  const double error = std::abs(got - want);
  report(error <= tolerance * std::max(scale, 1e-300), where, what, error / std::max(scale, 1e-300), comm.rank());
}

void check(const Grid& grid, const ElasticPair& pair, bool sliding, const mpi::MpiCommunicator& comm) {
  const std::string where =
      fmt::format("{} {} grid, beta = {:.3f}{}, {} processes", grid.shape_string(),
                  grid.periodic() ? "periodic" : "free", pair.dundurs_beta(), sliding ? ", sliding" : "", comm.size());
  // A sphere with a ripple: contact patches that cross the slabs' edges.
  const double radius = 0.01;
  Eigen::ArrayXd heights(static_cast<Eigen::Index>(grid.size()));
  for (std::size_t j = 0; j < grid.ny(); ++j) {
    for (std::size_t i = 0; i < grid.nx(); ++i) {
      const double x = (static_cast<double>(i) - 0.5 * static_cast<double>(grid.nx()) + 0.3) * grid.dx();
      const double y = (static_cast<double>(j) - 0.5 * static_cast<double>(grid.ny()) + 0.2) * grid.dy();
      heights[static_cast<Eigen::Index>(j * grid.nx() + i)] =
          -(x * x + y * y) / (2.0 * radius) + 2e-8 * std::sin(9e4 * x) * std::cos(7e4 * y);
    }
  }
  const Loading loading = Loading::force(2.0);
  solvers::SolverOptions normal;
  normal.type = solvers::SolverType::pk_fourier;
  normal.tolerance = 1e-12;
  solvers::FrictionOptions friction;
  friction.tangential.friction_coefficient = 0.3;
  friction.tangential.tolerance = 1e-10;
  friction.coupled_step.tolerance = 1e-10;
  if (sliding) {
    friction.sliding_direction = {{1.0, 0.5}};
  } else {
    // Loading, partial unloading and reversal in x, with a y component:
    // a fretting history (mu P is 0.6 N).
    friction.history = {TangentialLoading::force(0.25, 0.05), TangentialLoading::force(0.45, 0.1),
                        TangentialLoading::force(0.1, 0.1), TangentialLoading::force(-0.3, 0.0)};
  }
  friction.normal_load_steps = 2;
  const FrictionalSolveResult want =
      solvers::solve_frictional_surface(grid, {heights.data(), grid.size()}, pair, loading, normal, friction);
  const mpi::DistributedLayout layout(comm);
  const mpi::SlabLayout slab = mpi::slab_layout(grid.nx(), grid.ny(), comm);
  const std::size_t begin = slab.first_row * grid.nx();
  const FrictionalSolveResult got = solvers::solve_frictional_surface(grid, {heights.data() + begin, slab.local_size()},
                                                                      pair, loading, normal, friction, layout);
  if (!want.converged() || !got.converged() || got.steps.size() != want.steps.size()) {
    report(false, where, fmt::format("convergence (serial: {}; slabs: {})", want.failure(), got.failure()), 0.0,
           comm.rank());
    return;
  }
  expect_field(where, "pressure", got.normal.pressure, want.normal.pressure, begin, comm);
  int iterations = 0;
  int serial_iterations = 0;
  for (std::size_t k = 0; k < want.steps.size(); ++k) {
    const TangentialResult& g = got.steps[k];
    const TangentialResult& w = want.steps[k];
    const std::string step = fmt::format("step {} ", k + 1);
    expect_field(where, step + "shear_x", g.state.shear_x, w.state.shear_x, begin, comm);
    expect_field(where, step + "shear_y", g.state.shear_y, w.state.shear_y, begin, comm);
    expect_field(where, step + "stick", g.stick, w.stick, begin, comm);
    expect_field(where, step + "slip_x", g.state.slip_x, w.state.slip_x, begin, comm);
    expect_field(where, step + "slip_y", g.state.slip_y, w.state.slip_y, begin, comm);
    expect_field(where, step + "tangential displacement x", g.state.displacement_x, w.state.displacement_x, begin,
                 comm);
    expect_field(where, step + "tangential displacement y", g.state.displacement_y, w.state.displacement_y, begin,
                 comm);
    if (want.coupled) {
      expect_field(where, step + "pressure", got.step_normals[k].pressure, want.step_normals[k].pressure, begin, comm);
    }
    const double force = std::hypot(w.force_x, w.force_y);
    expect_value(where, step + "force x", g.force_x, w.force_x, force, comm);
    expect_value(where, step + "force y", g.force_y, w.force_y, force, comm);
    const double approach = std::hypot(w.state.approach_x, w.state.approach_y);
    expect_value(where, step + "approach x", g.state.approach_x, w.state.approach_x, approach, comm);
    expect_value(where, step + "approach y", g.state.approach_y, w.state.approach_y, approach, comm);
    expect_value(where, step + "stick fraction", g.stick_fraction, w.stick_fraction, 1.0, comm);
    expect_value(where, step + "dissipated energy", g.dissipated_energy, w.dissipated_energy,
                 std::max(std::abs(w.dissipated_energy), 1e-30), comm);
    iterations += g.iterations;
    serial_iterations += w.iterations;
  }
  if (comm.rank() == 0) {
    std::printf("%s: %zu steps, stick fraction %.3f at the last, %d iterations (serial %d)\n", where.c_str(),
                want.steps.size(), want.steps.back().stick_fraction, iterations, serial_iterations);
  }
}

// The tangential operator's products (compliance, both couplings and the
// approximate inverse) on slabs against the serial operator's rows, for
// random fields.
void check_operators(const Grid& grid, const ElasticPair& pair, const mpi::MpiCommunicator& comm) {
  const std::string where = fmt::format("{} {} grid operators, {} processes", grid.shape_string(),
                                        grid.periodic() ? "periodic" : "free", comm.size());
  const mpi::SlabLayout slab = mpi::slab_layout(grid.nx(), grid.ny(), comm);
  const std::size_t begin = slab.first_row * grid.nx();
  const Eigen::Index n = static_cast<Eigen::Index>(grid.size());
  const Eigen::Index local = static_cast<Eigen::Index>(slab.local_size());
  std::srand(7);
  const Eigen::ArrayXd qx = 1e6 * (Eigen::ArrayXd::Random(n) + 1.0);
  const Eigen::ArrayXd qy = 1e6 * (Eigen::ArrayXd::Random(n) + 1.0);
  operators::TangentialOperator serial(grid, pair);
  operators::TangentialOperator slabs(grid, pair, mpi::make_slab_transforms(grid, comm, FftPlanning::estimate));
  Eigen::ArrayXd want_x(n), want_y(n), got_x(local), got_y(local);
  auto mine = [&](const Eigen::ArrayXd& a) { return std::span<const double>(a.data() + begin, slab.local_size()); };
  auto all = [](const Eigen::ArrayXd& a) {
    return std::span<const double>(a.data(), static_cast<std::size_t>(a.size()));
  };
  auto out = [](Eigen::ArrayXd& a) { return std::span<double>(a.data(), static_cast<std::size_t>(a.size())); };
  auto expect_pair = [&](const std::string& what) {
    expect_field(where, what + " x", got_x, want_x, begin, comm);
    expect_field(where, what + " y", got_y, want_y, begin, comm);
  };
  tolerance = kOperatorTolerance;
  serial.apply(all(qx), all(qy), out(want_x), out(want_y));
  slabs.apply(mine(qx), mine(qy), out(got_x), out(got_y));
  expect_pair("compliance");
  serial.apply_pressure_coupling(all(qx), out(want_x), out(want_y));
  slabs.apply_pressure_coupling(mine(qx), out(got_x), out(got_y));
  expect_pair("pressure coupling");
  serial.apply_approximate_inverse(all(qx), all(qy), out(want_x), out(want_y));
  slabs.apply_approximate_inverse(mine(qx), mine(qy), out(got_x), out(got_y));
  expect_pair("approximate inverse");
  serial.apply_traction_coupling(all(qx), all(qy), out(want_x));
  slabs.apply_traction_coupling(mine(qx), mine(qy), out(got_x));
  expect_field(where, "traction coupling", got_x, want_x, begin, comm);
  tolerance = kTolerance;
}

}  // namespace

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  {
    const mpi::MpiCommunicator world(MPI_COMM_WORLD);
    const ElasticBody steel{2.1e11, 0.3};
    const ElasticBody aluminium{7.0e10, 0.33};
    for (const Boundary boundary : {Boundary::periodic, Boundary::free}) {
      // Rows not a multiple of the process counts: slabs of unequal height.
      const Grid grid = Grid::plane(32, 26, 4e-6, 5e-6, boundary);
      check(grid, ElasticPair::similar(steel), false, world);
      check(grid, ElasticPair(steel, aluminium), false, world);
      check(grid, ElasticPair::similar(steel), true, world);
    }
    // A coated body (a stiff layer on steel): coupled. On the free grid the
    // layer must be thin against the domain (FrictionOptions::check_body).
    const ElasticPair coated = ElasticPair::coated({1e-5, {4.2e11, 0.22}, steel});
    check(Grid::plane(32, 26, 4e-6, 5e-6, Boundary::periodic), coated, false, world);
    const ElasticPair thin = ElasticPair::coated({4e-6, {4.2e11, 0.22}, steel});
    const Grid free = Grid::plane(32, 26, 4e-6, 5e-6, Boundary::free);
    check_operators(free, thin, world);
    tolerance = kAmplifiedTolerance;
    check(free, thin, false, world);
    tolerance = kTolerance;
    int total = failures;
    MPI_Allreduce(&failures, &total, 1, MPI_INT, MPI_SUM, world.get());
    failures = total;
  }
  if (failures > 0 && session.rank() == 0) std::printf("%d mismatch(es)\n", failures);
  return failures == 0 ? 0 : 1;
}
