// Reads result files with the HDF5 C API: datasets converted to float64
// (uint8, int64) by HDF5, attributes by their stored class.
#include "halfspace/io/result_reader.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string_view>

#include "halfspace/checked_size.hpp"
#include "halfspace/error.hpp"
#include "hdf5_handle.hpp"
#include "hdf5_stored_data.hpp"
#include "hdf5_superblock.hpp"
#include "reader_support.hpp"
#include "step_group_name.hpp"

namespace halfspace::io {
namespace {

using detail::Attribute;
using detail::Dataset;
using detail::Dataspace;
using detail::Datatype;
using detail::File;
using detail::Object;

struct Reader {
  const std::filesystem::path& path;

  [[noreturn]] void fail(std::string_view what) const {
    throw FileError(fmt::format("cannot read result '{}': {}", path.string(), what));
  }

  bool exists(hid_t location, const std::string& name) const {
    return H5Lexists(location, name.c_str(), H5P_DEFAULT) > 0;
  }

  // The dataset's extents; fails unless it exists.
  std::vector<std::size_t> extents(const Dataset& dataset, const std::string& name) const {
    const Dataspace space(H5Dget_space(dataset.get()));
    const int rank = space.valid() ? H5Sget_simple_extent_ndims(space.get()) : -1;
    if (rank < 0 || rank > 2) fail(fmt::format("dataset '{}' has rank {}, expected 1 or 2", name, rank));
    hsize_t dims[2] = {0, 0};
    H5Sget_simple_extent_dims(space.get(), dims, nullptr);
    return {dims, dims + rank};
  }

