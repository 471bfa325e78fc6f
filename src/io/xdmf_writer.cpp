// XDMF 2 sidecars (xdmf_writer.hpp), the dialect VTK's vtkXdmfReader (and so
// ParaView) reads. Two of its rules shape the text: a field's DataItem
// carries the grid's full three-dimensional extent (one layer "1 ny nx"),
// whatever the HDF5 dataset's rank; and cell-centred data need at least one
// cell along every axis, so a 1D profile is node-centred on a line.
#include "halfspace/io/xdmf_writer.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/io/output_file.hpp"
#include "hdf5_handle.hpp"

namespace halfspace::io {
namespace {

using detail::Dataset;
using detail::Dataspace;
using detail::Datatype;
using detail::File;
using detail::Object;

// A dataset the sidecar points to: its path in the file and its element type.
struct FieldDataset {
  std::string name;
  std::string path;
  bool bytes = false;  // uint8 (contact, plastic); otherwise float64
};

struct StressVolume {
  std::vector<double> depths;
  std::vector<FieldDataset> fields;
};

struct Step {
  std::string name;
  std::vector<FieldDataset> fields;
};

struct Contents {
  std::vector<FieldDataset> fields;  // the root's
  std::vector<Step> steps;           // a sweep's
  std::optional<StressVolume> stress;
};

[[noreturn]] void fail(const std::filesystem::path& path, std::string_view reason) {
  throw FileError(fmt::format("cannot write XDMF sidecar for '{}': {}", path.string(), reason));
}

std::vector<std::string> link_names(hid_t group) {
  std::vector<std::string> names;
  const auto collect = [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
    static_cast<std::vector<std::string>*>(data)->emplace_back(name);
    return 0;
  };
  hsize_t index = 0;
  H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, &index, collect, &names);
  return names;
}

std::vector<hsize_t> dataset_shape(hid_t dataset) {
  const Dataspace space(H5Dget_space(dataset));
  if (!space.valid()) return {};
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank <= 0) return {};
  std::vector<hsize_t> shape(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.get(), shape.data(), nullptr);
  return shape;
}

// float64 -> false, uint8 -> true, anything else -> nothing.
std::optional<bool> element_is_byte(hid_t dataset) {
  const Datatype type(H5Dget_type(dataset));
  if (!type.valid()) return std::nullopt;
  const H5T_class_t kind = H5Tget_class(type.get());
  const std::size_t size = H5Tget_size(type.get());
  if (kind == H5T_FLOAT && size == 8) return false;
  if (kind == H5T_INTEGER && size == 1 && H5Tget_sign(type.get()) == H5T_SGN_NONE) return true;
  return std::nullopt;
}

// The datasets of `group` (at `prefix` in the file) whose shape is
// `shape`, in name order; `groups` receives the names of its subgroups.
std::vector<FieldDataset> fields_of(hid_t group, const std::string& prefix, const std::vector<hsize_t>& shape,
                                    std::vector<std::string>* groups = nullptr) {
  std::vector<FieldDataset> fields;
  for (const std::string& name : link_names(group)) {
    const Object object(H5Oopen(group, name.c_str(), H5P_DEFAULT));
    if (!object.valid()) continue;
    const H5I_type_t kind = H5Iget_type(object.get());
    if (kind == H5I_GROUP) {
      if (groups) groups->push_back(name);
      continue;
    }
    if (kind != H5I_DATASET || dataset_shape(object.get()) != shape) continue;
    if (const std::optional<bool> bytes = element_is_byte(object.get())) {
      fields.push_back({name, prefix + "/" + name, *bytes});
    }
  }
  return fields;
}

