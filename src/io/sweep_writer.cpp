// Writes sweep results (layout in docs/file-format.md#sweep-results) with the
// conventions of the single-result writer: the same fields per step, and the
// result attributes from the one table (result_attributes.hpp).
#include "halfspace/io/sweep_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "csv_text.hpp"
#include "halfspace/analysis/adhesion_sweep.hpp"
#include "halfspace/analysis/sweep_table.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/io/output_file.hpp"
#include "halfspace/io/result_attributes.hpp"
#include "halfspace/io/xdmf_writer.hpp"
#include "md5.hpp"
#include "step_group_name.hpp"
#include "sweep_writing.hpp"

namespace halfspace::io {
namespace {

void check_field(std::string_view field, std::size_t step, std::size_t size, const Grid& grid) {
  check_field_size(fmt::format("write_sweep_result: field '{}' of step {}", field, step), size, grid);
}

std::string column_unit(const analysis::SummaryColumn& column, const Grid& grid, std::string_view load_mode) {
  const std::string_view force = grid.dimension() == 1 ? "N/m" : "N";
  if (column.name == "load") {
    if (load_mode == "force") return std::string(force);
    if (load_mode == "mean_pressure") return "Pa";
    return "m";
  }
  if (column.unit == "force") return std::string(force);
  if (column.unit == "volume") return grid.dimension() == 1 ? "m^2" : "m^3";
  return std::string(column.unit);
}

// The small datasets (cluster sizes, the summary table) are written by the
// lead process alone when several write the file.
template <typename T>
std::span<const T> if_lead(const std::vector<T>& values, FieldRows rows) {
  return rows.lead ? std::span<const T>(values) : std::span<const T>();
}

void write_step(const Hdf5Node& steps_group, const std::string& name, const Grid& grid, const analysis::SweepStep& step,
                FieldRows rows) {
  const Hdf5Node group = steps_group.create_group(name);
  write_result_fields(group, grid, step.result, rows);
  const std::vector<std::int64_t>& clusters = step.statistics.cluster_sizes;
  group.write_dataset_rows("cluster_sizes", {clusters.size()}, 0, if_lead(clusters, rows), "cells");
  group.write_double_attribute("load", step.loading.value);
  write_result_attributes(group, step.result);
  write_contact_statistics_attributes(group, step.statistics);
  group.write_int64_attribute("warm_started", step.warm_started ? 1 : 0);
}

void write_summary_table(const Hdf5Node& root, const Grid& grid, std::span<const analysis::SweepStep> steps,
                         std::string_view load_mode, FieldRows rows) {
  const Hdf5Node table = root.create_group("sweep");
  for (const analysis::SummaryColumn& column : analysis::summary_columns()) {
    std::vector<double> values;
    for (const analysis::SweepStep& step : steps) values.push_back(column.value(step));
    const std::string unit = column_unit(column, grid, load_mode);
    table.write_dataset_rows(column.name, {values.size()}, 0, if_lead(values, rows), unit.empty() ? "1" : unit);
  }
}

// The summary table as CSV text (write_sweep_csv's contents).
std::string sweep_csv_text(std::span<const analysis::SweepStep> steps) {
  const std::span<const analysis::SummaryColumn> columns = analysis::summary_columns();
  return detail::csv_text(columns, steps.size(),
                          [&](std::size_t k, std::size_t c) { return columns[c].value(steps[k]); });
}

}  // namespace

void write_sweep_result(const std::filesystem::path& path, const Grid& grid, std::span<const double> height,
                        std::span<const analysis::SweepStep> steps, const ResultMetadata& metadata) {
  if (steps.empty()) throw InputError("write_sweep_result: the sweep has no steps");
  check_field("height", 0, height.size(), grid);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    check_field("pressure", k, static_cast<std::size_t>(steps[k].result.pressure.size()), grid);
    check_field("gap", k, static_cast<std::size_t>(steps[k].result.gap.size()), grid);
    check_field("displacement", k, static_cast<std::size_t>(steps[k].result.displacement.size()), grid);
  }
  // The .h5 and its .csv as one set (docs/file-format.md#sweep-results):
  // both complete on disk before either replaces anything, the previous
  // sweep's .csv removed before the new .h5 arrives.
  const std::vector<char> image =
      hdf5_file_image(path, [&](const Hdf5Node& root) { write_sweep_contents(root, grid, height, steps, metadata); });
  const std::string csv = sweep_csv_text(steps);
  const OutputBytes files[] = {{path, image}, {sweep_csv_path(path), csv}};
  write_output_set(files);
  write_xdmf_sidecar(path, grid);  // for ParaView (xdmf_writer.hpp)
}

void write_sweep_contents(const Hdf5Node& root, const Grid& grid, std::span<const double> height,
                          std::span<const analysis::SweepStep> steps, const ResultMetadata& metadata, FieldRows rows) {
  // The root describes the last step, like a single result at that load.
  ResultMetadata root_metadata = metadata;
  root_metadata.contact_statistics = steps.back().statistics;
  root.write_dataset_rows("height", field_shape(grid), rows.first_row, height, "m");
  {
    const Hdf5Node steps_group = root.create_group("steps");
    for (std::size_t k = 0; k < steps.size(); ++k) {
      write_step(steps_group, step_group_name(k, steps.size()), grid, steps[k], rows);
    }
  }
  write_summary_table(root, grid, steps, metadata.load_mode, rows);
  write_result_root_attributes(root, grid, steps.back().result, root_metadata);
  root.write_int64_attribute("sweep_steps", static_cast<std::int64_t>(steps.size()));
  // The digest of the .csv written with this file: a .csv beside it with
  // another digest belongs to another sweep.
  root.write_string_attribute("summary_csv_md5", detail::md5_hex(sweep_csv_text(steps)));
  // Adhesive sweeps: the pull-off force of the unloading branch (NaN without one).
  if (!steps.front().result.adhesion.law.empty()) {
    root.write_double_attribute("pull_off_force", analysis::pull_off_force(steps));
  }
}

std::uint64_t sweep_file_bound(const Grid& grid, std::span<const analysis::SweepStep> steps) {
  // Per step: pressure, gap, displacement, plastic_displacement, and the
  // uint8 contact and plastic within one more float64 field's bound; the
  // residual history, the cluster sizes (int64, bounded as float64) and the
  // group's attributes. Then the height and the summary table.
  constexpr std::uint64_t kStepFields = 5;
  constexpr std::uint64_t kStepSmallItems = std::uint64_t{64} << 10;
  const std::uint64_t field = hdf5_dataset_bound(field_shape(grid), Compression::deflate);
  std::uint64_t bytes = kHdf5SmallItemsBound + field;
  for (const analysis::SweepStep& step : steps) {
    bytes += kStepFields * field + kStepSmallItems +
             hdf5_dataset_bound({step.result.residual_history.size()}, Compression::deflate) +
             hdf5_dataset_bound({step.statistics.cluster_sizes.size()}, Compression::deflate);
  }
  bytes += analysis::summary_columns().size() * hdf5_dataset_bound({steps.size()}, Compression::deflate);
  return bytes;
}

void write_sweep_csv(const std::filesystem::path& path, std::span<const analysis::SweepStep> steps) {
  write_output_file(path, sweep_csv_text(steps));
}

std::filesystem::path sweep_csv_path(const std::filesystem::path& result_path) {
  std::filesystem::path csv = result_path;
  csv.replace_extension(".csv");
  return csv;
}

}  // namespace halfspace::io
