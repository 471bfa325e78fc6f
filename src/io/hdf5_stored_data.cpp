#include "hdf5_stored_data.hpp"

#include <fmt/format.h>

#include <limits>
#include <string>
#include <vector>

#include "hdf5_handle.hpp"

namespace halfspace::io::detail {
namespace {

// A chunked dataset of which only some chunks were written: the others
// would be read as the fill value, and libhdf5 keeps bookkeeping per chunk
// of the selection while reading (a 4 KB file declaring 16000 x 16000
// points in 4 x 4 chunks, one written, made it use more than 20 GB). Every
// chunk must be stored, so the chunk count is bounded by the file's size.
std::optional<std::string> partly_written_problem(hid_t dataset, hid_t creation) {
  const Dataspace space(H5Dget_space(dataset));
  const int rank = space.valid() ? H5Sget_simple_extent_ndims(space.get()) : -1;
  if (rank <= 0 || rank > H5S_MAX_RANK) return std::nullopt;  // the shape check names these
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  std::vector<hsize_t> chunk(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  if (H5Pget_chunk(creation, rank, chunk.data()) != rank) {
    return fmt::format("the dataset's chunk shape cannot be read: {}", error_reason());
  }
  // The number of chunks the dataspace covers, saturating instead of
  // overflowing (a damaged file can declare any dimensions).
  constexpr hsize_t kMax = std::numeric_limits<hsize_t>::max();
  hsize_t chunks = 1;
  for (int axis = 0; axis < rank; ++axis) {
    if (chunk[axis] == 0) return "the dataset's chunk shape has a zero dimension";
    const hsize_t along = dims[axis] / chunk[axis] + (dims[axis] % chunk[axis] != 0 ? 1 : 0);
    chunks = along != 0 && chunks > kMax / along ? kMax : chunks * along;
  }
  hsize_t stored = 0;
  if (H5Dget_num_chunks(dataset, space.get(), &stored) < 0) {
    return fmt::format("the dataset's chunks cannot be counted: {}", error_reason());
  }
  if (stored < chunks) {
    return fmt::format(
        "the dataset is only partly written: {} of its {} chunks are stored (the rest would be fill values); "
        "write every chunk",
        stored, chunks == kMax ? std::string("more than 10^19") : std::to_string(chunks));
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> unstored_data_problem(hid_t dataset) {
  const PropertyList creation(H5Dget_create_plist(dataset));
  if (!creation.valid()) return fmt::format("the dataset's layout cannot be read: {}", error_reason());
  if (H5Pget_layout(creation.get()) == H5D_VIRTUAL) {
    return "the dataset is virtual (its data are in other files); store the data in this file";
  }
  if (H5Pget_external_count(creation.get()) != 0) {
    return "the dataset's data are in external files; store the data in this file";
  }
  const hsize_t stored = H5Dget_storage_size(dataset);
  if (stored == 0) return "the dataset holds no stored data (it was created but never written)";
  // Data the file cannot hold: a damaged header declaring more than there is
  // (the read would fail only after the buffer for it was made).
  const File file(H5Iget_file_id(dataset));
  hsize_t file_size = 0;
  if (file.valid() && H5Fget_filesize(file.get(), &file_size) >= 0 && stored > file_size) {
    return fmt::format("the dataset declares {} bytes of stored data, but the file has only {} bytes", stored,
                       file_size);
  }
  if (H5Pget_layout(creation.get()) == H5D_CHUNKED) return partly_written_problem(dataset, creation.get());
  return std::nullopt;
}

}  // namespace halfspace::io::detail
