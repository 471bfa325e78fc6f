// Reads a height map from an HDF5 file: a rank-1 profile or a rank-2 (ny, nx)
// map of any integer or floating-point storage, converted to float64 by HDF5,
// with the spacing from the root attributes dx and dy.
#include "halfspace/io/hdf5_height_map_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "halfspace/error.hpp"
#include "hdf5_handle.hpp"
#include "hdf5_stored_data.hpp"
#include "hdf5_superblock.hpp"
#include "reader_support.hpp"

namespace halfspace::io {
namespace {

using detail::Attribute;
using detail::Dataspace;
using detail::Datatype;
using detail::File;
using detail::Object;
using detail::PropertyList;

// Enough names to recognise a typo without flooding the message.
constexpr std::size_t kMaxListedDatasets = 10;

// What is being read; every message starts with it so that it can be found
// in a log of a batch run.
struct Target {
  const std::filesystem::path& path;
  const std::string& dataset;

  [[noreturn]] void fail(std::string_view what) const {
    throw FileError(fmt::format("cannot read height map '{}' dataset '{}': {}", path.string(), dataset, what));
  }
};

std::string_view class_name(H5T_class_t type_class) {
  switch (type_class) {
    case H5T_INTEGER:
      return "integer";
    case H5T_FLOAT:
      return "floating-point";
    case H5T_TIME:
      return "time";
    case H5T_STRING:
      return "string";
    case H5T_BITFIELD:
      return "bitfield";
    case H5T_OPAQUE:
      return "opaque";
    case H5T_COMPOUND:
      return "compound";
    case H5T_REFERENCE:
      return "reference";
    case H5T_ENUM:
      return "enum";
    case H5T_VLEN:
      return "variable-length";
    case H5T_ARRAY:
      return "array";
    default:
      return "unknown";
  }
}

bool is_numeric(H5T_class_t type_class) {
  return type_class == H5T_INTEGER || type_class == H5T_FLOAT;
}

// HDF5 identifies HDF5 files by their signature, which may sit after a user
// block, so the check is left to it rather than done on the first bytes.
// A damaged file that HDF5 fails to open can leave HDF5 unable to close
// its internals; printing then stays off (see ErrorPrintingOff::keep_off).
File open_file(const Target& target, detail::ErrorPrintingOff& quiet, hid_t access) {
  std::error_code error;
  const auto status = std::filesystem::status(target.path, error);
  if (!std::filesystem::exists(status)) target.fail("the file does not exist");
  if (std::filesystem::is_directory(status)) target.fail("the path is a directory, not a file");
  // HDF5 reads by seeking: a pipe or device cannot be read, and /dev/zero
  // must not be searched for a signature.
  if (!std::filesystem::is_regular_file(status)) {
    target.fail("the path is not a regular file (a device, pipe or socket); save the data to a file first");
  }

#if H5_VERSION_GE(1, 12, 0)
  const htri_t is_hdf5 = H5Fis_accessible(target.path.c_str(), H5P_DEFAULT);
#else
  const htri_t is_hdf5 = H5Fis_hdf5(target.path.c_str());
#endif
  if (is_hdf5 < 0) {
    quiet.keep_off();
    target.fail(fmt::format("the file cannot be opened: {}", detail::error_reason()));
  }
  if (is_hdf5 == 0) target.fail("the file is not an HDF5 file (no HDF5 signature found)");
  if (const auto problem = detail::hdf5_superblock_problem(target.path)) {
    target.fail(fmt::format("the HDF5 file is damaged: {}", *problem));
  }

  File file(H5Fopen(target.path.c_str(), H5F_ACC_RDONLY, access));
  if (!file.valid()) {
    quiet.keep_off();
    target.fail(fmt::format("the HDF5 file cannot be opened: {}", detail::error_reason()));
  }
  return file;
}

// H5Lexists fails, rather than answering no, when an intermediate group is
// missing, so the path is checked one link at a time.
bool link_exists(hid_t file, const std::string& name) {
  std::string prefix;
  std::size_t begin = 0;
  while (begin <= name.size()) {
    std::size_t end = name.find('/', begin);
    if (end == std::string::npos) end = name.size();
    if (end > begin) {
      prefix += '/';
      prefix.append(name, begin, end - begin);
      if (H5Lexists(file, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
    }
    begin = end + 1;
  }
  return true;
}

// Names of the datasets in the root group, for a "did you mean" hint.
std::string describe_root_datasets(hid_t file) {
  H5G_info_t info;
  if (H5Gget_info(file, &info) < 0) return "the datasets in the file could not be listed";
  std::vector<std::string> names;
  std::size_t count = 0;
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    const ssize_t length = H5Lget_name_by_idx(file, ".", H5_INDEX_NAME, H5_ITER_INC, k, nullptr, 0, H5P_DEFAULT);
    if (length < 0) continue;
    std::string name(static_cast<std::size_t>(length), '\0');
    H5Lget_name_by_idx(file, ".", H5_INDEX_NAME, H5_ITER_INC, k, name.data(), name.size() + 1, H5P_DEFAULT);
    const Object object(H5Oopen(file, name.c_str(), H5P_DEFAULT));
    if (!object.valid() || H5Iget_type(object.get()) != H5I_DATASET) continue;
    if (names.size() < kMaxListedDatasets) names.push_back("'/" + detail::printable(name, 80) + "'");
    ++count;
  }
  if (count == 0) return "the root group holds no datasets";
  std::string text = fmt::format("datasets in the root group: {}", fmt::join(names, ", "));
  if (count > names.size()) text += fmt::format(" and {} more", count - names.size());
  return text;
}

Object open_dataset(hid_t file, const Target& target) {
  if (target.dataset.empty()) target.fail("the dataset name is empty");
  if (!link_exists(file, target.dataset)) {
    target.fail(fmt::format("the dataset does not exist; {}", describe_root_datasets(file)));
  }
  Object object(H5Oopen(file, target.dataset.c_str(), H5P_DEFAULT));
  if (!object.valid()) target.fail(fmt::format("the dataset cannot be opened: {}", detail::error_reason()));
  const H5I_type_t kind = H5Iget_type(object.get());
  if (kind == H5I_GROUP) target.fail("the name refers to a group, not a dataset");
  if (kind != H5I_DATASET) target.fail("the name refers to a named datatype, not a dataset");
  return object;
}

// The heights must be stored in this file (hdf5_stored_data.hpp).
void check_storage(hid_t dataset, const Target& target) {
  if (const auto problem = detail::unstored_data_problem(dataset)) target.fail(*problem);
}

void check_numeric_type(hid_t dataset, const Target& target) {
  const Datatype type(H5Dget_type(dataset));
  if (!type.valid()) target.fail(fmt::format("the datatype cannot be read: {}", detail::error_reason()));
  const H5T_class_t type_class = H5Tget_class(type.get());
  if (!is_numeric(type_class)) {
    target.fail(
        fmt::format("the dataset holds {} data, not numbers; heights must be stored as integers or "
                    "floating-point values",
                    class_name(type_class)));
  }
}

std::string shape_text(const std::vector<hsize_t>& dims) {
  return dims.size() == 1 ? fmt::format("({},)", dims[0]) : fmt::format("({})", fmt::join(dims, ", "));
}

// Returns the dimensions in file order: (n) for a profile, (ny, nx) for a map.
std::vector<hsize_t> read_shape(hid_t dataset, const Target& target) {
  const Dataspace space(H5Dget_space(dataset));
  if (!space.valid()) target.fail(fmt::format("the dataspace cannot be read: {}", detail::error_reason()));
  const H5S_class_t space_class = H5Sget_simple_extent_type(space.get());
  if (space_class == H5S_NULL) target.fail("the dataset is empty (null dataspace)");
  if (space_class == H5S_SCALAR) {
    target.fail(
        "the dataset is a scalar (rank 0); expected rank 1, shape (n,), for a profile or rank 2, "
        "shape (ny, nx), for a map");
  }
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) target.fail(fmt::format("the rank cannot be read: {}", detail::error_reason()));
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  if (rank != 1 && rank != 2) {
    target.fail(
        fmt::format("the dataset has rank {} (shape {}); expected rank 1, shape (n,), for a profile or "
                    "rank 2, shape (ny, nx), for a map",
                    rank, shape_text(dims)));
  }
  const char* axis_names[2][2] = {{"x", ""}, {"y", "x"}};
  for (std::size_t axis = 0; axis < dims.size(); ++axis) {
    if (dims[axis] < 2) {
      target.fail(
          fmt::format("the dataset has shape {}, i.e. {} point(s) along {}; need at least 2 points "
                      "along each axis",
                      shape_text(dims), dims[axis], axis_names[rank - 1][axis]));
    }
  }
  const hsize_t limit = static_cast<hsize_t>(std::numeric_limits<Eigen::Index>::max()) / sizeof(double);
  if (rank == 2 && dims[0] > limit / dims[1]) {
    target.fail(fmt::format("the dataset of shape {} is too large to hold in memory", shape_text(dims)));
  }
  const std::uint64_t points = rank == 2 ? dims[0] * dims[1] : dims[0];
  const std::uint64_t memory = detail::physical_memory_bytes();
  if (points > memory / sizeof(double)) {
    target.fail(
        fmt::format("the dataset of shape {} needs {} for its heights alone, more than the {} of memory "
                    "this machine has",
                    shape_text(dims), detail::byte_size_text(points * sizeof(double)), detail::byte_size_text(memory)));
  }
  return dims;
}

// The rows {first, count} of a dataset a process reads; all of them unless
// it reads a slab.
struct RowSelection {
  bool all = true;
  std::size_t first = 0;
  std::size_t count = 0;
};

// Reads the selected rows of `dataset` (dims in file order) as `memory_type`
// into `buffer` (count * nx values, or all of them).
herr_t read_rows(hid_t dataset, hid_t memory_type, const std::vector<hsize_t>& dims, const RowSelection& rows,
                 hid_t transfer, void* buffer) {
  if (rows.all) return H5Dread(dataset, memory_type, H5S_ALL, H5S_ALL, transfer, buffer);
  const Dataspace file_space(H5Dget_space(dataset));
  const hsize_t start[2] = {rows.first, 0};
  const hsize_t count[2] = {rows.count, dims[1]};
  const hsize_t memory_count = std::max<hsize_t>(rows.count * dims[1], 1);
  const Dataspace memory_space(H5Screate_simple(1, &memory_count, nullptr));
  if (!file_space.valid() || !memory_space.valid()) return -1;
  // A process without rows still takes part in the collective read.
  const herr_t selected =
      rows.count == 0 ? (H5Sselect_none(file_space.get()) < 0 || H5Sselect_none(memory_space.get()) < 0 ? -1 : 0)
                      : H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr);
  if (selected < 0) return -1;
  return H5Dread(dataset, memory_type, memory_space.get(), file_space.get(), transfer, buffer);
}

// Finite heights are a precondition of every solver; one bad pixel (a
// dropout marked NaN by the instrument) must be reported, not propagated.
void check_finite(const Eigen::ArrayXd& heights, std::size_t nx, int dimension, const Target& target) {
  std::size_t count = 0;
  Eigen::Index first = -1;
  for (Eigen::Index k = 0; k < heights.size(); ++k) {
    if (!std::isfinite(heights[k])) {
      if (count == 0) first = k;
      ++count;
    }
  }
  if (count == 0) return;
  const auto index = static_cast<std::size_t>(first);
  const std::string where = dimension == 1 ? fmt::format("index i = {}", index)
                                           : fmt::format("(j, i) = ({}, {}) (row j, column i)", index / nx, index % nx);
  target.fail(fmt::format("{} of {} heights are not finite; the first is at {}: {}", count, heights.size(), where,
                          heights[first]));
}

// A root attribute dx or dy: one number, finite and >= 0; absent means 0,
// "not given", and the caller must supply the spacing.
double read_spacing(hid_t file, const char* name, const Target& target) {
  const htri_t exists = H5Aexists(file, name);
  if (exists < 0) target.fail(fmt::format("root attribute '{}' cannot be checked: {}", name, detail::error_reason()));
  if (exists == 0) return 0.0;

  const Attribute attribute(H5Aopen(file, name, H5P_DEFAULT));
  if (!attribute.valid()) {
    target.fail(fmt::format("root attribute '{}' cannot be opened: {}", name, detail::error_reason()));
  }
  const Dataspace space(H5Aget_space(attribute.get()));
  const hssize_t points = H5Sget_simple_extent_npoints(space.get());
  if (points != 1) target.fail(fmt::format("root attribute '{}' holds {} values; expected one number", name, points));
  const Datatype type(H5Aget_type(attribute.get()));
  const H5T_class_t type_class = H5Tget_class(type.get());
  if (!is_numeric(type_class)) {
    target.fail(
        fmt::format("root attribute '{}' is of {} type; expected a number (metres)", name, class_name(type_class)));
  }
  double value = 0.0;
  if (H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value) < 0) {
    target.fail(fmt::format("root attribute '{}' cannot be read: {}", name, detail::error_reason()));
  }
  if (!std::isfinite(value) || value < 0.0) {
    target.fail(
        fmt::format("root attribute '{}' = {} is invalid: a spacing must be finite and >= 0 m "
                    "(0 means not given)",
                    name, value));
  }
  return value;
}

