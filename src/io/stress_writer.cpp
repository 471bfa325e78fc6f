// The /stress group and the stress command's file, with the conventions of
// hdf5_output.hpp (units attributes, chunked and compressed fields).
#include "halfspace/io/stress_writer.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <vector>

#include "halfspace/io/result_attributes.hpp"
#include "halfspace/version.hpp"

namespace halfspace::io {
namespace {

constexpr std::int64_t kStressFormatVersion = 1;

}  // namespace

void write_stress_group(const Hdf5Node& root, const Grid& grid, const stress::StressVolume& volume, double nu) {
  const Hdf5Node group = root.create_group("stress");
  group.write_double_attribute("poisson_ratio", nu);
  if (volume.coating) {
    // Which depths lie in the layer (z <= t), and the constants of each body.
    group.write_double_attribute("layer_thickness", volume.coating->thickness);
    group.write_double_attribute("layer_poisson_ratio", volume.coating->layer.poissons_ratio);
    group.write_double_attribute("substrate_poisson_ratio", volume.coating->substrate.poissons_ratio);
    const std::vector<std::uint8_t> in_layer(volume.in_layer.begin(), volume.in_layer.end());
    group.write_dataset("in_layer", {in_layer.size()}, std::span<const std::uint8_t>(in_layer), "")
        .write_string_attribute("meaning", "1: the depth is in the layer (z <= layer_thickness); 0: in the substrate");
  }
  group.write_string_attribute("sign_convention", "tension positive (compression negative); z positive downwards");
  group.write_dataset("depths", {volume.depths.size()}, std::span<const double>(volume.depths), "m");
  std::vector<std::size_t> shape = field_shape(grid);
  shape.insert(shape.begin(), volume.depths.size());
  // Without deflate: the fields' float64 mantissas barely compress (23% at
  // 512^2) at 15 times the time of the plain write (docs/performance.md).
  const auto write_field = [&](std::string_view name, const std::vector<double>& values) {
    group.write_dataset(name, shape, std::span<const double>(values), "Pa", Compression::none);
  };
  for (std::size_t c = 0; c < stress::kComponentCount; ++c)
    write_field(stress::kComponentNames[c], volume.components[c]);
  write_field("von_mises", volume.von_mises);
  write_field("max_shear", volume.max_shear);
  write_field("hydrostatic", volume.hydrostatic);
  root.write_double_attribute("max_von_mises", volume.max_von_mises.value);
  root.write_double_attribute("max_von_mises_x", volume.max_von_mises.x);
  root.write_double_attribute("max_von_mises_y", volume.max_von_mises.y);
  root.write_double_attribute("max_von_mises_z", volume.max_von_mises.z);
}

void write_stress_file(const std::filesystem::path& path, const Grid& grid, std::span<const double> pressure,
                       const stress::StressVolume& volume, double nu, const StressFileMetadata& metadata) {
  write_hdf5_file(path, [&](const Hdf5Node& root) {
    root.write_string_attribute("format", "halfspace-stress");
    root.write_int64_attribute("format_version", kStressFormatVersion);
    root.write_string_attribute("units", "SI: depths, dx, dy and positions in m; stresses and pressure in Pa");
    write_grid_attributes(root, grid);
    root.write_string_attribute("halfspace_version", fmt::format("{} ({})", kVersion, kGitHash));
    root.write_string_attribute("command_line", metadata.command_line);
    root.write_string_attribute("source", metadata.source);
    root.write_dataset("pressure", field_shape(grid), pressure, "Pa");
    write_stress_group(root, grid, volume, nu);
  });
}

}  // namespace halfspace::io
