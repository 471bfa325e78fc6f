// The HDF5 writing conventions (hdf5_output.hpp): attribute types, dataset
// storage, and the in-memory file handed to write_output_file.
#include "halfspace/io/hdf5_output.hpp"

#include <fmt/format.h>
#include <hdf5.h>
#include <sys/types.h>

#include <algorithm>
#include <string>
#include <type_traits>
#include <utility>

#include "halfspace/error.hpp"
#include "halfspace/io/output_file.hpp"
#include "hdf5_chunk_compression.hpp"
#include "hdf5_handle.hpp"
#include "hdf5_writing.hpp"

namespace halfspace::io {
namespace {

static_assert(std::is_same_v<hid_t, std::int64_t>, "Hdf5Node stores an hid_t as std::int64_t (HDF5 1.10 and later)");

using detail::Attribute;
using detail::Dataset;
using detail::Dataspace;
using detail::Datatype;
using detail::File;
using detail::PropertyList;

// Fields larger than this are chunked and compressed; a chunk holds about this
// many elements (512 KiB of float64, inside HDF5's default 1 MiB chunk cache).
constexpr hsize_t kChunkElements = 65536;
// Level 4 gives most of deflate's gain on smooth fields at a fraction of the
// time of level 9.
constexpr unsigned kDeflateLevel = 4;
// Growth step of the in-memory file: few reallocations for large results,
// little waste for small ones.
constexpr std::size_t kImageIncrement = std::size_t{4} << 20;

[[noreturn]] void fail_hdf5(std::string_view what) {
  throw FileError(fmt::format("{}: {}", what, detail::error_reason()));
}

// The dimensions of a dataset written in slabs (at least two), from its
// dataspace.
std::vector<hsize_t> slab_dims(const Dataspace& space) {
  const int rank = space.valid() ? H5Sget_simple_extent_ndims(space.get()) : -1;
  if (rank < 2) fail_hdf5("could not read the shape of the dataset being written");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return dims;
}

// HDF5 stores variable-length strings as C strings and h5py decodes UTF-8
// strictly, so invalid bytes (a Latin-1 file name on the command line) and
// embedded NULs are replaced by U+FFFD instead of making the attribute
// unreadable or silently truncated.
std::string to_valid_utf8(std::string_view text) {
  static constexpr std::string_view kReplacement = "\xEF\xBF\xBD";
  std::string out;
  out.reserve(text.size());
  std::size_t k = 0;
  while (k < text.size()) {
    const auto lead = static_cast<unsigned char>(text[k]);
    std::size_t length = 0;
    unsigned char low = 0x80;  // range of the second byte (RFC 3629, table 3-7 of Unicode)
    unsigned char high = 0xBF;
    if (lead >= 0x01 && lead <= 0x7F) {
      length = 1;
    } else if (lead >= 0xC2 && lead <= 0xDF) {
      length = 2;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
      length = 3;
      if (lead == 0xE0) low = 0xA0;
      if (lead == 0xED) high = 0x9F;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
      length = 4;
      if (lead == 0xF0) low = 0x90;
      if (lead == 0xF4) high = 0x8F;
    }
    bool valid = length > 0 && k + length <= text.size();
    for (std::size_t m = 1; valid && m < length; ++m) {
      const auto byte = static_cast<unsigned char>(text[k + m]);
      valid = m == 1 ? (byte >= low && byte <= high) : (byte >= 0x80 && byte <= 0xBF);
    }
    if (valid) {
      out.append(text, k, length);
      k += length;
    } else {
      out.append(kReplacement);
      ++k;
    }
  }
  return out;
}

void attach_scalar(hid_t location, std::string_view name, hid_t file_type, hid_t memory_type, const void* value) {
  const std::string key(name);
  const Dataspace space(H5Screate(H5S_SCALAR));
  const Attribute attribute(H5Acreate2(location, key.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT));
  if (!attribute.valid() || H5Awrite(attribute.get(), memory_type, value) < 0) {
    fail_hdf5(fmt::format("could not write attribute '{}'", name));
  }
}

// Variable-length UTF-8: the global heap holds the text, so a long config
// does not hit the 64 KiB object-header limit of fixed-length attributes, and
// the empty string needs no special case; h5py reads it as str.
void attach_string(hid_t location, std::string_view name, std::string_view value) {
  const Datatype type(H5Tcopy(H5T_C_S1));
  if (!type.valid() || H5Tset_size(type.get(), H5T_VARIABLE) < 0 || H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0) {
    fail_hdf5(fmt::format("could not make the string type of attribute '{}'", name));
  }
  const std::string text = to_valid_utf8(value);
  const char* data = text.c_str();
  attach_scalar(location, name, type.get(), type.get(), &data);
}

// The fewest equal pieces of at most `limit` that cover `extent`, so that the
// last chunk is not mostly padding (300 rows in chunks of 150, not 163 + 137).
hsize_t balanced_piece(hsize_t extent, hsize_t limit) {
  const hsize_t pieces = (extent + limit - 1) / limit;
  return (extent + pieces - 1) / pieces;
}

// Chunks of whole rows, at most kChunkElements each: a row is the unit that
// post-processing reads most often, and a whole-field read touches every
// chunk once. Empty for a field stored contiguously.
std::vector<hsize_t> chunk_shape(const std::vector<hsize_t>& dims) {
  hsize_t elements = 1;
  for (const hsize_t d : dims) elements *= d;
  if (elements <= kChunkElements) return {};  // contiguous

  std::vector<hsize_t> chunk(dims.size());
  chunk.back() = balanced_piece(dims.back(), kChunkElements);
  if (dims.size() >= 2) {
    const std::size_t row_axis = dims.size() - 2;
    chunk[row_axis] = balanced_piece(dims[row_axis], std::max<hsize_t>(1, kChunkElements / chunk.back()));
    // Rank 3 (the stress fields, one (ny, nx) slice per depth): one slice a chunk.
    for (std::size_t k = 0; k < row_axis; ++k) chunk[k] = 1;
  }
  return chunk;
}

// Whether a dataset with chunks `chunk` (empty: contiguous) is stored with
// the shuffle and deflate filters. Deflate is optional in an HDF5 build;
// without it the file stays valid, only larger.
bool deflated(const std::vector<hsize_t>& chunk, Compression compression) {
  return !chunk.empty() && compression == Compression::deflate && H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0;
}

PropertyList creation_properties(const std::vector<hsize_t>& dims, Compression compression) {
  PropertyList properties(H5Pcreate(H5P_DATASET_CREATE));
  if (!properties.valid()) fail_hdf5("could not create dataset properties");
  const std::vector<hsize_t> chunk = chunk_shape(dims);
  if (chunk.empty()) return properties;
  if (H5Pset_chunk(properties.get(), static_cast<int>(chunk.size()), chunk.data()) < 0) {
    fail_hdf5("could not set the chunk shape");
  }
  if (deflated(chunk, compression)) {
    if (H5Pset_shuffle(properties.get()) < 0 || H5Pset_deflate(properties.get(), kDeflateLevel) < 0) {
      fail_hdf5("could not set the compression filters");
    }
  }
  return properties;
}

// Writes rows first_row .. of a dataset of `shape` (all of them when `count`
// is the shape's product), creating it first.
hid_t write_array(hid_t location, std::string_view name, const std::vector<std::size_t>& shape, std::size_t first_row,
                  std::size_t count, hid_t file_type, hid_t memory_type, const void* data, std::string_view units,
                  hid_t transfer, Compression compression = Compression::deflate) {
  const std::string key(name);
  const std::vector<hsize_t> dims(shape.begin(), shape.end());
  hsize_t elements = 1;
  for (const hsize_t d : dims) elements *= d;
  const hsize_t row_elements = dims.empty() || dims[0] == 0 ? 1 : elements / dims[0];
  const bool whole = first_row == 0 && count == elements;
  if (!whole && (dims.empty() || count % row_elements != 0 || first_row > dims[0] ||
                 count / row_elements > dims[0] - first_row)) {
    throw InputError(fmt::format("dataset '{}': {} values from row {} for a shape of {} elements", name, count,
                                 first_row, elements));
  }
  const Dataspace space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr));
  if (!space.valid()) fail_hdf5(fmt::format("could not create the dataspace of '{}'", name));
  const PropertyList properties = creation_properties(dims, compression);
  Dataset dataset(
      H5Dcreate2(location, key.c_str(), file_type, space.get(), H5P_DEFAULT, properties.get(), H5P_DEFAULT));
  if (!dataset.valid()) fail_hdf5(fmt::format("could not create dataset '{}'", name));
  if (whole) {
    // Deflated chunks are compressed on the threads where the types need no
    // conversion; elsewhere (and in the parallel HDF5) HDF5's pipeline runs.
    const std::vector<hsize_t> chunk = chunk_shape(dims);
    const bool threaded = deflated(chunk, compression) && H5Tequal(file_type, memory_type) > 0;
    const bool written = threaded && detail::write_deflated_chunks(dataset.get(), name, dims, chunk,
                                                                   H5Tget_size(file_type), kDeflateLevel, data);
    if (!written && elements > 0 && H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, transfer, data) < 0) {
      fail_hdf5(fmt::format("could not write dataset '{}'", name));
    }
  } else {
    // This process's rows; one without rows still takes part (collective).
    std::vector<hsize_t> start(dims.size(), 0);
    std::vector<hsize_t> block = dims;
    start[0] = first_row;
    block[0] = count / row_elements;
    const hsize_t memory_count = std::max<hsize_t>(count, 1);
    const Dataspace memory_space(H5Screate_simple(1, &memory_count, nullptr));
    if (!memory_space.valid()) fail_hdf5(fmt::format("could not create the dataspace of '{}'", name));
    const herr_t selected =
        count == 0 ? std::min(H5Sselect_none(space.get()), H5Sselect_none(memory_space.get()))
                   : H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start.data(), nullptr, block.data(), nullptr);
    if (selected < 0 || H5Dwrite(dataset.get(), memory_type, memory_space.get(), space.get(), transfer, data) < 0) {
      fail_hdf5(fmt::format("could not write dataset '{}'", name));
    }
  }
  if (!units.empty()) attach_string(dataset.get(), "units", units);
  // Closing flushes the chunk cache, where the compression runs and can fail.
  if (!dataset.close()) fail_hdf5(fmt::format("could not write dataset '{}'", name));
  const hid_t reopened = H5Oopen(location, key.c_str(), H5P_DEFAULT);
  if (reopened < 0) fail_hdf5(fmt::format("could not reopen dataset '{}'", name));
  return reopened;
}

