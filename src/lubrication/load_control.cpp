// The separation that carries a load. A rigid film's load falls
// monotonically as the separation grows (about as separation^-2 for a
// converging film), so log load is nearly linear in log separation: a bracket
// by factors of 4, then the secant in those variables with the Illinois
// safeguard (Dowell & Jarratt 1971) and bisection when it leaves the bracket.
#include "halfspace/lubrication/load_control.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "halfspace/error.hpp"
#include "halfspace/lubrication/film.hpp"
#include "load_search.hpp"

namespace halfspace::lubrication {

void LoadControlOptions::validate() const {
  if (!(std::isfinite(load) && load > 0.0)) {
    throw OptionError("load", format_number(load), "is invalid: the film's load must be positive and finite");
  }
  if (!(relative_tolerance > 0.0 && relative_tolerance < 1.0)) {
    throw OptionError("relative_tolerance", format_number(relative_tolerance),
                      "is invalid: allowed range is 0 < tolerance < 1");
  }
  if (!(std::isfinite(initial_separation) && initial_separation >= 0.0)) {
    throw OptionError("initial_separation", format_number(initial_separation) + " m",
                      "is invalid: it must be >= 0 (0: automatic) and finite");
  }
  if (max_evaluations < 2) {
    throw OptionError("max_evaluations", fmt::format("{}", max_evaluations), "is invalid: at least 2 film solves");
  }
}

namespace {

// The highest and lowest heights of the whole surface.
std::array<double, 2> height_range(const Eigen::ArrayXd& heights, const FilmRows* rows) {
  double highest = heights.size() > 0 ? heights.maxCoeff() : -std::numeric_limits<double>::infinity();
  double lowest = heights.size() > 0 ? heights.minCoeff() : std::numeric_limits<double>::infinity();
  if (rows != nullptr) {
    highest = rows->max(highest);
    lowest = rows->min(lowest);
  }
  return {highest, lowest};
}

LubricatedFilm solve_at(const Grid& grid, const Eigen::ArrayXd& heights, double highest,
                        const FlowConditions& conditions, double separation, const CavitationSolverOptions& solver,
                        const FilmSolution* start, FilmRows* rows) {
  LubricatedFilm result;
  result.separation = separation;
  const Eigen::ArrayXd own = film_thickness(heights, highest, separation);
  result.film = rows != nullptr ? rows->stencil_field({own.data(), static_cast<std::size_t>(own.size())}) : own;
  const ReynoldsStencil stencil(rows != nullptr ? rows->stencil_grid() : grid, result.film,
                                rows != nullptr ? rows->stencil_conditions() : conditions);
  result.solution = solve_cavitating_film(stencil, solver, start, rows);
  result.forces = film_forces(stencil, result.solution, rows);
  result.film_solves = 1;
  return result;
}

void check_heights(const Grid& grid, const Eigen::ArrayXd& heights, const FilmRows* rows) {
  const std::size_t expected = rows != nullptr ? rows->own_nodes() : grid.size();
  if (static_cast<std::size_t>(heights.size()) != expected) {
    throw InputError(fmt::format("heights have {} values, {} {} grid {} {} cells", heights.size(),
                                 rows != nullptr ? "this process's rows of the" : "the", grid.shape_string(),
                                 rows != nullptr ? "have" : "has", expected));
  }
}

}  // namespace

LubricatedFilm lubricate_at_separation(const Grid& grid, const Eigen::ArrayXd& heights,
                                       const FlowConditions& conditions, double separation,
                                       const CavitationSolverOptions& solver, FilmRows* rows) {
  conditions.validate(grid);
  solver.validate();
  check_heights(grid, heights, rows);
  return solve_at(grid, heights, height_range(heights, rows)[0], conditions, separation, solver, nullptr, rows);
}

LubricatedFilm lubricate_at_load(const Grid& grid, const Eigen::ArrayXd& heights, const FlowConditions& conditions,
                                 const LoadControlOptions& load, const CavitationSolverOptions& solver,
                                 FilmRows* rows) {
  conditions.validate(grid);
  solver.validate();
  load.validate();
  check_heights(grid, heights, rows);
  const auto [highest, lowest] = height_range(heights, rows);
  const double range = grid.size() > 0 ? highest - lowest : 0.0;
  const double separation =
      load.initial_separation > 0.0 ? load.initial_separation : (range > 0.0 ? 0.1 * range : 1e-6);
  return search_separation_for_load(load, separation, [&](double s, const FilmSolution* start) {
    return solve_at(grid, heights, highest, conditions, s, solver, start, rows);
  });
}

LubricatedFilm search_separation_for_load(const LoadControlOptions& load, double initial_separation,
                                          const FilmAtSeparation& solve) {
  double separation = initial_separation;
  int solves = 0;
  LubricatedFilm current;
  // log(load / target): positive while the film carries too much.
  const auto excess = [&](const LubricatedFilm& film) {
    return std::log(std::max(film.forces.load, std::numeric_limits<double>::min()) / load.load);
  };
  const auto evaluate = [&](double s) {
    const FilmSolution* start = solves > 0 ? &current.solution : nullptr;
    LubricatedFilm next = solve(s, start);
    ++solves;
    current = std::move(next);
    current.film_solves = solves;
    return current.solution.converged();
  };
  const auto give_up = [&](FilmStatus status, std::string message) {
    current.solution.status = status;
    current.solution.message = std::move(message);
    current.film_solves = solves;
    return current;
  };
  if (!evaluate(separation)) return current;
  if (std::abs(excess(current)) <= std::log1p(load.relative_tolerance)) return current;
  // Bracket: `high` has too little load at the larger separation, `low` too much.
  double log_low = 0.0, f_low = 0.0, log_high = 0.0, f_high = 0.0;
  const double first_excess = excess(current);
  const double step = first_excess > 0.0 ? 4.0 : 0.25;
  double previous_load = current.forces.load;
  (first_excess > 0.0 ? log_low : log_high) = std::log(separation);
  (first_excess > 0.0 ? f_low : f_high) = first_excess;
  for (;;) {
    if (solves >= load.max_evaluations) {
      return give_up(FilmStatus::iteration_limit,
                     fmt::format("the load {} could not be bracketed in {} film solves", load.load, solves));
    }
    separation *= step;
    if (!evaluate(separation)) return current;
    const double f = excess(current);
    if (std::abs(current.forces.load - previous_load) <= 1e-12 * std::abs(previous_load)) {
      return give_up(FilmStatus::failure,
                     fmt::format("the film's load {} does not change with the separation: no separation carries {}",
                                 current.forces.load, load.load));
    }
    previous_load = current.forces.load;
    if ((f > 0.0) == (first_excess > 0.0)) {
      (f > 0.0 ? log_low : log_high) = std::log(separation);
      (f > 0.0 ? f_low : f_high) = f;
      continue;
    }
    (f > 0.0 ? log_low : log_high) = std::log(separation);
    (f > 0.0 ? f_low : f_high) = f;
    break;
  }
  int stuck_side = 0;  // Illinois: the side kept twice in a row has its value halved
  while (std::abs(excess(current)) > std::log1p(load.relative_tolerance)) {
    if (solves >= load.max_evaluations) {
      return give_up(FilmStatus::iteration_limit,
                     fmt::format("the load {} was not met in {} film solves: the film carries {}", load.load, solves,
                                 current.forces.load));
    }
    double x = log_high - f_high * (log_high - log_low) / (f_high - f_low);
    if (!(x > log_low && x < log_high)) x = 0.5 * (log_low + log_high);
    if (!evaluate(std::exp(x))) return current;
    const double f = excess(current);
    if (f > 0.0) {
      log_low = x;
      f_low = f;
      if (stuck_side == -1) f_high *= 0.5;
      stuck_side = -1;
    } else {
      log_high = x;
      f_high = f;
      if (stuck_side == 1) f_low *= 0.5;
      stuck_side = 1;
    }
  }
  return current;
}

}  // namespace halfspace::lubrication
