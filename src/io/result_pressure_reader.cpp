// The pressure and grid of a result file: the field through the HDF5 height
// map reader (which checks rank, type, size and finiteness), the boundary
// from its root attribute.
#include "halfspace/io/result_pressure_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <hdf5.h>

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "halfspace/error.hpp"
#include "halfspace/io/hdf5_height_map_reader.hpp"
#include "hdf5_handle.hpp"

namespace halfspace::io {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw FileError(fmt::format("cannot read result file '{}': {}", path.string(), what));
}

// A root string attribute holding one value (a scalar or a single-element
// array), or nullopt if the file has none.
std::optional<std::string> read_root_string(const std::filesystem::path& path, const char* name) {
  const detail::ErrorPrintingOff quiet;
  const detail::File file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!file.valid()) fail(path, "it cannot be opened as HDF5");
  if (H5Aexists(file.get(), name) <= 0) return std::nullopt;
  const detail::Attribute attribute(H5Aopen(file.get(), name, H5P_DEFAULT));
  const detail::Datatype type(H5Aget_type(attribute.get()));
  if (!attribute.valid() || !type.valid() || H5Tget_class(type.get()) != H5T_STRING) {
    fail(path, fmt::format("its root attribute '{}' is not a string", name));
  }
  const detail::Dataspace space(H5Aget_space(attribute.get()));
  const hssize_t points = space.valid() ? H5Sget_simple_extent_npoints(space.get()) : -1;
  if (points != 1) {
    fail(path, fmt::format("its root attribute '{}' holds {} values; expected one string", name, points));
  }
  std::string value;
  if (H5Tis_variable_str(type.get()) > 0) {
    const detail::Datatype memory(H5Tcopy(H5T_C_S1));
    H5Tset_size(memory.get(), H5T_VARIABLE);
    H5Tset_cset(memory.get(), H5Tget_cset(type.get()));
    char* text = nullptr;
    if (H5Aread(attribute.get(), memory.get(), &text) < 0 || text == nullptr) {
      fail(path, fmt::format("its root attribute '{}' cannot be read", name));
    }
    value = text;
    H5free_memory(text);
  } else {
    const std::size_t size = H5Tget_size(type.get());
    if (size == 0 || size > 64) fail(path, fmt::format("its root attribute '{}' is longer than 64 characters", name));
    std::string buffer(size, '\0');
    if (H5Aread(attribute.get(), type.get(), buffer.data()) < 0) {
      fail(path, fmt::format("its root attribute '{}' cannot be read", name));
    }
    value = buffer.substr(0, buffer.find('\0'));
  }
  return value;
}

std::string read_boundary(const std::filesystem::path& path) {
  const std::optional<std::string> boundary = read_root_string(path, "boundary");
  if (!boundary) {
    fail(path, "it has no root attribute 'boundary' (periodic or free): is it a halfspace result file?");
  }
  return *boundary;
}

// Only a result of `halfspace solve` (format = 'halfspace-result') holds the
// contact pressure; a stress file also has a /pressure, but is an output.
void require_result_kind(const std::filesystem::path& path) {
  const std::optional<std::string> format = read_root_string(path, "format");
  if (!format)
    fail(path, "it has no root attribute 'format': a result of `halfspace solve` has format = 'halfspace-result'");
  if (*format != "halfspace-result") {
    fail(path, fmt::format("its root attribute format = '{}' is not 'halfspace-result': pass a result of `halfspace "
                           "solve` (or one step of a sweep's)",
                           *format));
  }
}

// Root attributes that come all together or not at all (a coating's five,
// both bodies' four): their values, or none.
std::optional<std::vector<double>> read_attribute_set(const std::filesystem::path& path,
                                                      std::span<const char* const> names, std::string_view what) {
  const detail::ErrorPrintingOff quiet;
  const detail::File file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!file.valid()) fail(path, "it cannot be opened as HDF5");
  std::vector<double> values(names.size());
  std::size_t found = 0;
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (H5Aexists(file.get(), names[k]) <= 0) continue;
    const detail::Attribute attribute(H5Aopen(file.get(), names[k], H5P_DEFAULT));
    if (!attribute.valid() || H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &values[k]) < 0) {
      fail(path, fmt::format("its root attribute '{}' cannot be read as a number", names[k]));
    }
    ++found;
  }
  if (found == 0) return std::nullopt;
  if (found != names.size()) {
    fail(path, fmt::format("it has some but not all of {} attributes ({})", what, fmt::join(names, ", ")));
  }
  return values;
}

