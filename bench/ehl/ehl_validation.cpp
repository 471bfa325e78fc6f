// EHL film thickness against the classical fits, for docs/validation.md:
// line contacts against Pan & Hamrock (1989) over W, U, G, both Couette
// schemes and three grids; point contacts against Hamrock & Dowson (1977,
// k = 1) on three grids; Newton steps and seconds per solve. Run with
// OMP_NUM_THREADS=1 (the dense LU is serial); `ehl_validation quick` runs a
// subset; `ehl_validation point 16,32` only the point contacts, on the
// given cells per Hertz radius (finer grids take the GMRES path with its
// multigrid preconditioner and grid sequencing, elastic_film.hpp).
#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "../number_list.hpp"
#include "ehl_case.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/lubrication/elastic_film.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "support/analytic_solutions.hpp"

namespace {

using namespace halfspace;
using namespace halfspace::lubrication;
using bench::kEStar;
using bench::kRadius;

struct Film {
  ElasticFilm film;
  double central, minimum;
};

// The film on `grid` whose gap has its vertex at node (upstream, centre_row);
// its thicknesses in units of R.
Film solved(const Grid& grid, std::size_t upstream, std::size_t centre_row, double load, double u, double g,
            CouetteScheme scheme) {
  FftInfluenceOperator op(grid, kEStar);
  Film f{solve_elastic_film(op, bench::parabolic_gap(grid, upstream, centre_row), bench::rolling(u),
                            bench::roelands_laws(g), {.load = load, .couette_scheme = scheme}),
         0, 0};
  f.central = f.film.central_film_thickness / kRadius;
  f.minimum = f.film.minimum_film_thickness / kRadius;
  return f;
}

// x in [-4.5 b, 1.5 b] on `cells` per Hertz half-width b.
Film line(double w, double u, double g, double cells, CouetteScheme scheme) {
  const double e_prime = 2.0 * kEStar;
  const double load = w * e_prime * kRadius;
  const double b = std::sqrt(4.0 * load * kRadius / (M_PI * kEStar));
  const double dx = b / cells;
  const auto upstream = static_cast<std::size_t>(std::lround(4.5 * cells));
  const std::size_t n = upstream + static_cast<std::size_t>(std::lround(1.5 * cells)) + 1;
  const Grid grid = Grid::line(n, dx, Boundary::free);
  return solved(grid, upstream, 0, load, u, g, scheme);
}

// x in [-3.5 a, 1.5 a), y in [-2 a, 2 a) on `cells` per Hertz radius a: an
// even grid (for even `cells`), which grid sequencing can coarsen; the
// contact's centre is a node.
Film point(double w, double u, double g, double cells, CouetteScheme scheme) {
  const double e_prime = 2.0 * kEStar;
  const double load = w * e_prime * kRadius * kRadius;
  const double a = std::cbrt(3.0 * load * kRadius / (4.0 * kEStar));
  const double dx = a / cells;
  const auto upstream = static_cast<std::size_t>(std::lround(3.5 * cells));
  const std::size_t nx = upstream + static_cast<std::size_t>(std::lround(1.5 * cells));
  const auto half = static_cast<std::size_t>(std::lround(2.0 * cells));
  const std::size_t ny = 2 * half;
  const Grid grid = Grid::plane(nx, ny, dx, dx, Boundary::free);
  return solved(grid, upstream, half, load, u, g, scheme);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::string_view(argv[1]) == "quick";
  const bool low = argc > 1 && std::string_view(argv[1]) == "low";
  const bool points_only = argc > 2 && std::string_view(argv[1]) == "point";
  if (!points_only) {
    fmt::print("# line contact vs Pan & Hamrock 1989 (Roelands, Dowson-Higginson; x in [-4.5b, 1.5b])\n");
    fmt::print("{:>8} {:>8} {:>6} {:>6} {:>13} {:>8} {:>8} {:>6} {:>8}\n", "W", "U", "G", "cells", "scheme", "Hc/PH",
               "Hmin/PH", "steps", "seconds");
    const std::vector<double> loads = low     ? std::vector<double>{1e-5}
                                      : quick ? std::vector<double>{2e-5, 1e-4}
                                              : std::vector<double>{1e-5, 2e-5, 5e-5, 1e-4, 2e-4};
    const std::vector<double> speeds = quick ? std::vector<double>{1e-11} : std::vector<double>{1e-11, 3e-11};
    const std::vector<double> materials = quick ? std::vector<double>{5000} : std::vector<double>{2500, 5000};
    const std::vector<double> grids = low     ? std::vector<double>{32, 128}
                                      : quick ? std::vector<double>{32}
                                              : std::vector<double>{16, 32, 64, 128};
    for (double w : loads) {
      for (double u : speeds) {
        for (double g : materials) {
          const double pan_central = 2.922 * std::pow(w, -0.166) * std::pow(u, 0.692) * std::pow(g, 0.470);
          const double pan_minimum = 1.714 * std::pow(w, -0.128) * std::pow(u, 0.694) * std::pow(g, 0.568);
          for (double cells : grids) {
            for (CouetteScheme scheme : {CouetteScheme::first_order, CouetteScheme::second_order}) {
              const Film f = line(w, u, g, cells, scheme);
              fmt::print("{:8.1e} {:8.1e} {:6.0f} {:6.0f} {:>13} {:8.4f} {:8.4f} {:6d} {:8.3f}{}\n", w, u, g, cells,
                         to_string(scheme), f.central / pan_central, f.minimum / pan_minimum, f.film.iterations,
                         f.film.wall_seconds, f.film.converged() ? "" : fmt::format("  {}", f.film.message));
            }
          }
        }
      }
    }
  }
  if (low) return 0;
  fmt::print("\n# point contact vs Hamrock & Dowson 1977, k = 1 (x in [-3.5a, 1.5a), y in [-2a, 2a))\n");
  fmt::print("{:>8} {:>8} {:>6} {:>6} {:>8} {:>13} {:>8} {:>8} {:>6} {:>8}\n", "W", "U", "G", "cells", "nodes",
             "scheme", "Hc/HD", "Hmin/HD", "steps", "seconds");
  const std::vector<double> point_loads = quick ? std::vector<double>{3e-7} : std::vector<double>{1e-7, 3e-7, 1e-6};
  const std::vector<double> point_grids = points_only ? bench::number_list(argv[2])
                                          : quick     ? std::vector<double>{6}
                                                      : std::vector<double>{6, 8, 10};
  for (double w : point_loads) {
    const double u = 1e-11, g = 5000;
    const auto [hd_central, hd_minimum] = testing::hamrock_dowson_point(u, g, w);
    for (double cells : point_grids) {
      for (CouetteScheme scheme : {CouetteScheme::first_order, CouetteScheme::second_order}) {
        const Film f = point(w, u, g, cells, scheme);
        fmt::print("{:8.1e} {:8.1e} {:6.0f} {:6.0f} {:8d} {:>13} {:8.4f} {:8.4f} {:6d} {:8.3f}{}\n", w, u, g, cells,
                   f.film.pressure.size(), to_string(scheme), f.central / hd_central, f.minimum / hd_minimum,
                   f.film.iterations, f.film.wall_seconds,
                   f.film.converged() ? "" : fmt::format("  {}", f.film.message));
      }
    }
  }
  return 0;
}
