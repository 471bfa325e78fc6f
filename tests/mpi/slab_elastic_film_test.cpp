// The EHL film on slabs against the serial solve of the whole film (run by
// ctest under mpiexec -np 1, 2 and 3 in the MPI build): every process
// makes the same gap whole, solves it with the serial operator, and solves
// its rows with the operator on slab transforms (solve_elastic_film on a
// distributed operator: the Newton iteration on this process's rows and
// their halo, GMRES reduced over the processes, its preconditioner each
// slab's block with an overlap). The two solves take different GMRES
// iterates (the preconditioners differ), so they agree to the solver's
// tolerance, not to the bit: the films, pressures and h0 must agree within kTolerance of
// their scale, both converged and checked. Free and periodic grids, the
// first- and second-order Couette fluxes, entrainment along x and
// oblique, a grid taller than the preconditioner's overlap reaches, and
// one whose coarse film is solved on slabs too. Exits non-zero on a mismatch, printing it.
#include <fmt/format.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "halfspace/grid.hpp"
#include "halfspace/lubrication/elastic_film.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/session.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/mpi/slab_spectral_transforms.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"

namespace {

using namespace halfspace;
using namespace halfspace::lubrication;

constexpr double kEStar = 1.1e11;
constexpr double kRadius = 0.01;
constexpr double kViscosity = 0.05;
// Both solves to a relative mass residual and load error of 1e-10: their
// films agree far closer than this share of their scale.
constexpr double kSolveTolerance = 1e-10;
constexpr double kTolerance = 1e-8;

int failures = 0;

struct Case {
  std::string name;
  Grid grid;
  Eigen::ArrayXd gap;
  FlowConditions conditions;
  double load = 0.0;
  CouetteScheme scheme = CouetteScheme::first_order;
};

// A ball on a free grid, Hamrock & Dowson's W = 3e-7, U = 1e-11, G = 5000,
// 8 cells per Hertz radius, the inlet 3.5 radii upstream, 2 radii each side
// (or `half` rows: beyond the overlap of the processes' preconditioner
// blocks, kSlabOverlapRows, on a tall grid).
Case ball(const std::string& name, double vy, CouetteScheme scheme, std::size_t half = 16) {
  const double e_prime = 2.0 * kEStar;
  const double load = 3e-7 * e_prime * kRadius * kRadius;
  const double radius = std::cbrt(3.0 * load * kRadius / (4.0 * kEStar));
  const double dx = radius / 8.0;
  const std::size_t nx = 41, ny = 2 * half + 1, upstream = 28;
  Case c{.name = name, .grid = Grid::plane(nx, ny, dx, dx, Boundary::free), .gap = {}, .conditions = {}};
  c.gap.resize(static_cast<Eigen::Index>(nx * ny));
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const double x = (static_cast<double>(i) - static_cast<double>(upstream)) * dx;
      const double y = (static_cast<double>(j) - static_cast<double>(half)) * dx;
      c.gap[static_cast<Eigen::Index>(j * nx + i)] = (x * x + y * y) / (2.0 * kRadius);
    }
  }
  const double u = 1e-11 * e_prime * kRadius / kViscosity;
  c.conditions.viscosity = kViscosity;
  c.conditions.entrainment_velocity = {u, vy * u};
  c.load = load;
  c.scheme = scheme;
  return c;
}

// A cylinder across x on a periodic grid, the film periodic along y, its
// gap waved along y so that the rows differ; `ny` rows (128: the coarse
// film of grid sequencing on slabs of its rows too, kMinSlabRows each).
Case waved_cylinder(const std::string& name, double vy, std::size_t ny = 24) {
  const std::size_t nx = 64;
  const double dx = 4e-6;
  Case c{.name = name, .grid = Grid::plane(nx, ny, dx, dx, Boundary::periodic), .gap = {}, .conditions = {}};
  c.gap.resize(static_cast<Eigen::Index>(nx * ny));
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const double x = (static_cast<double>(i) - 40.0) * dx;
      const double wave = 0.1e-6 * (1.0 - std::cos(2.0 * std::numbers::pi * static_cast<double>(j) / ny));
      c.gap[static_cast<Eigen::Index>(j * nx + i)] = x * x / (2.0 * kRadius) + wave;
    }
  }
  c.conditions.viscosity = kViscosity;
  c.conditions.entrainment_velocity = {0.5, vy};
  c.conditions.boundary.y = AxisBoundary::periodic;
  c.load = 0.3e9 * 20.0 * dx * static_cast<double>(ny) * dx;  // ~0.3 GPa over 20 cells
  return c;
}

