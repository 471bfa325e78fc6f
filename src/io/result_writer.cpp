// Writes a solve's fields and summary to HDF5 (layout in docs/file-format.md).
// The file is assembled in memory, written under a temporary name beside the
// target, synced and renamed, so a reader never sees a partial result.
#include "halfspace/io/result_writer.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string_view>
#include <system_error>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/version.hpp"
#include "hdf5_handle.hpp"
#include "hdf5_writing.hpp"

namespace halfspace::io {
namespace {

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
constexpr std::int64_t kFormatVersion = 1;
// Growth step of the in-memory file: few reallocations for large results,
// little waste for small ones.
constexpr std::size_t kImageIncrement = std::size_t{4} << 20;
constexpr const char* kUnits =
    "SI: lengths (dx, dy, approach, height, gap, displacement) in m; pressures and E_star in Pa; "
    "total_force in N (N/m in 1D); solve_seconds in s";

// Internal failures carry only the reason; write_result adds the path.
[[noreturn]] void fail(std::string_view what) {
  throw FileError(std::string(what));
}
[[noreturn]] void fail_hdf5(std::string_view what) {
  throw FileError(fmt::format("{}: {}", what, detail::error_reason()));
}

void check_size(std::string_view field, std::size_t size, const Grid& grid) {
  if (size != grid.size()) {
    throw InputError(fmt::format("write_result: field '{}' has {} values but the grid has {} cells ({})", field, size,
                                 grid.size(), grid.shape_string()));
  }
}

void check_output_directory(const std::filesystem::path& path) {
  const std::string shown = path.string();
  if (path.empty()) throw FileError("cannot write output: the output path is empty");
  if (!path.has_filename()) {
    throw FileError(fmt::format("cannot write output '{}': the path names a directory, not a file", shown));
  }
  const std::filesystem::path parent = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::error_code error;
  const auto status = std::filesystem::status(parent, error);
  if (!std::filesystem::exists(status)) {
    throw FileError(fmt::format("cannot write output '{}': directory '{}' does not exist", shown, parent.string()));
  }
  if (!std::filesystem::is_directory(status)) {
    throw FileError(fmt::format("cannot write output '{}': '{}' is not a directory", shown, parent.string()));
  }
  if (::access(parent.c_str(), W_OK) != 0) {
    throw FileError(fmt::format("cannot write output '{}': directory '{}' is not writable: {}", shown, parent.string(),
                                std::strerror(errno)));
  }
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

void attach_double(hid_t location, const char* name, double value) {
  const Dataspace space(H5Screate(H5S_SCALAR));
  const Attribute attribute(H5Acreate2(location, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT));
  if (!attribute.valid() || H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, &value) < 0) {
    fail_hdf5(fmt::format("could not write attribute '{}'", name));
  }
}

void attach_int64(hid_t location, const char* name, std::int64_t value) {
  const Dataspace space(H5Screate(H5S_SCALAR));
  const Attribute attribute(H5Acreate2(location, name, H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT));
  if (!attribute.valid() || H5Awrite(attribute.get(), H5T_NATIVE_INT64, &value) < 0) {
    fail_hdf5(fmt::format("could not write attribute '{}'", name));
  }
}

// Variable-length UTF-8: the global heap holds the text, so a long config
// does not hit the 64 KiB object-header limit of fixed-length attributes, and
// the empty string needs no special case; h5py reads it as str.
void attach_string(hid_t location, const char* name, std::string_view value) {
  const Datatype type(H5Tcopy(H5T_C_S1));
  if (!type.valid() || H5Tset_size(type.get(), H5T_VARIABLE) < 0 || H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0) {
    fail_hdf5(fmt::format("could not make the string type of attribute '{}'", name));
  }
  const Dataspace space(H5Screate(H5S_SCALAR));
  const Attribute attribute(H5Acreate2(location, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT));
  const std::string text = to_valid_utf8(value);
  const char* data = text.c_str();
  if (!attribute.valid() || H5Awrite(attribute.get(), type.get(), &data) < 0) {
    fail_hdf5(fmt::format("could not write attribute '{}'", name));
  }
}

// The fewest equal pieces of at most `limit` that cover `extent`, so that the
// last chunk is not mostly padding (300 rows in chunks of 150, not 163 + 137).
hsize_t balanced_piece(hsize_t extent, hsize_t limit) {
  const hsize_t pieces = (extent + limit - 1) / limit;
  return (extent + pieces - 1) / pieces;
}

// Chunks of whole rows, at most kChunkElements each: a row is the unit that
// post-processing reads most often, and a whole-field read touches every
// chunk once.
PropertyList creation_properties(const std::vector<hsize_t>& dims) {
  PropertyList properties(H5Pcreate(H5P_DATASET_CREATE));
  if (!properties.valid()) fail_hdf5("could not create dataset properties");
  hsize_t elements = 1;
  for (const hsize_t d : dims) elements *= d;
  if (elements <= kChunkElements) return properties;  // contiguous

  std::vector<hsize_t> chunk(dims.size());
  chunk.back() = balanced_piece(dims.back(), kChunkElements);
  if (dims.size() == 2) chunk[0] = balanced_piece(dims[0], std::max<hsize_t>(1, kChunkElements / chunk.back()));
  if (H5Pset_chunk(properties.get(), static_cast<int>(chunk.size()), chunk.data()) < 0) {
    fail_hdf5("could not set the chunk shape");
  }
  // Deflate is optional in an HDF5 build; without it the file stays valid,
  // only larger.
  if (H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0) {
    if (H5Pset_shuffle(properties.get()) < 0 || H5Pset_deflate(properties.get(), kDeflateLevel) < 0) {
      fail_hdf5("could not set the compression filters");
    }
  }
  return properties;
}

void write_dataset(hid_t file, const char* name, const std::vector<hsize_t>& dims, hid_t file_type, hid_t memory_type,
                   const void* data, const char* units) {
  const Dataspace space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr));
  if (!space.valid()) fail_hdf5(fmt::format("could not create the dataspace of '{}'", name));
  const PropertyList properties = creation_properties(dims);
  Dataset dataset(H5Dcreate2(file, name, file_type, space.get(), H5P_DEFAULT, properties.get(), H5P_DEFAULT));
  if (!dataset.valid()) fail_hdf5(fmt::format("could not create dataset '{}'", name));
  const bool empty = std::any_of(dims.begin(), dims.end(), [](hsize_t d) { return d == 0; });
  if (!empty && H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0) {
    fail_hdf5(fmt::format("could not write dataset '{}'", name));
  }
  if (units != nullptr) attach_string(dataset.get(), "units", units);
  // Closing flushes the chunk cache, where the compression runs and can fail.
  if (!dataset.close()) fail_hdf5(fmt::format("could not write dataset '{}'", name));
}

