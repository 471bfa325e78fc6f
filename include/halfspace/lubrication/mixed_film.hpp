// Mixed lubrication: the EHL film of elastic_film.hpp where the film may
// close. Where the gap between the elastic body and the rough rigid surface
// would become negative the asperities touch and carry a contact pressure
// p_c; elsewhere the fluid carries the Reynolds pressure p_f. Both deform the
// one elastic body through the same influence operator K:
//
//   div( rho h_R^3 / (12 eta) grad p_f ) = div( U rho h_R theta ),
//   h = h0 + g + K (p_f + p_c),   h_R = R(h; h_b),     sum(p_f + p_c) dA = w,
//   p_f >= 0,  0 <= theta <= 1,  p_f (1 - theta) = 0        (cavitation, JFO)
//   h >= 0,    p_c >= 0,         h p_c = 0                  (contact)
//
// h_b is a boundary film (a few molecular layers): the Reynolds equation sees
// at least h_b (R, reynolds_film below: max(h, h_b) rounded off), so its
// rows stay regular in contact cells (fluid pressure is
// still defined there, and the Poiseuille flow through a contact patch is
// that of h_b, negligible, as h_b^3) and the fluid's film is the elastic gap
// wherever that is thicker. At high speeds (no cell below h_b) the equations
// are the EHL film's exactly. The solver is the EHL solver's semi-smooth
// Newton with a second unknown per node, the contact pressure, whose
// complementarity is the row min(p_c / P, h / H) = 0 (an active-set Newton,
// as the contact solvers' LCP; docs/theory.md#mixed-lubrication). Each
// Newton step's linear system is solved densely ((2n + 1)^2: line contacts
// of at most kMaxMixedFilmNodes nodes) or by GMRES with K applied by the
// operator to the total pressure and a sparse preconditioner (any grid,
// point contacts included).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "halfspace/linalg/communicator.hpp"
#include "halfspace/lubrication/elastic_film.hpp"
#include "halfspace/lubrication/film_shear.hpp"
#include "halfspace/lubrication/film_solution.hpp"
#include "halfspace/lubrication/flow_conditions.hpp"
#include "halfspace/lubrication/lubricant.hpp"
#include "halfspace/operators/influence_operator.hpp"

namespace halfspace::lubrication {

// Nodes up to which the mixed film's dense Newton path is allowed: its
// Jacobian and LU are (2n + 1)^2 each (134 MB each at the limit). Line
// contacts up to this take it by default; the GMRES path has no limit but
// memory.
inline constexpr std::size_t kMaxMixedFilmNodes = 2048;

// Above this many nodes a load-controlled point contact solved without a
// start is grid-sequenced (MixedFilmOptions::grid_sequencing): solved first
// on the grid of twice the spacing, recursively, to
// kSequencingCoarseTolerance, and interpolated as the Newton start.
inline constexpr std::size_t kMixedSequencingNodes = 1024;

// Nodes up to which a sequenced solve whose coarse film failed, or that
// failed from it, starts again cold and continues in the speed; above, that
// takes hours (a 128^2 rough point contact did not finish in 30 minutes;
// docs/development-log.md) and the failure is reported instead.
inline constexpr std::size_t kMaxMixedColdRestartNodes = 64 * 64;

// The film the Reynolds equation sees, R(h; h_b): the gap h where h >= 1.5
// h_b, the boundary film h_b where h <= h_b / 2, and between them the
// quadratic h_b + (h - h_b / 2)^2 / (2 h_b) that joins the two with a
// continuous slope. The kink of max(h, h_b) stalled the Newton iteration on
// rough point contacts in the mixed regime: nodes around contact spots sit
// at h = h_b, where the film's derivative jumped from 0 to 1 and no step
// lowered the residual (docs/development-log.md, 2026-11-30).
double reynolds_film(double film, double boundary_film);
// dR/dh, in [0, 1].
double reynolds_film_slope(double film, double boundary_film);
// R on every cell of `film`.
Eigen::ArrayXd reynolds_film(const Eigen::ArrayXd& film, double boundary_film);

// How the film's shear and the asperities' friction are taken.
struct MixedFrictionOptions {
  double contact_friction = 0.1;  // Coulomb coefficient on contact cells, >= 0
  // The fluid's shear on cells without contact: film_shear's laws (Eyring,
  // limiting shear stress tau_L0 + gamma p_f); all 0: Newtonian.
  ShearLimits shear;