// The validity mask of the shared height-map layout: a dataset 'valid' next
// to the heights (1 measured, 0 filled in by whoever made the file). Points it
// marks 0 become invalid points of the map, so that the --invalid choice
// (refuse, fill or crop) decides about them rather than the file's own fill;
// their stored heights are kept. A mask that is present but unusable is an
// error: silently ignoring it would hand invented heights to the solver.
void read_validity_mask(hid_t file, const std::vector<hsize_t>& dims, HeightMap& map, const Target& target,
                        const RowSelection& rows, hid_t transfer) {
  const std::size_t slash = target.dataset.find_last_of('/');
  const std::string name = (slash == std::string::npos ? std::string() : target.dataset.substr(0, slash + 1)) + "valid";
  if (name == target.dataset || !link_exists(file, name)) return;
  const Target mask{target.path, name};
  const Object data = open_dataset(file, mask);
  const Datatype type(H5Dget_type(data.get()));
  if (!type.valid() || H5Tget_class(type.get()) != H5T_INTEGER) {
    mask.fail("the validity mask must hold integers (1 measured, 0 invalid)");
  }
  const std::vector<hsize_t> mask_dims = read_shape(data.get(), mask);
  check_storage(data.get(), mask);
  if (mask_dims != dims) {
    mask.fail(fmt::format("the validity mask has shape {}, but the heights '{}' have shape {}", shape_text(mask_dims),
                          target.dataset, shape_text(dims)));
  }
  std::vector<std::uint8_t> flags(static_cast<std::size_t>(map.heights.size()));
  if (read_rows(data.get(), H5T_NATIVE_UINT8, dims, rows, transfer, flags.data()) < 0) {
    mask.fail(fmt::format("the validity mask cannot be read: {}", detail::error_reason()));
  }
  if (std::find(flags.begin(), flags.end(), std::uint8_t{0}) == flags.end()) return;
  if (map.valid.empty()) map.valid.assign(flags.size(), 1);
  for (std::size_t k = 0; k < flags.size(); ++k) {
    if (flags[k] == 0) map.valid[k] = 0;
  }
}

