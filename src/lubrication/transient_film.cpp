// Time stepping of the rigid film. Each step folds the previous steps' fluid
// h theta into the stencil's time term (ReynoldsStencil::set_time_term) and
// solves one p–theta complementarity problem warm-started from the previous
// state, so the cavitated zone's fluid is carried from step to step (film
// rupture and reformation conserve mass: Ausas, Jai & Buscaglia 2009).
// BDF2's stored fluid 2 m1 - m0 / 2 can turn negative where a film empties
// fast (more than three quarters lost in a step); that step falls back to
// backward Euler, which keeps the fluid fraction in [0, 1].
#include "halfspace/lubrication/transient_film.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "halfspace/error.hpp"
#include "halfspace/lubrication/film.hpp"
#include "halfspace/lubrication/film_forces.hpp"
#include "load_search.hpp"

namespace halfspace::lubrication {

std::string_view to_string(TimeScheme scheme) {
  return scheme == TimeScheme::bdf2 ? "bdf2" : "backward-euler";
}

TimeScheme parse_time_scheme(std::string_view text) {
  if (text == "bdf2") return TimeScheme::bdf2;
  if (text == "backward-euler") return TimeScheme::backward_euler;
  throw InputError(fmt::format("unknown time scheme '{}': allowed are backward-euler, bdf2", text));
}

void TransientFilmOptions::validate() const {
  if (!(std::isfinite(time_step) && time_step > 0.0)) {
    throw OptionError("time_step", format_number(time_step) + " s", "is invalid: it must be positive and finite");
  }
  if (steps < 1) throw OptionError("steps", fmt::format("{}", steps), "is invalid: at least 1 step");
  if (!(std::isfinite(initial_separation) && initial_separation > 0.0)) {
    throw OptionError("initial_separation", format_number(initial_separation) + " m",
                      "is invalid: it must be positive and finite");
  }
  const int drivers = approach_velocity.has_value() + separation_history.has_value() + load.has_value();
  if (drivers != 1) {
    throw OptionError("approach_velocity", approach_velocity ? format_number(*approach_velocity) + " m/s" : "none",
                      "is invalid: give exactly one of the approach velocity, the separation history and the load");
  }
  if (approach_velocity) {
    const double last = initial_separation - *approach_velocity * time_step * steps;
    if (!(std::isfinite(*approach_velocity) && last > 0.0)) {
      throw OptionError("approach_velocity", format_number(*approach_velocity) + " m/s",
                        fmt::format("is invalid: it must be finite and keep the separation positive over {} s "
                                    "(the surfaces would touch)",
                                    format_number(time_step * steps)));
    }
  }
  if (separation_history) {
    if (separation_history->size() != static_cast<std::size_t>(steps)) {
      throw OptionError("separation_history", fmt::format("{} values", separation_history->size()),
                        fmt::format("is invalid: give one separation a step ({})", steps));
    }
    for (const double s : *separation_history) {
      if (!(std::isfinite(s) && s > 0.0)) {
        throw OptionError("separation_history", format_number(s) + " m", "is invalid: separations must be positive");
      }
    }
  }
  if (load) load->validate();
}

double TransientFilmOptions::separation_at(int step) const {
  if (separation_history) return (*separation_history)[static_cast<std::size_t>(step - 1)];
  return initial_separation - approach_velocity.value_or(0.0) * time_step * step;
}

namespace {

// The film at a separation with the time term's rate and stored fluid.
LubricatedFilm solve_step(const Grid& grid, const Eigen::ArrayXd& heights, const FlowConditions& conditions,
                          double separation, double rate, const Eigen::ArrayXd& stored,
                          const CavitationSolverOptions& solver, const FilmSolution* start) {
  LubricatedFilm result;
  result.separation = separation;
  result.film = film_thickness(grid, heights, separation);
  ReynoldsStencil stencil(grid, result.film, conditions);
  if (rate > 0.0) stencil.set_time_term(rate, stored);
  result.solution = solve_cavitating_film(stencil, solver, start);
  result.forces = film_forces(stencil, result.solution);
  result.film_solves = 1;
  return result;
}

double fluid_volume(const Grid& grid, const ReynoldsStencil& topology, const Eigen::ArrayXd& fluid) {
  double volume = 0.0;
  for (std::size_t k = 0; k < topology.size(); ++k) {
    if (!topology.fixed(k)) volume += fluid[static_cast<Eigen::Index>(k)];
  }
  return volume * grid.cell_area();
}

}  // namespace

TransientOutcome lubricate_transient(const Grid& grid, const Eigen::ArrayXd& heights, const FlowConditions& conditions,
                                     const TransientFilmOptions& options, const CavitationSolverOptions& solver,
                                     const TransientObserver& observer) {
  conditions.validate(grid);
  solver.validate();
  options.validate();
  const auto n = static_cast<Eigen::Index>(grid.size());
  const ReynoldsStencil topology(grid, Eigen::ArrayXd::Ones(n), conditions);  // which nodes are fixed
  const double dt = options.time_step;
  TransientOutcome outcome;

  TransientStep current;
  current.film = solve_step(grid, heights, conditions, options.initial_separation, 0.0, {}, solver, nullptr);
  Eigen::ArrayXd fluid = current.film.film * current.film.solution.fluid_fraction;  // m = h theta
  current.fluid_volume = fluid_volume(grid, topology, fluid);
  observer(current);
  if (!current.film.solution.converged()) {
    outcome.status = current.film.solution.status;
    outcome.message = "the initial (steady) film: " + current.film.solution.message;
    return outcome;
  }
  Eigen::ArrayXd previous_fluid;  // m one step before `fluid` (BDF2)
  Eigen::ArrayXd stored(n);
  double previous_separation = options.initial_separation;
  for (int step = 1; step <= options.steps; ++step) {
    double rate = 1.0 / dt;
    stored = fluid / dt;
    if (options.scheme == TimeScheme::bdf2 && step > 1) {
      const Eigen::ArrayXd bdf2 = (2.0 * fluid - 0.5 * previous_fluid) / dt;
      if ((bdf2 >= 0.0).all()) {
        rate = 1.5 / dt;
        stored = bdf2;
      }
    }
    const FilmSolution start = current.film.solution;
    const auto solve = [&](double separation, const FilmSolution* warm) {
      return solve_step(grid, heights, conditions, separation, rate, stored, solver, warm ? warm : &start);
    };
    LubricatedFilm film;
    if (options.load) {
      // The last step's approach continued, or a hundredth of the separation.
      const double last = current.film.separation;
      const double trend = step > 1 ? last - (previous_separation - last) : 0.99 * last;
      film = search_separation_for_load(*options.load, trend > 0.0 ? trend : 0.5 * last, solve);
    } else {
      film = solve(options.separation_at(step), nullptr);
    }
    previous_separation = current.film.separation;
    current.step = step;
    current.time = dt * step;
    current.film = std::move(film);
    previous_fluid = std::move(fluid);
    fluid = current.film.film * current.film.solution.fluid_fraction;
    current.fluid_volume = fluid_volume(grid, topology, fluid);
    observer(current);
    if (!current.film.solution.converged()) {
      outcome.status = current.film.solution.status;
      outcome.message =
          fmt::format("step {} (t = {} s): {}", step, format_number(current.time), current.film.solution.message);
      return outcome;
    }
    outcome.steps_done = step;
  }
  return outcome;
}

}  // namespace halfspace::lubrication
