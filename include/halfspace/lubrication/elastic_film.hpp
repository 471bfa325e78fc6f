// Elastohydrodynamic lubrication (EHL): the Reynolds film of
// reynolds_stencil.hpp between an elastic half-space and a rigid surface,
// whose film thickness grows with the surface's deformation under the
// fluid pressure, with a viscosity and density that grow with pressure
// (lubricant.hpp):
//
//   div( rho h^3 / (12 eta) grad p ) = div( U rho h theta ),
//   h = h0 + g + K p,    sum(p) dA = w,
//   p >= 0,  0 <= theta <= 1,  p (1 - theta) = 0,
//
// g the undeformed surface gap (min 0), K the influence operator
// (influence_operator.hpp, free or periodic, homogeneous or coated), h0 the
// offset that load balance fixes. Mass-conserving cavitation (p–theta) as in
// cavitation_solver.hpp.
//
// The solver is Newton's method on all of it at once, as Houpert & Hamrock
// (1986, J. Tribol. 108, 411) do for line contacts at high loads: the
// unknowns are one variable s per node (p = p_scale max(s, 0) and theta =
// 1 + min(s, 0), so the complementarity holds by construction and the
// method is a semi-smooth Newton) and h0. Its Jacobian couples every node
// through K. Each Newton step's linear system is solved either densely (K
// and J formed, LU; line contacts and modest point-contact grids up to
// kMaxElasticFilmNodes) or by restarted GMRES with K applied by the
// operator and a sparse preconditioner (any grid that fits in memory).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <string_view>

#include "halfspace/lubrication/film_solution.hpp"
#include "halfspace/lubrication/flow_conditions.hpp"
#include "halfspace/lubrication/lubricant.hpp"
#include "halfspace/operators/influence_operator.hpp"

namespace halfspace::lubrication {

// Nodes up to which the dense Newton path is allowed: its Jacobian, its LU
// and K are n x n each (3 x 134 MB at the limit).
inline constexpr std::size_t kMaxElasticFilmNodes = 4096;

// Above this many nodes FilmLinearSolve::automatic takes GMRES, and grid
// sequencing (ElasticFilmOptions::grid_sequencing) starts from a coarser
// grid.
inline constexpr std::size_t kAutomaticKrylovNodes = 1024;

// The relative mass residual and load error to which the coarse grids of
// grid sequencing are solved: their films are only a start, and differ from
// the fine one by the discretisation error, far above this.
inline constexpr double kSequencingCoarseTolerance = 1e-6;

// Nodes up to which a sequenced solve whose coarse start failed, or that
// failed from it, starts again cold (from the dry contact). Above, the cold
// start does not converge in the default Newton steps (a 512^2 point
// contact at 100 cells per Hertz radius: 100 steps, ten minutes; see
// docs/development-log.md) and the failure is reported instead.
inline constexpr std::size_t kMaxColdRestartNodes = 256 * 256;

// The linear solve of each Newton step: the dense LU (K formed), restarted
// GMRES matrix-free with a sparse preconditioner, or the dense one up to
// kAutomaticKrylovNodes nodes and GMRES above.
enum class FilmLinearSolve { automatic, dense, gmres };

std::string_view to_string(FilmLinearSolve solve);
// "automatic", "dense" or "gmres"; InputError naming the value otherwise.
FilmLinearSolve parse_film_linear_solve(std::string_view text);

// The preconditioner of the GMRES solve, an approximate inverse of the
// Jacobian's sparse part (the Reynolds stencil's derivatives with K's
// diagonal): a geometric multigrid V-cycle (line relaxation along the
// entrainment, Galerkin coarse grids; its cost grows as the nodes), or
// that part's sparse LU (exact, but its fill grows as n^1.5: kept for
// cross-checks).
enum class KrylovPreconditioner { multigrid, sparse_lu };

std::string_view to_string(KrylovPreconditioner preconditioner);
// "multigrid" or "sparse-lu"; InputError naming the value otherwise.
KrylovPreconditioner parse_krylov_preconditioner(std::string_view text);

// How the Couette (wedge) flux U rho h theta of a face is taken from
// upstream: from the upstream node (first order: monotone, robust at any
// load, its artificial diffusion thickens the film by O(dx)), or by linear
// extrapolation from the two upstream nodes (second order, Venner &
// Lubrecht 2000: more accurate on a given grid, but at very high loads the
// Newton iteration may stall in the pressure spike; docs/solvers.md).
enum class CouetteScheme { first_order, second_order };

std::string_view to_string(CouetteScheme scheme);
// "first-order" or "second-order"; InputError naming the value otherwise.
CouetteScheme parse_couette_scheme(std::string_view text);

struct ElasticFilmOptions {
  double load = 0.0;  // N in 2D, N/m in 1D; > 0: the sum of the cells' pressures times their area
  // Converged when the largest |mass balance| <= tolerance * the largest
  // Couette outflow U rho h (as relative_mass_residual) and |load - w| <=
  // load_tolerance * w.
  double tolerance = 1e-8;
  double load_tolerance = 1e-8;
  int max_iterations = 100;  // Newton steps
  CouetteScheme couette_scheme = CouetteScheme::first_order;
  FilmLinearSolve linear_solve = FilmLinearSolve::automatic;
  // GMRES: the restart length, the iterations per Newton step (all
  // restarts), the relative residual ||J dx + r|| / ||r|| it must reach,
  // and how many cells around a node the preconditioner keeps of K.
  int krylov_restart = 40;
  int krylov_max_iterations = 400;
  double krylov_tolerance = 1e-9;
  int preconditioner_neighbourhood = 0;
  KrylovPreconditioner preconditioner = KrylovPreconditioner::multigrid;
  // Grid sequencing: on a grid of more than kAutomaticKrylovNodes nodes
  // with an even number of cells per axis, and without a `start`, the film
  // is first solved on the grid of twice the spacing (recursively, the
  // coarse influence operator seen through this one) to the coarse
  // tolerance max(tolerance, kSequencingCoarseTolerance), and interpolated
  // as the Newton start; if that start fails, the solve starts again cold
  // on grids of at most kMaxColdRestartNodes nodes and reports the failure
  // on larger ones.
  bool grid_sequencing = true;