// The file image: HDF5's core driver without backing store, flushed so that
// the copy has the superblock of a closed file, unlike the raw core buffer.
std::vector<char> build_image(const std::filesystem::path& path, const std::function<void(const Hdf5Node& root)>& fill,
                              const std::function<Hdf5Node(hid_t)>& make_node) {
  PropertyList access(H5Pcreate(H5P_FILE_ACCESS));
  if (!access.valid() || H5Pset_fapl_core(access.get(), kImageIncrement, false) < 0) {
    fail_hdf5("could not set up the in-memory file");
  }
  // The name only identifies the in-memory file; nothing is created on disk.
  const std::string name = path.string() + ".in-memory";
  File file(H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()));
  if (!file.valid()) fail_hdf5("could not create the in-memory file");
  {
    const hid_t root = H5Oopen(file.get(), "/", H5P_DEFAULT);
    if (root < 0) fail_hdf5("could not open the root group");
    const Hdf5Node node = make_node(root);
    fill(node);
  }
  if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0) fail_hdf5("could not flush the in-memory file");
  const ssize_t size = H5Fget_file_image(file.get(), nullptr, 0);
  if (size < 0) fail_hdf5("could not assemble the file image");
  std::vector<char> image(static_cast<std::size_t>(size));
  if (H5Fget_file_image(file.get(), image.data(), image.size()) != size) fail_hdf5("could not copy the file image");
  if (!file.close()) fail_hdf5("could not close the in-memory file");
  return image;
}

}  // namespace