void write_fields(hid_t file, const Grid& grid, std::span<const double> height, const SolveResult& result) {
  const std::vector<hsize_t> shape =
      grid.dimension() == 1 ? std::vector<hsize_t>{grid.nx()} : std::vector<hsize_t>{grid.ny(), grid.nx()};
  write_dataset(file, "/height", shape, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, height.data(), "m");
  write_dataset(file, "/pressure", shape, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, result.pressure.data(), "Pa");
  write_dataset(file, "/gap", shape, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, result.gap.data(), "m");
  write_dataset(file, "/displacement", shape, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, result.displacement.data(), "m");

  std::vector<std::uint8_t> contact(grid.size());
  for (std::size_t k = 0; k < contact.size(); ++k) {
    contact[k] = result.pressure[static_cast<Eigen::Index>(k)] > 0.0 ? 1 : 0;
  }
  write_dataset(file, "/contact", shape, H5T_STD_U8LE, H5T_NATIVE_UINT8, contact.data(), "1");

  const std::vector<hsize_t> history{result.residual_history.size()};
  write_dataset(file, "/residual_history", history, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, result.residual_history.data(),
                nullptr);
}

// The surface and contact statistics, when the caller computed them.
void write_statistics(hid_t root, const ResultMetadata& metadata) {
  if (const auto& s = metadata.contact_statistics) {
    attach_double(root, "mean_gap", s->mean_gap);
    attach_double(root, "rms_gap", s->rms_gap);
    attach_double(root, "free_volume", s->free_volume);
    attach_int64(root, "clusters", s->clusters());
  }
  if (const auto& s = metadata.surface_statistics) {
    attach_double(root, "surface_rms_height", s->rms_height);
    attach_double(root, "surface_rms_slope", s->rms_slope);
  }
}

