// halfspace.solve and halfspace.sweep: the options mapped onto the library's
// typed front door (SolverOptions, Loading), the solve run with the GIL
// released, and Ctrl-C and the progress callable served between iterations.
#include <fmt/format.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "halfspace/error.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/material.hpp"
#include "halfspace/physical_ranges.hpp"
#include "halfspace/solvers/adhesion_law.hpp"
#include "halfspace/solvers/frictional_solve.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/threads.hpp"
#include "run.hpp"

namespace halfspace::python {
namespace {

// Thrown from the progress hook when a Python error (KeyboardInterrupt from
// Ctrl-C, or an exception of the user's progress callable) is pending: it
// unwinds the solve, whose state is all RAII, and the binding re-raises the
// Python error once the GIL is back.
struct PythonErrorPending {};

// SolverOptions::progress while the GIL is released. It runs on the calling
// thread between iterations; it takes the GIL to check for signals every
// kSignalCheckInterval, or at every iteration when the user gave a callable
// (calling it needs the GIL anyway).
class ProgressHook {
 public:
  explicit ProgressHook(nb::object callback) : callback_(std::move(callback)) {}

  void operator()(int iteration, double residual) {
    const bool call = !callback_.is_none();
    if (!call) {
      const auto now = std::chrono::steady_clock::now();
      if (now < next_check_) return;
      next_check_ = now + kSignalCheckInterval;
    }
    nb::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw PythonErrorPending{};
    if (call) {
      try {
        callback_(iteration, residual);
      } catch (nb::python_error& error) {
        error.restore();
        throw PythonErrorPending{};
      }
    }
  }

