// Writes a tangential load history (layout in friction_history_writer.hpp and
// docs/file-format.md#friction-histories) with the single result's fields
// and the one attribute tables (result_attributes.hpp).
#include "halfspace/io/friction_history_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "csv_text.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/io/output_file.hpp"
#include "halfspace/io/result_attributes.hpp"
#include "halfspace/io/xdmf_writer.hpp"
#include "hdf5_writing.hpp"
#include "md5.hpp"
#include "step_group_name.hpp"

namespace halfspace::io {
namespace {

struct HistoryColumn {
  std::string_view name;
  std::string_view unit;  // "force", "energy" (per metre in 1D) or an SI unit
  double (*value)(std::size_t step, const TangentialResult& result);
};

const std::array<HistoryColumn, 7> kColumns{{
    {"step", "1", [](std::size_t step, const TangentialResult&) { return static_cast<double>(step); }},
    {"Q_x", "force", [](std::size_t, const TangentialResult& r) { return r.force_x; }},
    {"Q_y", "force", [](std::size_t, const TangentialResult& r) { return r.force_y; }},
    {"delta_x", "m", [](std::size_t, const TangentialResult& r) { return r.state.approach_x; }},
    {"delta_y", "m", [](std::size_t, const TangentialResult& r) { return r.state.approach_y; }},
    {"stick_fraction", "1", [](std::size_t, const TangentialResult& r) { return r.stick_fraction; }},
    {"dissipated_energy", "energy", [](std::size_t, const TangentialResult& r) { return r.dissipated_energy; }},
}};

std::string column_unit(const HistoryColumn& column, const Grid& grid) {
  if (column.unit == "force") return grid.dimension() == 1 ? "N/m" : "N";
  if (column.unit == "energy") return grid.dimension() == 1 ? "J/m" : "J";
  return std::string(column.unit);
}

void check_field(std::string_view field, std::size_t step, Eigen::Index size, const Grid& grid) {
  check_field_size(fmt::format("write_friction_history: field '{}' of step {}", field, step),
                   static_cast<std::size_t>(size), grid);
}

}  // namespace

std::string friction_history_csv(std::span<const TangentialResult> steps) {
  return detail::csv_text(kColumns, steps.size(),
                          [&](std::size_t k, std::size_t c) { return kColumns[c].value(k, steps[k]); });
}

std::filesystem::path history_csv_path(const std::filesystem::path& result_path) {
  std::filesystem::path csv = result_path;
  csv.replace_extension(".csv");
  return csv;
}

void write_friction_history_contents(const Hdf5Node& root, const Grid& grid, std::span<const double> height,
                                     const SolveResult& normal, std::span<const TangentialResult> steps,
                                     std::span<const TangentialLoading> loads, const ResultMetadata& metadata,
                                     const std::string& csv, FieldRows rows) {
  root.write_dataset_rows("height", field_shape(grid), rows.first_row, height, "m");
  write_result_fields(root, grid, normal, rows);
  write_tangential_fields(root, grid, steps.back(), rows);
  {
    const Hdf5Node group = root.create_group("steps");
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const Hdf5Node step = group.create_group(step_group_name(k, steps.size()));
      write_tangential_fields(step, grid, steps[k], rows);
      write_tangential_attributes(step, steps[k]);
      if (!metadata.step_normals.empty()) {
        // Coupled: the step's own pressure, gap, displacement and contact, and its normal solve's record.
        write_result_fields(step, grid, *metadata.step_normals[k], rows);
        write_result_attributes(step, *metadata.step_normals[k]);
      }
      step.write_string_attribute("tangential_control",
                                  loads[k].control == TangentialControl::force ? "force" : "displacement");
      step.write_double_attribute("tangential_load_x", loads[k].x);
      step.write_double_attribute("tangential_load_y", loads[k].y);
    }
  }
  {
    const Hdf5Node table = root.create_group("history");
    for (const HistoryColumn& column : kColumns) {
      std::vector<double> values;
      for (std::size_t k = 0; k < steps.size(); ++k) values.push_back(column.value(k, steps[k]));
      table.write_dataset_rows(column.name, {values.size()}, 0,
                               rows.lead ? std::span<const double>(values) : std::span<const double>(),
                               column_unit(column, grid));
    }
  }
  ResultMetadata root_metadata = metadata;
  root_metadata.tangential = &steps.back();
  write_result_root_attributes(root, grid, normal, root_metadata);
  root.write_int64_attribute("history_steps", static_cast<std::int64_t>(steps.size()));
  // The digest of the .csv written with this file: a .csv beside it with
  // another digest belongs to another history.
  root.write_string_attribute("history_csv_md5", detail::md5_hex(csv));
  if (metadata.extra_groups) metadata.extra_groups(root);
}

void write_friction_history(const std::filesystem::path& path, const Grid& grid, std::span<const double> height,
                            const SolveResult& normal, std::span<const TangentialResult> steps,
                            std::span<const TangentialLoading> loads, const ResultMetadata& metadata) {
  if (steps.empty()) throw InputError("write_friction_history: the history has no steps");
  if (loads.size() != steps.size()) {
    throw InputError(fmt::format("write_friction_history: {} loads for {} steps", loads.size(), steps.size()));
  }
  check_field("height", 0, static_cast<Eigen::Index>(height.size()), grid);
  check_field("pressure", 0, normal.pressure.size(), grid);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const TangentialResult& s = steps[k];
    check_field("shear_x", k, s.state.shear_x.size(), grid);
    check_field("shear_y", k, s.state.shear_y.size(), grid);
    check_field("stick", k, s.stick.size(), grid);
    check_field("slip_x", k, s.state.slip_x.size(), grid);
    check_field("slip_y", k, s.state.slip_y.size(), grid);
    check_field("tangential_displacement_x", k, s.state.displacement_x.size(), grid);
    check_field("tangential_displacement_y", k, s.state.displacement_y.size(), grid);
  }
  if (!metadata.step_normals.empty()) {
    if (metadata.step_normals.size() != steps.size()) {
      throw InputError(fmt::format("write_friction_history: {} step normal solutions for {} steps",
                                   metadata.step_normals.size(), steps.size()));
    }
    for (std::size_t k = 0; k < steps.size(); ++k) {
      check_field("pressure", k, metadata.step_normals[k]->pressure.size(), grid);
      check_field("gap", k, metadata.step_normals[k]->gap.size(), grid);
      check_field("displacement", k, metadata.step_normals[k]->displacement.size(), grid);
    }
  }
  const std::string csv = friction_history_csv(steps);
  const std::vector<char> image = hdf5_file_image(path, [&](const Hdf5Node& root) {
    write_friction_history_contents(root, grid, height, normal, steps, loads, metadata, csv);
  });
  const OutputBytes files[] = {{path, image}, {history_csv_path(path), csv}};
  write_output_set(files);
  write_xdmf_sidecar(path, grid);  // for ParaView (xdmf_writer.hpp)
}

}  // namespace halfspace::io