std::vector<double> read_depths(const std::filesystem::path& path, hid_t stress) {
  const Dataset depths(H5Dopen2(stress, "depths", H5P_DEFAULT));
  if (!depths.valid()) fail(path, "the /stress group has no 'depths' dataset");
  const std::vector<hsize_t> shape = dataset_shape(depths.get());
  if (shape.size() != 1 || shape[0] == 0) fail(path, "/stress/depths is not a non-empty one-dimensional dataset");
  std::vector<double> values(shape[0]);
  if (H5Dread(depths.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
    fail(path, fmt::format("could not read /stress/depths: {}", detail::error_reason()));
  }
  return values;
}

Contents read_contents(const std::filesystem::path& path, const Grid& grid) {
  const detail::ErrorPrintingOff quiet;
  const File file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!file.valid()) fail(path, fmt::format("could not open it: {}", detail::error_reason()));
  std::vector<hsize_t> field;
  for (const std::size_t extent : field_shape(grid)) field.push_back(extent);
  Contents contents;
  std::vector<std::string> groups;
  contents.fields = fields_of(file.get(), "", field, &groups);
  for (const std::string& group_name : groups) {
    const Object group(H5Oopen(file.get(), group_name.c_str(), H5P_DEFAULT));
    if (!group.valid()) continue;
    if (group_name == "steps") {
      std::vector<std::string> steps;
      fields_of(group.get(), "/steps", field, &steps);  // its groups; it has no fields
      for (const std::string& step : steps) {
        const Object step_group(H5Oopen(group.get(), step.c_str(), H5P_DEFAULT));
        if (step_group.valid()) contents.steps.push_back({step, fields_of(step_group.get(), "/steps/" + step, field)});
      }
    } else if (group_name == "stress") {
      StressVolume volume;
      volume.depths = read_depths(path, group.get());
      std::vector<hsize_t> shape = field;
      shape.insert(shape.begin(), volume.depths.size());
      volume.fields = fields_of(group.get(), "/stress", shape);
      if (!volume.fields.empty()) contents.stress = std::move(volume);
    }
  }
  if (contents.fields.empty() && contents.steps.empty() && !contents.stress) {
    fail(path, fmt::format("it holds no dataset shaped like the grid ({})", grid.shape_string()));
  }
  return contents;
}

std::string escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// The XML text of a list of numbers, each in the shortest form that reads
// back to the same double.
template <typename Numbers>
std::string number_list(const Numbers& values) {
  std::string text;
  for (const double value : values) text += fmt::format("{}{}", text.empty() ? "" : " ", value);
  return text;
}

std::string inline_item(std::size_t count, const std::string& values) {
  return fmt::format(R"(<DataItem Dimensions="{}" NumberType="Float" Precision="8" Format="XML">{}</DataItem>)", count,
                     values);
}

std::string attribute(const FieldDataset& field, std::string_view center, std::string_view dimensions,
                      const std::string& file_name) {
  return fmt::format(
      "      <Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"{}\">\n"
      "        <DataItem Dimensions=\"{}\" NumberType=\"{}\" Precision=\"{}\" Format=\"HDF\">{}:{}</DataItem>\n"
      "      </Attribute>\n",
      escaped(field.name), center, dimensions, field.bytes ? "UChar" : "Float", field.bytes ? 1 : 8, file_name,
      escaped(field.path));
}

// A grid of the surface fields: in 2D one layer of cells centred on the
// nodes x = i*dx, y = j*dy; in 1D the nodes x = i*dx of a line.
std::string surface_grid(std::string_view name, const Grid& grid, const std::vector<FieldDataset>& fields,
                         const std::string& file_name, std::optional<std::size_t> time) {
  std::string text = fmt::format("    <Grid Name=\"{}\" GridType=\"Uniform\">\n", escaped(name));
  if (time) text += fmt::format("      <Time Value=\"{}\"/>\n", *time);
  const double dx = grid.dx();
  std::string dimensions;
  std::string center;
  if (grid.dimension() == 1) {
    text += fmt::format("      <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"1 1 {}\"/>\n", grid.nx());
    text += "      <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n        " + inline_item(3, "0 0 0") + "\n        " +
            inline_item(3, number_list(std::vector<double>{dx, dx, dx})) + "\n      </Geometry>\n";
    dimensions = fmt::format("1 1 {}", grid.nx());
    center = "Node";
  } else {
    const double dy = grid.dy();
    // ORIGIN_DXDYDZ lists z, y, x: the slowest axis first, like the dimensions.
    text += fmt::format("      <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"2 {} {}\"/>\n", grid.ny() + 1,
                        grid.nx() + 1);
    text += "      <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n        " +
            inline_item(3, number_list(std::vector<double>{0.0, -dy / 2, -dx / 2})) + "\n        " +
            inline_item(3, number_list(std::vector<double>{dx, dy, dx})) + "\n      </Geometry>\n";
    dimensions = fmt::format("1 {} {}", grid.ny(), grid.nx());
    center = "Cell";
  }
  for (const FieldDataset& field : fields) text += attribute(field, center, dimensions, file_name);
  return text + "    </Grid>\n";
}

