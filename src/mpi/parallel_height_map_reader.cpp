// The parallel read: an MPI-IO file access and a collective transfer handed
// to the serial reader, which selects this process's rows.
#include "halfspace/mpi/parallel_height_map_reader.hpp"

#include <hdf5.h>

#include <stdexcept>

#include "../io/hdf5_handle.hpp"
#include "halfspace/mpi/slab_fft.hpp"

namespace halfspace::mpi {

io::HeightMapRows read_height_map_slab(const MpiCommunicator& comm, const std::filesystem::path& path,
                                       const std::string& dataset) {
  const io::detail::PropertyList access(H5Pcreate(H5P_FILE_ACCESS));
  const io::detail::PropertyList transfer(H5Pcreate(H5P_DATASET_XFER));
  if (!access.valid() || !transfer.valid() || H5Pset_fapl_mpio(access.get(), comm.get(), MPI_INFO_NULL) < 0 ||
      H5Pset_dxpl_mpio(transfer.get(), H5FD_MPIO_COLLECTIVE) < 0) {
    throw std::runtime_error("cannot set up the parallel HDF5 reading");
  }
  io::Hdf5RowReading reading;
  reading.file_access = access.get();
  reading.transfer = transfer.get();
  reading.rows = [&comm](std::size_t nx, std::size_t ny) {
    const SlabLayout layout = slab_layout(nx, ny, comm);
    return std::pair{layout.first_row, layout.rows};
  };
  return io::read_hdf5_height_map_rows(path, dataset, reading);
}

}  // namespace halfspace::mpi
