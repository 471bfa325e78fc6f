// The mass-conserving (Jakobsson–Floberg–Olsson) Reynolds problem as a
// complementarity problem in the p–theta form: on every unknown node the mass
// balance of reynolds_stencil.hpp holds with
//
//   p >= 0,   0 <= theta <= 1,   p (1 - theta) = 0,
//
// solved by projected successive over-relaxation on the nodes (Elrod–Adams'
// switch function as Giacopini et al. 2010, J. Tribol. 132, 041702, and
// Almqvist et al. 2014, J. Tribol. 136, 011706, write it as an LCP).
#pragma once

#include <Eigen/Core>

#include "halfspace/lubrication/film_rows.hpp"
#include "halfspace/lubrication/film_solution.hpp"
#include "halfspace/lubrication/reynolds_stencil.hpp"

namespace halfspace::lubrication {

struct CavitationSolverOptions {
  // Converged when the largest |mass balance| <= tolerance * balance scale
  // (ReynoldsStencil::balance_scale).
  double tolerance = 1e-11;
  int max_iterations = 2'000'000;  // sweeps over the grid
  // SOR factor on the pressure, in (0, 2); 0 picks 2 / (1 + sin(pi / N))
  // with N the larger node count of the grid's axes (the optimum for
  // Poisson's equation, Young 1954).
  double relaxation = 0.0;
  int check_every = 10;  // sweeps between measurements of the residual

  // Throws OptionError naming the option unless 0 < tolerance < 1,
  // max_iterations >= 1, relaxation is 0 or in (0, 2), check_every >= 1.
  void validate() const;
};

// Solves the film of `stencil`, starting from `start` (a previous solution of
// the same grid, for warm starts; empty pressure or fluid fraction: p = the
// boundary pressures' mean of fixed nodes, 0 elsewhere, theta = 1). Allocates
// the result once; the sweeps allocate nothing. Throws InputError for invalid
// options or a start of the wrong size.
// With `rows`, the stencil is this process's rows of a film and their halo
// rows (film_rows.hpp): the sweeps and the convergence measures are the
// whole film's; collective over the processes `rows` joins.
FilmSolution solve_cavitating_film(const ReynoldsStencil& stencil, const CavitationSolverOptions& options = {},
                                   const FilmSolution* start = nullptr, FilmRows* rows = nullptr);

// The largest |mass balance| over the unknown nodes, relative to the
// balance scale, and whether p >= 0, 0 <= theta <= 1 and p (1 - theta) = 0
// hold on every node (to rounding: theta may differ from 1 by at most
// `fraction_tolerance` where p > 0).
double relative_mass_residual(const ReynoldsStencil& stencil, const Eigen::ArrayXd& pressure,
                              const Eigen::ArrayXd& fluid_fraction);
bool satisfies_complementarity(const Eigen::ArrayXd& pressure, const Eigen::ArrayXd& fluid_fraction,
                               double fraction_tolerance = 0.0);

}  // namespace halfspace::lubrication