  // Throws OptionError naming the option unless contact_friction is >= 0
  // and finite and the shear limits are valid.
  void validate() const;
};

// One Newton solve of the mixed film as it ends (MixedFilmOptions::trace):
// a coarse level's, a continuation's or a smoothed solve's as well as the
// film's own, so that a long run shows where it is and where its time goes.
struct MixedSolveRecord {
  std::size_t nx = 0, ny = 0;      // the solve's grid (ny 1 on a profile)
  double entrainment_speed = 0.0;  // |U| (m/s)
  double smoothing = 0.0;          // mu of smoothed contact rows; 0: the film's own rows
  bool warm = false;               // from a given film, else the standard starts
  bool checked_step_branches = false;
  FilmStatus status = FilmStatus::failure;
  int newton_steps = 0;
  int krylov_iterations = 0;  // GMRES iterations in all (0 on the dense path)
  int most_krylov_per_step = 0;
  int line_search_halvings = 0;
  int watchdog_steps = 0;
  double relative_residual = 0.0;  // the flux-form mass residual checked at the end
  double contact_load_fraction = 0.0;
  double wall_seconds = 0.0;
};
using MixedSolveTrace = std::function<void(const MixedSolveRecord&)>;

struct MixedFilmOptions {
  // Load control: the load w (N in 2D, N/m in 1D) > 0, h0 unknown. Separation
  // control (load 0): h0 = offset is given and the load follows.
  double load = 0.0;
  double offset = 0.0;          // m; h0 under separation control (ElasticFilm::offset's meaning)
  double boundary_film = 1e-9;  // m, h_b > 0
  // Converged when the largest |mass balance| <= tolerance * the largest
  // Couette outflow, |load - w| <= load_tolerance * w, and the contact rows
  // |min(p_c / P, h / H)| <= contact_tolerance (P the pressure scale, H the
  // film scale: the largest gap inside the dry contact).
  double tolerance = 1e-8;
  double load_tolerance = 1e-8;
  double contact_tolerance = 1e-10;
  int max_iterations = 200;  // Newton steps over all starts
  CouetteScheme couette_scheme = CouetteScheme::first_order;
  // The Newton step's linear solve: dense (the (2n + 1)^2 LU), GMRES
  // (matrix-free), or automatic: dense on line contacts of at most
  // kMaxMixedFilmNodes nodes, GMRES otherwise (2D grids).
  FilmLinearSolve linear_solve = FilmLinearSolve::automatic;
  // GMRES: the restart length, the iterations per Newton step, the
  // relative residual it must reach (looser far from the solution: an
  // inexact Newton) and how many cells around a node the preconditioner
  // keeps of K. A restart of 40 stagnated (0.2 after 800 iterations) on a
  // 256^2 rough point contact that 80 to 150 solve (docs/development-log.md,
  // 2026-11-30); the basis costs 16 (restart + 1) bytes per node.
  int krylov_restart = 100;
  int krylov_max_iterations = 800;
  double krylov_tolerance = 1e-9;
  int preconditioner_neighbourhood = 1;
  // The GMRES preconditioner: block Gauss–Seidel with the EHL film's
  // multigrid V-cycle on the mass rows and a sparse LU on the closed
  // contact rows (its cost grows as the nodes), or the sparse LU of the
  // whole 2n x 2n sparse part (fill growing faster than n: kept for
  // cross-checks).
  KrylovPreconditioner preconditioner = KrylovPreconditioner::multigrid;
  // Grid sequencing on 2D grids of more than kMixedSequencingNodes nodes
  // with even cell counts, under load control without a start.
  bool grid_sequencing = true;
  // The branches of a point contact's Newton step: the look-ahead's (a
  // contact row the step releases opens, a film it lifts reaches Reynolds)
  // kept only where they hold for the final step, else the current point's.
  // Off, the look-ahead is taken as its passes leave it: faster where it
  // converges (2-4x on the synthetic point contacts), but on a measured
  // map's mixed regime it stalled where the checked steps converge
  // (docs/development-log.md, 2026-11-30). A solve that fails with it off
  // is solved again with it on (solve_mixed_film).
  bool checked_step_branches = false;
  // Where a continuation's halving stalls on a 2D grid, the film from the
  // last converged one with the contact rows smoothed and the smoothing
  // followed down to zero (docs/theory.md, mixed lubrication). Off, the
  // stall is reported.
  bool smoothed_rescue = true;
  MixedFrictionOptions friction;
  // Called with every Newton solve as it ends (on several processes on
  // each, with the same record); empty: none.
  MixedSolveTrace trace;

