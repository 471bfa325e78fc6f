// Writes sweep results (layout in docs/file-format.md#sweep-results) with the
// conventions of the single-result writer, shared through hdf5_writing.hpp.
#include "halfspace/io/sweep_writer.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "hdf5_handle.hpp"
#include "hdf5_writing.hpp"

namespace halfspace::io {
namespace {

using Group = detail::Handle<H5Gclose>;
using detail::write_array_dataset;
using detail::write_double_attribute;
using detail::write_int64_attribute;
using detail::write_string_attribute;

void check_field(std::string_view field, std::size_t step, std::size_t size, const Grid& grid) {
  if (size != grid.size()) {
    throw InputError(
        fmt::format("write_sweep_result: field '{}' of step {} has {} values but the grid has {} cells ({})", field,
                    step, size, grid.size(), grid.shape_string()));
  }
}

Group create_group(hid_t location, const std::string& name) {
  Group group(H5Gcreate2(location, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  if (!group.valid()) throw FileError(fmt::format("could not create group '{}': {}", name, detail::error_reason()));
  return group;
}

// "000", "001", ...: zero-padded so that names sort in step order.
std::string step_name(std::size_t step, std::size_t steps) {
  const std::size_t digits = std::max<std::size_t>(3, fmt::format("{}", steps - 1).size());
  return fmt::format("{:0{}}", step, digits);
}

std::string column_unit(const solvers::SummaryColumn& column, const Grid& grid, std::string_view load_mode) {
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

void write_step(hid_t steps_group, const std::string& name, const Grid& grid, const solvers::SweepStep& step) {
  const Group group = create_group(steps_group, name);
  const hid_t g = group.get();
  const SolveResult& r = step.result;
  const std::vector<hsize_t> shape =
      grid.dimension() == 1 ? std::vector<hsize_t>{grid.nx()} : std::vector<hsize_t>{grid.ny(), grid.nx()};
  write_array_dataset(g, "pressure", shape, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, r.pressure.data(), "Pa");
  write_array_dataset(g, "gap", shape, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, r.gap.data(), "m");
  write_array_dataset(g, "displacement", shape, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, r.displacement.data(), "m");
  std::vector<std::uint8_t> contact(grid.size());
  for (std::size_t k = 0; k < contact.size(); ++k) contact[k] = r.pressure[static_cast<Eigen::Index>(k)] > 0.0 ? 1 : 0;
  write_array_dataset(g, "contact", shape, H5T_STD_U8LE, H5T_NATIVE_UINT8, contact.data(), "1");
  const std::vector<hsize_t> history{r.residual_history.size()};
  write_array_dataset(g, "residual_history", history, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, r.residual_history.data(),
                      nullptr);
  const std::vector<std::int64_t>& sizes = step.statistics.cluster_sizes;
  write_array_dataset(g, "cluster_sizes", {sizes.size()}, H5T_STD_I64LE, H5T_NATIVE_INT64, sizes.data(), "cells");

  write_double_attribute(g, "load", step.loading.value);
  write_double_attribute(g, "total_force", r.total_force);
  write_double_attribute(g, "mean_pressure", r.mean_pressure);
  write_double_attribute(g, "approach", r.approach);
  write_double_attribute(g, "contact_fraction", r.contact_fraction);
  write_double_attribute(g, "max_pressure", r.max_pressure);
  write_double_attribute(g, "mean_gap", step.statistics.mean_gap);
  write_double_attribute(g, "rms_gap", step.statistics.rms_gap);
  write_double_attribute(g, "free_volume", step.statistics.free_volume);
  write_int64_attribute(g, "clusters", step.statistics.clusters());
  write_string_attribute(g, "status", to_string(r.status));
  write_string_attribute(g, "message", r.message);
  write_int64_attribute(g, "converged", r.converged() ? 1 : 0);
  write_int64_attribute(g, "iterations", r.iterations);
  write_int64_attribute(g, "operator_applications", r.operator_applications);
  write_int64_attribute(g, "preconditioner_applications", r.preconditioner_applications);
  write_int64_attribute(g, "coarse_levels", r.coarse.levels);
  write_int64_attribute(g, "coarse_iterations", r.coarse.iterations);
  write_double_attribute(g, "coarse_operator_work", r.coarse.operator_work);
  write_double_attribute(g, "coarse_preconditioner_work", r.coarse.preconditioner_work);
  write_double_attribute(g, "residual", r.residual);
  write_double_attribute(g, "tolerance", r.tolerance);
  write_double_attribute(g, "solve_seconds", r.wall_seconds);
  write_int64_attribute(g, "warm_started", step.warm_started ? 1 : 0);
}

void write_summary_table(hid_t root, const Grid& grid, std::span<const solvers::SweepStep> steps,
                         std::string_view load_mode) {
  const Group table = create_group(root, "sweep");
  for (const solvers::SummaryColumn& column : solvers::summary_columns()) {
    std::vector<double> values;
    for (const solvers::SweepStep& step : steps) values.push_back(column.value(step));
    const std::string name(column.name);
    const std::string unit = column_unit(column, grid, load_mode);
    write_array_dataset(table.get(), name.c_str(), {values.size()}, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.data(),
                        unit.empty() ? "1" : unit.c_str());
  }
}

}  // namespace

void write_sweep_result(const std::filesystem::path& path, const Grid& grid, std::span<const double> height,
                        std::span<const solvers::SweepStep> steps, const ResultMetadata& metadata) {
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

  detail::write_file_atomically(path, [&](hid_t file) {
    write_array_dataset(
        file, "/height",
        grid.dimension() == 1 ? std::vector<hsize_t>{grid.nx()} : std::vector<hsize_t>{grid.ny(), grid.nx()},
        H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, height.data(), "m");
    const Group steps_group = create_group(file, "steps");
    for (std::size_t k = 0; k < steps.size(); ++k) {
      write_step(steps_group.get(), step_name(k, steps.size()), grid, steps[k]);
    }
    write_summary_table(file, grid, steps, metadata.load_mode);
    detail::write_result_attributes(file, grid, steps.back().result, root_metadata);
    write_int64_attribute(file, "sweep_steps", static_cast<std::int64_t>(steps.size()));
  });
}

void write_sweep_csv(const std::filesystem::path& path, std::span<const solvers::SweepStep> steps) {
  std::string text;
  const std::span<const solvers::SummaryColumn> columns = solvers::summary_columns();
  for (std::size_t c = 0; c < columns.size(); ++c) {
    text += c == 0 ? "" : ",";
    text += columns[c].name;
  }
  text += '\n';
  for (const solvers::SweepStep& step : steps) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      // {} is the shortest representation that reads back to the same double.
      text += fmt::format("{}{}", c == 0 ? "" : ",", columns[c].value(step));
    }
    text += '\n';
  }
  detail::write_bytes_atomically(path, std::vector<char>(text.begin(), text.end()));
}

std::filesystem::path sweep_csv_path(const std::filesystem::path& result_path) {
  std::filesystem::path csv = result_path;
  csv.replace_extension(".csv");
  return csv;
}

}  // namespace halfspace::io
