// Result and Sweep as Python sees them: fields as numpy views of the arrays
// the Run owns (no copies; each view keeps its Result alive), the summary
// numbers, the statistics, saving as `halfspace solve` does, and reading a
// result file back.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nanobind/stl/filesystem.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/shared_ptr.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <sstream>
#include <string>

#include "bindings.hpp"
#include "halfspace/analysis/sweep_table.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/friction_history_writer.hpp"
#include "halfspace/io/result_attributes.hpp"
#include "halfspace/io/result_reader.hpp"
#include "halfspace/io/result_writer.hpp"
#include "halfspace/io/sweep_writer.hpp"
#include "run.hpp"

namespace halfspace::python {
namespace {

using BoolArray = nb::ndarray<nb::numpy, bool>;

OutputArray view(const Eigen::ArrayXd& field, const std::vector<std::size_t>& shape) {
  return OutputArray(const_cast<double*>(field.data()), shape.size(), shape.data(), nb::handle());
}

io::ResultMetadata metadata_of(const Run& run) {
  io::ResultMetadata metadata = io::result_metadata(run.provenance, run.grid, run.heights);
  metadata.coating = run.coating;
  metadata.bodies = run.pair;
  return metadata;
}

nb::dict statistics_of(const Result& r) {
  const analysis::ContactStatistics& c = r.data().statistics;
  nb::dict out;
  out["contact_fraction"] = c.contact_fraction;
  out["mean_gap"] = c.mean_gap;
  out["rms_gap"] = c.rms_gap;
  out["free_volume"] = c.free_volume;
  out["clusters"] = c.clusters();
  out["cluster_sizes"] = nb::cast(c.cluster_sizes);
  out["surface_rms_height"] = r.run->surface.rms_height;
  out["surface_rms_slope"] = r.run->surface.rms_slope;
  return out;
}

// The tangential step a Result shows, or null for a frictionless one.
const TangentialResult* tangential_of(const Result& r) {
  return r.tangential_step < r.run->tangential.size() ? &r.run->tangential[r.tangential_step] : nullptr;
}

// A friction field of the shown step as a view, or None.
nb::object tangential_view(const Result& r, Eigen::ArrayXd TangentialState::*field) {
  const TangentialResult* t = tangential_of(r);
  if (t == nullptr) return nb::none();
  return nb::cast(view(t->state.*field, r.run->shape()), nb::rv_policy::reference_internal, nb::cast(r));
}

// The root attributes a result file holds for this result, as a dict.
nb::dict attributes_of(const Result& r) {
  if (nb::len(r.run->stored_attributes) > 0) return r.run->stored_attributes;
  nb::dict out;
  for (const io::ResultAttribute& attribute : io::result_attributes()) {
    std::visit([&](auto get) { out[nb::str(attribute.name.data(), attribute.name.size())] = get(r.result()); },
               attribute.value);
  }
  if (const TangentialResult* t = tangential_of(r)) {
    for (const io::TangentialAttribute& attribute : io::tangential_attributes()) {
      std::visit([&](auto get) { out[nb::str(attribute.name.data(), attribute.name.size())] = get(*t); },
                 attribute.value);
    }
  }
  return out;
}

std::string describe(const Result& r) {
  const SolveResult& s = r.result();
  return fmt::format(
      "Result({} {} grid, {}: {} after {} iterations, residual {:.2e}; mean pressure {:.6g} Pa, total force {:.6g} "
      "{}, approach {:.6g} m, contact fraction {:.4g})",
      r.run->grid.shape_string(), to_string(r.run->grid.boundary()), s.solver, to_string(s.status), s.iterations,
      s.residual, s.mean_pressure, s.total_force, r.run->grid.dimension() == 1 ? "N/m" : "N", s.approach,
      s.contact_fraction);
}

void save_result(const Result& r, const std::filesystem::path& path) {
  io::ResultMetadata metadata = metadata_of(*r.run);
  metadata.contact_statistics = r.data().statistics;
  metadata.tangential = tangential_of(r);
  nb::gil_scoped_release release;
  io::write_result(path, r.run->grid, r.run->heights, r.result(), metadata);
}

void save_sweep(const Sweep& s, const std::filesystem::path& path) {
  const io::ResultMetadata metadata = metadata_of(*s.run);
  nb::gil_scoped_release release;
  io::write_sweep_result(path, s.run->grid, s.run->heights, s.run->steps, metadata);
  io::write_sweep_csv(io::sweep_csv_path(path), s.run->steps);
}

void save_history(const History& h, const std::filesystem::path& path) {
  io::ResultMetadata metadata = metadata_of(*h.run);
  metadata.contact_statistics = h.run->steps.front().statistics;
  if (h.run->steps.size() > 1) {  // coupled: each step's own normal solution
    for (std::size_t k = 0; k < h.run->tangential.size(); ++k) {
      metadata.step_normals.push_back(&h.run->steps[h.run->normal_of_tangential(k)].result);
    }
  }
  nb::gil_scoped_release release;
  io::write_friction_history(path, h.run->grid, h.run->heights, h.run->steps.front().result, h.run->tangential,
                             h.run->tangential_loads, metadata);
}

template <class T>
T attribute(const io::StoredResult& stored, const std::filesystem::path& path, const std::string& name) {
  const io::AttributeValue* value = stored.find(name);
  if (!value || !std::holds_alternative<T>(*value)) {
    throw FileError(fmt::format("cannot read result '{}': root attribute '{}' is missing or of the wrong type",
                                path.string(), name));
  }
  return std::get<T>(*value);
}

template <class T>
T attribute_or(const io::StoredResult& stored, const std::string& name, T fallback) {
  const io::AttributeValue* value = stored.find(name);
  return value && std::holds_alternative<T>(*value) ? std::get<T>(*value) : fallback;
}

Result read(const std::filesystem::path& path, int step) {
  io::StoredResult stored;
  {
    nb::gil_scoped_release release;
    stored = io::read_result(path, step);
  }
  const auto number = [&](const char* name) { return attribute<double>(stored, path, name); };
  const auto integer = [&](const char* name) { return attribute<std::int64_t>(stored, path, name); };
  const auto text = [&](const char* name) { return attribute<std::string>(stored, path, name); };

  const Boundary boundary = parse_boundary(text("boundary"));
  const auto nx = static_cast<std::size_t>(integer("nx"));
  const auto ny = static_cast<std::size_t>(integer("ny"));
  Grid grid = integer("dimension") == 1 ? Grid::line(nx, number("dx"), boundary)
                                        : Grid::plane(nx, ny, number("dx"), number("dy"), boundary);
  if (grid.size() != static_cast<std::size_t>(stored.height.size())) {
    throw FileError(
        fmt::format("cannot read result '{}': /height does not have nx x ny = {} values", path.string(), grid.size()));
  }

  analysis::SweepStep data;
  SolveResult& s = data.result;
  const std::string status = text("status");
  if (const auto parsed = solvers::parse_solve_status(status)) s.status = *parsed;
  s.message = text("message");
  s.solver = text("solver");
  s.iterations = static_cast<int>(integer("iterations"));
  s.residual = number("residual");
  s.tolerance = number("tolerance");
  s.operator_applications = static_cast<int>(attribute_or<std::int64_t>(stored, "operator_applications", 0));
  s.preconditioner_applications =
      static_cast<int>(attribute_or<std::int64_t>(stored, "preconditioner_applications", 0));
  s.total_force = number("total_force");
  s.mean_pressure = number("mean_pressure");
  s.approach = number("approach");
  s.max_pressure = number("max_pressure");
  s.contact_fraction = number("contact_fraction");
  s.wall_seconds = number("solve_seconds");
  s.residual_history = std::move(stored.residual_history);
  s.pressure = std::move(stored.pressure);
  s.gap = std::move(stored.gap);
  s.displacement = std::move(stored.displacement);

  const std::string mode = text("load_mode");
  for (ControlMode candidate : {ControlMode::force, ControlMode::mean_pressure, ControlMode::approach}) {
    if (to_string(candidate) == mode) data.loading.mode = candidate;
  }
  data.loading.value = data.loading.mode == ControlMode::force           ? s.total_force
                       : data.loading.mode == ControlMode::mean_pressure ? s.mean_pressure
                                                                         : s.approach;
  data.statistics = contact_statistics_of(grid, s);

  auto run = std::make_shared<Run>(Run{std::move(grid), nb::none(), {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}});
  io::SolveProvenance& p = run->provenance;
  p.e_star = number("E_star");
  p.load_mode = data.loading.mode;
  p.threads = static_cast<int>(integer("threads"));
  p.command_line = text("command_line");
  p.config = attribute_or<std::string>(stored, "config", "");
  p.height_source = text("height_source");
  std::istringstream lines(attribute_or<std::string>(stored, "preparation", ""));
  for (std::string line; std::getline(lines, line);) p.preparation.push_back(line);

  const std::vector<std::size_t> shape = run->shape();
  OutputArray heights = owning_array(std::move(stored.height), shape);
  run->heights = {heights.data(), run->grid.size()};
  run->heights_owner = nb::cast(heights);
  run->surface = surface::surface_statistics(run->grid, run->heights);
  run->steps.push_back(std::move(data));
  run->mark_contact();
  for (const auto& [name, value] : stored.attributes) {
    std::visit([&, &key = name](const auto& v) { run->stored_attributes[nb::str(key.c_str())] = v; }, value);
  }
  // A friction result: its tangential step, so that the fields, `friction`
  // and stresses under shear come back as they were solved.
  if (stored.shear_x.size() > 0 && stored.find("tangential_status") != nullptr) {
    TangentialResult t;
    const std::string tangential_status = text("tangential_status");
    if (const auto parsed = solvers::parse_solve_status(tangential_status)) t.status = *parsed;
    t.state.shear_x = std::move(stored.shear_x);
    t.state.shear_y = std::move(stored.shear_y);
    t.state.slip_x = std::move(stored.slip_x);
    t.state.slip_y = std::move(stored.slip_y);
    t.state.displacement_x = std::move(stored.tangential_displacement_x);
    t.state.displacement_y = std::move(stored.tangential_displacement_y);
    t.state.approach_x = number("tangential_approach_x");
    t.state.approach_y = number("tangential_approach_y");
    t.stick = Eigen::ArrayXd(static_cast<Eigen::Index>(stored.stick.size()));
    for (std::size_t k = 0; k < stored.stick.size(); ++k) t.stick[static_cast<Eigen::Index>(k)] = stored.stick[k];
    t.friction_coefficient = number("friction_coefficient");
    t.force_x = number("tangential_force_x");
    t.force_y = number("tangential_force_y");
    t.normal_force = run->steps.front().result.total_force;
    t.stick_fraction = number("stick_fraction");
    t.slip_fraction = number("slip_fraction");
    t.dissipated_energy = number("dissipated_energy");
    t.gross_sliding = integer("gross_sliding") != 0;
    t.iterations = static_cast<int>(integer("tangential_iterations"));
    t.residual = number("tangential_residual");
    t.tolerance = number("tangential_tolerance");
    run->stick.push_back(std::move(stored.stick));
    run->tangential.push_back(std::move(t));
  }
  if (stored.find("body1_E") != nullptr) {
    run->pair = ElasticPair({number("body1_E"), number("body1_nu")}, {number("body2_E"), number("body2_nu")});
  }
  if (stored.find("layer_thickness") != nullptr) {
    run->coating = validated(LayeredMaterial{number("layer_thickness"),
                                             {number("layer_E"), number("layer_nu")},
                                             {number("substrate_E"), number("substrate_nu")}});
  }
  return Result{std::move(run), 0};
}

}  // namespace

std::vector<std::size_t> Run::shape() const {
  return io::field_shape(grid);
}

void Run::mark_contact() {
  contact.clear();
  for (const analysis::SweepStep& s : steps) {
    std::vector<std::uint8_t> marks(grid.size());
    for (std::size_t k = 0; k < marks.size(); ++k) marks[k] = s.result.pressure[static_cast<Eigen::Index>(k)] > 0.0;
    contact.push_back(std::move(marks));
  }
}

void bind_results(nb::module_& module) {
  const auto internal = nb::rv_policy::reference_internal;
  nb::class_<Result>(module, "Result", "The outcome of a solve: fields, summary numbers, statistics.")
      .def_prop_ro(
          "pressure", [](const Result& r) { return view(r.result().pressure, r.run->shape()); }, internal,
          "Contact pressure (Pa), shaped like the surface.")
      .def_prop_ro(
          "gap", [](const Result& r) { return view(r.result().gap, r.run->shape()); }, internal,
          "Gap (m) after loading: initial gap + displacement - approach.")
      .def_prop_ro(
          "displacement", [](const Result& r) { return view(r.result().displacement, r.run->shape()); }, internal,
          "Elastic surface displacement (m), K * pressure.")
      .def_prop_ro(
          "contact",
          [](const Result& r) {
            const std::vector<std::size_t> shape = r.run->shape();
            return BoolArray(reinterpret_cast<bool*>(r.run->contact[r.step].data()), shape.size(), shape.data(),
                             nb::handle());
          },
          internal, "True where the pressure is positive.")
      .def_prop_ro(
          "residual_history",
          [](const Result& r) {
            const std::vector<double>& h = r.result().residual_history;
            const std::size_t n = h.size();
            return OutputArray(const_cast<double*>(h.data()), 1, &n, nb::handle());
          },
          internal, "The residual after each iteration.")
      .def_prop_ro(
          "heights", [](const Result& r) { return r.run->heights_owner; }, "The surface heights (m) solved on.")
      .def_prop_ro("shape",
                   [](const Result& r) {
                     const Grid& g = r.run->grid;
                     return g.dimension() == 1 ? nb::make_tuple(g.nx()) : nb::make_tuple(g.ny(), g.nx());
                   })
      .def_prop_ro("dx", [](const Result& r) { return r.run->grid.dx(); })
      .def_prop_ro("dy", [](const Result& r) { return r.run->grid.dy(); })
      .def_prop_ro("boundary", [](const Result& r) { return std::string(to_string(r.run->grid.boundary())); })
      .def_prop_ro("e_star", [](const Result& r) { return r.run->provenance.e_star; })
      .def_prop_ro("coating",
                   [](const Result& r) -> nb::object {
                     if (!r.run->coating) return nb::none();
                     const LayeredMaterial& c = *r.run->coating;
                     nb::dict out;
                     out["thickness"] = c.thickness;
                     out["layer_E"] = c.layer.youngs_modulus;
                     out["layer_nu"] = c.layer.poissons_ratio;
                     out["substrate_E"] = c.substrate.youngs_modulus;
                     out["substrate_nu"] = c.substrate.poissons_ratio;
                     return out;
                   })
      .def_prop_ro("load_mode", [](const Result& r) { return std::string(to_string(r.data().loading.mode)); })
      .def_prop_ro(
          "load", [](const Result& r) { return r.data().loading.value; }, "The imposed load value.")
      .def_prop_ro(
          "total_force", [](const Result& r) { return r.result().total_force; }, "N (N/m in 1D)")
      .def_prop_ro(
          "mean_pressure", [](const Result& r) { return r.result().mean_pressure; }, "Pa")
      .def_prop_ro(
          "approach", [](const Result& r) { return r.result().approach; }, "m")
      .def_prop_ro("contact_fraction", [](const Result& r) { return r.result().contact_fraction; })
      .def_prop_ro(
          "max_pressure", [](const Result& r) { return r.result().max_pressure; }, "Pa")
      .def_prop_ro(
          "hardness", [](const Result& r) { return r.result().hardness; }, "The hardness cap H (Pa), None if elastic.")
      .def_prop_ro(
          "plastic_fraction", [](const Result& r) { return r.result().plastic_fraction; },
          "Cells at the hardness cap over all cells (0 without a cap).")
      .def_prop_ro(
          "adhesion",
          [](const Result& r) -> nb::object {
            const solvers::AdhesionRecord& a = r.result().adhesion;
            if (a.law.empty()) return nb::none();
            nb::dict out;
            out["law"] = a.law;
            out["work_of_adhesion"] = a.work;
            out["range"] = a.range;
            out["stress"] = a.stress;
            out["adhesive_force"] = a.adhesive_force;
            out["interaction_fraction"] = a.interaction_fraction;
            out["repulsive_contact_fraction"] = a.repulsive_contact_fraction;
            return out;
          },
          "Adhesive solves: the law and the attractive part (adhesive_force, interaction_fraction, "
          "repulsive_contact_fraction); None otherwise.")
      // Friction (solve(friction=...), history()): the shown tangential step's
      // fields as views and its record; None for a frictionless result.
      .def_prop_ro(
          "shear_x", [](const Result& r) { return tangential_view(r, &TangentialState::shear_x); },
          "Friction: shear traction q_x (Pa) that body 1 exerts on body 2, shaped like the surface; None without.")
      .def_prop_ro(
          "shear_y", [](const Result& r) { return tangential_view(r, &TangentialState::shear_y); },
          "Friction: shear traction q_y (Pa); None without friction.")
      .def_prop_ro(
          "slip_x", [](const Result& r) { return tangential_view(r, &TangentialState::slip_x); },
          "Friction: accumulated slip along x (m); None without friction.")
      .def_prop_ro(
          "slip_y", [](const Result& r) { return tangential_view(r, &TangentialState::slip_y); },
          "Friction: accumulated slip along y (m); None without friction.")
      .def_prop_ro(
          "tangential_displacement_x",
          [](const Result& r) { return tangential_view(r, &TangentialState::displacement_x); },
          "Friction: relative elastic tangential surface displacement u_x = (C q)_x (m); None without friction.")
      .def_prop_ro(
          "tangential_displacement_y",
          [](const Result& r) { return tangential_view(r, &TangentialState::displacement_y); },
          "Friction: relative elastic tangential surface displacement u_y (m); None without friction.")
      .def_prop_ro(
          "stick",
          [](const Result& r) -> nb::object {
            if (tangential_of(r) == nullptr) return nb::none();
            const std::vector<std::size_t> shape = r.run->shape();
            return nb::cast(BoolArray(reinterpret_cast<bool*>(r.run->stick[r.tangential_step].data()), shape.size(),
                                      shape.data(), nb::handle()),
                            nb::rv_policy::reference_internal, nb::cast(r));
          },
          "Friction: True where a contact cell sticks; None without friction.")
      .def_prop_ro(
          "friction",
          [](const Result& r) -> nb::object {
            const TangentialResult* t = tangential_of(r);
            if (t == nullptr) return nb::none();
            nb::dict out;
            out["friction_coefficient"] = t->friction_coefficient;
            out["tangential_force"] = nb::make_tuple(t->force_x, t->force_y);
            out["tangential_approach"] = nb::make_tuple(t->state.approach_x, t->state.approach_y);
            out["stick_fraction"] = t->stick_fraction;
            out["slip_fraction"] = t->slip_fraction;
            out["dissipated_energy"] = t->dissipated_energy;
            out["gross_sliding"] = t->gross_sliding;
            out["converged"] = t->converged();
            out["status"] = std::string(to_string(t->status));
            out["message"] = t->message;
            out["iterations"] = t->iterations;
            out["residual"] = t->residual;
            out["coarse_levels"] = t->coarse.levels;
            out["step"] = r.tangential_step;
            out["dundurs_beta"] = t->dundurs_beta;
            out["coupled"] = t->coupled;
            out["coupling_alternations"] = t->coupling_alternations;
            return out;
          },
          "Friction: the tangential step's record: friction_coefficient, tangential_force (x, y) (N, N/m in 1D), "
          "tangential_approach (x, y) (m), stick_fraction and slip_fraction (of the contact cells), "
          "dissipated_energy (J, J/m in 1D; in this step), gross_sliding, converged, status, message, iterations, "
          "residual, coarse_levels (coarser grids that started the step), step; None without friction.")
      .def_prop_ro("iterations", [](const Result& r) { return r.result().iterations; })
      .def_prop_ro("residual", [](const Result& r) { return r.result().residual; })
      .def_prop_ro("tolerance", [](const Result& r) { return r.result().tolerance; })
      .def_prop_ro("converged", [](const Result& r) { return r.result().converged(); })
      .def_prop_ro("status", [](const Result& r) { return std::string(to_string(r.result().status)); })
      .def_prop_ro("message", [](const Result& r) { return r.result().message; })
      .def_prop_ro("solver", [](const Result& r) { return r.result().solver; })
      .def_prop_ro("warnings", [](const Result& r) { return r.result().warnings; })
      .def_prop_ro("solve_seconds", [](const Result& r) { return r.result().wall_seconds; })
      .def_prop_ro("warm_started", [](const Result& r) { return r.data().warm_started; })
      .def_prop_ro("height_source", [](const Result& r) { return r.run->provenance.height_source; })
      .def_prop_ro("preparation", [](const Result& r) { return r.run->provenance.preparation; })
      .def_prop_ro("threads", [](const Result& r) { return r.run->provenance.threads; })
      .def_prop_ro("statistics", &statistics_of,
                   "Contact and surface statistics: contact_fraction, mean_gap, rms_gap, free_volume, clusters, "
                   "cluster_sizes, surface_rms_height, surface_rms_slope.")
      .def_prop_ro("attributes", &attributes_of, "The result file's attributes (those of the solve for a new one).")
      .def("save", &save_result, nb::arg("path"),
           "Writes the HDF5 result file `halfspace solve` writes (docs/file-format.md), and its XDMF sidecar "
           "(same name, .xdmf) for ParaView.")
      .def("__repr__", &describe);

  nb::class_<Sweep>(module, "Sweep", "A load sweep: one Result per step and the summary table.")
      .def("__len__", [](const Sweep& s) { return s.run->steps.size(); })
      .def(
          "__getitem__",
          [](const Sweep& s, long k) {
            const long n = static_cast<long>(s.run->steps.size());
            if (k < 0) k += n;
            if (k < 0 || k >= n) throw nb::index_error("sweep step out of range");
            return Result{s.run, static_cast<std::size_t>(k)};
          },
          nb::arg("step"))
      .def_prop_ro(
          "table",
          [](const Sweep& s) {
            nb::dict table;
            for (const analysis::SummaryColumn& column : analysis::summary_columns()) {
              Eigen::ArrayXd values(static_cast<Eigen::Index>(s.run->steps.size()));
              for (std::size_t k = 0; k < s.run->steps.size(); ++k) values[k] = column.value(s.run->steps[k]);
              table[nb::str(column.name.data(), column.name.size())] =
                  owning_array(std::move(values), {s.run->steps.size()});
            }
            return table;
          },
          "The summary table: one float64 array per column, one entry per step.")
      .def_prop_ro("load_mode", [](const Sweep& s) { return std::string(to_string(s.run->provenance.load_mode)); })
      .def("save", &save_sweep, nb::arg("path"),
           "Writes the sweep's HDF5 file, the CSV table (same name, .csv) and the XDMF sidecar (.xdmf) beside it, as "
           "`halfspace solve` does.")
      .def("__repr__", [](const Sweep& s) {
        std::size_t converged = 0;
        for (const auto& step : s.run->steps) converged += step.result.converged() ? 1 : 0;
        return fmt::format("Sweep({} steps of {} on the {} {} grid, {} converged)", s.run->steps.size(),
                           to_string(s.run->provenance.load_mode), s.run->grid.shape_string(),
                           to_string(s.run->grid.boundary()), converged);
      });

  nb::class_<History>(module, "History",
                      "A tangential load history (friction): one Result per step (the normal contact with that "
                      "step's shear; coupled, dissimilar bodies: the step's own pressure) and the history table.")
      .def("__len__", [](const History& h) { return h.run->tangential.size(); })
      .def(
          "__getitem__",
          [](const History& h, long k) {
            const long n = static_cast<long>(h.run->tangential.size());
            if (k < 0) k += n;
            if (k < 0 || k >= n) throw nb::index_error("history step out of range");
            const auto step = static_cast<std::size_t>(k);
            return Result{h.run, h.run->normal_of_tangential(step), step};
          },
          nb::arg("step"))
      .def_prop_ro(
          "normal",
          [](const History& h) {
            return Result{h.run, 0, h.run->tangential.size()};
          },
          "The normal contact alone (no friction fields).")
      .def_prop_ro(
          "converged",
          [](const History& h) {
            if (!h.run->steps.front().result.converged()) return false;
            for (const TangentialResult& t : h.run->tangential) {
              if (!t.converged()) return false;
            }
            return !h.run->tangential.empty();
          },
          "The normal solve and every step solved converged (a history stops at the first step that does not).")
      .def_prop_ro(
          "table",
          [](const History& h) {
            const std::size_t n = h.run->tangential.size();
            nb::dict table;
            const auto column = [&](const char* name, auto get) {
              Eigen::ArrayXd values(static_cast<Eigen::Index>(n));
              for (std::size_t k = 0; k < n; ++k) values[static_cast<Eigen::Index>(k)] = get(k, h.run->tangential[k]);
              table[name] = owning_array(std::move(values), {n});
            };
            column("step", [](std::size_t k, const TangentialResult&) { return static_cast<double>(k); });
            column("Q_x", [](std::size_t, const TangentialResult& t) { return t.force_x; });
            column("Q_y", [](std::size_t, const TangentialResult& t) { return t.force_y; });
            column("delta_x", [](std::size_t, const TangentialResult& t) { return t.state.approach_x; });
            column("delta_y", [](std::size_t, const TangentialResult& t) { return t.state.approach_y; });
            column("stick_fraction", [](std::size_t, const TangentialResult& t) { return t.stick_fraction; });
            column("dissipated_energy", [](std::size_t, const TangentialResult& t) { return t.dissipated_energy; });
            return table;
          },
          "The history table (the CSV's columns): step, Q_x, Q_y (N, N/m in 1D), delta_x, delta_y (m), "
          "stick_fraction, dissipated_energy (J, J/m in 1D, per step).")
      .def("save", &save_history, nb::arg("path"),
           "Writes the history file `halfspace solve --friction` writes for several steps, its CSV table (same "
           "name, .csv) and XDMF sidecar (.xdmf).")
      .def("__repr__", [](const History& h) {
        return fmt::format("History({} tangential steps on the {} {} grid, mu = {:g})", h.run->tangential.size(),
                           h.run->grid.shape_string(), to_string(h.run->grid.boundary()),
                           h.run->tangential.empty() ? 0.0 : h.run->tangential.front().friction_coefficient);
      });

  module.def("read_result", &read, nb::arg("path"), nb::arg("step") = -1);
}

}  // namespace halfspace::python