Hdf5Node::Hdf5Node(Hdf5Node&& other) noexcept : id_(std::exchange(other.id_, -1)), transfer_(other.transfer_) {}

Hdf5Node& Hdf5Node::operator=(Hdf5Node&& other) noexcept {
  if (this != &other) {
    if (id_ >= 0) H5Oclose(id_);
    id_ = std::exchange(other.id_, -1);
    transfer_ = other.transfer_;
  }
  return *this;
}

Hdf5Node::~Hdf5Node() {
  if (id_ >= 0) H5Oclose(id_);
}

void Hdf5Node::write_double_attribute(std::string_view name, double value) const {
  attach_scalar(id_, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void Hdf5Node::write_int64_attribute(std::string_view name, std::int64_t value) const {
  attach_scalar(id_, name, H5T_STD_I64LE, H5T_NATIVE_INT64, &value);
}

void Hdf5Node::write_string_attribute(std::string_view name, std::string_view value) const {
  attach_string(id_, name, value);
}

Hdf5Node Hdf5Node::write_dataset(std::string_view name, const std::vector<std::size_t>& shape,
                                 std::span<const double> values, std::string_view units,
                                 Compression compression) const {
  return Hdf5Node(write_array(id_, name, shape, 0, values.size(), H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.data(),
                              units, transfer_, compression),
                  transfer_);
}

Hdf5Node Hdf5Node::write_dataset(std::string_view name, const std::vector<std::size_t>& shape,
                                 std::span<const std::int64_t> values, std::string_view units) const {
  return write_dataset_rows(name, shape, 0, values, units);
}

Hdf5Node Hdf5Node::write_dataset(std::string_view name, const std::vector<std::size_t>& shape,
                                 std::span<const std::uint8_t> values, std::string_view units) const {
  return write_dataset_rows(name, shape, 0, values, units);
}

Hdf5Node Hdf5Node::write_dataset_rows(std::string_view name, const std::vector<std::size_t>& shape,
                                      std::size_t first_row, std::span<const double> values,
                                      std::string_view units) const {
  return Hdf5Node(write_array(id_, name, shape, first_row, values.size(), H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                              values.data(), units, transfer_),
                  transfer_);
}

Hdf5Node Hdf5Node::write_dataset_rows(std::string_view name, const std::vector<std::size_t>& shape,
                                      std::size_t first_row, std::span<const std::uint8_t> values,
                                      std::string_view units) const {
  return Hdf5Node(write_array(id_, name, shape, first_row, values.size(), H5T_STD_U8LE, H5T_NATIVE_UINT8, values.data(),
                              units, transfer_),
                  transfer_);
}

Hdf5Node Hdf5Node::write_dataset_rows(std::string_view name, const std::vector<std::size_t>& shape,
                                      std::size_t first_row, std::span<const std::int64_t> values,
                                      std::string_view units) const {
  return Hdf5Node(write_array(id_, name, shape, first_row, values.size(), H5T_STD_I64LE, H5T_NATIVE_INT64,
                              values.data(), units, transfer_),
                  transfer_);
}

Hdf5Node Hdf5Node::create_dataset(std::string_view name, const std::vector<std::size_t>& shape, std::string_view units,
                                  Compression compression) const {
  const std::string key(name);
  if (shape.size() < 2) throw InputError(fmt::format("dataset '{}': a dataset written in slabs needs rank >= 2", name));
  const std::vector<hsize_t> dims(shape.begin(), shape.end());
  const Dataspace space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr));
  if (!space.valid()) fail_hdf5(fmt::format("could not create the dataspace of '{}'", name));
  const PropertyList properties = creation_properties(dims, compression);
  Hdf5Node dataset(
      H5Dcreate2(id_, key.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, properties.get(), H5P_DEFAULT), transfer_);
  if (dataset.id_ < 0) fail_hdf5(fmt::format("could not create dataset '{}'", name));
  if (!units.empty()) attach_string(dataset.id_, "units", units);
  return dataset;
}