  template <class T>
  std::vector<T> read(hid_t location, const std::string& name, hid_t memory_type,
                      std::vector<std::size_t>* shape = nullptr) const {
    const Dataset dataset(H5Dopen2(location, name.c_str(), H5P_DEFAULT));
    if (!dataset.valid()) fail(fmt::format("no dataset '{}'", name));
    const std::vector<std::size_t> dims = extents(dataset, name);
    // A hostile file may declare any shape: the count must not overflow, fit
    // the machine's memory, and come from data stored in this file.
    std::size_t count = 1;
    for (std::size_t d : dims) {
      const std::optional<std::size_t> product = checked_multiply(count, d);
      if (!product) fail(fmt::format("dataset '{}' declares a shape whose size overflows", name));
      count = *product;
    }
    if (count > detail::physical_memory_bytes() / sizeof(T)) {
      fail(fmt::format("dataset '{}' declares {} values, more than this machine's memory holds", name, count));
    }
    if (count > 0) {
      if (const auto problem = detail::unstored_data_problem(dataset.get())) {
        fail(fmt::format("dataset '{}': {}", name, *problem));
      }
    }
    if (shape) *shape = dims;
    std::vector<T> values(count);
    if (count > 0 && H5Dread(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
      fail(fmt::format("dataset '{}' cannot be read: {}", name, detail::error_reason()));
    }
    return values;
  }

  Eigen::ArrayXd field(hid_t location, const std::string& name, const std::vector<std::size_t>& shape) const {
    std::vector<std::size_t> dims;
    const std::vector<double> values = read<double>(location, name, H5T_NATIVE_DOUBLE, &dims);
    if (dims != shape) fail(fmt::format("dataset '{}' does not have the shape of /height", name));
    return Eigen::Map<const Eigen::ArrayXd>(values.data(), static_cast<Eigen::Index>(values.size()));
  }
};

constexpr std::size_t kMaxAttributeText = std::size_t{1} << 20;  // 1 MiB

AttributeValue attribute_value(hid_t id, bool& readable) {
  readable = false;
  const Datatype type(H5Aget_type(id));
  switch (H5Tget_class(type.get())) {
    case H5T_FLOAT: {
      double number = 0.0;
      readable = H5Aread(id, H5T_NATIVE_DOUBLE, &number) >= 0;
      return number;
    }
    case H5T_INTEGER: {
      std::int64_t number = 0;
      readable = H5Aread(id, H5T_NATIVE_INT64, &number) >= 0;
      return number;
    }
    case H5T_STRING: {
      if (H5Tis_variable_str(type.get()) > 0) {
        char* text = nullptr;
        if (H5Aread(id, type.get(), &text) < 0) return std::string();
        std::string value(text ? text : "");
        const Dataspace space(H5Aget_space(id));
        H5Dvlen_reclaim(type.get(), space.get(), H5P_DEFAULT, &text);
        readable = true;
        return value;
      }
      // A fixed-length string's declared size, not trusted beyond what a
      // result's attributes (names, versions, command lines) need.
      const std::size_t size = H5Tget_size(type.get());
      if (size == 0 || size > kMaxAttributeText) return std::string();
      std::string text(size, '\0');
      readable = H5Aread(id, type.get(), text.data()) >= 0;
      text.erase(std::find(text.begin(), text.end(), '\0'), text.end());
      return text;
    }
    default:
      return std::string();
  }
}

// Appends (or replaces) every numeric and string attribute of `object`, in
// creation order where the file tracks it, by name otherwise.
void read_attributes(hid_t object, std::vector<std::pair<std::string, AttributeValue>>& out) {
  const auto visit = [](hid_t location, const char* name, const H5A_info_t*, void* data) -> herr_t {
    auto& list = *static_cast<std::vector<std::pair<std::string, AttributeValue>>*>(data);
    const Attribute attribute(H5Aopen(location, name, H5P_DEFAULT));
    if (!attribute.valid()) return 0;
    bool readable = false;
    AttributeValue value = attribute_value(attribute.get(), readable);
    if (!readable) return 0;
    const auto same = [&](const auto& entry) { return entry.first == name; };
    if (const auto found = std::find_if(list.begin(), list.end(), same); found != list.end()) {
      found->second = std::move(value);
    } else {
      list.emplace_back(name, std::move(value));
    }
    return 0;
  };
  hsize_t index = 0;
  if (H5Aiterate2(object, H5_INDEX_CRT_ORDER, H5_ITER_INC, &index, visit, &out) < 0) {
    index = 0;
    H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, &index, visit, &out);
  }
}

}  // namespace

const AttributeValue* StoredResult::find(const std::string& name) const {
  for (const auto& [key, value] : attributes) {
    if (key == name) return &value;
  }
  return nullptr;
}

StoredResult read_result(const std::filesystem::path& path, int step) {
  const Reader reader{path};
  detail::ErrorPrintingOff quiet;
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) reader.fail("no such file");
#if H5_VERSION_GE(1, 12, 0)
  const htri_t is_hdf5 = H5Fis_accessible(path.c_str(), H5P_DEFAULT);
#else
  const htri_t is_hdf5 = H5Fis_hdf5(path.c_str());
#endif
  if (is_hdf5 <= 0) reader.fail("not an HDF5 file");
  if (const auto problem = detail::hdf5_superblock_problem(path)) {
    reader.fail(fmt::format("the HDF5 file is damaged: {}", *problem));
  }
  const File file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!file.valid()) reader.fail(detail::error_reason());

  StoredResult stored;
  read_attributes(file.get(), stored.attributes);
  const AttributeValue* format = stored.find("format");
  if (!format || !std::holds_alternative<std::string>(*format) ||
      std::get<std::string>(*format) != "halfspace-result") {
    reader.fail("not a halfspace result (no root attribute format = 'halfspace-result')");
  }
  std::vector<std::size_t> shape;
  const std::vector<double> height = reader.read<double>(file.get(), "height", H5T_NATIVE_DOUBLE, &shape);
  stored.height = Eigen::Map<const Eigen::ArrayXd>(height.data(), static_cast<Eigen::Index>(height.size()));
  stored.shape = shape;

  if (reader.exists(file.get(), "steps")) {
    const Object steps(H5Oopen(file.get(), "steps", H5P_DEFAULT));
    H5G_info_t info;
    if (!steps.valid() || H5Gget_info(steps.get(), &info) < 0) reader.fail("group /steps cannot be read");
    stored.steps = static_cast<int>(info.nlinks);
    const int chosen = step < 0 ? stored.steps - 1 : step;
    if (chosen < 0 || chosen >= stored.steps) {
      reader.fail(fmt::format("step {} is out of range: the sweep has steps 0 to {}", step, stored.steps - 1));
    }
    stored.group =
        "/steps/" + step_group_name(static_cast<std::size_t>(chosen), static_cast<std::size_t>(stored.steps));
  } else if (step >= 0) {
    reader.fail(fmt::format("step {} was asked for, but the file holds a single result", step));
  }
  const Object group(H5Oopen(file.get(), stored.group.c_str(), H5P_DEFAULT));
  if (!group.valid()) reader.fail(fmt::format("no group '{}'", stored.group));
  if (stored.group != "/") read_attributes(group.get(), stored.attributes);
  stored.pressure = reader.field(group.get(), "pressure", shape);
  stored.gap = reader.field(group.get(), "gap", shape);
  stored.displacement = reader.field(group.get(), "displacement", shape);
  std::vector<std::size_t> contact_shape;
  stored.contact = reader.read<std::uint8_t>(group.get(), "contact", H5T_NATIVE_UINT8, &contact_shape);
  if (contact_shape != shape) reader.fail("dataset 'contact' does not have the shape of /height");
  stored.residual_history = reader.read<double>(group.get(), "residual_history", H5T_NATIVE_DOUBLE);
  if (reader.exists(group.get(), "cluster_sizes")) {
    stored.cluster_sizes = reader.read<std::int64_t>(group.get(), "cluster_sizes", H5T_NATIVE_INT64);
  }
  // Friction: all of the step's fields or none of them.
  if (reader.exists(group.get(), "shear_x")) {
    stored.shear_x = reader.field(group.get(), "shear_x", shape);
    stored.shear_y = reader.field(group.get(), "shear_y", shape);
    stored.slip_x = reader.field(group.get(), "slip_x", shape);
    stored.slip_y = reader.field(group.get(), "slip_y", shape);
    stored.tangential_displacement_x = reader.field(group.get(), "tangential_displacement_x", shape);
    stored.tangential_displacement_y = reader.field(group.get(), "tangential_displacement_y", shape);
    std::vector<std::size_t> stick_shape;
    stored.stick = reader.read<std::uint8_t>(group.get(), "stick", H5T_NATIVE_UINT8, &stick_shape);
    if (stick_shape != shape) reader.fail("dataset 'stick' does not have the shape of /height");
  }
  return stored;
}

}  // namespace halfspace::io
