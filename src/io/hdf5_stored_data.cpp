#include "hdf5_stored_data.hpp"

#include <fmt/format.h>

#include "hdf5_handle.hpp"

namespace halfspace::io::detail {

std::optional<std::string> unstored_data_problem(hid_t dataset) {
  const PropertyList creation(H5Dget_create_plist(dataset));
  if (!creation.valid()) return fmt::format("the dataset's layout cannot be read: {}", error_reason());
  if (H5Pget_layout(creation.get()) == H5D_VIRTUAL) {
    return "the dataset is virtual (its data are in other files); store the data in this file";
  }
  if (H5Pget_external_count(creation.get()) != 0) {
    return "the dataset's data are in external files; store the data in this file";
  }
  if (H5Dget_storage_size(dataset) == 0) return "the dataset holds no stored data (it was created but never written)";
  return std::nullopt;
}

}  // namespace halfspace::io::detail
