// The /stress group and the stress command's file, with the conventions of
// hdf5_output.hpp (units attributes, chunked fields), written depth by depth.
#include "halfspace/io/stress_writer.hpp"

#include <fmt/format.h>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "halfspace/io/result_attributes.hpp"
#include "halfspace/io/xdmf_writer.hpp"
#include "halfspace/stress/stressed_body.hpp"
#include "halfspace/version.hpp"

namespace halfspace::io {
namespace {

constexpr std::int64_t kStressFormatVersion = 1;

// The nine stored fields in file order: the six components, then the derived ones.
constexpr std::size_t kStoredFields = stress::kComponentCount + 3;

std::vector<std::size_t> volume_shape(const Grid& grid, std::size_t depth_count) {
  std::vector<std::size_t> shape = field_shape(grid);
  shape.insert(shape.begin(), depth_count);
  return shape;
}

}  // namespace

void attach_stress_group(ResultMetadata& metadata, const Grid& grid, const std::optional<LayeredMaterial>& coating,
                         const stress::StressedBodyChoice& body, const stress::SurfaceTractions& on_body2,
                         std::span<const double> depths, const solvers::Layout& layout, FftPlanning planning) {
  // Held by the writer's callback, which may be copied.
  struct Attached {
    std::unique_ptr<stress::SubsurfaceStress> stresses;
    std::array<std::vector<double>, 2> body1_shear;
    stress::SurfaceTractions tractions;
    std::vector<double> depths;
  };
  const auto attached = std::make_shared<Attached>();
  attached->stresses = stress::make_subsurface_stress(grid, coating, body, layout, planning);
  attached->tractions = stress::tractions_on(body.body, on_body2, attached->body1_shear);
  attached->depths.assign(depths.begin(), depths.end());
  metadata.extra_groups = [attached](const Hdf5Node& root) {
    write_stress_group(root, *attached->stresses, attached->tractions, attached->depths);
  };
  metadata.extra_groups_bytes = stress_group_bound(grid, depths.size());
}

stress::VonMisesMaximum write_stress_group(const Hdf5Node& root, stress::SubsurfaceStress& stresses,
                                           std::span<const double> pressure, std::span<const double> depths) {
  return write_stress_group(root, stresses, stress::SurfaceTractions{pressure, {}, {}}, depths);
}

stress::VonMisesMaximum write_stress_group(const Hdf5Node& root, stress::SubsurfaceStress& stresses,
                                           const stress::SurfaceTractions& tractions, std::span<const double> depths) {
  const Grid& grid = stresses.grid();
  stress::check_depths(grid, depths);
  stresses.check_tractions(tractions);  // refused before the group is made
  // On a distributed layout every process writes its rows of each field
  // (the file's processes are the layout's), and the first the small
  // datasets.
  const bool lead = stresses.communicator().rank() == 0;
  const std::size_t first_row = stresses.rows().first;
  const Hdf5Node group = root.create_group("stress");
  group.write_double_attribute("poisson_ratio", stresses.poisson_ratio());
  group.write_string_attribute("tractions", stresses.has_shear(tractions) ? "pressure and shear" : "pressure");
  group.write_int64_attribute("body", stress::body_number(tractions.body));
  if (const std::optional<LayeredMaterial> coating = stresses.coating()) {
    // Which depths lie in the layer (z <= t), and the constants of each body.
    group.write_double_attribute("layer_thickness", coating->thickness);
    group.write_double_attribute("layer_poisson_ratio", coating->layer.poissons_ratio);
    group.write_double_attribute("substrate_poisson_ratio", coating->substrate.poissons_ratio);
    std::vector<std::uint8_t> in_layer;
    for (const double z : depths) in_layer.push_back(stresses.in_layer(z) ? 1 : 0);
    group
        .write_dataset_rows("in_layer", {in_layer.size()}, 0,
                            lead ? std::span<const std::uint8_t>(in_layer) : std::span<const std::uint8_t>(), "")
        .write_string_attribute("meaning", "1: the depth is in the layer (z <= layer_thickness); 0: in the substrate");
  }
  group.write_string_attribute("sign_convention", "tension positive (compression negative); z positive downwards");
  group.write_dataset_rows("depths", {depths.size()}, 0, lead ? depths : std::span<const double>(), "m");
  // Without deflate: the fields' float64 mantissas barely compress (23% at
  // 512^2) at 15 times the time of the plain write (docs/development-log.md).
  const std::vector<std::size_t> shape = volume_shape(grid, depths.size());
  std::vector<Hdf5Node> fields;
  fields.reserve(kStoredFields);
  for (const char* name : stress::kComponentNames)
    fields.push_back(group.create_dataset(name, shape, "Pa", Compression::none));
  for (const char* name : {"von_mises", "max_shear", "hydrostatic"}) {
    fields.push_back(group.create_dataset(name, shape, "Pa", Compression::none));
  }
  const stress::VonMisesMaximum maximum =
      stress::stresses_by_depth(stresses, tractions, depths, [&](const stress::StressSlice& slice) {
        for (std::size_t c = 0; c < stress::kComponentCount; ++c) {
          fields[c].write_slab_rows(slice.index, first_row, slice.components[c]);
        }
        fields[stress::kComponentCount].write_slab_rows(slice.index, first_row, slice.von_mises);
        fields[stress::kComponentCount + 1].write_slab_rows(slice.index, first_row, slice.max_shear);
        fields[stress::kComponentCount + 2].write_slab_rows(slice.index, first_row, slice.hydrostatic);
      });
  root.write_double_attribute("max_von_mises", maximum.value);
  root.write_double_attribute("max_von_mises_x", maximum.x);
  root.write_double_attribute("max_von_mises_y", maximum.y);
  root.write_double_attribute("max_von_mises_z", maximum.z);
  return maximum;
}

std::uint64_t stress_group_bound(const Grid& grid, std::size_t depth_count) {
  return kStoredFields * hdf5_dataset_bound(volume_shape(grid, depth_count), Compression::none) + 8 * depth_count;
}

stress::VonMisesMaximum write_stress_file(const std::filesystem::path& path, stress::SubsurfaceStress& stresses,
                                          std::span<const double> pressure, std::span<const double> depths,
                                          const StressFileMetadata& metadata) {
  return write_stress_file(path, stresses, stress::SurfaceTractions{pressure, {}, {}}, depths, metadata);
}

stress::VonMisesMaximum write_stress_file(const std::filesystem::path& path, stress::SubsurfaceStress& stresses,
                                          const stress::SurfaceTractions& tractions, std::span<const double> depths,
                                          const StressFileMetadata& metadata) {
  const Grid& grid = stresses.grid();
  stresses.check_tractions(tractions);  // refused before the file is made
  stress::VonMisesMaximum maximum;
  write_large_hdf5_file(path, stress_file_bound(grid, tractions.has_shear(), depths.size()), [&](const Hdf5Node& root) {
    maximum = write_stress_file_contents(root, stresses, tractions, depths, metadata);
  });
  write_xdmf_sidecar(path, grid);  // for ParaView (xdmf_writer.hpp)
  return maximum;
}

std::uint64_t stress_file_bound(const Grid& grid, bool shear, std::size_t depth_count) {
  const std::uint64_t surface_fields = shear ? 3 : 1;
  return kHdf5SmallItemsBound + surface_fields * hdf5_dataset_bound(field_shape(grid), Compression::deflate) +
         stress_group_bound(grid, depth_count);
}

stress::VonMisesMaximum write_stress_file_contents(const Hdf5Node& root, stress::SubsurfaceStress& stresses,
                                                   const stress::SurfaceTractions& tractions,
                                                   std::span<const double> depths, const StressFileMetadata& metadata) {
  const Grid& grid = stresses.grid();
  stresses.check_tractions(tractions);
  // A 1D grid's one row is its cells: its rows of a field are the cells.
  const std::size_t first_row = grid.dimension() == 1 ? 0 : stresses.rows().first;
  root.write_string_attribute("format", "halfspace-stress");
  root.write_int64_attribute("format_version", kStressFormatVersion);
  root.write_string_attribute("units", "SI: depths, dx, dy and positions in m; stresses and pressure in Pa");
  write_grid_attributes(root, grid);
  root.write_string_attribute("halfspace_version", fmt::format("{} ({})", kVersion, kGitHash));
  root.write_string_attribute("command_line", metadata.command_line);
  root.write_string_attribute("source", metadata.source);
  root.write_dataset_rows("pressure", field_shape(grid), first_row, tractions.pressure, "Pa");
  if (stresses.has_shear(tractions)) {
    const std::size_t cells = stresses.local_size();
    const std::vector<double> zero(tractions.shear_x.empty() || tractions.shear_y.empty() ? cells : 0, 0.0);
    root.write_dataset_rows("shear_x", field_shape(grid), first_row,
                            tractions.shear_x.empty() ? zero : tractions.shear_x, "Pa");
    root.write_dataset_rows("shear_y", field_shape(grid), first_row,
                            tractions.shear_y.empty() ? zero : tractions.shear_y, "Pa");
  }
  return write_stress_group(root, stresses, tractions, depths);
}

}  // namespace halfspace::io