// The coating's five root attributes (result_attributes.hpp), if the result
// is of a coated half-space.
std::optional<LayeredMaterial> read_coating(const std::filesystem::path& path) {
  constexpr std::array<const char*, 5> kNames{"layer_thickness", "layer_E", "layer_nu", "substrate_E", "substrate_nu"};
  const std::optional<std::vector<double>> v = read_attribute_set(path, kNames, "the coating's");
  if (!v) return std::nullopt;
  LayeredMaterial coating{(*v)[0], {(*v)[1], (*v)[2]}, {(*v)[3], (*v)[4]}};
  try {
    validated(coating);
  } catch (const InputError& error) {
    fail(path, fmt::format("its coating attributes are invalid ({})", error.what()));
  }
  return coating;
}

// Both bodies' four root attributes (result_attributes.hpp), if recorded.
std::optional<std::array<ElasticBody, 2>> read_bodies(const std::filesystem::path& path) {
  constexpr std::array<const char*, 4> kNames{"body1_E", "body1_nu", "body2_E", "body2_nu"};
  const std::optional<std::vector<double>> v = read_attribute_set(path, kNames, "both bodies'");
  if (!v) return std::nullopt;
  try {
    return std::array<ElasticBody, 2>{checked_body({(*v)[0], (*v)[1]}, 1), checked_body({(*v)[2], (*v)[3]}, 2, true)};
  } catch (const InputError& error) {
    fail(path, fmt::format("its attributes body1_E, body1_nu, body2_E, body2_nu are invalid ({})", error.what()));
  }
}

bool has_dataset(const std::filesystem::path& path, const char* name) {
  const detail::ErrorPrintingOff quiet;
  const detail::File file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!file.valid()) fail(path, "it cannot be opened as HDF5");
  return H5Lexists(file.get(), name, H5P_DEFAULT) > 0;
}

// A friction result's /shear_x and /shear_y (both or neither), each of the
// pressure's shape, through the height map reader's checks.
void read_shear(const std::filesystem::path& path, const HeightMap& pressure, ResultPressure& result) {
  const bool x = has_dataset(path, "shear_x");
  const bool y = has_dataset(path, "shear_y");
  if (!x && !y) return;
  if (x != y) {
    fail(path, fmt::format("it has /{} but not /{}: a friction result holds both shear tractions",
                           x ? "shear_x" : "shear_y", x ? "shear_y" : "shear_x"));
  }
  const auto read = [&](const char* name) {
    HeightMap field;
    try {
      field = read_hdf5_height_map(path, fmt::format("/{}", name));
    } catch (const FileError& error) {
      fail(path, fmt::format("its {} cannot be read ({})", name, error.what()));
    }
    if (field.dimension != pressure.dimension || field.nx != pressure.nx || field.ny != pressure.ny) {
      fail(path, fmt::format("its /{} has {} x {} values but /pressure has {} x {}: the shear tractions lie on the "
                             "pressure's grid",
                             name, field.ny, field.nx, pressure.ny, pressure.nx));
    }
    return std::vector<double>(field.heights.data(), field.heights.data() + field.heights.size());
  };
  result.shear_x = read("shear_x");
  result.shear_y = read("shear_y");
}

}  // namespace

ResultPressure read_result_pressure(const std::filesystem::path& path) {
  HeightMap field;
  try {
    field = read_hdf5_height_map(path, "/pressure");
  } catch (const FileError& error) {
    fail(path, fmt::format("its pressure cannot be read ({})", error.what()));
  }
  Boundary boundary = Boundary::periodic;
  try {
    boundary = parse_boundary(read_boundary(path));
  } catch (const FileError&) {
    throw;
  } catch (const InputError& error) {
    fail(path, fmt::format("root attribute 'boundary': {}", error.what()));
  }
  require_result_kind(path);
  if (!(field.dx > 0.0) || (field.dimension == 2 && !(field.dy > 0.0))) {
    fail(path, fmt::format("its root attributes dx = {:.6g} m, dy = {:.6g} m do not give a grid spacing (> 0 m)",
                           field.dx, field.dy));
  }
  const Grid grid = [&] {
    try {
      return field.dimension == 1 ? Grid::line(field.nx, field.dx, boundary)
                                  : Grid::plane(field.nx, field.ny, field.dx, field.dy, boundary);
    } catch (const InputError& error) {
      fail(path, fmt::format("its root attributes dx = {:.6g} m, dy = {:.6g} m with the pressure's {} cells give no "
                             "valid grid ({})",
                             field.dx, field.dy, field.heights.size(), error.what()));
    }
  }();
  ResultPressure result{grid,
                        std::vector<double>(field.heights.data(), field.heights.data() + field.heights.size()),
                        read_coating(path),
                        read_bodies(path),
                        {},
                        {}};
  read_shear(path, field, result);
  return result;
}

}  // namespace halfspace::io