  // Throws InputError naming the option unless load >= 0 and finite, offset
  // finite, boundary_film > 0 and finite, the tolerances in (0, 1),
  // max_iterations >= 1, 2 <= krylov_restart <= 500, krylov_max_iterations
  // >= 1, 0 <= preconditioner_neighbourhood <= 8 and the friction options
  // valid.
  void validate() const;
  bool load_controlled() const { return load > 0.0; }
};

struct MixedFilm : NewtonFilmResult {
  // (ny, nx) row-major on the grid's cells; `pressure` is their sum.
  Eigen::ArrayXd fluid_pressure;    // p_f (Pa)
  Eigen::ArrayXd contact_pressure;  // p_c (Pa)
  double entrainment_speed = 0.0;   // |U| of the solve (m/s)
  double fluid_load = 0.0, contact_load = 0.0;
  double contact_load_fraction = 0.0;  // contact_load / load
  double contact_area = 0.0;           // m^2 (m in 1D): cells with p_c > 0
  double contact_area_fraction = 0.0;  // of all cells
  double cavitated_fraction = 0.0;     // cells with theta < 1 and no contact
  // Friction (N in 2D, N/m in 1D, (x, y)) on the rough surface, along the
  // sliding velocity: the film's shear (Couette, capped at the limiting
  // shear stress, and Poiseuille) on cells without contact, and Coulomb's
  // mu p_c on contact cells; the coefficient is |their sum| / load.
  std::array<double, 2> fluid_friction_force{0.0, 0.0};
  std::array<double, 2> contact_friction_force{0.0, 0.0};
  double friction_coefficient = 0.0;
  // The mass residual is measured on h_R; the contact complementarity is
  // the max over cells of max(-h, 0) / H, max(-p_c, 0) / P and min(h / H,
  // p_c / P).
  double complementarity_error = 0.0;
  // Stalls of this grid's continuations that the smoothed contact rows
  // got past (MixedFilmOptions::smoothed_rescue).
  int smoothed_rescues = 0;
};

// Solves the mixed film on the operator's grid (serial; the dense path on
// line contacts of at most kMaxMixedFilmNodes cells, GMRES on any grid:
// options.linear_solve). `gap` is g (m, >= 0 with its minimum at the
// contact's centre: the smooth shape plus the roughness, shifted). Starts
// from `start` (a previous film of the same grid), else tries in turn the
// EHL start (the dry contact under a thin film), the dry contact itself and
// a thick film. Under load control a solve that fails from there continues
// in the speed: from the start's speed, or from a faster film (4, 16, ...
// times the velocities) that converges, down in steps of at most a factor
// 2 (halved where a step fails); under separation control one continues in
// h0: from the start, or from the load-controlled film at the load of the
// dry contact at the approach -h0 (so a cold start needs h0 < 0: contact
// when dry). On 2D grids a continuation whose halving stalls tries, last,
// the contact rows smoothed and followed down to the film itself
// (docs/theory.md, mixed lubrication). `iterations` then counts every
// Newton step. Without a start,
// a load-controlled point contact of more than kMixedSequencingNodes nodes
// starts from the film of the grid of twice the spacing instead
// (options.grid_sequencing; its steps in coarse_iterations).
// Throws InputError for invalid input; non-convergence is a status.
MixedFilm solve_mixed_film(InfluenceOperator& op, const Eigen::ArrayXd& gap, const FlowConditions& conditions,
                           const LubricantLaws& laws, const MixedFilmOptions& options,
                           const MixedFilm* start = nullptr);

// Throws InputError naming `surface` and the grid if the linear solve
// `options` choose for `grid` cannot take it: the dense path beyond
// kMaxMixedFilmNodes nodes, or the GMRES path's memory estimate above the
// memory available, for `nodes` of the grid's nodes (0: all of them; on
// several processes a process's share). solve_mixed_film checks the same.
void require_mixed_film_fits(const Grid& grid, const MixedFilmOptions& options,
                             std::string_view surface = "the surface", std::size_t nodes = 0);

// The friction forces and coefficient of `film` (filled into it), from its
// pressures, fluid fraction and film; called by solve_mixed_film. With
// `rows` (film_rows.hpp) the film's fields are this process's rows of the
// grid and the forces the whole film's (collective).
void add_mixed_friction(const Grid& grid, const FlowConditions& conditions, const LubricantLaws& laws,
                        const MixedFrictionOptions& friction, double boundary_film, MixedFilm& film,
                        const FilmRows* rows = nullptr);

// One point of a Stribeck curve.
struct StribeckPoint {
  double entrainment_speed = 0.0;  // |U| (m/s)
  // eta0 |U| / w' with w' the load per unit width (1D: the load; 2D: the load
  // over the domain's extent across the entrainment).
  double hersey_number = 0.0;
  MixedFilm film;
};

// The mixed film at each entrainment speed (m/s, > 0, in the given order;
// each warm-started from the previous, and where that fails solved again
// without a start, as alone), the velocities scaled from
// `conditions` (their direction and slide-to-roll ratio kept; the
// entrainment velocity must not be zero). Load control only.
std::vector<StribeckPoint> stribeck_sweep(InfluenceOperator& op, const Eigen::ArrayXd& gap,
                                          const FlowConditions& conditions, const LubricantLaws& laws,
                                          const MixedFilmOptions& options, const std::vector<double>& speeds);

// The sweep shared out among `processes`, each holding the whole gap and a
// serial operator on the whole grid (the films are independent solves):
// contiguous runs of the speeds, the last run on process 0 (the runs go to
// the processes in reverse order) so that it holds the last speed's film
// whole. Within a run each speed starts from the previous one as above; a
// run's first speed starts as a single solve does (grid-sequenced), so its
// film equals the one-process sweep's to the solver's tolerance, not to
// the bit. Every process returns every point: its own whole, the others'
// with their film's summary (status, message, Newton and GMRES counts,
// load, friction forces and coefficient, contact share and area, central
// and minimum film thickness, peak pressure) but not its fields.
// Collective: every process passes the same speeds.
std::vector<StribeckPoint> stribeck_sweep(InfluenceOperator& op, const Eigen::ArrayXd& gap,
                                          const FlowConditions& conditions, const LubricantLaws& laws,
                                          const MixedFilmOptions& options, const std::vector<double>& speeds,
                                          const linalg::Communicator& processes);

// The run of `speeds` indices [first, end) that process `rank` of `size`
// solves in the shared sweep (possibly empty when there are fewer speeds
// than processes).
std::pair<std::size_t, std::size_t> stribeck_run(std::size_t speeds, int rank, int size);

}  // namespace halfspace::lubrication