// The reading itself, with HDF5's error printing off: all of the map, or
// (with `reading.rows`) this process's rows.
HeightMapRows read_quietly(const std::filesystem::path& path, const std::string& dataset, NonFiniteHeights non_finite,
                           detail::ErrorPrintingOff& quiet, const Hdf5RowReading& reading) {
  const Target target{path, dataset};
  const File file = open_file(target, quiet, reading.file_access);
  const Object data = open_dataset(file.get(), target);
  check_numeric_type(data.get(), target);
  const std::vector<hsize_t> dims = read_shape(data.get(), target);
  check_storage(data.get(), target);

  HeightMapRows part;
  HeightMap& map = part.map;
  map.dimension = static_cast<int>(dims.size());
  map.nx = static_cast<std::size_t>(dims.back());
  map.ny = map.dimension == 1 ? 1 : static_cast<std::size_t>(dims[0]);
  RowSelection rows;
  if (reading.rows && map.dimension == 2) {
    const auto [first, count] = reading.rows(map.nx, map.ny);
    rows = {false, first, count};
  } else {
    rows = {true, 0, map.ny};
  }
  part.first_row = rows.first;
  part.rows = rows.count;
  map.heights.resize(static_cast<Eigen::Index>(map.nx * rows.count));
  // HDF5 converts integer and float32 storage to double during the read.
  if (read_rows(data.get(), H5T_NATIVE_DOUBLE, dims, rows, reading.transfer, map.heights.data()) < 0) {
    target.fail(fmt::format("the heights cannot be read: {}", detail::error_reason()));
  }
  if (non_finite == NonFiniteHeights::reject) {
    check_finite(map.heights, map.nx, map.dimension, target);
  } else {
    detail::mark_non_finite_invalid(map);
  }
  read_validity_mask(file.get(), dims, map, target, rows, reading.transfer);

  map.dx = read_spacing(file.get(), "dx", target);
  // A profile has no y spacing, whatever the file says.
  map.dy = map.dimension == 2 ? read_spacing(file.get(), "dy", target) : 0.0;
  map.source = path.string() + ":" + dataset;
  return part;
}

}  // namespace

HeightMap read_hdf5_height_map(const std::filesystem::path& path, const std::string& dataset,
                               NonFiniteHeights non_finite) {
  detail::ErrorPrintingOff quiet;
  return read_quietly(path, dataset, non_finite, quiet, {}).map;
}

HeightMapRows read_hdf5_height_map_rows(const std::filesystem::path& path, const std::string& dataset,
                                        const Hdf5RowReading& reading) {
  detail::ErrorPrintingOff quiet;
  return read_quietly(path, dataset, NonFiniteHeights::mark_invalid, quiet, reading);
}

}  // namespace halfspace::io
