// Load control of a rigid film: the separation (minimum film thickness) at
// which the film carries a given load.
#pragma once

#include <Eigen/Core>

#include "halfspace/grid.hpp"
#include "halfspace/lubrication/cavitation_solver.hpp"
#include "halfspace/lubrication/film_forces.hpp"
#include "halfspace/lubrication/flow_conditions.hpp"

namespace halfspace::lubrication {

struct LoadControlOptions {
  double load = 0.0;                 // N in 2D, N/m in 1D; > 0
  double relative_tolerance = 1e-8;  // on the load
  double initial_separation = 0.0;   // m; 0 picks a tenth of the heights' range
  int max_evaluations = 200;         // film solves

  // Throws OptionError naming the option unless load > 0, 0 < relative_tolerance
  // < 1, initial_separation >= 0 and finite, max_evaluations >= 2.
  void validate() const;
};

struct LubricatedFilm {
  double separation = 0.0;  // m, the minimum film thickness
  // m; the film and the solution cover the whole film, or with FilmRows
  // (film_rows.hpp) its stencil: this process's rows and the halo rows.
  Eigen::ArrayXd film;
  FilmSolution solution;
  FilmForces forces;
  int film_solves = 0;  // the solves the separation search took (1 under separation control)
};

// Separation control: the film at `separation`.
// With `rows` (both functions), `grid` and `conditions` are the whole
// film's, `heights` this process's rows of it, and the film is solved on
// the processes `rows` joins (collective): the iterates are the serial
// ones, the forces' sums equal the serial ones to rounding.
LubricatedFilm lubricate_at_separation(const Grid& grid, const Eigen::ArrayXd& heights,
                                       const FlowConditions& conditions, double separation,
                                       const CavitationSolverOptions& solver = {}, FilmRows* rows = nullptr);

// Load control: brackets the separation (the load falls as it grows) by
// factors of 4 from the initial one, then a secant on log load against log
// separation safeguarded by bisection, each film warm-started from the last.
// A film that does not converge, or a load that cannot be bracketed (it does
// not change with the separation, as for a flat film), is returned with its
// status and message; a load not met is status iteration_limit.
LubricatedFilm lubricate_at_load(const Grid& grid, const Eigen::ArrayXd& heights, const FlowConditions& conditions,
                                 const LoadControlOptions& load, const CavitationSolverOptions& solver = {},
                                 FilmRows* rows = nullptr);

}  // namespace halfspace::lubrication
