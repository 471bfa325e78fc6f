// The mixed film on slabs against the serial solve of the whole film (run
// by ctest under mpiexec -np 1, 2 and 3 in the MPI build): every process
// makes the same rough gap whole, solves it with the serial operator, and
// solves its rows with the operator on slab transforms (solve_mixed_film on
// a distributed operator: the Newton iteration on this process's rows and
// their halo, GMRES reduced over the processes, the block preconditioner
// each slab's block with an overlap, the grid sequence's coarse film on
// slabs or whole). The two solves take different GMRES iterates, so they
// agree to the solver's tolerance, not to the bit: fluid and contact
// pressure, film and h0 within kTolerance of their scale, the contact
// share, area and friction alike, both converged and checked. Free and
// periodic grids, the first- and second-order Couette fluxes, entrainment
// along x and oblique, a grid taller than the preconditioner's overlap
// reaches, the contact rows' smoothing from a slower film. Exits non-zero on a mismatch, printing it.
#include <fmt/format.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "halfspace/grid.hpp"
#include "halfspace/lubrication/mixed_film.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/session.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/mpi/slab_spectral_transforms.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "lubrication/mixed_film_grid_sequence.hpp"

namespace {

using namespace halfspace;
using namespace halfspace::lubrication;

constexpr double kEStar = 1.1e11;
constexpr double kRadius = 0.01;
constexpr double kViscosity = 0.04;
// W = F / (E' R^2) = 3e-7: Hertz radius 77 um, peak 0.54 GPa.
constexpr double kLoad = 3e-7 * 2.0 * kEStar * kRadius * kRadius;
// Both solves to a relative mass residual, load error and contact row of
// 1e-11: their films agree far closer than this share of their scale.
constexpr double kSolveTolerance = 1e-11;
constexpr double kTolerance = 1e-8;

int failures = 0;

struct Case {
  std::string name;
  Grid grid;
  Eigen::ArrayXd gap;
  FlowConditions conditions;
  CouetteScheme scheme = CouetteScheme::first_order;
};

// Three incommensurate waves of `amplitude` in all at wavelengths that are
// fractions of `length`.
double waves(double x, double length, double amplitude, double phase) {
  return amplitude / 3.0 *
         (std::sin(2.0 * std::numbers::pi * x / (0.37 * length) + phase) +
          std::sin(2.0 * std::numbers::pi * x / (0.61 * length) + 1.0 + phase) +
          std::sin(2.0 * std::numbers::pi * x / (0.23 * length) + 2.0 + phase));
}

FlowConditions flow(double speed, double vy) {
  FlowConditions c;
  c.viscosity = kViscosity;
  c.entrainment_velocity = {speed, vy * speed};
  c.sliding_velocity = {0.5 * speed, 0.5 * vy * speed};
  return c;
}

// A sphere with 0.2 um of roughness in both directions on an nx x ny grid
// of the spacing 4a / (nx - 1), x from -2.5a, y centred (the tests' rough
// point contact of mixed_film_krylov_test.cpp; taller than nx rows: beyond
// the overlap of the processes' preconditioner blocks).
Case rough_ball(const std::string& name, std::size_t nx, std::size_t ny, double speed, double vy, CouetteScheme scheme,
                double amplitude = 0.2e-6) {
  const double a = std::cbrt(3.0 * kLoad * kRadius / (4.0 * kEStar));
  const double dx = 4.0 * a / static_cast<double>(nx - 1);
  const auto upstream = static_cast<std::size_t>(std::lround(2.5 * a / dx));
  const double half = 0.5 * static_cast<double>(ny - 1);
  Case c{.name = name, .grid = Grid::plane(nx, ny, dx, dx, Boundary::free), .gap = {}, .conditions = flow(speed, vy)};
  c.gap.resize(static_cast<Eigen::Index>(nx * ny));
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const double x = (static_cast<double>(i) - static_cast<double>(upstream)) * dx;
      const double y = (static_cast<double>(j) - half) * dx;
      c.gap[static_cast<Eigen::Index>(j * nx + i)] = (x * x + y * y) / (2.0 * kRadius) +
                                                     0.5 * waves(x, a, amplitude, 0.0) +
                                                     0.5 * waves(y + 0.3 * x, a, amplitude, 0.7);
    }
  }
  c.gap -= c.gap.minCoeff();
  c.scheme = scheme;
  return c;
}

