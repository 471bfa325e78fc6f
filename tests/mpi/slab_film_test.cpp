// The rigid Reynolds film with mass-conserving cavitation on slabs against
// the serial solve of the whole film (run by ctest under mpiexec -np 1, 2
// and 3 in the MPI build): every process makes the same surface whole,
// keeps its rows and solves them as `halfspace lubricate` does under MPI
// (lubricate_at_separation with mpi::SlabFilmRows); the slabs' pressure
// and fluid fraction must equal the serial ones to the last bit (the
// iterates are the serial ones: slab_film_rows.hpp), with the same sweeps and status, on films that
// cavitate and reform, with fixed or periodic edges along either axis and
// the entrainment up or down the rows. Exits non-zero on a mismatch,
// printing it.
#include <fmt/format.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "halfspace/lubrication/cavitation_solver.hpp"
#include "halfspace/lubrication/load_control.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/session.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/mpi/slab_film_rows.hpp"

namespace {

using namespace halfspace;
using lubrication::AxisBoundary;

int failures = 0;

// A textured film: a converging-diverging pad (parabolic in x and y) with a
// dimple pattern, so that the film cavitates behind the pad and in the
// dimples' diverging halves and reforms after them.
Eigen::ArrayXd textured_film(const Grid& grid) {
  Eigen::ArrayXd film(static_cast<Eigen::Index>(grid.size()));
  const double lx = grid.dx() * static_cast<double>(grid.nx());
  const double ly = grid.dy() * static_cast<double>(grid.ny());
  for (std::size_t j = 0; j < grid.ny(); ++j) {
    for (std::size_t i = 0; i < grid.nx(); ++i) {
      const double x = grid.dx() * static_cast<double>(i) / lx - 0.5;
      const double y = grid.dy() * static_cast<double>(j) / ly - 0.5;
      const double dimples = std::sin(6.0 * std::numbers::pi * x) * std::sin(4.0 * std::numbers::pi * y);
      film[static_cast<Eigen::Index>(j * grid.nx() + i)] = 1e-6 * (1.0 + 4.0 * (x * x + 0.5 * y * y) + 0.4 * dimples);
    }
  }
  return film;
}

void check(const std::string& name, const Grid& grid, const lubrication::FlowConditions& conditions,
           const mpi::MpiCommunicator& comm) {
  const std::string where = fmt::format("{} ({}, {} processes)", name, grid.shape_string(), comm.size());
  // The texture as heights below a flat plane at its thinnest film: the
  // film separation + (highest - heights) is the texture to rounding, the
  // same bits on both paths.
  const Eigen::ArrayXd film = textured_film(grid);
  const Eigen::ArrayXd heights = -film;
  const double separation = film.minCoeff();
  lubrication::CavitationSolverOptions options;
  options.tolerance = 1e-10;
  const lubrication::FilmSolution serial =
      lubrication::lubricate_at_separation(grid, heights, conditions, separation, options).solution;

  // The path of `halfspace lubricate` under MPI (apps/mpi/mpi_lubricate.cpp).
  const mpi::SlabLayout slab = mpi::slab_layout(grid.nx(), grid.ny(), comm);
  const std::size_t begin = slab.first_row * grid.nx();
  mpi::SlabFilmRows rows(grid, conditions, slab, comm);
  const Eigen::ArrayXd own =
      heights.segment(static_cast<Eigen::Index>(begin), static_cast<Eigen::Index>(slab.local_size()));
  lubrication::FilmSolution slabs =
      lubrication::lubricate_at_separation(grid, own, conditions, separation, options, &rows).solution;
  const auto first = static_cast<Eigen::Index>(rows.first_own_node());
  slabs.pressure = slabs.pressure.segment(first, static_cast<Eigen::Index>(rows.own_nodes())).eval();
  slabs.fluid_fraction = slabs.fluid_fraction.segment(first, static_cast<Eigen::Index>(rows.own_nodes())).eval();

  const auto n = static_cast<Eigen::Index>(slab.local_size());
  const auto b = static_cast<Eigen::Index>(begin);
  const double pressure_difference =
      comm.max(n > 0 ? (slabs.pressure - serial.pressure.segment(b, n)).abs().maxCoeff() : 0.0);
  const double fraction_difference =
      comm.max(n > 0 ? (slabs.fluid_fraction - serial.fluid_fraction.segment(b, n)).abs().maxCoeff() : 0.0);
  const bool cavitated = serial.fluid_fraction.minCoeff() < 0.99;
  const bool ok = serial.converged() && cavitated && slabs.status == serial.status &&
                  slabs.iterations == serial.iterations && pressure_difference == 0.0 && fraction_difference == 0.0;
  if (comm.rank() == 0) {
    std::printf(
        "%s %s: %d sweeps (serial %d), residual %.3g, largest pressure %.4g Pa, least fluid fraction %.3f, "
        "differences %.3g Pa and %.3g\n",
        ok ? "ok" : "FAIL", where.c_str(), slabs.iterations, serial.iterations, slabs.relative_residual,
        serial.pressure.maxCoeff(), serial.fluid_fraction.minCoeff(), pressure_difference, fraction_difference);
  }
  if (!ok) ++failures;
}

}  // namespace

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  {
    const mpi::MpiCommunicator world(MPI_COMM_WORLD);
    const Grid free = Grid::plane(40, 27, 2e-5, 3e-5, Boundary::free);
    const Grid periodic = Grid::plane(40, 27, 2e-5, 3e-5, Boundary::periodic);
    lubrication::FlowConditions conditions;
    conditions.viscosity = 0.05;
    conditions.entrainment_velocity = {1.0, 0.2};
    conditions.boundary.x_low_pressure = 2e5;
    check("fixed pressures on every edge, entrainment along +x", free, conditions, world);
    conditions.entrainment_velocity = {0.3, 1.0};
    conditions.boundary.y_low_pressure = 1e5;
    check("fixed pressures on every edge, entrainment along +y", free, conditions, world);
    conditions.entrainment_velocity = {0.3, -1.0};
    conditions.boundary.y_high_pressure = 1e5;
    conditions.boundary.y_low_pressure = 0.0;
    check("fixed pressures on every edge, entrainment along -y", free, conditions, world);
    // A film periodic along both axes has no pressure level: one axis at a time.
    conditions.boundary.x = AxisBoundary::periodic;
    conditions.entrainment_velocity = {1.0, 0.4};
    check("periodic x edges, fixed y edges", periodic, conditions, world);
    conditions.boundary.x = AxisBoundary::fixed_pressure;
    conditions.boundary.y = AxisBoundary::periodic;
    conditions.entrainment_velocity = {1.0, 0.3};
    check("fixed x edges, periodic y, entrainment along +y", periodic, conditions, world);
    conditions.entrainment_velocity = {-0.5, -1.0};
    check("fixed x edges, periodic y, entrainment along -x and -y", periodic, conditions, world);
    int total = failures;
    MPI_Allreduce(&failures, &total, 1, MPI_INT, MPI_SUM, world.get());
    failures = total;
  }
  if (failures > 0 && session.rank() == 0) std::printf("%d mismatch(es)\n", failures);
  return failures == 0 ? 0 : 1;
}