void Hdf5Node::write_slabs(std::size_t first, std::span<const double> values) const {
  const Dataspace file_space(H5Dget_space(id_));
  const std::vector<hsize_t> dims = slab_dims(file_space);
  hsize_t slab = 1;
  for (std::size_t k = 1; k < dims.size(); ++k) slab *= dims[k];
  const hsize_t count = slab > 0 ? values.size() / slab : 0;
  if (count * slab != values.size() || first + count > dims[0]) {
    throw InputError(fmt::format("dataset slabs: {} values from slab {} do not fit a dataset of {} slabs of {} values",
                                 values.size(), first, dims[0], slab));
  }
  if (count == 0) return;
  std::vector<hsize_t> start(dims.size(), 0);
  std::vector<hsize_t> extent = dims;
  start[0] = first;
  extent[0] = count;
  const Dataspace memory_space(H5Screate_simple(static_cast<int>(extent.size()), extent.data(), nullptr));
  if (!memory_space.valid() ||
      H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, extent.data(), nullptr) < 0 ||
      H5Dwrite(id_, H5T_NATIVE_DOUBLE, memory_space.get(), file_space.get(), transfer_, values.data()) < 0) {
    fail_hdf5(fmt::format("could not write slabs {} to {} of a dataset", first, first + count - 1));
  }
}

