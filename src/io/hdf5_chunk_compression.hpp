// Private: a whole dataset's chunks compressed on the threads and handed to
// HDF5 ready made (H5Dwrite_chunk). HDF5 runs its filter pipeline on one
// thread, and deflate at about 60 MB/s made writing a large result's fields
// a minute or more of a 16384^2 run; the bytes stored are those HDF5's own
// shuffle + deflate pipeline stores, so every reader decodes them as usual.
#pragma once

#include <hdf5.h>

#include <string_view>
#include <vector>

namespace halfspace::io::detail {

// Writes all of `data` (row-major, shaped `dims`, elements of
// `element_size` bytes as the file stores them) into `dataset`, created with
// chunks of shape `chunk`, the shuffle filter and then deflate at `level`
// (the only filters). Returns false, having written nothing, where the
// HDF5 build cannot write chunks directly (the parallel one); the caller
// then writes through H5Dwrite. Throws FileError when HDF5 refuses a chunk or
// zlib fails, naming `name`.
bool write_deflated_chunks(hid_t dataset, std::string_view name, const std::vector<hsize_t>& dims,
                           const std::vector<hsize_t>& chunk, std::size_t element_size, unsigned level,
                           const void* data);

}  // namespace halfspace::io::detail
