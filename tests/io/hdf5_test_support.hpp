// Helpers for the io tests: a scratch directory, and small HDF5 C API calls to
// build input files and inspect output files independently of src/io.
#pragma once

#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace halfspace::test {

// A fresh directory under the system temp directory, removed with its contents.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("halfspace-io-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

  // Names of the entries in the directory, sorted.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(path_)) names.push_back(entry.path().filename());
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  std::filesystem::path path_;
};

// Owns an hid_t; throws when the call that produced it failed, so a broken
// helper shows up as a test error with the call named.
class H5 {
 public:
  H5(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close) {
    if (id_ < 0) throw std::runtime_error("HDF5 call failed in test helper: " + what);
  }
  H5(const H5&) = delete;
  H5& operator=(const H5&) = delete;
  ~H5() { close_(id_); }
  hid_t get() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

inline void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5 call failed in test helper: " + what);
}

inline H5 create_file(const std::filesystem::path& path) {
  return H5(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, "create " + path.string());
}

inline H5 open_file(const std::filesystem::path& path) {
  return H5(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open " + path.string());
}

// A dataset of `dims` (empty dims: scalar) stored as `file_type`, written from
// `data` in `memory_type`.
inline void add_dataset(hid_t location, const std::string& name, const std::vector<hsize_t>& dims, hid_t file_type,
                        hid_t memory_type, const void* data) {
  const H5 space(
      dims.empty() ? H5Screate(H5S_SCALAR) : H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
      H5Sclose, "dataspace of " + name);
  const H5 dataset(H5Dcreate2(location, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   H5Dclose, "create dataset " + name);
  check(H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write dataset " + name);
}

inline void add_double_dataset(hid_t location, const std::string& name, const std::vector<hsize_t>& dims,
                               const std::vector<double>& values) {
  add_dataset(location, name, dims, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.data());
}

inline void add_double_attribute(hid_t location, const std::string& name, double value) {
  const H5 space(H5Screate(H5S_SCALAR), H5Sclose, "scalar dataspace");
  const H5 attribute(H5Acreate2(location, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                     H5Aclose, "create attribute " + name);
  check(H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, &value), "write attribute " + name);
}

// Fixed-length ASCII, as in the measured topography files.
inline void add_string_attribute(hid_t location, const std::string& name, const std::string& value) {
  const H5 type(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  check(H5Tset_size(type.get(), value.size()), "string size");
  const H5 space(H5Screate(H5S_SCALAR), H5Sclose, "scalar dataspace");
  const H5 attribute(H5Acreate2(location, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                     "create attribute " + name);
  check(H5Awrite(attribute.get(), type.get(), value.data()), "write attribute " + name);
}

inline std::vector<hsize_t> dataset_shape(hid_t file, const std::string& name) {
  const H5 dataset(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + name);
  const H5 space(H5Dget_space(dataset.get()), H5Sclose, "dataspace of " + name);
  std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space.get())));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return dims;
}

// The stored type's class, size and byte order, for checks of the on-disk
// format rather than of what a conversion would give.
struct StoredType {
  H5T_class_t type_class;
  std::size_t size;
  H5T_order_t order;
  H5T_sign_t sign;  // integers only
};

inline StoredType dataset_type(hid_t file, const std::string& name) {
  const H5 dataset(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + name);
  const H5 type(H5Dget_type(dataset.get()), H5Tclose, "type of " + name);
  const H5T_class_t type_class = H5Tget_class(type.get());
  return {type_class, H5Tget_size(type.get()), H5Tget_order(type.get()),
          type_class == H5T_INTEGER ? H5Tget_sign(type.get()) : H5T_SGN_ERROR};
}

template <typename T>
std::vector<T> read_dataset(hid_t file, const std::string& name, hid_t memory_type) {
  const H5 dataset(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + name);
  const H5 space(H5Dget_space(dataset.get()), H5Sclose, "dataspace of " + name);
  std::vector<T> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get())));
  if (!values.empty()) {
    check(H5Dread(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "read " + name);
  }
  return values;
}

inline StoredType attribute_type(hid_t location, const std::string& name) {
  const H5 attribute(H5Aopen(location, name.c_str(), H5P_DEFAULT), H5Aclose, "open attribute " + name);
  const H5 type(H5Aget_type(attribute.get()), H5Tclose, "type of attribute " + name);
  const H5T_class_t type_class = H5Tget_class(type.get());
  return {type_class, H5Tget_size(type.get()), H5Tget_order(type.get()),
          type_class == H5T_INTEGER ? H5Tget_sign(type.get()) : H5T_SGN_ERROR};
}

inline double read_double_attribute(hid_t location, const std::string& name) {
  const H5 attribute(H5Aopen(location, name.c_str(), H5P_DEFAULT), H5Aclose, "open attribute " + name);
  double value = 0.0;
  check(H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value), "read attribute " + name);
  return value;
}

inline std::int64_t read_int64_attribute(hid_t location, const std::string& name) {
  const H5 attribute(H5Aopen(location, name.c_str(), H5P_DEFAULT), H5Aclose, "open attribute " + name);
  std::int64_t value = 0;
  check(H5Aread(attribute.get(), H5T_NATIVE_INT64, &value), "read attribute " + name);
  return value;
}

// Reads a variable-length string attribute; throws if it is stored otherwise,
// since variable-length UTF-8 is the documented format.
inline std::string read_string_attribute(hid_t location, const std::string& name) {
  const H5 attribute(H5Aopen(location, name.c_str(), H5P_DEFAULT), H5Aclose, "open attribute " + name);
  const H5 type(H5Aget_type(attribute.get()), H5Tclose, "type of attribute " + name);
  if (H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get()) <= 0 ||
      H5Tget_cset(type.get()) != H5T_CSET_UTF8) {
    throw std::runtime_error("attribute " + name + " is not a variable-length UTF-8 string");
  }
  char* data = nullptr;
  check(H5Aread(attribute.get(), type.get(), &data), "read attribute " + name);
  std::string value = data != nullptr ? data : "";
  H5free_memory(data);
  return value;
}

}  // namespace halfspace::test