void check(const Case& c, const mpi::MpiCommunicator& comm) {
  const std::string where = fmt::format("{} ({}, {} processes)", c.name, c.grid.shape_string(), comm.size());
  const LubricantLaws laws{.piezoviscosity = Piezoviscosity::roelands,
                           .pressure_viscosity = 2e-8,
                           .compressibility = Compressibility::dowson_higginson};
  const ElasticFilmOptions options{.load = c.load,
                                   .tolerance = kSolveTolerance,
                                   .load_tolerance = kSolveTolerance,
                                   .couette_scheme = c.scheme,
                                   .linear_solve = FilmLinearSolve::gmres};
  FftInfluenceOperator serial_op(c.grid, kEStar);
  const ElasticFilm serial = solve_elastic_film(serial_op, c.gap, c.conditions, laws, options);

  FftInfluenceOperator slab_op(c.grid, kEStar,
                               mpi::make_slab_transforms(c.grid, comm, FftPlanning::estimate, {.count = 1}));
  const std::size_t own = slab_op.local_size();
  const mpi::SlabLayout layout = mpi::slab_layout(c.grid.nx(), c.grid.ny(), comm);
  const auto begin = static_cast<Eigen::Index>(layout.first_row * c.grid.nx());
  const auto n = static_cast<Eigen::Index>(own);
  const Eigen::ArrayXd gap = c.gap.segment(begin, n);
  const ElasticFilm slabs = solve_elastic_film(slab_op, gap, c.conditions, laws, options);

  const bool sized = slabs.pressure.size() == n && slabs.film.size() == n && slabs.fluid_fraction.size() == n;
  const auto largest = [&](const Eigen::ArrayXd& got, const Eigen::ArrayXd& whole) {
    return comm.max(sized && n > 0 ? (got - whole.segment(begin, n)).abs().maxCoeff() : (sized ? 0.0 : INFINITY));
  };
  const double pressure = largest(slabs.pressure, serial.pressure) / serial.max_pressure;
  const double film = largest(slabs.film, serial.film) / serial.central_film_thickness;
  const double fraction = largest(slabs.fluid_fraction, serial.fluid_fraction);
  const double offset = std::abs(slabs.offset - serial.offset) / serial.central_film_thickness;
  const double central = std::abs(slabs.central_film_thickness / serial.central_film_thickness - 1.0);
  const double minimum = std::abs(slabs.minimum_film_thickness / serial.minimum_film_thickness - 1.0);
  const double load = std::abs(slabs.load / serial.load - 1.0);
  const bool cavitated = serial.fluid_fraction.minCoeff() < 0.99;
  const bool ok = serial.converged() && slabs.converged() && cavitated && pressure <= kTolerance &&
                  film <= kTolerance && fraction <= kTolerance && offset <= kTolerance && central <= kTolerance &&
                  minimum <= kTolerance && load <= 1e-9 && slabs.relative_residual <= 10.0 * kSolveTolerance;
  if (comm.rank() == 0) {
    std::printf(
        "%s %s: %d Newton steps, %d GMRES its (serial %d, %d), residual %.3g; differences: pressure %.2e of the "
        "peak, film %.2e of the central, fluid fraction %.2e, h0 %.2e, central %.2e, minimum %.2e, load %.2e%s%s\n",
        ok ? "ok" : "FAIL", where.c_str(), slabs.iterations, slabs.krylov_iterations, serial.iterations,
        serial.krylov_iterations, slabs.relative_residual, pressure, film, fraction, offset, central, minimum, load,
        slabs.converged() ? "" : "; slabs: ", slabs.message.c_str());
  }
  if (!ok) ++failures;
}

}  // namespace

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  {
    const mpi::MpiCommunicator world(MPI_COMM_WORLD);
    check(ball("ball, free grid, entrainment along x", 0.0, CouetteScheme::first_order), world);
    check(ball("ball, free grid, oblique entrainment, second order", 0.5, CouetteScheme::second_order), world);
    check(ball("ball, tall free grid, entrainment along x", 0.0, CouetteScheme::first_order, 56), world);
    check(waved_cylinder("waved cylinder, periodic grid, film periodic along y", 0.0), world);
    check(waved_cylinder("waved cylinder, periodic grid, entrainment down y", -0.2), world);
    check(waved_cylinder("waved cylinder, tall periodic grid, the coarse film on slabs too", -0.2, 128), world);
    int total = failures;
    MPI_Allreduce(&failures, &total, 1, MPI_INT, MPI_SUM, world.get());
    failures = total;
  }
  if (failures > 0 && session.rank() == 0) std::printf("%d mismatch(es)\n", failures);
  return failures == 0 ? 0 : 1;
}
