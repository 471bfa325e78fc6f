// Height-map output with the conventions of every HDF5 output (hdf5_output.hpp).
#include "halfspace/io/height_map_writer.hpp"

#include <fmt/format.h>

#include "halfspace/error.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/io/xdmf_writer.hpp"
#include "halfspace/version.hpp"

namespace halfspace::io {

void write_height_map(const std::filesystem::path& path, const Grid& grid, std::span<const double> heights,
                      const HeightMapMetadata& metadata) {
  if (heights.size() != grid.size()) {
    throw InputError(fmt::format("write_height_map: {} heights for a grid of {} cells ({})", heights.size(),
                                 grid.size(), grid.shape_string()));
  }
  write_hdf5_file(path, [&](const Hdf5Node& root) { write_height_map_contents(root, grid, 0, heights, metadata); });
  write_xdmf_sidecar(path, grid);  // for ParaView (xdmf_writer.hpp)
}

void write_height_map_contents(const Hdf5Node& root, const Grid& grid, std::size_t first_row,
                               std::span<const double> rows, const HeightMapMetadata& metadata) {
  root.write_dataset_rows("height", field_shape(grid), first_row, rows, "m");
  root.write_double_attribute("dx", grid.dx());
  root.write_double_attribute("dy", grid.dimension() == 1 ? 0.0 : grid.dy());
  root.write_int64_attribute("nx", static_cast<std::int64_t>(grid.nx()));
  root.write_int64_attribute("ny", static_cast<std::int64_t>(grid.ny()));
  root.write_string_attribute("unit", "m");
  root.write_string_attribute("layout", grid.dimension() == 1 ? "height[i] = h(x = i*dx)"
                                                              : "height[j][i] = h(x = i*dx, y = j*dy), shape (ny, nx)");
  root.write_int64_attribute("periodic", metadata.periodic ? 1 : 0);
  root.write_string_attribute("source", metadata.source);
  root.write_string_attribute("command_line", metadata.command_line);
  root.write_string_attribute("halfspace_version", fmt::format("{} ({})", kVersion, kGitHash));
  for (const auto& [name, value] : metadata.numbers) root.write_double_attribute(name, value);
  for (const auto& [name, value] : metadata.integers) root.write_int64_attribute(name, value);
  for (const auto& [name, value] : metadata.strings) root.write_string_attribute(name, value);
}

}  // namespace halfspace::io
