// The transient Reynolds equation of a rigid film, stepped in time: the
// steady balance of reynolds_stencil.hpp plus the time term d(h theta)/dt,
//
//   div( h^3 / (12 eta) grad p ) = div( U h theta ) + d(h theta)/dt,
//
// with the same p–theta complementarity (mass-conserving cavitation:
// Elrod–Adams' fluid fraction in the time term, Ausas, Jai & Buscaglia 2009,
// J. Tribol. 131, 031702). The time term is a backward difference (backward
// Euler, or BDF2 from the second step on), implicit: each step is one
// complementarity problem of the p–theta solver, started from the previous
// step's state. The separation (the minimum film, at the surface's highest
// point) follows an approach velocity, a list of separations, or the load:
// then each step's separation is the one at which the film (its squeeze
// included) carries the load — quasi-static, the body's inertia neglected
// (the film's squeeze damping dominates a lubricated approach).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/lubrication/cavitation_solver.hpp"
#include "halfspace/lubrication/flow_conditions.hpp"
#include "halfspace/lubrication/load_control.hpp"

namespace halfspace::lubrication {

enum class TimeScheme {
  backward_euler,  // first order: (m1 - m0) / dt
  bdf2,            // second order: (3 m2 - 4 m1 + m0) / (2 dt); its first step backward Euler
};

std::string_view to_string(TimeScheme scheme);
// "backward-euler" or "bdf2"; throws InputError naming the allowed values.
TimeScheme parse_time_scheme(std::string_view text);

struct TransientFilmOptions {
  double time_step = 0.0;           // s, > 0
  int steps = 0;                    // >= 1 (with a separation history: its length)
  double initial_separation = 0.0;  // m, > 0: the separation at t = 0
  TimeScheme scheme = TimeScheme::bdf2;
  // Exactly one drives the separation: the approach velocity (m/s; the
  // separation falls as s0 - V t, V < 0 separates), the separations at the
  // end of each step (m, > 0), or the load (N, N/m on a profile).
  std::optional<double> approach_velocity;
  std::optional<std::vector<double>> separation_history;
  std::optional<LoadControlOptions> load;

  // Throws OptionError naming the option ("time_step", "steps",
  // "initial_separation", "approach_velocity", "separation_history") unless
  // the values are in range, exactly one driver is given, the history has
  // `steps` values and the approach keeps the separation positive.
  void validate() const;
  // The prescribed separation at the end of step n (1-based); not under load.
  double separation_at(int step) const;
};

// One time step's film. Step 0 is the initial state: the steady film at the
// initial separation.
struct TransientStep {
  int step = 0;
  double time = 0.0;  // s
  LubricatedFilm film;
  // The fluid the unknown nodes' control volumes hold, sum of h theta times
  // their area (m^3 in 2D, m^2/m in 1D): its change over a step is the net
  // inflow through the fixed-pressure edges (film.forces) times the step,
  // by backward Euler's balance.
  double fluid_volume = 0.0;
};

struct TransientOutcome {
  FilmStatus status = FilmStatus::converged;  // of the first step that failed, else converged
  std::string message;
  int steps_done = 0;  // steps after the initial state that converged
};

// Receives each step (the initial state first) as it is solved; the stepper
// keeps only the last two states, so a long run's fields go to the
// observer (a writer) and nowhere else.
using TransientObserver = std::function<void(const TransientStep&)>;

// Steps the rigid film of `heights` (as lubricate_at_separation) from the
// steady film at options.initial_separation. Stops at the first step whose
// film does not converge (its state is observed, with its status). Throws
// InputError for invalid options.
TransientOutcome lubricate_transient(const Grid& grid, const Eigen::ArrayXd& heights, const FlowConditions& conditions,
                                     const TransientFilmOptions& options, const CavitationSolverOptions& solver,
                                     const TransientObserver& observer);

}  // namespace halfspace::lubrication
