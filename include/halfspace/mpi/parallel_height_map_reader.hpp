// An HDF5 height map read by every MPI process at once, each its own slab of
// rows (a hyperslab, read collectively through the parallel HDF5), with the
// serial reader's checks and messages. Compiled only with HALFSPACE_MPI.
#pragma once

#include <filesystem>
#include <string>

#include "halfspace/io/hdf5_height_map_reader.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"

namespace halfspace::mpi {

// Reads `dataset` of `path` as io::read_hdf5_height_map_rows does, each
// process the rows slab_layout gives it on `comm` (a profile whole, on every
// process). Collective; every process throws the same FileError for a file
// they cannot read, as they all check the same file.
io::HeightMapRows read_height_map_slab(const MpiCommunicator& comm, const std::filesystem::path& path,
                                       const std::string& dataset);

}  // namespace halfspace::mpi
