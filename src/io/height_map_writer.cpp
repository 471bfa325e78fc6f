// Height-map output with the result writer's conventions (hdf5_writing.hpp).
#include "halfspace/io/height_map_writer.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include "halfspace/error.hpp"
#include "halfspace/version.hpp"
#include "hdf5_writing.hpp"

namespace halfspace::io {

void write_height_map(const std::filesystem::path& path, const Grid& grid, std::span<const double> heights,
                      const HeightMapMetadata& metadata) {
  if (heights.size() != grid.size()) {
    throw InputError(fmt::format("write_height_map: {} heights for a grid of {} cells ({})", heights.size(),
                                 grid.size(), grid.shape_string()));
  }
  using namespace detail;
  write_file_atomically(path, [&](hid_t file) {
    const std::vector<hsize_t> shape =
        grid.dimension() == 1 ? std::vector<hsize_t>{grid.nx()} : std::vector<hsize_t>{grid.ny(), grid.nx()};
    write_array_dataset(file, "/height", shape, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, heights.data(), "m");
    write_double_attribute(file, "dx", grid.dx());
    write_double_attribute(file, "dy", grid.dimension() == 1 ? 0.0 : grid.dy());
    write_int64_attribute(file, "nx", static_cast<std::int64_t>(grid.nx()));
    write_int64_attribute(file, "ny", static_cast<std::int64_t>(grid.ny()));
    write_string_attribute(file, "unit", "m");
    write_string_attribute(
        file, "layout",
        grid.dimension() == 1 ? "height[i] = h(x = i*dx)" : "height[j][i] = h(x = i*dx, y = j*dy), shape (ny, nx)");
    write_int64_attribute(file, "periodic", metadata.periodic ? 1 : 0);
    write_string_attribute(file, "source", metadata.source);
    write_string_attribute(file, "command_line", metadata.command_line);
    write_string_attribute(file, "halfspace_version", fmt::format("{} ({})", kVersion, kGitHash));
    for (const auto& [name, value] : metadata.numbers) write_double_attribute(file, name.c_str(), value);
    for (const auto& [name, value] : metadata.integers) write_int64_attribute(file, name.c_str(), value);
    for (const auto& [name, value] : metadata.strings) write_string_attribute(file, name.c_str(), value);
  });
}

}  // namespace halfspace::io
