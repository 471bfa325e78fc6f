// A solve's (or a load sweep's) result file written by every MPI process at once, each its rows
// of every field (hyperslabs, written collectively through the parallel
// HDF5): the serial io::write_result's layout, storage and attributes, with
// no field gathered. Compiled only with HALFSPACE_MPI.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>

#include "halfspace/analysis/load_sweep.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/io/height_map_writer.hpp"
#include "halfspace/io/result_writer.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/solvers/solve_result.hpp"
#include "halfspace/solvers/tangential_loading.hpp"
#include "halfspace/solvers/tangential_result.hpp"

namespace halfspace::mpi {

// `heights` and result's fields hold this process's layout.rows rows of the
// 2D `grid`; result's other members and `metadata` are the same on every
// process. Atomic as the serial writer: the first process creates
// `<target>.tmp-<pid>` beside the target (io::OutputTemporary), all write
// into it and close it, then the first renames it onto `path`; on any
// failure it is removed and every process throws the same FileError
// "cannot write output '<path>': <reason>". Collective.
void write_result_slabs(const MpiCommunicator& comm, const std::filesystem::path& path, const Grid& grid,
                        const SlabLayout& layout, std::span<const double> heights, const solvers::SolveResult& result,
                        const io::ResultMetadata& metadata);

// A friction history (io::write_friction_history's file and its CSV
// beside it) written the same way: `heights`, the normal result's and every
// step's fields (metadata.step_normals' too) hold this process's rows; the steps' integrals, `loads` and
// `metadata` are the same on every process. The CSV, written by the first
// process once the file is complete, is removed first, so an interrupted
// write leaves no mismatched pair. Throws InputError if `steps` is empty or
// `loads` has another length. Collective.
void write_friction_history_slabs(const MpiCommunicator& comm, const std::filesystem::path& path, const Grid& grid,
                                  const SlabLayout& layout, std::span<const double> heights,
                                  const solvers::SolveResult& normal, std::span<const TangentialResult> steps,
                                  std::span<const TangentialLoading> loads, const io::ResultMetadata& metadata);

// A height map (io::write_height_map's file) written the same way, each
// process its rows of the 2D `grid`'s heights. Collective.
void write_height_map_slabs(const MpiCommunicator& comm, const std::filesystem::path& path, const Grid& grid,
                            const SlabLayout& layout, std::span<const double> heights,
                            const io::HeightMapMetadata& metadata);

// The plumbing of both: fill(root) makes the same calls on every process
// (datasets by rows, attributes alike), into one temporary file the first
// process renames, with write_result_slabs's failures. The first process
// reserves `reserved_bytes` (an upper bound on the file) before any field
// is written, so that a full disk or a file-size limit fails on every
// process alike, not on one inside a collective write. Collective.
void write_file_slabs(const MpiCommunicator& comm, const std::filesystem::path& path, std::uint64_t reserved_bytes,
                      const std::function<void(const io::Hdf5Node& root)>& fill);

// The same for a load sweep: io::write_sweep_result's layout, storage and
// attributes. `heights` and every step's fields hold this process's rows;
// the steps' other members (their statistics among them) and `metadata` are
// the same on every process. Throws InputError if `steps` is empty.
// Collective.
void write_sweep_slabs(const MpiCommunicator& comm, const std::filesystem::path& path, const Grid& grid,
                       const SlabLayout& layout, std::span<const double> heights,
                       std::span<const analysis::SweepStep> steps, const io::ResultMetadata& metadata);

}  // namespace halfspace::mpi
