// Private: the sweep file's contents (docs/file-format.md#sweep-results),
// defined in sweep_writer.cpp, shared by the serial writer and the
// collective one (mpi/parallel_result_writer.cpp).
#pragma once

#include <cstdint>
#include <span>

#include "halfspace/analysis/load_sweep.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/io/result_writer.hpp"
#include "hdf5_writing.hpp"

namespace halfspace::io {

// Everything write_sweep_result puts under the root; `height` and the
// steps' fields hold the rows `rows` says (all of them in the serial
// writer), the steps' other members, their statistics and `metadata` are
// the same in every process that writes the file.
void write_sweep_contents(const Hdf5Node& root, const Grid& grid, std::span<const double> height,
                          std::span<const analysis::SweepStep> steps, const ResultMetadata& metadata,
                          FieldRows rows = {});

// An upper bound on the bytes of the sweep file (reserve_output_space).
std::uint64_t sweep_file_bound(const Grid& grid, std::span<const analysis::SweepStep> steps);

}  // namespace halfspace::io
