// Writes sweep results (layout in docs/file-format.md#sweep-results) with the
// conventions of the single-result writer: the same fields per step, and the
// result attributes from the one table (result_attributes.hpp).
#include "halfspace/io/sweep_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "halfspace/analysis/adhesion_sweep.hpp"
#include "halfspace/analysis/sweep_table.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/io/output_file.hpp"
#include "halfspace/io/result_attributes.hpp"
#include "hdf5_writing.hpp"

namespace halfspace::io {
namespace {

void check_field(std::string_view field, std::size_t step, std::size_t size, const Grid& grid) {
  if (size != grid.size()) {
    throw InputError(
        fmt::format("write_sweep_result: field '{}' of step {} has {} values but the grid has {} cells ({})", field,
                    step, size, grid.size(), grid.shape_string()));
  }
}

// "000", "001", ...: zero-padded so that names sort in step order.
std::string step_name(std::size_t step, std::size_t steps) {
  const std::size_t digits = std::max<std::size_t>(3, fmt::format("{}", steps - 1).size());
  return fmt::format("{:0{}}", step, digits);
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

void write_step(const Hdf5Node& steps_group, const std::string& name, const Grid& grid,
                const analysis::SweepStep& step) {
  const Hdf5Node group = steps_group.create_group(name);
  write_result_fields(group, grid, step.result);
  group.write_dataset("cluster_sizes", {step.statistics.cluster_sizes.size()},
                      std::span<const std::int64_t>(step.statistics.cluster_sizes), "cells");
  group.write_double_attribute("load", step.loading.value);
  write_result_attributes(group, step.result);
  write_contact_statistics_attributes(group, step.statistics);
  group.write_int64_attribute("warm_started", step.warm_started ? 1 : 0);
}

void write_summary_table(const Hdf5Node& root, const Grid& grid, std::span<const analysis::SweepStep> steps,
                         std::string_view load_mode) {
  const Hdf5Node table = root.create_group("sweep");
  for (const analysis::SummaryColumn& column : analysis::summary_columns()) {
    std::vector<double> values;
    for (const analysis::SweepStep& step : steps) values.push_back(column.value(step));
    const std::string unit = column_unit(column, grid, load_mode);
    table.write_dataset(column.name, {values.size()}, std::span<const double>(values), unit.empty() ? "1" : unit);
  }
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
  // The root describes the last step, like a single result at that load.
  ResultMetadata root_metadata = metadata;
  root_metadata.contact_statistics = steps.back().statistics;

  write_hdf5_file(path, [&](const Hdf5Node& root) {
    root.write_dataset("height", field_shape(grid), height, "m");
    {
      const Hdf5Node steps_group = root.create_group("steps");
      for (std::size_t k = 0; k < steps.size(); ++k) {
        write_step(steps_group, step_name(k, steps.size()), grid, steps[k]);
      }
    }
    write_summary_table(root, grid, steps, metadata.load_mode);
    write_result_root_attributes(root, grid, steps.back().result, root_metadata);
    root.write_int64_attribute("sweep_steps", static_cast<std::int64_t>(steps.size()));
    // Adhesive sweeps: the pull-off force of the unloading branch (NaN without one).
    if (!steps.front().result.adhesion.law.empty()) {
      root.write_double_attribute("pull_off_force", analysis::pull_off_force(steps));
    }
  });
}

void write_sweep_csv(const std::filesystem::path& path, std::span<const analysis::SweepStep> steps) {
  std::string text;
  const std::span<const analysis::SummaryColumn> columns = analysis::summary_columns();
  for (std::size_t c = 0; c < columns.size(); ++c) {
    text += c == 0 ? "" : ",";
    text += columns[c].name;
  }
  text += '\n';
  for (const analysis::SweepStep& step : steps) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      // {} is the shortest representation that reads back to the same double.
      text += fmt::format("{}{}", c == 0 ? "" : ",", columns[c].value(step));
    }
    text += '\n';
  }
  write_output_file(path, text);
}

std::filesystem::path sweep_csv_path(const std::filesystem::path& result_path) {
  std::filesystem::path csv = result_path;
  csv.replace_extension(".csv");
  return csv;
}

}  // namespace halfspace::io