// A rough cylinder across x on a periodic grid, the film periodic along y.
Case rough_cylinder(const std::string& name, double speed, double vy) {
  const double a = std::cbrt(3.0 * kLoad * kRadius / (4.0 * kEStar));
  const std::size_t nx = 48, ny = 24;
  const double dx = 4.0 * a / 33.0;
  Case c{
      .name = name, .grid = Grid::plane(nx, ny, dx, dx, Boundary::periodic), .gap = {}, .conditions = flow(speed, vy)};
  c.gap.resize(static_cast<Eigen::Index>(nx * ny));
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const double x = (static_cast<double>(i) - 30.0) * dx;
      const double y = static_cast<double>(j) * dx;
      c.gap[static_cast<Eigen::Index>(j * nx + i)] =
          x * x / (2.0 * kRadius) + 0.5 * waves(x, a, 0.2e-6, 0.0) +
          0.1e-6 * std::cos(2.0 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(ny)) +
          0.5 * waves(y + 0.3 * x, a, 0.2e-6, 0.7);
    }
  }
  c.gap -= c.gap.minCoeff();
  c.conditions.boundary.y = AxisBoundary::periodic;
  return c;
}

// `smoothed_from`: both films by the contact rows' smoothing (the speed
// continuation's last resort where it stalls) from the film at this speed,
// each solved its own way. Driven directly, not through a stall: whether
// and where a continuation stalls is decided by the GMRES sums' rounding,
// which differs between the serial and the slab solves.
void check(const Case& c, double total_load, const mpi::MpiCommunicator& comm, double smoothed_from = 0.0) {
  const std::string where = fmt::format("{} ({}, {} processes)", c.name, c.grid.shape_string(), comm.size());
  LubricantLaws laws;
  laws.piezoviscosity = Piezoviscosity::roelands;
  laws.pressure_viscosity = 5000.0 / (2.0 * kEStar);
  laws.compressibility = Compressibility::dowson_higginson;
  MixedFilmOptions options;
  options.load = total_load;
  options.tolerance = kSolveTolerance;
  options.load_tolerance = kSolveTolerance;
  options.contact_tolerance = kSolveTolerance;
  options.couette_scheme = c.scheme;
  options.linear_solve = FilmLinearSolve::gmres;
  options.friction.contact_friction = 0.1;
  options.friction.shear.limiting_shear_slope = 0.05;
  const bool smoothed = smoothed_from > 0.0;
  const double speed = std::hypot(c.conditions.entrainment_velocity[0], c.conditions.entrainment_velocity[1]);
  const auto start_conditions = [&] {
    FlowConditions slower = c.conditions;
    for (int axis = 0; axis < 2; ++axis) {
      slower.entrainment_velocity[axis] *= smoothed_from / speed;
      slower.sliding_velocity[axis] *= smoothed_from / speed;
    }
    return slower;
  };
  FftInfluenceOperator serial_op(c.grid, kEStar);
  detail::MixedFilmKeep serial_keep;
  const MixedFilm serial = smoothed ? detail::solve_mixed_film_smoothed(
                                          serial_op, c.gap, serial_keep, c.conditions, laws, options,
                                          solve_mixed_film(serial_op, c.gap, start_conditions(), laws, options))
                                    : solve_mixed_film(serial_op, c.gap, c.conditions, laws, options);

  FftInfluenceOperator slab_op(c.grid, kEStar,
                               mpi::make_slab_transforms(c.grid, comm, FftPlanning::estimate, {.count = 1}));
  const std::size_t own = slab_op.local_size();
  const mpi::SlabLayout layout = mpi::slab_layout(c.grid.nx(), c.grid.ny(), comm);
  const auto begin = static_cast<Eigen::Index>(layout.first_row * c.grid.nx());
  const auto n = static_cast<Eigen::Index>(own);
  const Eigen::ArrayXd gap = c.gap.segment(begin, n);
  detail::MixedFilmKeep slab_keep;
  const MixedFilm slabs =
      smoothed ? detail::solve_mixed_film_smoothed(slab_op, gap, slab_keep, c.conditions, laws, options,
                                                   solve_mixed_film(slab_op, gap, start_conditions(), laws, options))
               : solve_mixed_film(slab_op, gap, c.conditions, laws, options);

  const bool sized = slabs.fluid_pressure.size() == n && slabs.contact_pressure.size() == n && slabs.film.size() == n &&
                     slabs.fluid_fraction.size() == n;
  const auto largest = [&](const Eigen::ArrayXd& got, const Eigen::ArrayXd& whole) {
    return comm.max(sized && n > 0 ? (got - whole.segment(begin, n)).abs().maxCoeff() : (sized ? 0.0 : INFINITY));
  };
  const double peak = serial.max_pressure;
  const double film_scale = (c.gap.maxCoeff() - c.gap.minCoeff());
  const double fluid = largest(slabs.fluid_pressure, serial.fluid_pressure) / peak;
  const double contact = largest(slabs.contact_pressure, serial.contact_pressure) / peak;
  const double film = largest(slabs.film, serial.film) / film_scale;
  const double fraction = largest(slabs.fluid_fraction, serial.fluid_fraction);
  const double offset = std::abs(slabs.offset - serial.offset) / film_scale;
  const double share = std::abs(slabs.contact_load_fraction - serial.contact_load_fraction);
  const double area = std::abs(slabs.contact_area_fraction - serial.contact_area_fraction);
  const double friction = std::abs(slabs.friction_coefficient / serial.friction_coefficient - 1.0);
  const double minimum = std::abs(slabs.minimum_film_thickness - serial.minimum_film_thickness) / film_scale;
  const double central = std::abs(slabs.central_film_thickness - serial.central_film_thickness) / film_scale;
  const double load = std::abs(slabs.load / serial.load - 1.0);
  const bool mixed = serial.contact_load_fraction > 0.01 && serial.contact_load_fraction < 0.99;
  const bool ok = serial.converged() && slabs.converged() && mixed && fluid <= kTolerance && contact <= kTolerance &&
                  film <= kTolerance && fraction <= kTolerance && offset <= kTolerance && share <= kTolerance &&
                  area <= kTolerance && friction <= kTolerance && minimum <= kTolerance && central <= kTolerance &&
                  load <= 1e-9;
  if (comm.rank() == 0) {
    std::printf(
        "%s %s: contact share %.4f, %d Newton steps, %d GMRES its (serial %d, %d); "
        "differences: fluid %.2e and "
        "contact pressure %.2e of the peak, film %.2e of the gap's range, fluid fraction %.2e, h0 %.2e, share %.2e, "
        "area %.2e, friction %.2e, minimum %.2e, central %.2e, load %.2e%s%s%s%s\n",
        ok ? "ok" : "FAIL", where.c_str(), serial.contact_load_fraction, slabs.iterations, slabs.krylov_iterations,
        serial.iterations, serial.krylov_iterations, fluid, contact, film, fraction, offset, share, area, friction,
        minimum, central, load, serial.converged() ? "" : "; serial: ", serial.message.c_str(),
        slabs.converged() ? "" : "; slabs: ", slabs.message.c_str());
  }
  if (!ok) ++failures;
}

}  // namespace

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  {
    const mpi::MpiCommunicator world(MPI_COMM_WORLD);
    check(rough_ball("rough ball, free grid, entrainment along x", 34, 34, 0.1, 0.0, CouetteScheme::first_order), kLoad,
          world);
    check(rough_ball("rough ball, free grid, oblique entrainment, second order", 34, 34, 0.3, 0.5,
                     CouetteScheme::second_order),
          kLoad, world);
    check(rough_ball("rough ball, tall free grid (the coarse film on slabs on 2 processes)", 34, 70, 0.1, 0.0,
                     CouetteScheme::first_order),
          kLoad, world);
    check(rough_cylinder("rough cylinder, periodic grid, film periodic along y", 0.1, 0.0), 0.4 * kLoad, world);
    // mixed_film_krylov_test.cpp's smoothed contact rows, from 4e-3 to
    // 1e-3 m/s; and two 17^2 balls whose smoothed rows stalled on 2 or 3
    // processes before their line search tried the step to the first kink.
    check(rough_ball("rough ball, smoothed contact rows from a faster film", 13, 13, 1e-3, 0.0,
                     CouetteScheme::first_order),
          kLoad, world, 4e-3);
    check(rough_ball("rough ball, smoothed contact rows from a slower film", 17, 17, 1e-3, 0.0,
                     CouetteScheme::first_order, 0.1e-6),
          kLoad, world, 5e-4);
    check(rough_ball("rougher ball, smoothed contact rows from a faster film", 17, 17, 1e-3, 0.0,
                     CouetteScheme::first_order),
          kLoad, world, 4e-3);
    int total = failures;
    MPI_Allreduce(&failures, &total, 1, MPI_INT, MPI_SUM, world.get());
    failures = total;
  }
  if (failures > 0 && session.rank() == 0) std::printf("%d mismatch(es)\n", failures);
  return failures == 0 ? 0 : 1;
}
