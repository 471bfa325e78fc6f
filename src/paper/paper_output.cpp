// CSV, HDF5 and Markdown output of the Table 1 reproduction. The HDF5 file is
// assembled in memory and written by us, as the result writer does, so that
// a full disk is reported as an error instead of failing inside HDF5's close.
#include "halfspace/paper/paper_output.hpp"

#include <fmt/format.h>
#include <hdf5.h>
#include <unistd.h>

#include <cstdint>
#include <fstream>

#include "../io/hdf5_handle.hpp"
#include "halfspace/error.hpp"
#include "halfspace/version.hpp"

namespace halfspace::paper {
namespace {

using io::detail::Attribute;
using io::detail::Dataset;
using io::detail::Dataspace;
using io::detail::Datatype;
using io::detail::File;
using io::detail::PropertyList;

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

[[noreturn]] void fail_hdf5(std::string_view what) {
  throw FileError(fmt::format("{}: {}", what, io::detail::error_reason()));
}

void attach_double(hid_t location, const std::string& name, double value) {
  const Dataspace space(H5Screate(H5S_SCALAR));
  const Attribute attribute(H5Acreate2(location, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT));
  if (!attribute.valid() || H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, &value) < 0) {
    fail_hdf5(fmt::format("could not write attribute '{}'", name));
  }
}

void attach_int64(hid_t location, const std::string& name, std::int64_t value) {
  const Dataspace space(H5Screate(H5S_SCALAR));
  const Attribute attribute(H5Acreate2(location, name.c_str(), H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT));
  if (!attribute.valid() || H5Awrite(attribute.get(), H5T_NATIVE_INT64, &value) < 0) {
    fail_hdf5(fmt::format("could not write attribute '{}'", name));
  }
}

// Variable-length UTF-8 strings, read by h5py as str (all ours are ASCII).
void attach_string(hid_t location, const std::string& name, const std::string& value) {
  const Datatype type(H5Tcopy(H5T_C_S1));
  if (!type.valid() || H5Tset_size(type.get(), H5T_VARIABLE) < 0 || H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0) {
    fail_hdf5(fmt::format("could not make the string type of attribute '{}'", name));
  }
  const Dataspace space(H5Screate(H5S_SCALAR));
  const Attribute attribute(H5Acreate2(location, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT));
  const char* data = value.c_str();
  if (!attribute.valid() || H5Awrite(attribute.get(), type.get(), &data) < 0) {
    fail_hdf5(fmt::format("could not write attribute '{}'", name));
  }
}

void write_column(hid_t file, const Column& column, std::size_t n, const std::string& description) {
  const hsize_t dims[1] = {n};
  const Dataspace space(H5Screate_simple(1, dims, nullptr));
  Dataset dataset(
      H5Dcreate2(file, column.name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  if (!dataset.valid() || H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, column.data) < 0) {
    fail_hdf5(fmt::format("could not write dataset '{}'", column.name));
  }
  attach_string(dataset.get(), "units", column.units);
  if (!description.empty()) attach_string(dataset.get(), "description", description);
}

// Outcome of one method as root attributes with a common prefix.
void attach_method(hid_t root, const std::string& prefix, const SolveResult& result) {
  attach_string(root, prefix + "_status", std::string(to_string(result.status)));
  attach_string(root, prefix + "_message", result.message);
  attach_int64(root, prefix + "_iterations", result.iterations);
  attach_double(root, prefix + "_seconds", result.wall_seconds);
  attach_double(root, prefix + "_residual", result.residual);
  attach_double(root, prefix + "_approach", result.approach);
  attach_double(root, prefix + "_total_force", result.total_force);
  attach_double(root, prefix + "_max_pressure", result.max_pressure);
  attach_int64(root, prefix + "_contact_nodes", contact_nodes(result));
}

void write_attributes(hid_t root, const TestReproduction& run, const ReproductionOptions& options) {
  const LineContact& c = run.contact;
  attach_string(root, "format", "halfspace-paper-test");
  attach_int64(root, "format_version", kFormatVersion);
  attach_string(root, "units",
                "SI: x, gap, dx, radii, half-width, approach in m; pressures and moduli in Pa; "
                "load and forces in N/m; times in s");
  attach_int64(root, "test", c.test.number);
  attach_int64(root, "nodes", static_cast<std::int64_t>(c.test.nodes));
  attach_double(root, "dx", c.grid.dx());
  attach_double(root, "R1", c.test.radius1);
  attach_double(root, "R2", c.test.radius2);
  attach_double(root, "E", c.test.youngs_modulus);
  attach_double(root, "nu", c.test.poissons_ratio);
  attach_double(root, "radius", c.radius);
  attach_double(root, "E_star", c.e_star);
  attach_double(root, "load", c.load);
  attach_double(root, "hertz_half_width", c.hertz.half_width);
  attach_double(root, "hertz_peak", c.hertz.peak);
  attach_method(root, "lemke", run.lemke);
  attach_method(root, "lcpquad", run.lcpquad);
  attach_method(root, "pk", run.pk);
  attach_string(root, "lemke_termination", std::string(to_string(run.lemke_report.status)));
  attach_int64(root, "lemke_pivots", run.lemke_report.iterations);
  attach_double(root, "lcpquad_objective", run.lcpquad_report.objective);
  attach_double(root, "pk_tolerance", options.pk_tolerance);
  attach_double(root, "lcpquad_tolerance", options.lcpquad_tolerance);
  attach_double(root, "lemke_vs_lcpquad", run.lemke_vs_lcpquad);
  attach_double(root, "lemke_vs_pk", run.lemke_vs_pk);
  attach_double(root, "lcpquad_vs_pk", run.lcpquad_vs_pk);
  for (const ExtraPressure& extra : run.extras) {
    attach_string(root, extra.column + "_status", std::string(to_string(extra.lcp.status)));
    attach_string(root, extra.column + "_message", extra.lcp.message);
    attach_int64(root, extra.column + "_iterations", extra.lcp.iterations);
  }
  attach_string(root, "halfspace_version", fmt::format("{} ({})", kVersion, kGitHash));
}

std::vector<char> build_image(const std::filesystem::path& name, const TestReproduction& run,
                              const ReproductionOptions& options) {
  PropertyList access(H5Pcreate(H5P_FILE_ACCESS));
  if (!access.valid() || H5Pset_fapl_core(access.get(), std::size_t{1} << 20, false) < 0) {
    fail_hdf5("could not set up the in-memory file");
  }
  File file(H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()));
  if (!file.valid()) fail_hdf5("could not create the in-memory file");
  for (const Column& column : columns(run)) {
    std::string description;
    for (const ExtraPressure& extra : run.extras) {
      if (extra.column == column.name) description = extra.description;
    }
    write_column(file.get(), column, run.contact.x.size(), description);
  }
  write_attributes(file.get(), run, options);
  if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0) fail_hdf5("could not flush the in-memory file");
  const ssize_t size = H5Fget_file_image(file.get(), nullptr, 0);
  if (size < 0) fail_hdf5("could not assemble the file image");
  std::vector<char> image(static_cast<std::size_t>(size));
  if (H5Fget_file_image(file.get(), image.data(), image.size()) != size) fail_hdf5("could not copy the file image");
  if (!file.close()) fail_hdf5("could not close the in-memory file");
  return image;
}

// Writes `data` under a temporary name beside `path` and renames it.
void write_file(const std::filesystem::path& path, const char* data, std::size_t size) {
  std::filesystem::path temporary = path;
  temporary += fmt::format(".tmp-{}", ::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(data, static_cast<std::streamsize>(size));
    out.close();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw FileError(fmt::format("cannot write output '{}': could not write temporary file '{}'", path.string(),
                                  temporary.string()));
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw FileError(fmt::format("cannot write output '{}': {}", path.string(), error.message()));
  }
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
  write_file(path, text.data(), text.size());
}

void write_hdf5(const std::filesystem::path& path, const TestReproduction& run, const ReproductionOptions& options) {
  const io::detail::ErrorPrintingOff quiet;
  std::vector<char> image;
  try {
    image = build_image(path, run, options);
  } catch (const FileError& error) {
    throw FileError(fmt::format("cannot write output '{}': {}", path.string(), error.what()));
  }
  write_file(path, image.data(), image.size());
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
