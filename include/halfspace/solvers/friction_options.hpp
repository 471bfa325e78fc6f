// What a frictional solve asks for beyond the normal contact: Coulomb's
// coefficient, and either a history of tangential load steps (each starting
// from the state the previous one left, tangential_solver.hpp) or gross
// sliding along a direction (every contact cell at |q| = mu p). Every rule a
// front end must respect is here, once: the problem builder (problem.hpp)
// maps the program's flags and Python's keywords onto these fields and names
// a SolverOptionError by the front end's spelling of the option.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "halfspace/elastic_pair.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/solvers/coupled_step.hpp"
#include "halfspace/solvers/loading.hpp"
#include "halfspace/solvers/solver_options.hpp"
#include "halfspace/solvers/tangential_loading.hpp"
#include "halfspace/solvers/tangential_solver.hpp"

namespace halfspace::solvers {

struct FrictionOptions {
  // mu and the tangential solver's tolerance, iteration limit, release
  // period, active-set updates and coarse start (its progress is set per
  // step from `progress` below).
  TangentialOptions tangential;
  // The tangential load steps in order (a force, N or N/m in 1D, or a
  // tangential approach, m); more than one is a history.
  std::vector<TangentialLoading> history;
  // Gross sliding along (x, y) (any length but zero) instead of a history:
  // one step at the force mu P in that direction.
  std::optional<std::array<double, 2>> sliding_direction;
  // Elastically dissimilar bodies (Dundurs' beta != 0): solve the coupled
  // normal-tangential problem (coupled_step.hpp), or, false, ignore the
  // coupling (the uncoupled approximation, for comparison). No effect for
  // similar bodies, which do not couple.
  bool coupling = true;
  // Coupled only: the normal load is applied in this many equal increments
  // before the tangential history, each a coupled step at zero tangential
  // load (the shear the normal loading leaves depends on the path: a
  // growing contact sticks where it lands).
  int normal_load_steps = 1;
  CoupledStepOptions coupled_step;  // the coupled alternation's tolerance and limit
  // Called once per tangential iteration with (step, iteration, residual);
  // may be empty or stop the solve (solve_result.hpp's IterationDecision).
  std::function<IterationDecision(std::size_t, int, double)> progress;

  // The number of tangential steps solved: the history's, or 1 when sliding.
  std::size_t steps() const { return sliding_direction ? 1 : history.size(); }
  // `tangential`, its progress reporting `progress` at the step `current`.
  TangentialOptions tangential_options(const std::size_t& current) const;
  // Whether a solve on `pair` is coupled: coupling on and beta != 0.
  bool coupled(const ElasticPair& pair) const { return coupling && !pair.similar(); }

  // Throws SolverOptionError naming the option unless: `tangential` is
  // valid (TangentialOptions::validate, mu as "friction"); exactly one of a
  // non-empty history ("tangential_load") and a sliding direction
  // ("sliding") is given; every load step is finite; the direction is
  // finite and not zero, and mu > 0 when sliding; normal_load_steps is at
  // least 1; `coupled_step` is valid (CoupledStepOptions::validate).
  void validate() const;

  // validate(), and no adhesion in `normal`: the cohesive tractions make
  // negative pressures, where Coulomb's bound mu p has no meaning yet
  // ("adhesion").
  void validate(const SolverOptions& normal) const;

  // validate(normal), and the rules of the solve on `grid`:
  //  - on a 1D grid the y components are zero ("tangential_load", "sliding");
  //  - under force or mean-pressure control, every force step is at most
  //    mu P, P the normal load (beyond it the contact slides: impose a
  //    displacement or use sliding) ("tangential_load").
  // Every normal solver is accepted (the dense ones too): for similar
  // bodies the pressure does not depend on the shear, and the tangential
  // step has its own operator; the coupled alternation calls the normal
  // solver as a black box. Any pair of bodies is accepted (dissimilar ones
  // are solved coupled, coupled_step.hpp).
  void validate(const Grid& grid, const SolverOptions& normal, const Loading& loading) const;

  // The rule of the bodies on `grid`: a coated half-space
  // (ElasticPair::coated) is refused ("coating") where its tangential
  // compliance is not built (operators::coated_free_grid_refusal: free 1D
  // grids, free 2D grids less than 8 split heights across). Throws
  // SolverOptionError.
  static void check_body(const Grid& grid, const ElasticPair& pair);
  // The refusal of a material given as E* alone ("pair": E* does not fix
  // the tangential compliance), named for front ends that find it before
  // they build a pair.
  static void refuse_composite_modulus_only();
};

}  // namespace halfspace::solvers

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using solvers::FrictionOptions;
}  // namespace halfspace