  // Throws OptionError naming the option unless load > 0 and finite, 0 <
  // tolerance < 1, 0 < load_tolerance < 1, max_iterations >= 1, 2 <=
  // krylov_restart <= 500, krylov_max_iterations >= 1, 0 <
  // krylov_tolerance < 1, 0 <= preconditioner_neighbourhood <= 8, and
  // preconditioner one of KrylovPreconditioner's values.
  void validate() const;
};

// What the EHL and the mixed film's Newton solves report alike (ElasticFilm,
// MixedFilm). Fields (ny, nx) row-major on the grid's cells (the film's nodes).
struct NewtonFilmResult {
  FilmStatus status = FilmStatus::failure;
  std::string message;            // empty when converged
  Eigen::ArrayXd pressure;        // Pa (the mixed film's: p_f + p_c)
  Eigen::ArrayXd fluid_fraction;  // theta
  Eigen::ArrayXd film;            // h (m; the mixed film's: 0 on contact cells)
  Eigen::ArrayXd deformation;     // K p (m, positive away from the rigid surface)
  double offset = 0.0;            // h0 (m); with a free 1D grid it includes the kernel's datum
  double load = 0.0;              // sum(p) dA (N, N/m in 1D)
  // h at the contact's centre (the node of the smallest undeformed gap) and
  // the smallest h anywhere.
  double central_film_thickness = 0.0;
  double minimum_film_thickness = 0.0;
  double max_pressure = 0.0;
  int iterations = 0;  // Newton steps
  int line_search_halvings = 0;
  // Stalls the Newton iteration stepped over anyway (the mixed film's
  // watchdog, docs/solvers.md), kept or not; as line_search_halvings, the
  // last Newton solve's (not summed over a continuation's solves).
  int watchdog_steps = 0;
  // The GMRES path: whether it was taken, its iterations in all and the
  // most in one Newton step's linear solve (all branch passes).
  bool used_krylov = false;
  int krylov_iterations = 0;
  int max_krylov_iterations_per_step = 0;
  // Grid sequencing: the coarser grids solved for the start, their Newton
  // steps and GMRES iterations in all (not in iterations and
  // krylov_iterations), and whether the sequenced start failed and the
  // solve started again cold (kMaxColdRestartNodes,
  // kMaxMixedColdRestartNodes; iterations then counts both).
  int coarse_levels = 0;
  int coarse_iterations = 0;
  int coarse_krylov_iterations = 0;
  bool sequencing_fell_back = false;
  double wall_seconds = 0.0;  // all of it, coarse grids included
  // Measured after the solve with the operator's own product (not the
  // Newton's factorised Jacobian): the relative mass residual (flux form)
  // and |load - w| / w.
  double relative_residual = 0.0;
  double load_error = 0.0;

  bool converged() const { return status == FilmStatus::converged; }
};

struct ElasticFilm : NewtonFilmResult {
  // Newton steps whose GMRES direction was solved again to
  // krylov_tolerance because no step along the inexact one lowered the
  // residual.
  int tight_retries = 0;
};

// Solves the EHL film on the operator's grid. `gap` is g (m, one value per
// cell, >= 0 with its minimum at the contact); `conditions` gives the
// ambient viscosity eta0, the velocities and the flow boundary (validated
// here); `laws` the pressure laws. Starts from the dry contact (Polonsky &
// Keer on the same operator) at the load, unless `start` holds a previous
// film of the same grid or grid sequencing applies (options). Throws InputError for invalid input, for the
// dense solve on more than kMaxElasticFilmNodes nodes, and for a GMRES
// solve whose memory estimate exceeds the memory available; non-convergence
// (of the Newton iteration or of a step's GMRES) is a status.
//
// On an operator spread over processes in slabs of rows (the distributed
// operators of mpi/; collective then): `gap` and the result's fields are
// this process's rows, its scalars the whole film's, and `start` a film of
// the same slabs. The Newton iteration runs on each process's rows and a
// halo of the rows next to them, with GMRES (the dense solve is refused),
// its preconditioner each process's block of rows with an overlap (so the
// iterates, not the film, differ from one process's); grid sequencing's
// coarse films run on slabs of their rows too, or whole on every process
// where the slabs would be thin. Each process needs at least two rows with
// the second-order Couette flux, one without.
ElasticFilm solve_elastic_film(InfluenceOperator& op, const Eigen::ArrayXd& gap, const FlowConditions& conditions,
                               const LubricantLaws& laws, const ElasticFilmOptions& options,
                               const ElasticFilm* start = nullptr);

// The largest |mass balance| of the compressible, piezoviscous p–theta
// Reynolds equation over the unknown nodes for the film `film`, relative to
// the largest Couette outflow (the check solve_elastic_film makes).
double elastic_film_residual(const Grid& grid, const FlowConditions& conditions, const LubricantLaws& laws,
                             const Eigen::ArrayXd& film, const Eigen::ArrayXd& pressure,
                             const Eigen::ArrayXd& fluid_fraction, CouetteScheme scheme = CouetteScheme::first_order);

}  // namespace halfspace::lubrication