 private:
  // Short enough that Ctrl-C feels immediate, long enough that the GIL is
  // taken a negligible number of times.
  static constexpr std::chrono::milliseconds kSignalCheckInterval{100};
  nb::object callback_;
  std::chrono::steady_clock::time_point next_check_ = std::chrono::steady_clock::now() + kSignalCheckInterval;
};

struct Problem {
  Grid grid;
  nb::object heights_owner;
  std::span<const double> heights;
};

Problem problem_from(const nb::object& heights_object, double dx, double dy, const std::string& boundary_name) {
  const auto heights = nb::cast<InputArray>(heights_object, false);
  if (heights.ndim() != 1 && heights.ndim() != 2) {
    throw InputError(fmt::format("the surface must be a 1D or 2D array, got {} dimensions", heights.ndim()));
  }
  Boundary boundary;
  try {
    boundary = parse_boundary(boundary_name);
  } catch (const InputError& error) {
    throw InputError(fmt::format("boundary: {}", error.what()));
  }
  Grid grid = heights.ndim() == 1 ? Grid::line(heights.shape(0), dx, boundary)
                                  : Grid::plane(heights.shape(1), heights.shape(0), dx, dy, boundary);
  for (std::size_t k = 0; k < heights.size(); ++k) {
    if (!std::isfinite(heights.data()[k])) {
      throw InputError(fmt::format(
          "the surface has a non-finite height at index {}: prepare it first (HeightMap.prepare(invalid='fill'))", k));
    }
  }
  return {std::move(grid), heights_object, values(heights)};
}

// The keywords of halfspace.solve that set SolverOptions, each mapped onto
// its member here and nowhere else; validate() holds the rules. A feature
// that adds a solver option adds one entry (docs/python.md, "Adding an
// option"). Keywords not listed are refused, so a misspelt one never passes
// silently.
solvers::SolverOptions solver_options(const nb::dict& given, const Grid& grid) {
  solvers::SolverOptions options;
  // Adhesion comes in four keywords; the law is made from them after the loop.
  std::optional<std::string> adhesion;
  std::optional<double> work, range, stress, adhesion_tol;
  std::optional<bool> adhesion_precondition;
  for (const auto& [key_object, value] : given) {
    if (value.is_none()) continue;
    const std::string key = nb::cast<std::string>(key_object);
    const auto named = [&](auto&& parse) {
      try {
        return parse();
      } catch (const OptionError&) {
        throw;
      } catch (const InputError& error) {
        throw InputError(fmt::format("{}: {}", key, error.what()));
      }
    };
    if (key == "solver") {
      options.type = solvers::parse_solver_type(nb::cast<std::string>(value));
    } else if (key == "tol") {
      options.tolerance = nb::cast<double>(value);
    } else if (key == "max_iter") {
      options.max_iterations = nb::cast<int>(value);
    } else if (key == "fft_planning") {
      options.fft_planning = named([&] { return parse_fft_planning(nb::cast<std::string>(value)); });
    } else if (key == "deflation_block") {
      const long block = nb::cast<long>(value);
      if (block < 0)
        throw InputError(fmt::format("deflation_block={} is invalid: give 0 (off) or a block size", block));
      options.deflation.mode = block == 0 ? solvers::DeflationOptions::Mode::off : solvers::DeflationOptions::Mode::on;
      if (block != 0) options.deflation.block = static_cast<std::size_t>(block);
    } else if (key == "hardness") {
      options.interface_law.hardness = nb::cast<double>(value);
    } else if (key == "adhesion") {
      adhesion = nb::cast<std::string>(value);
    } else if (key == "work_of_adhesion") {
      work = nb::cast<double>(value);
    } else if (key == "adhesion_range") {
      range = nb::cast<double>(value);
    } else if (key == "adhesion_stress") {
      stress = nb::cast<double>(value);
    } else if (key == "adhesion_tol") {
      adhesion_tol = nb::cast<double>(value);
    } else if (key == "adhesion_precondition") {
      adhesion_precondition = nb::cast<bool>(value);
    } else {
      throw InputError(fmt::format("unknown solver option '{}'", key));
    }
  }
  if (!adhesion) {
    if (work || range || stress || adhesion_tol || adhesion_precondition) {
      throw InputError(
          "work_of_adhesion, adhesion_range, adhesion_stress, adhesion_tol and adhesion_precondition need "
          "adhesion=\"md\" or adhesion=\"exponential\"");
    }
  } else {
    const solvers::AdhesionLawType type = solvers::parse_adhesion_law_type(*adhesion);
    if (!work) throw InputError(fmt::format("adhesion='{}' needs work_of_adhesion (J/m^2)", *adhesion));
    if (range && stress) {
      throw InputError("adhesion_range and adhesion_stress cannot be combined: give h0 or sigma0 = w / h0");
    }
    if (stress && type != solvers::AdhesionLawType::maugis_dugdale) {
      throw InputError("adhesion_stress applies to adhesion='md' only; give adhesion_range (rho, m)");
    }
    if (!range && !stress) throw InputError(fmt::format("adhesion='{}' needs adhesion_range (m)", *adhesion));
    solvers::SolverOptions::Adhesion law;
    law.law = stress ? solvers::AdhesionLaw::maugis_dugdale_from_stress(*work, *stress)
                     : solvers::AdhesionLaw{type, *work, *range};
    // The program's ranges, given or derived (physical_ranges.hpp).
    check_adhesion_law_ranges(law.law, stress.has_value());
    if (adhesion_tol) law.tolerance = *adhesion_tol;
    if (adhesion_precondition) law.precondition = *adhesion_precondition;
    options.adhesion = law;
  }
  options.validate(grid);
  return options;
}

ControlMode control_mode(const std::string& mode) {
  for (ControlMode candidate : {ControlMode::force, ControlMode::mean_pressure, ControlMode::approach}) {
    if (to_string(candidate) == mode) return candidate;
  }
  throw InputError(fmt::format("load mode '{}' is invalid: use force, mean_pressure or approach", mode));
}

int thread_count(std::optional<int> threads) {
  if (!threads) return default_threads();
  if (*threads < 1 || *threads > max_threads()) {
    throw InputError(fmt::format("threads={} is invalid: allowed range is 1 to {} ({} x the {} hardware threads)",
                                 *threads, max_threads(), kThreadsPerHardwareThread, hardware_threads()));
  }
  return *threads;
}

// Runs `work` with the GIL released and `hook` as the solver's progress;
// re-raises a Python error the hook left pending.
template <class Work>
auto run_released(Work&& work) {
  try {
    nb::gil_scoped_release release;
    return work();
  } catch (const PythonErrorPending&) {
    throw nb::python_error();
  }
}

std::shared_ptr<Run> make_run(Problem&& problem, io::SolveProvenance&& provenance,
                              std::vector<analysis::SweepStep>&& steps, const std::optional<LayeredMaterial>& coating) {
  auto run = std::make_shared<Run>(Run{std::move(problem.grid),
                                       std::move(problem.heights_owner),
                                       problem.heights,
                                       std::move(provenance),
                                       {},
                                       {},
                                       {},
                                       {},
                                       coating,
                                       {},
                                       {},
                                       {},
                                       {}});
  run->steps = std::move(steps);
  run->surface = surface::surface_statistics(run->grid, run->heights);
  run->mark_contact();
  return run;
}

// The coated half-space of the `coating` keyword (thickness, layer E and nu,
// substrate E and nu, as _solve.py orders them), validated; E* becomes the
// layer's E1*, as the program records it.
std::optional<LayeredMaterial> coating_from(const std::optional<std::vector<double>>& values, double& e_star) {
  if (!values) {
    e_star = checked_composite_modulus(e_star);
    return std::nullopt;
  }
  if (values->size() != 5)
    throw InputError("coating needs five values: thickness, layer_E, layer_nu, substrate_E, substrate_nu");
  const std::vector<double>& v = *values;
  LayeredMaterial coating{v[0], {v[1], v[2]}, {v[3], v[4]}};
  try {
    validated(coating);
  } catch (const InputError& error) {
    throw InputError(fmt::format("coating: {}", error.what()));
  }
  e_star = plane_strain_modulus(coating.layer);
  return coating;
}

Result solve(const nb::object& heights, double dx, double dy, const std::string& boundary, double e_star,
             const std::optional<std::vector<double>>& coating_values, const std::string& mode, double value,
             const nb::dict& solver, std::optional<int> threads, const std::optional<InputArray>& initial_pressure,
             nb::object progress, const std::string& command_line, const std::string& height_source,
             const std::vector<std::string>& preparation) {
  Problem problem = problem_from(heights, dx, dy, boundary);
  const std::optional<LayeredMaterial> coating = coating_from(coating_values, e_star);
  const Loading loading{control_mode(mode), value};
  solvers::SolverOptions options = solver_options(solver, problem.grid);
  if (!options.adhesion) {
    loading.validate();
  } else if (!std::isfinite(value)) {  // adhesive loads are signed (pulling is negative)
    throw InputError(fmt::format("{} = {} is invalid: must be finite", mode, format_number(value)));
  }
  const int thread_number = thread_count(threads);
  std::span<const double> start;
  if (initial_pressure) {
    start = values(*initial_pressure);
    if (start.size() != problem.grid.size()) {
      throw InputError(
          fmt::format("initial_pressure has {} values but the surface has {}", start.size(), problem.grid.size()));
    }
  }
  ProgressHook hook(std::move(progress));
  options.progress = [&hook](int iteration, double residual) { hook(iteration, residual); };

  analysis::SweepStep step;
  step.loading = loading;
  step.warm_started = !start.empty();
  step.result = run_released([&] {
    set_threads(thread_number);
    return coating ? solvers::solve_surface(problem.grid, problem.heights, *coating, loading, options, start)
                   : solvers::solve_surface(problem.grid, problem.heights, e_star, loading, options, start);
  });
  step.statistics = contact_statistics_of(problem.grid, step.result);
  std::vector<analysis::SweepStep> steps;
  steps.push_back(std::move(step));
  return Result{
      make_run(std::move(problem), {e_star, loading.mode, thread_number, command_line, "", height_source, preparation},
               std::move(steps), coating),
      0};
}

Sweep sweep(const nb::object& heights, double dx, double dy, const std::string& boundary, double e_star,
            const std::optional<std::vector<double>>& coating_values, const std::string& mode,
            const std::vector<double>& load_values, const nb::dict& solver, std::optional<int> threads, bool warm_start,
            nb::object progress, const std::string& command_line, const std::string& height_source,
            const std::vector<std::string>& preparation) {
  Problem problem = problem_from(heights, dx, dy, boundary);
  const std::optional<LayeredMaterial> coating = coating_from(coating_values, e_star);
  const ControlMode control = control_mode(mode);
  solvers::SolverOptions options = solver_options(solver, problem.grid);
  const int thread_number = thread_count(threads);
  ProgressHook hook(std::move(progress));
  options.progress = [&hook](int iteration, double residual) { hook(iteration, residual); };
  analysis::LoadSweepOptions sweep_options;
  sweep_options.warm_start = warm_start;
  sweep_options.signed_loads = options.adhesion.has_value();  // pulling is a negative load

  std::vector<analysis::SweepStep> steps = run_released([&] {
    set_threads(thread_number);
    return coating ? analysis::sweep_surface(problem.grid, problem.heights, *coating, control, load_values, options,
                                             sweep_options)
                   : analysis::sweep_surface(problem.grid, problem.heights, e_star, control, load_values, options,
                                             sweep_options);
  });
  return Sweep{make_run(std::move(problem),
                        {e_star, control, thread_number, command_line, "", height_source, preparation},
                        std::move(steps), coating)};
}

// A FrictionOptions rule restated with the keyword it came from.
[[noreturn]] void restate_friction_rule(const solvers::SolverOptionError& error, const std::string& control) {
  const std::string& option = error.option();
  const std::string keyword = option == "tangential_load"  ? "tangential_" + control
                              : option == "tolerance"      ? "tangential_tol"
                              : option == "max_iterations" ? "tangential_max_iter"
                              : option == "pair"           ? "E1, nu1, E2, nu2"
                                                           : option;
  if (option == "coating" || option == "processes" || (option == "pair" && error.value() == "E* only")) {
    throw InputError(fmt::format("{} {} (friction)", option == "pair" ? "e_star" : option, error.rule()));
  }
  throw InputError(fmt::format("{}={} {}", keyword, error.value(), error.rule()));
}

// halfspace.solve(friction=...) and halfspace.history: the normal solve, then
// the tangential steps under its pressure (frictional_solve.hpp), mapped from
// the keywords onto FrictionOptions, whose validate() holds the rules.
// `control` is "force", "displacement" or "sliding" (then `loads` holds the
// one direction); E1 is None when the material was given as e_star.
History friction(const nb::object& heights, double dx, double dy, const std::string& boundary, std::optional<double> e1,
                 double nu1, double e2, double nu2, bool coated, const std::string& mode, double value,
                 const nb::dict& solver, std::optional<int> threads, nb::object progress, double mu,
                 const std::string& control, const std::vector<std::vector<double>>& loads,
                 std::optional<double> tangential_tol, std::optional<int> tangential_max_iter,
                 const std::string& command_line, const std::string& height_source,
                 const std::vector<std::string>& preparation) {
  Problem problem = problem_from(heights, dx, dy, boundary);
  const Loading loading{control_mode(mode), value};
  solvers::SolverOptions options = solver_options(solver, problem.grid);
  solvers::FrictionOptions friction;
  friction.friction_coefficient = mu;
  for (const std::vector<double>& load : loads) {
    if (load.size() != 2) throw InputError(fmt::format("tangential_{}: each step is (x, y)", control));
    if (control == "sliding") {
      friction.sliding_direction = {{load[0], load[1]}};
    } else {
      friction.history.push_back(control == "force" ? TangentialLoading::force(load[0], load[1])
                                                    : TangentialLoading::displacement(load[0], load[1]));
    }
  }
  if (tangential_tol) friction.tolerance = *tangential_tol;
  if (tangential_max_iter) friction.max_iterations = *tangential_max_iter;
  std::optional<ElasticPair> pair;
  try {
    friction.validate();
    if (coated) solvers::FrictionOptions::refuse_coating();
    if (!e1) solvers::FrictionOptions::refuse_composite_modulus_only();
    pair.emplace(ElasticBody{*e1, nu1}, ElasticBody{e2, nu2});
    friction.validate(problem.grid, *pair, options, loading);
  } catch (const solvers::SolverOptionError& error) {
    restate_friction_rule(error, control);
  }
  if (!options.adhesion) loading.validate();
  const int thread_number = thread_count(threads);
  ProgressHook hook(std::move(progress));
  options.progress = [&hook](int iteration, double residual) { hook(iteration, residual); };
  friction.progress = [&hook](std::size_t, int iteration, double residual) { hook(iteration, residual); };

  const double e_star = pair->composite_modulus();
  FrictionalSolveResult solved = run_released([&] {
    set_threads(thread_number);
    return solvers::solve_frictional_surface(problem.grid, problem.heights, *pair, loading, options, friction);
  });
  analysis::SweepStep step;
  step.loading = loading;
  // A coupled single step (dissimilar bodies) carries its own pressure, under
  // its shear; a history the normal loading's.
  const bool own_pressure = solved.coupled && solved.steps.size() == 1 && solved.step_normals.size() == 1;
  step.result = own_pressure ? std::move(solved.step_normals.front()) : std::move(solved.normal);
  step.statistics = contact_statistics_of(problem.grid, step.result);
  std::vector<analysis::SweepStep> steps;
  steps.push_back(std::move(step));
  std::shared_ptr<Run> run =
      make_run(std::move(problem), {e_star, loading.mode, thread_number, command_line, "", height_source, preparation},
               std::move(steps), std::nullopt);
  run->pair = pair;
  run->tangential = std::move(solved.steps);
  run->tangential_loads = friction.history;
  if (friction.sliding_direction && !run->tangential.empty()) {
    run->tangential_loads = {
        TangentialLoading::force(run->tangential.front().force_x, run->tangential.front().force_y)};
  }
  run->tangential_loads.resize(run->tangential.size());
  for (const TangentialResult& t : run->tangential) {
    std::vector<std::uint8_t> marks(static_cast<std::size_t>(t.stick.size()));
    for (std::size_t k = 0; k < marks.size(); ++k) marks[k] = t.stick[static_cast<Eigen::Index>(k)] > 0.5 ? 1 : 0;
    run->stick.push_back(std::move(marks));
  }
  return History{std::move(run)};
}

}  // namespace

void bind_solve(nb::module_& module) {
  module.def("friction", &friction, nb::arg("heights"), nb::arg("dx"), nb::arg("dy"), nb::arg("boundary"),
             nb::arg("E1").none(), nb::arg("nu1"), nb::arg("E2"), nb::arg("nu2"), nb::arg("coated"), nb::arg("mode"),
             nb::arg("value"), nb::arg("solver"), nb::arg("threads").none(), nb::arg("progress").none(), nb::arg("mu"),
             nb::arg("control"), nb::arg("loads"), nb::arg("tangential_tol").none(),
             nb::arg("tangential_max_iter").none(), nb::arg("command_line"), nb::arg("height_source"),
             nb::arg("preparation"));
  module.def("solve", &solve, nb::arg("heights"), nb::arg("dx"), nb::arg("dy"), nb::arg("boundary"), nb::arg("e_star"),
             nb::arg("coating").none(), nb::arg("mode"), nb::arg("value"), nb::arg("solver"), nb::arg("threads").none(),
             nb::arg("initial_pressure").none(), nb::arg("progress").none(), nb::arg("command_line"),
             nb::arg("height_source"), nb::arg("preparation"));
  module.def("sweep", &sweep, nb::arg("heights"), nb::arg("dx"), nb::arg("dy"), nb::arg("boundary"), nb::arg("e_star"),
             nb::arg("coating").none(), nb::arg("mode"), nb::arg("values"), nb::arg("solver"),
             nb::arg("threads").none(), nb::arg("warm_start"), nb::arg("progress").none(), nb::arg("command_line"),
             nb::arg("height_source"), nb::arg("preparation"));
}

}  // namespace halfspace::python
