// halfspace.solve and halfspace.sweep: the keywords mapped onto the library's
// problem (problem.hpp, whose make_problem holds every rule), the solve run with the GIL
// released, and Ctrl-C and the progress callable served between iterations.
#include <fmt/format.h>
#include <nanobind/stl/array.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <variant>

#include "bindings.hpp"
#include "halfspace/error.hpp"
#include "halfspace/problem.hpp"
#include "halfspace/solvers/frictional_solve.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/threads.hpp"
#include "run.hpp"

namespace halfspace::python {
namespace {

// SolverOptions::progress while the GIL is released. It runs on the calling
// thread between iterations; it takes the GIL to check for signals every
// kSignalCheckInterval, or at every iteration when the user gave a callable
// (calling it needs the GIL anyway). The solve stops (status "stopped") when
// the callable returns False, or when a Python error is pending
// (KeyboardInterrupt from Ctrl-C, or the callable's exception): run_released
// then raises it.
class ProgressHook {
 public:
  explicit ProgressHook(nb::object callback) : callback_(std::move(callback)) {}

  solvers::IterationDecision operator()(int iteration, double residual) {
    if (error_pending_) return solvers::IterationDecision::stop;
    const bool call = !callback_.is_none();
    if (!call) {
      const auto now = std::chrono::steady_clock::now();
      if (now < next_check_) return solvers::IterationDecision::proceed;
      next_check_ = now + kSignalCheckInterval;
    }
    nb::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) return stop_with_error();
    if (!call) return solvers::IterationDecision::proceed;
    try {
      const nb::object answer = callback_(iteration, residual);
      return answer.ptr() == Py_False ? solvers::IterationDecision::stop : solvers::IterationDecision::proceed;
    } catch (nb::python_error& error) {
      error.restore();
      return stop_with_error();
    }
  }
  solvers::ProgressCallback callback() {
    return [this](int iteration, double residual) { return (*this)(iteration, residual); };
  }
  bool error_pending() const { return error_pending_; }