void Hdf5Node::write_slab_rows(std::size_t slab, std::size_t first_row, std::span<const double> values) const {
  const Dataspace file_space(H5Dget_space(id_));
  const std::vector<hsize_t> dims = slab_dims(file_space);
  hsize_t row = 1;
  for (std::size_t k = 2; k < dims.size(); ++k) row *= dims[k];
  const hsize_t count = values.size() / row;
  if (count * row != values.size() || slab >= dims[0] || first_row + count > dims[1]) {
    throw InputError(
        fmt::format("dataset rows: {} values from row {} of slab {} do not fit a dataset of {} slabs of {} "
                    "rows of {} values",
                    values.size(), first_row, slab, dims[0], dims[1], row));
  }
  // A process without rows still takes part (the write is collective).
  std::vector<hsize_t> start(dims.size(), 0);
  std::vector<hsize_t> extent = dims;
  start[0] = slab;
  start[1] = first_row;
  extent[0] = 1;
  extent[1] = count;
  // The memory space shaped like the selection (HDF5's contiguous fast path);
  // one element, selecting none, for a process without rows.
  std::vector<hsize_t> memory_extent = extent;
  if (count == 0) memory_extent.assign(1, 1);
  const Dataspace memory_space(H5Screate_simple(static_cast<int>(memory_extent.size()), memory_extent.data(), nullptr));
  const herr_t selected = !memory_space.valid() ? -1
                          : count == 0 ? std::min(H5Sselect_none(file_space.get()), H5Sselect_none(memory_space.get()))
                                       : H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr,
                                                             extent.data(), nullptr);
  if (selected < 0 ||
      H5Dwrite(id_, H5T_NATIVE_DOUBLE, memory_space.get(), file_space.get(), transfer_, values.data()) < 0) {
    fail_hdf5(fmt::format("could not write rows {} to {} of slab {} of a dataset", first_row, first_row + count, slab));
  }
}