std::string stress_grid(const Grid& grid, const StressVolume& volume, const std::string& file_name) {
  const std::size_t ny = grid.dimension() == 1 ? 1 : grid.ny();
  std::vector<double> x(grid.nx());
  std::vector<double> y(ny);
  std::vector<double> z;
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = static_cast<double>(i) * grid.dx();
  for (std::size_t j = 0; j < y.size(); ++j) y[j] = grid.dimension() == 1 ? 0.0 : static_cast<double>(j) * grid.dy();
  for (const double depth : volume.depths) z.push_back(-depth);
  const std::string dimensions = fmt::format("{} {} {}", volume.depths.size(), ny, grid.nx());
  std::string text = "    <Grid Name=\"stress\" GridType=\"Uniform\">\n";
  text += fmt::format("      <Topology TopologyType=\"3DRectMesh\" Dimensions=\"{}\"/>\n", dimensions);
  text += "      <Geometry GeometryType=\"VXVYVZ\">\n        " + inline_item(x.size(), number_list(x)) + "\n        " +
          inline_item(y.size(), number_list(y)) + "\n        " + inline_item(z.size(), number_list(z)) +
          "\n      </Geometry>\n";
  for (const FieldDataset& field : volume.fields) text += attribute(field, "Node", dimensions, file_name);
  return text + "    </Grid>\n";
}

}  // namespace

std::filesystem::path xdmf_sidecar_path(const std::filesystem::path& hdf5_path) {
  std::filesystem::path sidecar = hdf5_path;
  sidecar.replace_extension(".xdmf");
  return sidecar;
}

std::string xdmf_sidecar_text(const std::filesystem::path& hdf5_path, const Grid& grid) {
  const Contents contents = read_contents(hdf5_path, grid);
  // The sidecar lies beside the file and names it relative to itself, so
  // the pair can be moved together.
  const std::string file_name = escaped(hdf5_path.filename().string());
  std::string text =
      "<?xml version=\"1.0\" ?>\n"
      "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      "<Xdmf Version=\"2.0\">\n"
      "  <Domain>\n";
  if (!contents.steps.empty()) {
    text += "    <Grid Name=\"sweep\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (std::size_t k = 0; k < contents.steps.size(); ++k) {
      std::vector<FieldDataset> fields = contents.fields;  // the height, the same in every step
      fields.insert(fields.end(), contents.steps[k].fields.begin(), contents.steps[k].fields.end());
      text += surface_grid("step " + contents.steps[k].name, grid, fields, file_name, k);
    }
    text += "    </Grid>\n";
  } else if (!contents.fields.empty()) {
    text += surface_grid("surface", grid, contents.fields, file_name, std::nullopt);
  }
  if (contents.stress) text += stress_grid(grid, *contents.stress, file_name);
  return text + "  </Domain>\n</Xdmf>\n";
}

void check_xdmf_sidecar_path(const std::filesystem::path& hdf5_path) {
  const std::filesystem::path sidecar = xdmf_sidecar_path(hdf5_path);
  if (same_file(sidecar, hdf5_path)) {
    throw InputError(fmt::format(
        "output '{}' ends in .xdmf, the name of its XDMF sidecar: name the HDF5 file with another extension (.h5)",
        hdf5_path.string()));
  }
  check_output_path(sidecar);
}

void write_xdmf_sidecar(const std::filesystem::path& hdf5_path, const Grid& grid) {
  check_xdmf_sidecar_path(hdf5_path);
  write_output_file(xdmf_sidecar_path(hdf5_path), xdmf_sidecar_text(hdf5_path, grid));
}

}  // namespace halfspace::io