void write_summary(hid_t root, const Grid& grid, const SolveResult& result, const ResultMetadata& metadata) {
  attach_string(root, "format", "halfspace-result");
  attach_int64(root, "format_version", kFormatVersion);
  attach_string(root, "units", kUnits);

  attach_int64(root, "dimension", grid.dimension());
  attach_int64(root, "nx", static_cast<std::int64_t>(grid.nx()));
  attach_int64(root, "ny", static_cast<std::int64_t>(grid.ny()));
  attach_double(root, "dx", grid.dx());
  attach_double(root, "dy", grid.dimension() == 1 ? 0.0 : grid.dy());
  attach_string(root, "boundary", to_string(grid.boundary()));
  attach_double(root, "E_star", metadata.e_star);
  attach_string(root, "load_mode", metadata.load_mode);

  attach_double(root, "total_force", result.total_force);
  attach_double(root, "mean_pressure", result.mean_pressure);
  attach_double(root, "approach", result.approach);
  attach_double(root, "contact_fraction", result.contact_fraction);
  attach_double(root, "max_pressure", result.max_pressure);

  attach_string(root, "solver", result.solver);
  attach_string(root, "status", to_string(result.status));
  attach_string(root, "message", result.message);
  attach_int64(root, "converged", result.converged() ? 1 : 0);
  attach_int64(root, "iterations", result.iterations);
  attach_int64(root, "operator_applications", result.operator_applications);
  attach_int64(root, "preconditioner_applications", result.preconditioner_applications);
  attach_int64(root, "coarse_levels", result.coarse.levels);
  attach_int64(root, "coarse_iterations", result.coarse.iterations);
  attach_double(root, "coarse_operator_work", result.coarse.operator_work);
  attach_double(root, "coarse_preconditioner_work", result.coarse.preconditioner_work);
  attach_int64(root, "deflation_block", static_cast<std::int64_t>(result.deflation.block));
  attach_int64(root, "deflated_iterations", result.deflation.deflated_iterations);
  attach_int64(root, "deflation_declined", result.deflation.declined);
  attach_double(root, "undeflated_rate", result.deflation.fast_rate);
  attach_double(root, "residual", result.residual);
  attach_double(root, "tolerance", result.tolerance);
  attach_double(root, "solve_seconds", result.wall_seconds);
  attach_int64(root, "threads", metadata.threads);

  attach_string(root, "halfspace_version", fmt::format("{} ({})", kVersion, kGitHash));
  attach_string(root, "command_line", metadata.command_line);
  attach_string(root, "config", metadata.config);
  attach_string(root, "height_source", metadata.height_source);
  attach_string(root, "preparation", metadata.preparation);
  write_statistics(root, metadata);
}

// The file is assembled in memory (HDF5's core driver without backing store)
// and written to disk by us. HDF5 1.10 cannot recover from an I/O error while
// closing a file on disk, which is exactly where a full disk shows up: the
// failed close leaves a dangling file ID and the library crashes at exit
// (HDFGroup/hdf5 pull request 2291). In memory HDF5 never meets an I/O error,
// and ours are reported like any other. The price is about twice the file's
// size in memory while writing (HDF5's buffer and the image).
std::vector<char> build_image(const std::filesystem::path& name, const std::function<void(hid_t file)>& fill) {
  PropertyList access(H5Pcreate(H5P_FILE_ACCESS));
  if (!access.valid() || H5Pset_fapl_core(access.get(), kImageIncrement, false) < 0) {
    fail_hdf5("could not set up the in-memory file");
  }
  // The name only identifies the in-memory file; nothing is created on disk.
  File file(H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()));
  if (!file.valid()) fail_hdf5("could not create the in-memory file");
  fill(file.get());

  // H5Fget_file_image copies what the driver holds, so the metadata cache
  // must be flushed into it first; the copy has the superblock of a closed
  // file, unlike the raw core buffer.
  if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0) fail_hdf5("could not flush the in-memory file");
  const ssize_t size = H5Fget_file_image(file.get(), nullptr, 0);
  if (size < 0) fail_hdf5("could not assemble the file image");
  std::vector<char> image(static_cast<std::size_t>(size));
  if (H5Fget_file_image(file.get(), image.data(), image.size()) != size) fail_hdf5("could not copy the file image");
  if (!file.close()) fail_hdf5("could not close the in-memory file");
  return image;
}

