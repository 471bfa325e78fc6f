// Mixed lubrication of a rough point contact on N x N grids with the GMRES
// linear solve (or the dense one where it fits): Newton steps, GMRES
// iterations, seconds, peak resident bytes per node, the contact's share of
// the load. The ball of ehl_scaling.cpp (W = 3e-7, G = 5000, Roelands) with
// 0.2 um of roughness, incommensurate waves of wavelengths 0.23a to 0.61a
// along x and obliquely, the same surface on every grid.
// Usage: mixed_scaling N [speed m/s, 0.05] [gmres|dense|automatic]
// [neighbourhood, 1] [sequenced|cold] [multigrid|sparse-lu]. One solve per process, so that the
// peak resident size is the solve's.
#include <fmt/format.h>
#include <sys/resource.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string_view>

#include "ehl_case.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/lubrication/mixed_film.hpp"
#include "halfspace/openmp_waiting.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"

using namespace halfspace;
using namespace halfspace::lubrication;
using bench::kEStar;
using bench::kRadius;

namespace {
double waves(double x, double length, double amplitude, double phase) {
  return amplitude / 3.0 *
         (std::sin(2.0 * std::numbers::pi * x / (0.37 * length) + phase) +
          std::sin(2.0 * std::numbers::pi * x / (0.61 * length) + 1.0 + phase) +
          std::sin(2.0 * std::numbers::pi * x / (0.23 * length) + 2.0 + phase));
}
}  // namespace

int main(int argc, char** argv) {
  // As the halfspace program: spinning threads beside another process made
  // a 128^2 mixed film take 279 s instead of 31 (development log, 2026-12-01).
  halfspace::use_passive_openmp_waiting(argv);
  if (argc < 2) {
    fmt::print(stderr,
               "usage: mixed_scaling N [speed] [gmres|dense|automatic] [neighbourhood] [sequenced|cold] "
               "[multigrid|sparse-lu]\n");
    return 2;
  }
  const auto n = static_cast<std::size_t>(std::atol(argv[1]));
  const double speed = argc > 2 ? std::atof(argv[2]) : 0.05;
  const FilmLinearSolve solve = argc > 3 ? parse_film_linear_solve(argv[3]) : FilmLinearSolve::automatic;
  const int neighbourhood = argc > 4 ? std::atoi(argv[4]) : 1;
  const bool sequenced = argc > 5 ? std::string_view(argv[5]) != "cold" : true;
  const KrylovPreconditioner preconditioner =
      argc > 6 ? parse_krylov_preconditioner(argv[6]) : MixedFilmOptions{}.preconditioner;
  const double e_prime = 2.0 * kEStar;
  const double load = 3e-7 * e_prime * kRadius * kRadius;
  const double a = std::cbrt(3.0 * load * kRadius / (4.0 * kEStar));
  // x in [-2.5a, 1.5a], y in [-2a, 2a].
  const double dx = 4.0 * a / static_cast<double>(n - 1);
  const auto upstream = static_cast<std::size_t>(std::lround(2.5 * a / dx));
  const std::size_t half = (n - 1) / 2;
  const Grid grid = Grid::plane(n, n, dx, dx, Boundary::free);
  Eigen::ArrayXd gap(static_cast<Eigen::Index>(n * n));
  const double amplitude = 0.2e-6;
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t i = 0; i < n; ++i) {
      const double x = (static_cast<double>(i) - static_cast<double>(upstream)) * dx;
      const double y = (static_cast<double>(j) - static_cast<double>(half)) * dx;
      gap[static_cast<Eigen::Index>(j * n + i)] = (x * x + y * y) / (2.0 * kRadius) +
                                                  0.5 * waves(x, a, amplitude, 0.0) +
                                                  0.5 * waves(y + 0.3 * x, a, amplitude, 0.7);
    }
  }
  gap -= gap.minCoeff();
  FftInfluenceOperator op(grid, kEStar);
  FlowConditions conditions;
  conditions.viscosity = bench::kViscosity;
  conditions.entrainment_velocity = {speed, 0.0};
  conditions.sliding_velocity = {0.5 * speed, 0.0};
  MixedFilmOptions options;
  options.load = load;
  options.linear_solve = solve;
  options.preconditioner_neighbourhood = neighbourhood;
  options.grid_sequencing = sequenced;
  options.preconditioner = preconditioner;
  options.friction.shear.limiting_shear_slope = 0.05;
  const MixedFilm f = solve_mixed_film(op, gap, conditions, bench::roelands_laws(5000), options);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double peak = static_cast<double>(usage.ru_maxrss) * 1024.0;
  fmt::print(
      "N {} u {} solve {} r {} {} {}: {} ({}), {} Newton steps, {} GMRES its (most {} per step), {} halvings, coarse "
      "levels {} ({} Newton steps, {} GMRES its){}, {:.2f} s, contact load fraction {:.4f}, contact area {:.4f}, h_c "
      "{:.4g} m, mu {:.4f}, residual {:.2e}, load error "
      "{:.2e}, complementarity {:.2e}, peak RSS {:.0f} B/node\n",
      n, speed, to_string(solve), neighbourhood, sequenced ? "sequenced" : "cold", to_string(preconditioner),
      f.converged() ? "converged" : "FAILED", f.message, f.iterations, f.krylov_iterations,
      f.max_krylov_iterations_per_step, f.line_search_halvings, f.coarse_levels, f.coarse_iterations,
      f.coarse_krylov_iterations, f.sequencing_fell_back ? ", fell back cold" : "", f.wall_seconds,
      f.contact_load_fraction, f.contact_area_fraction, f.central_film_thickness, f.friction_coefficient,
      f.relative_residual, f.load_error, f.complementarity_error, peak / static_cast<double>(n * n));
  return f.converged() ? 0 : 1;
}