 private:
  solvers::IterationDecision stop_with_error() {
    error_pending_ = true;
    return solvers::IterationDecision::stop;
  }
  // Short enough that Ctrl-C feels immediate, long enough that the GIL is
  // taken a negligible number of times.
  static constexpr std::chrono::milliseconds kSignalCheckInterval{100};
  nb::object callback_;
  std::chrono::steady_clock::time_point next_check_ = std::chrono::steady_clock::now() + kSignalCheckInterval;
  bool error_pending_ = false;
};

struct ArraySurface {
  Grid grid;
  nb::object heights_owner;
  std::span<const double> heights;
};

ArraySurface surface_from(const nb::object& heights_object, double dx, double dy, const std::string& boundary_name) {
  const auto heights = nb::cast<InputArray>(heights_object, false);
  const Boundary boundary = in_context("boundary", [&] { return parse_boundary(boundary_name); });
  Grid grid = array_grid(heights, dx, dy, boundary, "the surface");
  require_finite_heights(heights, "the surface");
  return {std::move(grid), heights_object, values(heights)};
}

// The problem's keywords (halfspace/problem.hpp: the keyword is the name in
// problem_option_names) set from `given`, and checked on `surface` by the
// library's make_problem.
Problem checked_problem(const nb::dict& given, const ArraySurface& surface) {
  const auto options = options_from<ProblemOptions>(given, problem_option_names(), "solver option");
  const KeywordSpelling keywords;
  Problem problem = make_problem(options, keywords);
  problem.check_grid(surface.grid, keywords);
  problem.check_heights(surface.grid, surface.heights, keywords);
  return problem;
}

// Runs `work` with the GIL released and `hook` as the solver's progress;
// raises the Python error the hook stopped the solve for.
template <class Work>
auto run_released(const ProgressHook& hook, Work&& work) {
  auto result = [&] {
    nb::gil_scoped_release release;
    return work();
  }();
  if (hook.error_pending()) throw nb::python_error();
  return result;
}

std::shared_ptr<Run> make_run(ArraySurface&& surface, const Problem& problem, io::SolveProvenance&& provenance,
                              std::vector<analysis::SweepStep>&& steps) {
  auto run = std::make_shared<Run>(Run{std::move(surface.grid),
                                       std::move(surface.heights_owner),
                                       surface.heights,
                                       std::move(provenance),
                                       {},
                                       {},
                                       {},
                                       {},
                                       problem.coating,
                                       {},
                                       {},
                                       {},
                                       {}});
  if (!problem.coating) run->pair = problem.pair;  // both bodies, when given (whose stresses)
  run->steps = std::move(steps);
  run->surface = surface::surface_statistics(run->grid, run->heights);
  run->mark_contact();
  return run;
}

// The single solve of halfspace.solve: `problem` holds the keywords of
// problem.hpp (body, interface law, the load as a one-value list, solver,
// threads).
Result solve(const nb::object& heights, double dx, double dy, const std::string& boundary,
             const nb::dict& problem_keywords, const std::optional<InputArray>& initial_pressure, nb::object progress,
             const std::string& command_line, const std::string& height_source,
             const std::vector<std::string>& preparation) {
  ArraySurface surface = surface_from(heights, dx, dy, boundary);
  Problem problem = checked_problem(problem_keywords, surface);
  std::span<const double> start;
  if (initial_pressure) {
    start = values(*initial_pressure);
    check_field_size("initial_pressure", start.size(), surface.grid);
  }
  ProgressHook hook(std::move(progress));
  problem.solver.progress = hook.callback();

  analysis::SweepStep step;
  step.loading = problem.loading;
  step.warm_started = !start.empty();
  step.result = run_released(hook, [&] {
    set_threads(problem.threads);
    return problem.coating ? solvers::solve_surface(surface.grid, surface.heights, *problem.coating, problem.loading,
                                                    problem.solver, start)
                           : solvers::solve_surface(surface.grid, surface.heights, problem.e_star, problem.loading,
                                                    problem.solver, start);
  });
  step.statistics = contact_statistics_of(surface.grid, step.result);
  std::vector<analysis::SweepStep> steps;
  steps.push_back(std::move(step));
  io::SolveProvenance provenance{problem.e_star, problem.loading.mode, problem.threads, command_line, "",
                                 height_source,  preparation};
  return Result{make_run(std::move(surface), problem, std::move(provenance), std::move(steps)), 0};
}

Sweep sweep(const nb::object& heights, double dx, double dy, const std::string& boundary,
            const nb::dict& problem_keywords, bool warm_start, nb::object progress, const std::string& command_line,
            const std::string& height_source, const std::vector<std::string>& preparation) {
  ArraySurface surface = surface_from(heights, dx, dy, boundary);
  Problem problem = checked_problem(problem_keywords, surface);
  ProgressHook hook(std::move(progress));
  problem.solver.progress = hook.callback();
  analysis::LoadSweepOptions sweep_options;
  sweep_options.warm_start = warm_start;
  sweep_options.signed_loads = problem.solver.adhesion.has_value();  // pulling is a negative load

  const ControlMode mode = problem.loading.mode;
  std::vector<analysis::SweepStep> steps = run_released(hook, [&] {
    set_threads(problem.threads);
    return problem.coating ? analysis::sweep_surface(surface.grid, surface.heights, *problem.coating, mode,
                                                     problem.load_values, problem.solver, sweep_options)
                           : analysis::sweep_surface(surface.grid, surface.heights, problem.e_star, mode,
                                                     problem.load_values, problem.solver, sweep_options);
  });
  io::SolveProvenance provenance{problem.e_star, mode, problem.threads, command_line, "", height_source, preparation};
  return Sweep{make_run(std::move(surface), problem, std::move(provenance), std::move(steps))};
}

// halfspace.solve(friction=...) and halfspace.history: the normal solve, then
// the tangential steps under its pressure (frictional_solve.hpp).
// `problem_keywords` as for solve, with friction's (problem.hpp: friction,
// tangential_force or tangential_displacement as steps (x, y), or sliding,
// tangential_tol, tangential_max_iter, tangential_release_period,
// tangential_active_set, tangential_coarse_start);
// make_problem holds their rules.
History friction(const nb::object& heights, double dx, double dy, const std::string& boundary,
                 const nb::dict& problem_keywords, nb::object progress, const std::string& command_line,
                 const std::string& height_source, const std::vector<std::string>& preparation) {
  ArraySurface surface = surface_from(heights, dx, dy, boundary);
  Problem problem = checked_problem(problem_keywords, surface);
  if (!problem.friction) throw InputError("the frictional solve needs friction=MU (the Coulomb friction coefficient)");
  // With friction make_problem has both bodies.
  solvers::FrictionOptions& friction = *problem.friction;
  const ElasticPair& pair = *problem.pair;
  ProgressHook hook(std::move(progress));
  problem.solver.progress = hook.callback();
  friction.progress = [&hook](std::size_t, int iteration, double residual) { return hook(iteration, residual); };

  FrictionalSolveResult solved = run_released(hook, [&] {
    set_threads(problem.threads);
    return solvers::solve_frictional_surface(surface.grid, surface.heights, pair, problem.loading, problem.solver,
                                             friction);
  });
  // The normal contact first (Run's steps[0]). A coupled single step
  // (dissimilar bodies) carries its own pressure, under its shear; a coupled
  // history has the normal loading's and then each step's own (Run).
  const bool own_pressure = solved.coupled && solved.steps.size() == 1 && solved.step_normals.size() == 1;
  std::vector<analysis::SweepStep> steps;
  const auto add = [&](SolveResult&& result) {
    analysis::SweepStep& step = steps.emplace_back();
    step.loading = problem.loading;
    step.result = std::move(result);
    step.statistics = contact_statistics_of(surface.grid, step.result);
  };
  add(own_pressure ? std::move(solved.step_normals.front()) : std::move(solved.normal));
  if (solved.coupled && solved.steps.size() > 1) {
    for (SolveResult& normal : solved.step_normals) add(std::move(normal));
  }
  io::SolveProvenance provenance{
      pair.composite_modulus(), problem.loading.mode, problem.threads, command_line, "", height_source, preparation};
  std::shared_ptr<Run> run = make_run(std::move(surface), problem, std::move(provenance), std::move(steps));
  run->pair = problem.pair;  // the coated body too (ElasticPair::coated)
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
             nb::arg("problem"), nb::arg("progress").none(), nb::arg("command_line"), nb::arg("height_source"),
             nb::arg("preparation"));
  module.def("solve", &solve, nb::arg("heights"), nb::arg("dx"), nb::arg("dy"), nb::arg("boundary"), nb::arg("problem"),
             nb::arg("initial_pressure").none(), nb::arg("progress").none(), nb::arg("command_line"),
             nb::arg("height_source"), nb::arg("preparation"));
  module.def("sweep", &sweep, nb::arg("heights"), nb::arg("dx"), nb::arg("dy"), nb::arg("boundary"), nb::arg("problem"),
             nb::arg("warm_start"), nb::arg("progress").none(), nb::arg("command_line"), nb::arg("height_source"),
             nb::arg("preparation"));
}

}  // namespace halfspace::python
