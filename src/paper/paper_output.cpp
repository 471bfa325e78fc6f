// CSV, HDF5 and Markdown output of the Table 1 reproduction, written with
// the public io conventions: output_file for the atomic write, hdf5_output
// for the HDF5 layout, result_attributes for each method's outcome.
#include "halfspace/paper/paper_output.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <span>

#include "halfspace/error.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/io/output_file.hpp"
#include "halfspace/io/result_attributes.hpp"
#include "halfspace/version.hpp"

namespace halfspace::paper {
namespace {

constexpr std::int64_t kFormatVersion = 1;

struct Column {
  std::string name;
  const double* data;
  std::string units;
};

std::vector<Column> columns(const TestReproduction& run) {
  std::vector<Column> out{{"x", run.contact.x.data(), "m"},
                          {"gap", run.contact.initial_gap.data(), "m"},
                          {"p_lemke", run.lemke.pressure.data(), "Pa"},
                          {"p_lcpquad", run.lcpquad.pressure.data(), "Pa"},
                          {"p_pk", run.pk.pressure.data(), "Pa"},
                          {"p_hertz", run.hertz_pressure.data(), "Pa"}};
  for (const ExtraPressure& extra : run.extras) out.push_back({extra.column, extra.pressure.data(), "Pa"});
  return out;
}

// Outcome of one method as root attributes with a common prefix: every
// result attribute (result_attributes.hpp), plus the contact nodes and the
// wall time under the name this file has always used (`<prefix>_seconds`).
// Not `tolerance`: this file's `pk_tolerance` and `lcpquad_tolerance` are
// the options given to the methods (LCPquad's is its interior-point
// tolerance, not the one its result is measured against).
void write_method(const io::Hdf5Node& root, const std::string& prefix, const SolveResult& result) {
  static constexpr std::string_view kSkip[] = {"tolerance"};
  io::write_result_attributes(root, result, prefix + "_", kSkip);
  root.write_double_attribute(prefix + "_seconds", result.wall_seconds);
  root.write_int64_attribute(prefix + "_contact_nodes", contact_nodes(result));
}

void write_attributes(const io::Hdf5Node& root, const TestReproduction& run, const ReproductionOptions& options) {
  const LineContact& c = run.contact;
  root.write_string_attribute("format", "halfspace-paper-test");
  root.write_int64_attribute("format_version", kFormatVersion);
  root.write_string_attribute("units",
                              "SI: x, gap, dx, radii, half-width, approach in m; pressures and moduli in Pa; "
                              "load and forces in N/m; times in s");
  root.write_int64_attribute("test", c.test.number);
  root.write_int64_attribute("nodes", static_cast<std::int64_t>(c.test.nodes));
  root.write_double_attribute("dx", c.grid.dx());
  root.write_double_attribute("R1", c.test.radius1);
  root.write_double_attribute("R2", c.test.radius2);
  root.write_double_attribute("E", c.test.youngs_modulus);
  root.write_double_attribute("nu", c.test.poissons_ratio);
  root.write_double_attribute("radius", c.radius);
  root.write_double_attribute("E_star", c.e_star);
  root.write_double_attribute("load", c.load);
  root.write_double_attribute("hertz_half_width", c.hertz.half_width);
  root.write_double_attribute("hertz_peak", c.hertz.peak);
  write_method(root, "lemke", run.lemke);
  write_method(root, "lcpquad", run.lcpquad);
  write_method(root, "pk", run.pk);
  root.write_string_attribute("lemke_termination", to_string(run.lemke_report.status));
  root.write_int64_attribute("lemke_pivots", run.lemke_report.iterations);
  root.write_double_attribute("lcpquad_objective", run.lcpquad_report.objective);
  root.write_double_attribute("pk_tolerance", options.pk_tolerance);
  root.write_double_attribute("lcpquad_tolerance", options.lcpquad_tolerance);
  root.write_double_attribute("lemke_vs_lcpquad", run.lemke_vs_lcpquad);
  root.write_double_attribute("lemke_vs_pk", run.lemke_vs_pk);
  root.write_double_attribute("lcpquad_vs_pk", run.lcpquad_vs_pk);
  for (const ExtraPressure& extra : run.extras) {
    root.write_string_attribute(extra.column + "_status", to_string(extra.lcp.status));
    root.write_string_attribute(extra.column + "_message", extra.lcp.message);
    root.write_int64_attribute(extra.column + "_iterations", extra.lcp.iterations);
  }
  root.write_string_attribute("halfspace_version", fmt::format("{} ({})", kVersion, kGitHash));
}

std::string status_cell(const SolveResult& result) {
  return result.converged() ? "" : fmt::format(" ({})", to_string(result.status));
}

}  // namespace

void write_csv(const std::filesystem::path& path, const TestReproduction& run) {
  const std::vector<Column> cols = columns(run);
  std::string text;
  for (std::size_t c = 0; c < cols.size(); ++c) text += (c == 0 ? "" : ",") + cols[c].name;
  text += '\n';
  for (std::size_t i = 0; i < run.contact.x.size(); ++i) {
    for (std::size_t c = 0; c < cols.size(); ++c) {
      text += fmt::format("{}{:.17g}", c == 0 ? "" : ",", cols[c].data[i]);
    }
    text += '\n';
  }
  io::write_output_file(path, text);
}

void write_hdf5(const std::filesystem::path& path, const TestReproduction& run, const ReproductionOptions& options) {
  io::write_hdf5_file(path, [&](const io::Hdf5Node& root) {
    const std::size_t n = run.contact.x.size();
    for (const Column& column : columns(run)) {
      const io::Hdf5Node dataset =
          root.write_dataset(column.name, {n}, std::span<const double>(column.data, n), column.units);
      for (const ExtraPressure& extra : run.extras) {
        if (extra.column == column.name && !extra.description.empty()) {
          dataset.write_string_attribute("description", extra.description);
        }
      }
    }
    write_attributes(root, run, options);
  });
}

std::string summary_markdown(const std::vector<TestReproduction>& runs, const ReproductionOptions& options) {
  std::string text = fmt::format(
      "# Table 1 reproduction\n\n"
      "Load W = {:g} N/m per unit length; plane strain; pressures over the Hertz maximum p_H. "
      "Differences are max |p_a - p_b| / p_H over the nodes; times are wall-clock seconds of each solve. "
      "Polonsky-Keer tolerance {:g}, LCPquad (ALGLIB dense IPM) tolerance {:g}.\n\n",
      options.load, options.pk_tolerance, options.lcpquad_tolerance);
  text +=
      "| test | N | E* (GPa) | R (mm) | b (um) | p_H (MPa) | contact nodes | a / b | max p/p_H Lemke | LCPquad | PK "
      "| Lemke-LCPquad | Lemke-PK | LCPquad-PK | Lemke pivots | LCPquad iterations | LCPquad objective "
      "| PK iterations | Lemke s | LCPquad s | PK s |\n";
  text +=
      "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const TestReproduction& run : runs) {
    const LineContact& c = run.contact;
    const double p_h = c.hertz.peak;
    text += fmt::format(
        "| {} | {} | {:.4g} | {:.4g} | {:.4g} | {:.4g} | {} | {:.4f} | {:.6f}{} | {:.6f}{} | {:.6f}{} | {:.1e} | "
        "{:.1e} "
        "| {:.1e} | {}{} | {} | {:.1e} | {} | {:.4f} | {:.4f} | {:.4f} |\n",
        c.test.number, c.test.nodes, c.e_star / 1e9, c.radius * 1e3, c.hertz.half_width * 1e6, p_h / 1e6,
        contact_nodes(run.lemke), contact_half_width(run.lemke, c.grid.dx()) / c.hertz.half_width,
        run.lemke.max_pressure / p_h, status_cell(run.lemke), run.lcpquad.max_pressure / p_h, status_cell(run.lcpquad),
        run.pk.max_pressure / p_h, status_cell(run.pk), run.lemke_vs_lcpquad, run.lemke_vs_pk, run.lcpquad_vs_pk,
        run.lemke_report.iterations, run.lemke_report.status == solvers::LcpStatus::ray_termination ? " (ray)" : "",
        run.lcpquad_report.iterations, run.lcpquad_report.objective, run.pk.iterations, run.lemke.wall_seconds,
        run.lcpquad.wall_seconds, run.pk.wall_seconds);
  }
  text +=
      "\na / b: contact half-width (half the width of the cells in contact, Lemke) over the Hertz half-width. "
      "The LCPquad objective is p'(Kp + g) in Hertz units (zero at the solution).\n";
  return text;
}

}  // namespace halfspace::paper
