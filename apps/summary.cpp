// Formatting of the solve summary: a label column and values with their units
// (force is N on a 2D grid and N/m on a 1D one, as everywhere in halfspace).
#include "summary.hpp"

#include <fmt/format.h>

#include <string>

#include "halfspace/version.hpp"
#include "sweep_command.hpp"

namespace halfspace::app {
namespace {

void row(std::FILE* out, std::string_view label, const std::string& value) {
  fmt::print(out, "  {:<17} {}\n", label, value);
}

std::string_view force_unit(const Grid& grid) {
  return grid.dimension() == 1 ? "N/m" : "N";
}

std::string grid_text(const Grid& grid) {
  if (grid.dimension() == 1) {
    return fmt::format("{} cells (1D), dx = {:.6g} m, {} boundary", grid.nx(), grid.dx(), to_string(grid.boundary()));
  }
  return fmt::format("{} cells (2D), dx = {:.6g} m, dy = {:.6g} m, {} boundary", grid.shape_string(), grid.dx(),
                     grid.dy(), to_string(grid.boundary()));
}

// Why the solve stopped, in a few words: the solver's message repeats the
// residual for an iteration limit, so it is only shown for a breakdown.
std::string stop_reason(const SolveResult& result) {
  switch (result.status) {
    case SolveStatus::converged:
      return "converged";
    case SolveStatus::iteration_limit:
      return "iteration limit reached";
    case SolveStatus::stopped:
      return "stopped";
    case SolveStatus::breakdown:
      return result.message.empty() ? std::string("breakdown") : fmt::format("breakdown ({})", result.message);
  }
  return std::string(to_string(result.status));
}

}  // namespace

void print_summary(std::FILE* out, const SolveSetup& setup, const SolveResult& result) {
  const Grid& grid = setup.grid;
  const auto contact_cells = static_cast<long long>(result.contact_fraction * static_cast<double>(grid.size()) + 0.5);
  fmt::print(out, "halfspace {} ({}) solve\n", kVersion, kGitHash);
  row(out, "surface", setup.height_source);
  for (std::size_t k = 0; k < setup.preparation.size(); ++k) {
    row(out, k == 0 ? "preparation" : "", setup.preparation[k]);
  }
  row(out, "grid", grid_text(grid));
  row(out, "E*", fmt::format("{:.6g} Pa", setup.e_star));
  if (const auto& c = setup.coating) row(out, "coating", coating_text(*c));
  row(out, "load", describe_load(setup.loading.mode, setup.loading.value, grid));
  const bool uses_fft = solvers::uses_fft(setup.solver.type);
  row(out, "solver",
      fmt::format("{}, {} thread{}{}", result.solver, setup.threads, setup.threads == 1 ? "" : "s",
                  uses_fft ? fmt::format(", FFT planning {}", to_string(setup.solver.fft_planning)) : ""));
  row(out, "status", stop_reason(result));
  row(out, "iterations", fmt::format("{}", result.iterations));
  if (uses_fft) {
    row(out, "FFT products",
        fmt::format("{} K, {} M^-1", result.operator_applications, result.preconditioner_applications));
  }
  if (result.coarse.levels > 0) {
    row(out, "coarse start",
        fmt::format("{} grids, {} iterations, costing {:.1f} K and {:.1f} M^-1 products of this grid",
                    result.coarse.levels, result.coarse.iterations, result.coarse.operator_work,
                    result.coarse.preconditioner_work));
  }
  if (result.active_set_outer > 0) {
    row(out, "active set",
        fmt::format("{} set updates, {} of the {} iterations", result.active_set_outer, result.active_set_inner,
                    result.iterations));
  }
  if (result.deflation.block > 0) {
    const DeflationRecord& d = result.deflation;
    row(out, "deflation",
        d.deflated_iterations > 0
            ? fmt::format("{0}x{0} blocks, in {1} of {2} iterations ({3} coarse CG steps)", d.block,
                          d.deflated_iterations, result.iterations, d.coarse_iterations)
            : fmt::format("{0}x{0} blocks, not used ({1})", d.block,
                          d.declined > 0      ? "contact too dense for its coarse matrix"
                          : d.fast_rate > 0.0 ? fmt::format("fast without it: {:.2f} per iteration", d.fast_rate)
                                              : "contact set never settled"));
  }
  for (std::size_t k = 0; k < result.warnings.size(); ++k) {
    row(out, k == 0 ? "warnings" : "", result.warnings[k]);
  }
  row(out, "residual", fmt::format("{:.3e} (tolerance {:.3e})", result.residual, result.tolerance));
  row(out, "total force", fmt::format("{:.6g} {}", result.total_force, force_unit(grid)));
  row(out, "mean pressure", fmt::format("{:.6g} Pa", result.mean_pressure));
  row(out, "max pressure", fmt::format("{:.6g} Pa", result.max_pressure));
  row(out, "approach", fmt::format("{:.6g} m", result.approach));
  row(out, "contact fraction",
      fmt::format("{:.6g} ({} of {} cells)", result.contact_fraction, contact_cells, grid.size()));
  if (result.hardness) {  // hardness cap
    const auto plastic_cells = static_cast<long long>(result.plastic_fraction * static_cast<double>(grid.size()) + 0.5);
    row(out, "plastic fraction",
        fmt::format("{:.6g} ({} of {} cells at the hardness {:.6g} Pa)", result.plastic_fraction, plastic_cells,
                    grid.size(), *result.hardness));
  }
  if (const AdhesionRecord& a = result.adhesion; !a.law.empty()) {
    // Adhesion: the law, and the attractive part of the pressure.
    row(out, "adhesion",
        fmt::format("{}, w = {:.6g} J/m^2, range {:.6g} m, stress {:.6g} Pa", a.law, a.work, a.range, a.stress));
    row(out, "adhesive force", fmt::format("{:.6g} {}", a.adhesive_force, force_unit(grid)));
    row(out, "interaction",
        fmt::format("{:.6g} of the cells within range; {:.6g} in repulsive contact", a.interaction_fraction,
                    a.repulsive_contact_fraction));
  }
  row(out, "solve time", fmt::format("{:.3f} s", result.wall_seconds));
  row(out, "output", setup.output.string());
}

std::string non_convergence_message(const SolveSetup& setup, const SolveResult& result) {
  const char* comparison = result.residual > result.tolerance ? ">" : "vs";
  return fmt::format(
      "error: solver did not converge: {} after {} iterations (residual {:.3e} {} tolerance {:.3e}); "
      "result written to {}",
      stop_reason(result), result.iterations, result.residual, comparison, result.tolerance, setup.output.string());
}

}  // namespace halfspace::app
