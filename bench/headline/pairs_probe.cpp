// The FFT pairs of one periodic solve, split: what the default solver
// (pk-multilevel) spends on the fine grid's K and M^-1 products and on its
// coarse grids, with the iterations, the block deflation's and the
// active-set phase's work, for one height map. Issue 31's pair counts
// (docs/performance.md) are measured with it; the counts are exact
// whatever the machine's load, the seconds are not.
//
//   pairs_probe MAP.h5 [--threads T] [--planning estimate|measure]
//               [--active-set on|off|automatic] [--coarse-tolerance X]
//               [--deflation on|off|automatic] [--history]
//
// The map is solved as `halfspace solve --boundary periodic --E-star 1e9
// --mean-pressure 4e6` solves it (the growing-domain surfaces of
// scripts/growing-domain.sh). Prints one line of JSON; --history adds the
// fine residual history. Bad arguments: a message on stderr, exit code 2.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>

#include "halfspace/grid.hpp"
#include "halfspace/io/hdf5_height_map_reader.hpp"
#include "halfspace/solvers/solver_options.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/threads.hpp"

int main(int argc, char** argv) {
  using namespace halfspace;
  if (argc < 2) {
    std::fputs(
        "usage: pairs_probe MAP.h5 [--threads T] [--planning estimate|measure] [--active-set MODE] "
        "[--coarse-tolerance X] [--deflation MODE] [--history]\n",
        stderr);
    return 2;
  }
  solvers::SolverOptions options;
  int threads = 1;
  bool history = false;
  try {
    for (int a = 2; a < argc; ++a) {
      const std::string_view arg = argv[a];
      if (arg == "--history") {
        history = true;
        continue;
      }
      if (a + 1 >= argc) throw std::invalid_argument(fmt::format("{} needs a value", arg));
      const std::string value = argv[++a];
      if (arg == "--threads") {
        threads = std::stoi(value);
      } else if (arg == "--planning") {
        options.fft_planning = value == "estimate" ? FftPlanning::estimate : FftPlanning::measure;
      } else if (arg == "--active-set") {
        options.multilevel.active_set = solvers::parse_active_set(value);
      } else if (arg == "--coarse-tolerance") {
        options.multilevel.coarse_tolerance = std::stod(value);
      } else if (arg == "--deflation") {
        options.deflation.mode = value == "on"    ? solvers::DeflationOptions::Mode::on
                                 : value == "off" ? solvers::DeflationOptions::Mode::off
                                                  : solvers::DeflationOptions::Mode::automatic;
      } else {
        throw std::invalid_argument(fmt::format("unknown argument {}", arg));
      }
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "pairs_probe: %s\n", error.what());
    return 2;
  }
  set_threads(threads);
  HeightMap map = io::read_hdf5_height_map(argv[1]);
  const Grid grid = Grid::plane(map.nx, map.ny, map.dx, map.dy, Boundary::periodic);
  const solvers::SolveResult r = solvers::solve_surface(grid, {map.heights.data(), map.size()}, 1e9,
                                                        solvers::Loading::mean_pressure(4e6), options);
  const double coarse = r.coarse.operator_work + r.coarse.preconditioner_work;
  fmt::print(
      "{{\"n\":{},\"converged\":{},\"iterations\":{},\"K\":{},\"M\":{},\"coarse\":{:.2f},\"pairs\":{:.2f},"
      "\"coarse_levels\":{},\"coarse_iterations\":{},\"deflated\":{},\"coarse_cg\":{},\"as_outer\":{},"
      "\"as_inner\":{},\"contact\":{:.6f},\"residual\":{:.3e},\"seconds\":{:.3f}",
      map.nx, r.converged() ? 1 : 0, r.iterations, r.operator_applications, r.preconditioner_applications, coarse,
      r.operator_applications + r.preconditioner_applications + coarse, r.coarse.levels, r.coarse.iterations,
      r.deflation.deflated_iterations, r.deflation.coarse_iterations, r.active_set_outer, r.active_set_inner,
      r.contact_fraction, r.residual, r.wall_seconds);
  if (history) fmt::print(",\"history\":[{:.2e}]", fmt::join(r.residual_history, ","));
  fmt::print("}}\n");
  return r.converged() ? 0 : 1;
}
