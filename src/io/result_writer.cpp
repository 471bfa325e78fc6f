// Writes a solve's fields and summary to HDF5 (layout in docs/file-format.md)
// with the conventions of hdf5_output.hpp: assembled in memory (or, with a
// large extra group, in place), written under a temporary name beside the
// target, synced and renamed, so a reader never sees a partial result.
#include "halfspace/io/result_writer.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/io/result_attributes.hpp"
#include "halfspace/io/xdmf_writer.hpp"
#include "halfspace/solvers/interface_law.hpp"
#include "halfspace/version.hpp"
#include "hdf5_writing.hpp"

namespace halfspace::io {
namespace {

constexpr std::int64_t kFormatVersion = 1;
constexpr const char* kUnits =
    "SI: lengths (dx, dy, approach, height, gap, displacement, slip) in m; pressures, shear and E_star in Pa; "
    "total_force and tangential_force in N (N/m in 1D); solve_seconds in s";

void check_size(std::string_view field, std::size_t size, const Grid& grid) {
  check_field_size(fmt::format("write_result: field '{}'", field), size, grid);
}

std::span<const double> values(const Eigen::ArrayXd& field) {
  return {field.data(), static_cast<std::size_t>(field.size())};
}

}  // namespace

void write_result_fields(const Hdf5Node& node, const Grid& grid, const SolveResult& result, FieldRows rows) {
  const std::vector<std::size_t> shape = field_shape(grid);
  const std::size_t first = rows.first_row;
  node.write_dataset_rows("pressure", shape, first, values(result.pressure), "Pa");
  node.write_dataset_rows("gap", shape, first, values(result.gap), "m");
  node.write_dataset_rows("displacement", shape, first, values(result.displacement), "m");
  const auto cells = static_cast<std::size_t>(result.pressure.size());
  std::vector<std::uint8_t> contact(cells);
  // Adhesive results: contact is the wall (gap 0), where the pressure may
  // be negative; otherwise the cells with pressure.
  const bool adhesive = !result.adhesion.law.empty();
  for (std::size_t k = 0; k < contact.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(k);
    contact[k] = (adhesive ? result.gap[i] <= 0.0 : result.pressure[i] > 0.0) ? 1 : 0;
  }
  node.write_dataset_rows("contact", shape, first, std::span<const std::uint8_t>(contact), "1");
  if (result.hardness) {
    // Hardness cap: the cells at it, and the plastic displacement
    // (interface_law.hpp, docs/theory.md#hardness-cap).
    const std::span<const double> pressure = values(result.pressure);
    const auto plastic = solvers::plastic_cells(pressure, result.hardness);
    node.write_dataset_rows("plastic", shape, first, std::span<const std::uint8_t>(plastic.data(), cells), "1");
    const Eigen::ArrayXd plastic_displacement =
        solvers::plastic_displacement(pressure, values(result.gap), result.hardness);
    node.write_dataset_rows("plastic_displacement", shape, first, values(plastic_displacement), "m");
  }
  const std::span<const double> history(result.residual_history);
  node.write_dataset_rows("residual_history", {history.size()}, 0, rows.lead ? history : std::span<const double>(), "");
}

void write_tangential_fields(const Hdf5Node& node, const Grid& grid, const TangentialResult& result, FieldRows rows) {
  const std::vector<std::size_t> shape = field_shape(grid);
  const std::size_t first = rows.first_row;
  const TangentialState& s = result.state;
  node.write_dataset_rows("shear_x", shape, first, values(s.shear_x), "Pa");
  node.write_dataset_rows("shear_y", shape, first, values(s.shear_y), "Pa");
  std::vector<std::uint8_t> stick(static_cast<std::size_t>(result.stick.size()));
  for (std::size_t k = 0; k < stick.size(); ++k) stick[k] = result.stick[static_cast<Eigen::Index>(k)] > 0.5 ? 1 : 0;
  node.write_dataset_rows("stick", shape, first, std::span<const std::uint8_t>(stick), "1");
  node.write_dataset_rows("slip_x", shape, first, values(s.slip_x), "m");
  node.write_dataset_rows("slip_y", shape, first, values(s.slip_y), "m");
  node.write_dataset_rows("tangential_displacement_x", shape, first, values(s.displacement_x), "m");
  node.write_dataset_rows("tangential_displacement_y", shape, first, values(s.displacement_y), "m");
}

void write_result_root_attributes(const Hdf5Node& root, const Grid& grid, const SolveResult& result,
                                  const ResultMetadata& metadata) {
  root.write_string_attribute("format", "halfspace-result");
  root.write_int64_attribute("format_version", kFormatVersion);
  root.write_string_attribute("units", kUnits);

  write_grid_attributes(root, grid);
  root.write_double_attribute("E_star", metadata.e_star);
  if (metadata.coating) write_coating_attributes(root, *metadata.coating);
  if (metadata.bodies && !metadata.bodies->coating()) write_body_attributes(root, *metadata.bodies);
  root.write_string_attribute("load_mode", metadata.load_mode);

  write_result_attributes(root, result);
  if (metadata.tangential) write_tangential_attributes(root, *metadata.tangential);
  root.write_int64_attribute("threads", metadata.threads);

  root.write_string_attribute("halfspace_version", fmt::format("{} ({})", kVersion, kGitHash));
  root.write_string_attribute("command_line", metadata.command_line);
  root.write_string_attribute("config", metadata.config);
  root.write_string_attribute("height_source", metadata.height_source);
  root.write_string_attribute("preparation", metadata.preparation);
  if (metadata.contact_statistics) write_contact_statistics_attributes(root, *metadata.contact_statistics);
  if (const auto& s = metadata.surface_statistics) {
    root.write_double_attribute("surface_rms_height", s->rms_height);
    root.write_double_attribute("surface_rms_slope", s->rms_slope);
  }
}

void write_result_contents(const Hdf5Node& root, const Grid& grid, std::span<const double> height,
                           const SolveResult& result, const ResultMetadata& metadata, FieldRows rows) {
  root.write_dataset_rows("height", field_shape(grid), rows.first_row, height, "m");
  write_result_fields(root, grid, result, rows);
  if (metadata.tangential) write_tangential_fields(root, grid, *metadata.tangential, rows);
  write_result_root_attributes(root, grid, result, metadata);
  if (metadata.extra_groups) metadata.extra_groups(root);
}

void write_result(const std::filesystem::path& path, const Grid& grid, std::span<const double> height,
                  const SolveResult& result, const ResultMetadata& metadata) {
  check_size("height", height.size(), grid);
  check_size("pressure", static_cast<std::size_t>(result.pressure.size()), grid);
  check_size("gap", static_cast<std::size_t>(result.gap.size()), grid);
  check_size("displacement", static_cast<std::size_t>(result.displacement.size()), grid);
  if (const TangentialResult* t = metadata.tangential) {
    for (const auto& [name, size] :
         {std::pair{"shear_x", t->state.shear_x.size()}, std::pair{"shear_y", t->state.shear_y.size()},
          std::pair{"stick", t->stick.size()}, std::pair{"slip_x", t->state.slip_x.size()},
          std::pair{"slip_y", t->state.slip_y.size()},
          std::pair{"tangential_displacement_x", t->state.displacement_x.size()},
          std::pair{"tangential_displacement_y", t->state.displacement_y.size()}}) {
      check_size(name, static_cast<std::size_t>(size), grid);
    }
  }
  const auto fill = [&](const Hdf5Node& root) { write_result_contents(root, grid, height, result, metadata); };
  const std::uint64_t bound = result_file_bound(grid, result, metadata);
  if (metadata.extra_groups_bytes == 0 && bound <= kInMemoryResultBytes) {
    write_hdf5_file(path, fill);
  } else {
    write_large_hdf5_file(path, bound, fill);
  }
  write_xdmf_sidecar(path, grid);  // for ParaView (xdmf_writer.hpp)
}

std::uint64_t result_file_bound(const Grid& grid, const SolveResult& result, const ResultMetadata& metadata) {
  // height, pressure, gap, displacement, plastic_displacement, and the uint8
  // contact and plastic within one more float64 field's bound.
  // Friction: six float64 fields and the uint8 stick map within a seventh.
  const std::uint64_t fields = metadata.tangential != nullptr ? 13 : 6;
  return kHdf5SmallItemsBound + fields * hdf5_dataset_bound(field_shape(grid), Compression::deflate) +
         hdf5_dataset_bound({result.residual_history.size()}, Compression::deflate) + metadata.extra_groups_bytes;
}

}  // namespace halfspace::io
