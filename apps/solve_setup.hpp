// Validation of `halfspace solve` options into library objects: every input
// error is found here, before anything is solved or written.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "halfspace/elastic_pair.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/io/hdf5_height_map_reader.hpp"
#include "halfspace/linalg/communicator.hpp"
#include "halfspace/problem.hpp"
#include "halfspace/solvers/contact_solver.hpp"
#include "halfspace/solvers/friction_options.hpp"
#include "halfspace/stress/stressed_body.hpp"
#include "halfspace/surface/surface_options.hpp"
#include "memory_check.hpp"
#include "solve_options.hpp"

namespace halfspace::app {

// A fully checked solve: the problem (body, interface law, loads, solver,
// threads), the surface on its grid and where the result goes.
struct SolveSetup : Problem {
  Grid grid;
  // m, (ny, nx) row-major: every row, or (on an MPI process other than the
  // first) the rows from first_row on that this process solves. Mutable:
  // a single solve lends their storage to the solver for the initial gap and
  // gets them back unchanged (solvers::solve_surface_in_place).
  mutable Eigen::ArrayXd heights;
  std::size_t first_row = 0;
  std::string height_source;  // "file.h5:/height" or "sphere (radius = 0.01 m)"
  // Height-map preparation steps, one line each; empty if none.
  std::vector<std::string> preparation;
  std::filesystem::path output;
  bool quiet = false;
  std::string command_line;
  std::string config_text;
  bool plot = false;  // draw figures with the plotting tool after writing
  // Subsurface stresses to write into the result: none when empty.
  std::vector<double> stress_depths;  // m
  stress::StressedBodyChoice stress_body;
  // Friction (--friction with --tangential-force, --tangential-displacement
  // or --sliding): the tangential steps (the bodies are Problem::pair).
  std::optional<solvers::FrictionOptions> friction;
};

// "t = 1e-06 m, layer E1 = 3e+09 Pa, nu1 = 0.35 on substrate E2 = ... (E* is the layer's)".
std::string coating_text(const LayeredMaterial& coating);

// The surface of a solve as make_solve_setup makes it.
struct Surface {
  Grid grid;
  Eigen::ArrayXd heights;  // `rows` rows of nx heights (m), from row first_row on
  std::string source;
  std::vector<std::string> preparation;  // one line per preparation step of a height map
  std::size_t first_row = 0;
  std::size_t rows = 0;  // the grid's ny (1 in 1D) unless the surface is shared out in slabs
};

// Which rows of a 2D grid a process holds: {first_row, rows}.
using RowRange = std::pair<std::size_t, std::size_t>;

inline Surface make_whole_surface(const std::function<Surface()>& make_whole) {
  return make_whole();
}

// How the processes of a run get the surface. The serial program (the
// defaults) reads or builds it whole. An MPI run (apps/mpi/) sets the rest:
// a built-in surface is made by every process for its rows, an HDF5 height
// map read by every process for its rows (when its preparation can be done
// on slabs: see reads_height_map_in_slabs), and any other surface read
// whole by the first process, which hands the others their rows.
struct SurfaceSharing {
  // Given the function that reads or builds the surface whole, returns this
  // process's surface.
  std::function<Surface(const std::function<Surface()>& make_whole)> whole = make_whole_surface;
  // The rows of a 2D grid this process holds; unset: all. Collective.
  std::function<RowRange(const Grid& grid)> rows;
  // Reads this process's rows of an HDF5 height map; unset: maps are read
  // whole. Collective.
  std::function<io::HeightMapRows(const std::filesystem::path& path, const std::string& dataset)> read_hdf5_rows;
  // The processes that the preparation of a map read in rows adds its sums over.
  const linalg::Communicator* communicator = &linalg::serial_communicator();
  // The memory check of a run on `grid`; estimate(rows) is what a process
  // holding that many of its rows needs (all of them: the serial run).
  // Unset: require_memory(request, estimate(all rows), limit).
  std::function<void(const std::string& request, const Grid& grid,
                     const std::function<double(std::size_t rows)>& estimate, const std::optional<MemoryLimit>& limit)>
      check_memory;
};

// Whether make_solve_setup reads the height map `file` in rows when `share`
// can: an HDF5 file whose preparation needs no whole map (no window or
// padding, invalid points refused, any detrending).
bool reads_height_map_in_slabs(const HeightMapFile& file);

// Applies the defaults, checks every option and their combinations, builds
// the surface (reading the height map file, if any; through `share`) and
// checks that the output file can be created. Throws InputError (FileError
// for files) with a one-line message naming the option, its value and the
// rule it broke.
SolveSetup make_solve_setup(const SolveOptions& options, const SurfaceSharing& share = {});

}  // namespace halfspace::app
