// The provenance every result file of a solve records (material, load mode,
// threads, where the surface came from and how it was prepared, what asked
// for the solve) and the surface's statistics, made the same way by every
// front end (the program, the Python package).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/io/result_writer.hpp"
#include "halfspace/solvers/loading.hpp"

namespace halfspace::io {

struct SolveProvenance {
  double e_star = 0.0;  // Pa
  ControlMode load_mode = ControlMode::force;
  int threads = 1;
  std::string command_line;  // the program's command line, or the Python call
  std::string config;        // a TOML config text, empty if none
  std::string height_source;
  std::vector<std::string> preparation;  // one line per preparation step
};

// The metadata of a result file with surface_statistics of `heights` on
// `grid` filled in; contact_statistics is left to the caller (a sweep's
// differ per step). Throws InputError if heights do not match the grid.
ResultMetadata result_metadata(const SolveProvenance& run, const Grid& grid, std::span<const double> heights);

// The same without surface_statistics, for a caller that computes them
// itself (the slabs of an MPI run).
ResultMetadata provenance_metadata(const SolveProvenance& run);

}  // namespace halfspace::io