Hdf5Node Hdf5Node::create_group(std::string_view name) const {
  const std::string key(name);
  const hid_t group = H5Gcreate2(id_, key.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (group < 0) fail_hdf5(fmt::format("could not create group '{}'", name));
  return Hdf5Node(group, transfer_);
}

std::vector<char> hdf5_file_image(const std::filesystem::path& path,
                                  const std::function<void(const Hdf5Node& root)>& fill) {
  check_output_path(path);  // before assembling, which may take a while
  const detail::ErrorPrintingOff quiet;
  try {
    return build_image(path, fill, [](hid_t root) { return Hdf5Node(root); });
  } catch (const FileError& error) {
    throw FileError(fmt::format("cannot write output '{}': {}", path.string(), error.what()));
  }
}

void write_hdf5_file(const std::filesystem::path& path, const std::function<void(const Hdf5Node& root)>& fill) {
  write_output_file(path, hdf5_file_image(path, fill));
}

void fill_hdf5_file(std::int64_t file, std::int64_t transfer, const std::function<void(const Hdf5Node& root)>& fill) {
  const hid_t root = H5Oopen(file, "/", H5P_DEFAULT);
  if (root < 0) fail_hdf5("could not open the root group");
  const Hdf5Node node(root, transfer);
  fill(node);
}

void write_large_hdf5_file(const std::filesystem::path& path, std::uint64_t reserved_bytes,
                           const std::function<void(const Hdf5Node& root)>& fill) {
  OutputTemporary output(path);
  {
    const detail::ErrorPrintingOff quiet;
    try {
      PropertyList access(H5Pcreate(H5P_FILE_ACCESS));
      if (!access.valid() || H5Pset_fapl_sec2(access.get()) < 0) fail_hdf5("could not set up the file access");
      // The empty temporary OutputTemporary created exclusively.
      File file(H5Fcreate(output.temporary().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()));
      if (!file.valid()) fail_hdf5(fmt::format("could not create temporary file '{}'", output.temporary().string()));
      reserve_output_space(path, output.temporary(), reserved_bytes);
      fill_hdf5_file(file.get(), H5P_DEFAULT, fill);
      if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0) fail_hdf5("could not flush the file");
      if (!file.close()) fail_hdf5("could not close the file");
    } catch (const FileError& error) {
      const std::string message = error.what();
      if (message.starts_with("cannot write output")) throw;
      throw FileError(fmt::format("cannot write output '{}': {}", path.string(), message));
    }
  }
  output.commit();
}

std::uint64_t hdf5_dataset_bound(const std::vector<std::size_t>& shape, Compression compression) {
  const std::vector<hsize_t> dims(shape.begin(), shape.end());
  std::uint64_t elements = 1;
  for (const hsize_t d : dims) elements *= d;
  std::uint64_t bytes = 8 * elements + 4096;  // the values; the object header with its attributes
  const std::vector<hsize_t> chunk = chunk_shape(dims);
  if (chunk.empty()) return bytes;
  std::uint64_t chunks = 1;
  for (std::size_t k = 0; k < dims.size(); ++k) chunks *= (dims[k] + chunk[k] - 1) / chunk[k];
  // The v1 B-tree of chunk addresses: nodes of 64 entries of a key (at most
  // 48 bytes at rank 3) and an address, half full after a split, plus the
  // levels above: 160 bytes a chunk bounds it.
  bytes += 160 * chunks + 4096;
  // Deflate's stored blocks on incompressible data: 5 bytes per 64 KiB and
  // a few bytes a chunk.
  if (compression == Compression::deflate) bytes += elements / 1024 + 64 * chunks;
  return bytes;
}

std::vector<std::size_t> field_shape(const Grid& grid) {
  return grid.dimension() == 1 ? std::vector<std::size_t>{grid.nx()} : std::vector<std::size_t>{grid.ny(), grid.nx()};
}

}  // namespace halfspace::io