// Creates the temporary file exclusively, so that nothing already there (a
// symlink planted in a shared directory, another writer's file) is followed
// or clobbered, writes the image and syncs it: without fsync a crash soon
// after the rename can leave an empty file under the final name (delayed
// allocation). The directory entry is not synced: a crash may lose the
// rename, and so the new result, but never yields a partial file. On failure
// the file is removed.
void write_image(const std::filesystem::path& file_path, const std::vector<char>& image) {
  const int descriptor = ::open(file_path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (descriptor < 0 && errno == EEXIST) {
    fail(fmt::format("temporary file '{}' already exists (left by an interrupted run?); remove it and retry",
                     file_path.string()));
  }
  if (descriptor < 0) {
    fail(fmt::format("could not create temporary file '{}': {}", file_path.string(), std::strerror(errno)));
  }
  int error = 0;
  const char* data = image.data();
  std::size_t left = image.size();
  while (left > 0 && error == 0) {
    const ssize_t written = ::write(descriptor, data, left);  // may write less than asked
    if (written < 0) {
      if (errno != EINTR) error = errno;
      continue;
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  // EINVAL: the file system cannot sync (some FUSE mounts); nothing to report.
  if (error == 0 && ::fsync(descriptor) != 0 && errno != EINVAL) error = errno;
  // Network file systems may report a failed write only at close.
  if (::close(descriptor) != 0 && error == 0 && errno != EINTR) error = errno;
  if (error != 0) {
    ::unlink(file_path.c_str());
    fail(fmt::format("could not write temporary file '{}': {}", file_path.string(), std::strerror(error)));
  }
}

}  // namespace

// The conventions above, for the other writers (hdf5_writing.hpp).
namespace detail {

void write_double_attribute(hid_t location, const char* name, double value) {
  attach_double(location, name, value);
}
void write_int64_attribute(hid_t location, const char* name, std::int64_t value) {
  attach_int64(location, name, value);
}
void write_string_attribute(hid_t location, const char* name, std::string_view value) {
  attach_string(location, name, value);
}
void write_array_dataset(hid_t location, const char* name, const std::vector<hsize_t>& dims, hid_t file_type,
                         hid_t memory_type, const void* data, const char* units) {
  write_dataset(location, name, dims, file_type, memory_type, data, units);
}
void write_result_attributes(hid_t root, const Grid& grid, const SolveResult& result, const ResultMetadata& metadata) {
  write_summary(root, grid, result, metadata);
}

void write_bytes_atomically(const std::filesystem::path& path, const std::vector<char>& bytes) {
  check_output_directory(path);
  std::filesystem::path temporary = path;
  temporary += fmt::format(".tmp-{}", ::getpid());
  try {
    write_image(temporary, bytes);
  } catch (const FileError& error) {
    throw FileError(fmt::format("cannot write output '{}': {}", path.string(), error.what()));
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw FileError(fmt::format("cannot write output '{}': could not rename temporary file '{}' onto it: {}",
                                path.string(), temporary.string(), error.message()));
  }
}

void write_file_atomically(const std::filesystem::path& path, const std::function<void(hid_t file)>& fill) {
  check_output_directory(path);  // before assembling, which may take a while
  const ErrorPrintingOff quiet;
  std::filesystem::path name = path;
  name += fmt::format(".tmp-{}", ::getpid());
  std::vector<char> image;
  try {
    image = build_image(name, fill);
  } catch (const FileError& error) {
    throw FileError(fmt::format("cannot write output '{}': {}", path.string(), error.what()));
  }
  write_bytes_atomically(path, image);
}

}  // namespace detail

void write_result(const std::filesystem::path& path, const Grid& grid, std::span<const double> height,
                  const SolveResult& result, const ResultMetadata& metadata) {
  check_size("height", height.size(), grid);
  check_size("pressure", static_cast<std::size_t>(result.pressure.size()), grid);
  check_size("gap", static_cast<std::size_t>(result.gap.size()), grid);
  check_size("displacement", static_cast<std::size_t>(result.displacement.size()), grid);
  detail::write_file_atomically(path, [&](hid_t file) {
    write_fields(file, grid, height, result);
    write_summary(file, grid, result, metadata);
  });
}

}  // namespace halfspace::io
