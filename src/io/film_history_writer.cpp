// A transient film's history (film_history_writer.hpp): each step's group is
// written into the in-memory file as the step is solved, so the steps' fields
// are held compressed in the file image and nowhere else.
#include "halfspace/io/film_history_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <string_view>
#include <vector>

#include "csv_text.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/friction_history_writer.hpp"
#include "halfspace/io/output_file.hpp"
#include "hdf5_writing.hpp"
#include "md5.hpp"
#include "step_group_name.hpp"

namespace halfspace::io {
namespace {

using Step = lubrication::TransientStep;

struct HistoryColumn {
  std::string_view name;
  std::string_view unit;  // "force", "volume", "flow" (per metre on a profile) or an SI unit
  double (*value)(const Step& step);
};

const std::array<HistoryColumn, 11> kColumns{{
    {"step", "1", [](const Step& s) { return static_cast<double>(s.step); }},
    {"time", "s", [](const Step& s) { return s.time; }},
    {"separation", "m", [](const Step& s) { return s.film.separation; }},
    {"load", "force", [](const Step& s) { return s.film.forces.load; }},
    {"minimum_film_thickness", "m", [](const Step& s) { return s.film.forces.minimum_film_thickness; }},
    {"max_pressure", "Pa", [](const Step& s) { return s.film.solution.pressure.maxCoeff(); }},
    {"cavitated_fraction", "1", [](const Step& s) { return s.film.forces.cavitated_fraction; }},
    {"fluid_volume", "volume", [](const Step& s) { return s.fluid_volume; }},
    {"inflow", "flow", [](const Step& s) { return s.film.forces.inflow; }},
    {"outflow", "flow", [](const Step& s) { return s.film.forces.outflow; }},
    {"film_solves", "1", [](const Step& s) { return static_cast<double>(s.film.film_solves); }},
}};

std::string column_unit(const HistoryColumn& column, const Grid& grid) {
  const bool profile = grid.dimension() == 1;
  if (column.unit == "force") return profile ? "N/m" : "N";
  if (column.unit == "volume") return profile ? "m^2" : "m^3";
  if (column.unit == "flow") return profile ? "m^2/s" : "m^3/s";
  return std::string(column.unit);
}

void check_field(std::string_view field, const Step& step, Eigen::Index size, const Grid& grid) {
  if (static_cast<std::size_t>(size) != grid.size()) {
    throw InputError(
        fmt::format("write_film_history: field '{}' of step {} has {} values but the grid has {} nodes ({})", field,
                    step.step, size, grid.size(), grid.shape_string()));
  }
}

void write_step(const Hdf5Node& group, const Grid& grid, std::string_view name, const Step& s) {
  const Hdf5Node node = group.create_group(name);
  const std::vector<std::size_t> shape = field_shape(grid);
  const auto field = [&](std::string_view field_name, const Eigen::ArrayXd& values, std::string_view unit) {
    check_field(field_name, s, values.size(), grid);
    node.write_dataset(field_name, shape, std::span<const double>(values.data(), grid.size()), unit);
  };
  field("pressure", s.film.solution.pressure, "Pa");
  field("film", s.film.film, "m");
  field("fluid_fraction", s.film.solution.fluid_fraction, "");
  for (const HistoryColumn& column : kColumns) {
    if (column.name == "step" || column.name == "film_solves") continue;
    node.write_double_attribute(column.name, column.value(s));
  }
  node.write_int64_attribute("step", s.step);
  node.write_int64_attribute("film_solves", s.film.film_solves);
  node.write_int64_attribute("iterations", s.film.solution.iterations);
  node.write_double_attribute("relative_residual", s.film.solution.relative_residual);
  node.write_string_attribute("status", lubrication::to_string(s.film.solution.status));
  node.write_string_attribute("message", s.film.solution.message);
}

}  // namespace

void write_film_history(const std::filesystem::path& path, const Grid& grid, std::size_t steps,
                        const std::function<void(const FilmStepSink&)>& run,
                        const std::function<void(const Hdf5Node& root)>& fill_root) {
  std::vector<std::array<double, kColumns.size()>> rows;
  std::string csv;
  const std::vector<char> image = hdf5_file_image(path, [&](const Hdf5Node& root) {
    {
      const Hdf5Node group = root.create_group("steps");
      run([&](const Step& s) {
        write_step(group, grid, step_group_name(s.step, steps + 1), s);
        std::array<double, kColumns.size()> row{};
        for (std::size_t c = 0; c < kColumns.size(); ++c) row[c] = kColumns[c].value(s);
        rows.push_back(row);
      });
    }
    if (rows.empty()) throw InputError("write_film_history: the history has no steps");
    {
      const Hdf5Node table = root.create_group("history");
      for (std::size_t c = 0; c < kColumns.size(); ++c) {
        std::vector<double> values(rows.size());
        for (std::size_t k = 0; k < rows.size(); ++k) values[k] = rows[k][c];
        table.write_dataset(kColumns[c].name, {values.size()}, std::span<const double>(values),
                            column_unit(kColumns[c], grid));
      }
    }
    csv = detail::csv_text(kColumns, rows.size(), [&](std::size_t k, std::size_t c) { return rows[k][c]; });
    root.write_int64_attribute("history_steps", static_cast<std::int64_t>(rows.size()));
    // The digest of the .csv written with this file: a .csv beside it with
    // another digest belongs to another history.
    root.write_string_attribute("history_csv_md5", detail::md5_hex(csv));
    fill_root(root);
  });
  const std::filesystem::path csv_path = history_csv_path(path);
  const OutputBytes files[] = {{path, image}, {csv_path, csv}};
  write_output_set(files);
}

}  // namespace halfspace::io
