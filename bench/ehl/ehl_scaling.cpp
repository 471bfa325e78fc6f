// EHL point contacts on N x N grids with the GMRES linear solve (and the
// dense one where it fits): Newton steps, GMRES iterations per step,
// seconds, peak resident bytes per node, and the films against Hamrock &
// Dowson (1977, k = 1). Usage: ehl_scaling N [gmres|dense] [neighbourhood]
// [cold|sequenced] [tolerance] [multigrid|sparse-lu] ("cold": no grid
// sequencing; the relative mass residual and load error to reach, 1e-8 by
// default; the GMRES preconditioner, multigrid by default).
// One solve per process, so that the peak resident size is the solve's.
#include <fmt/format.h>
#include <sys/resource.h>

#include <cmath>
#include <cstdlib>
#include <string_view>

#include "ehl_case.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/lubrication/elastic_film.hpp"
#include "halfspace/openmp_waiting.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "support/analytic_solutions.hpp"

using namespace halfspace;
using namespace halfspace::lubrication;
using bench::kEStar;
using bench::kRadius;

int main(int argc, char** argv) {
  // As the halfspace program: spinning threads beside another process made
  // a 128^2 mixed film take 279 s instead of 31 (development log, 2026-12-01).
  halfspace::use_passive_openmp_waiting(argv);
  if (argc < 2) {
    fmt::print(stderr,
               "usage: ehl_scaling N [gmres|dense] [neighbourhood] [cold|sequenced] [tolerance] "
               "[multigrid|sparse-lu]\n");
    return 2;
  }
  const auto n = static_cast<std::size_t>(std::atol(argv[1]));
  const FilmLinearSolve solve = argc > 2 ? parse_film_linear_solve(argv[2]) : FilmLinearSolve::gmres;
  const int neighbourhood = argc > 3 ? std::atoi(argv[3]) : 0;
  const bool sequencing = !(argc > 4 && std::string_view(argv[4]) == "cold");
  const double tolerance = argc > 5 ? std::atof(argv[5]) : 1e-8;
  const KrylovPreconditioner preconditioner =
      argc > 6 ? parse_krylov_preconditioner(argv[6]) : KrylovPreconditioner::multigrid;
  const double w = 3e-7, u = 1e-11, g = 5000;
  const double e_prime = 2.0 * kEStar;
  const double load = w * e_prime * kRadius * kRadius;
  const double a = std::cbrt(3.0 * load * kRadius / (4.0 * kEStar));
  // x in [-3.5a, 1.5a], y in [-2.5a, 2.5a]: the contact's centre on a node.
  const double dx = 5.0 * a / static_cast<double>(n - 1);
  const auto upstream = static_cast<std::size_t>(std::lround(3.5 * a / dx));
  const std::size_t half = (n - 1) / 2;
  const Grid grid = Grid::plane(n, n, dx, dx, Boundary::free);
  FftInfluenceOperator op(grid, kEStar);
  ElasticFilmOptions options{.load = load,
                             .tolerance = tolerance,
                             .load_tolerance = tolerance,
                             .linear_solve = solve,
                             .preconditioner_neighbourhood = neighbourhood,
                             .preconditioner = preconditioner,
                             .grid_sequencing = sequencing};
  const ElasticFilm f = solve_elastic_film(op, bench::parabolic_gap(grid, upstream, half), bench::rolling(u),
                                           bench::roelands_laws(g), options);
  const auto [hd_central, hd_minimum] = testing::hamrock_dowson_point(u, g, w);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double peak = static_cast<double>(usage.ru_maxrss) * 1024.0;
  fmt::print(
      "N {} solve {} {} r {} cells/a {:.1f}: {} coarse levels ({} steps, {} GMRES its{}), {} steps ({} tight retries), "
      "{} "
      "GMRES its "
      "({} most per step), {:.2f} s, {:.0f} B/node, Hc/HD {:.6f} Hmin/HD {:.6f}, h0 {:.9e} {}\n",
      n, to_string(solve), to_string(preconditioner), neighbourhood, a / dx, f.coarse_levels, f.coarse_iterations,
      f.coarse_krylov_iterations, f.sequencing_fell_back ? ", fell back to cold" : "", f.iterations, f.tight_retries,
      f.krylov_iterations, f.max_krylov_iterations_per_step, f.wall_seconds, peak / static_cast<double>(n * n),
      f.central_film_thickness / kRadius / hd_central, f.minimum_film_thickness / kRadius / hd_minimum, f.offset,
      f.converged() ? "converged" : f.message);
  return f.converged() ? 0 : 1;
}
