// Newton's method on the mixed film (mixed_film.hpp): the EHL solver's
// semi-smooth Newton (elastic_film.cpp, film_newton.hpp) with a contact
// pressure per node.
// The unknowns are [s (n), q (n), h0] with p_f = P max(s, 0), theta = 1 +
// min(s, 0) and p_c = P q; the rows are the n mass balances (on the film h_R
// = reynolds_film(h, h_b)), the n contact rows min(q, h / H) and the load.
// With dh/dp = K for the fluid and the contact pressure alike, the
// Jacobian's blocks are
//
//   d balance / d s = (A_p + A_h D K) diag(P full) + A_theta diag(cavitated)
//   d balance / d q = A_h D K P,          D = diag(dh_R / dh) (or the step's)
//   d contact / d q = I (open rows) or K P / H (closed rows, h = 0 imposed)
//   d contact / d s = 0 (open) or K diag(P full) / H (closed)
//
// plus the h0 column and the load row; the contact rows are the active-set
// form of the complementarity (Hintermüller, Ito & Kunisch 2003: the
// primal-dual active set method is a semi-smooth Newton on the min
// function). With a smoothing mu > 0 the contact rows are instead the
// smoothed Fischer–Burmeister function q + h/H - sqrt(q^2 + (h/H)^2 + 2 mu),
// zero where q > 0, h > 0 and q h / H = mu (Kanzow 1996, Chen & Harker
// 1993): a smooth exchange of contact and fluid pressure on contact cells,
// followed down to mu = 0 (solve_mixed_film_smoothed).
#include "halfspace/lubrication/mixed_film.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "film_grid_sequence.hpp"
#include "film_newton.hpp"
#include "film_slab.hpp"
#include "halfspace/error.hpp"
#include "halfspace/lubrication/cavitation_solver.hpp"
#include "halfspace/lubrication/reynolds_stencil.hpp"
#include "halfspace/memory_estimate.hpp"
#include "mixed_film_grid_sequence.hpp"
#include "mixed_film_krylov.hpp"
#include "newton_forcing.hpp"
#include "reynolds_linearisation.hpp"

namespace halfspace::lubrication {

double reynolds_film(double film, double boundary_film) {
  if (film >= 1.5 * boundary_film) return film;
  if (film <= 0.5 * boundary_film) return boundary_film;
  const double above = film - 0.5 * boundary_film;
  return boundary_film + above * above / (2.0 * boundary_film);
}

double reynolds_film_slope(double film, double boundary_film) {
  if (film >= 1.5 * boundary_film) return 1.0;
  if (film <= 0.5 * boundary_film) return 0.0;
  return (film - 0.5 * boundary_film) / boundary_film;
}

Eigen::ArrayXd reynolds_film(const Eigen::ArrayXd& film, double boundary_film) {
  return film.unaryExpr([boundary_film](double h) { return reynolds_film(h, boundary_film); });
}

void MixedFrictionOptions::validate() const {
  if (!(std::isfinite(contact_friction) && contact_friction >= 0.0)) {
    throw OptionError("contact_friction", format_number(contact_friction), "is invalid: it must be >= 0 and finite");
  }
  shear.validate();
}

void MixedFilmOptions::validate() const {
  // OptionError: the front ends restate the option as their flag or keyword.
  if (!(std::isfinite(load) && load >= 0.0)) {
    throw OptionError("load", format_number(load),
                      "is invalid: it must be positive and finite (or 0 for separation control)");
  }
  if (!std::isfinite(offset)) throw OptionError("offset", format_number(offset) + " m", "is invalid: not finite");
  if (!(std::isfinite(boundary_film) && boundary_film > 0.0)) {
    throw OptionError("boundary_film", format_number(boundary_film) + " m",
                      "is invalid: it must be positive and finite (e.g. 1e-9)");
  }
  const auto fraction = [](double value, const char* name) {
    if (!(value > 0.0 && value < 1.0)) {
      throw OptionError(name, format_number(value), "is invalid: allowed range is 0 < tolerance < 1");
    }
  };
  fraction(tolerance, "tolerance");
  fraction(load_tolerance, "load_tolerance");
  fraction(contact_tolerance, "contact_tolerance");
  if (max_iterations < 1) {
    throw OptionError("max_iterations", std::to_string(max_iterations), "is invalid: at least 1 Newton step");
  }
  detail::MixedKrylovSettings{krylov_restart, krylov_max_iterations, krylov_tolerance, preconditioner_neighbourhood,
                              preconditioner}
      .validate();
  if (preconditioner != KrylovPreconditioner::multigrid && preconditioner != KrylovPreconditioner::sparse_lu) {
    throw OptionError("preconditioner", std::to_string(static_cast<int>(preconditioner)),
                      "is invalid: allowed are multigrid, sparse-lu");
  }
  friction.validate();
}

namespace {

// FilmLinearSolve::automatic: dense on line contacts within the dense
// path's limit, GMRES otherwise.
bool takes_krylov(const Grid& grid, const MixedFilmOptions& options) {
  return options.linear_solve == FilmLinearSolve::gmres ||
         (options.linear_solve == FilmLinearSolve::automatic &&
          (grid.dimension() != 1 || grid.size() > kMaxMixedFilmNodes));
}

detail::MixedKrylovSettings mixed_krylov_settings(const MixedFilmOptions& options) {
  return {options.krylov_restart, options.krylov_max_iterations, options.krylov_tolerance,
          options.preconditioner_neighbourhood, options.preconditioner};
}

}  // namespace

void require_mixed_film_fits(const Grid& grid, const MixedFilmOptions& options, std::string_view surface,
                             std::size_t nodes) {
  const std::size_t n = nodes > 0 ? nodes : grid.size();
  if (!takes_krylov(grid, options)) {
    if (n > kMaxMixedFilmNodes) {
      throw InputError(fmt::format(
          "{} ({} grid) has {} points: the mixed film's dense Newton path allows at most {} (use the gmres linear "
          "solve)",
          surface, grid.shape_string(), n, kMaxMixedFilmNodes));
    }
    return;
  }
  const double needed = detail::mixed_krylov_memory_estimate(n, mixed_krylov_settings(options));
  const auto available = available_memory();
  if (available && needed > available->bytes) {
    throw InputError(fmt::format("{}: the mixed film on the {} grid needs about {}, more than the {} available ({})",
                                 surface, grid.shape_string(), format_bytes(needed), format_bytes(available->bytes),
                                 available->source));
  }
}

namespace {

using detail::influence_matrix;
using detail::linearise;
using detail::LocalTerm;
using detail::NodeCoefficients;

// The starts tried in turn when none is given: the EHL start (the dry
// contact's pressure as fluid under half an edge gap of film), the dry
// contact itself (all pressure in contact, no fluid pressure), a thick film.
enum class Start { thin_film, dry_contact, thick_film };
constexpr std::array<Start, 3> kStarts{Start::thin_film, Start::dry_contact, Start::thick_film};
constexpr double kThinFilm = 0.5;
constexpr double kThickFilm = 8.0;
// The trust region of a step: s and q by at most this, h0 by at most this
// times the thinnest fluid film (at least kFilmFloorShare of H).
constexpr double kLargestStep = 0.5;
constexpr double kFilmFloorShare = 0.05;
// A GMRES step that stops short of its forcing term (the iteration limit)
// is still taken, far from the solution (a residual norm of at least
// kLargestForcing), if it lowers the linear model's residual below this
// share of the Newton residual: ||J d + F|| < ||F|| makes d a descent
// direction of ||F||^2 (Dembo, Eisenstat & Steihaug 1982), and the line
// search judges it. On the fine grid's first steps from an interpolated
// coarse film GMRES stalled far above the forcing term (128^2: 0.59 after
// 800 iterations) and the failed step ended the Newton iteration. Near the
// solution such steps crept (256^2: the norm moved in its fifth digit per
// 800 iterations) where the continuation's smaller speed step converges
// (docs/development-log.md, 2026-11-29, branches lub30g and lub30h).
constexpr double kLoosestLinearResidual = 0.9;

// The share of the Newton steps (1 / this) a cold start gets on the GMRES path.
constexpr int kKrylovColdShare = 4;
// The fine grid's first try from the coarse film (MixedStartUse::try_only)
// gives up where GMRES stops short of its forcing term or the residual's
// norm has not fallen below kStagnationShare of its value kStagnationSteps
// steps before: on a rough point contact such a try crept for thousands of
// GMRES iterations before it stalled (at 128^2 80 % of the fine grid's),
// and the way round, a faster film and the continuation in the speed, was
// the cheaper one (docs/development-log.md, 2026-12-01). On larger grids
// (MixedStartUse::try_until_short) only the first rule holds: a measured
// map's 256^2 try took 1,200 GMRES iterations per step before it failed.
constexpr int kStagnationSteps = 3;
constexpr double kStagnationShare = 0.75;
// The watchdog's steps (detail::FilmNewtonRules::watchdog_steps) past a
// stall. Where the line search finds no lower point the residual's norm
// has a kink along the Newton direction (a contact row's or the cavitation
// switch's branch, docs/development-log.md, 2026-12-01, twenty-seventh
// session), and a step over it often pays: the measured window resampled
// to 512^2 stalled at a relative mass residual of 3e-7 and, with the
// watchdog, converged (twenty-eighth session). A try
// (MixedStartUse::try_only) gives up at a stall instead.
constexpr int kWatchdogSteps = 4;
// The GMRES path's passes over the switch nodes' branches per solve of the
// step (the dense path's detail::kBranchPasses): each is a GMRES solve, and
// a node whose branch still disagrees with its step after them stays on
// the switch along the trial path (detail::stays_on_switch). From 4, at
// 1024^2 the GMRES iterations after the coarse levels fell by a fifth and
// the answer's first step from 16 solves to 8 (docs/development-log.md,
// 2026-12-04, forty-second and forty-third sessions).
constexpr int kKrylovSwitchPasses = 2;

// The smoothed contact row at q and f = h / H.
double smoothed_contact_row(double q, double f, double mu) {
  return q + f - std::sqrt(q * q + f * f + 2.0 * mu);
}

// The Newton state: s and q on this process's nodes, fluid pressure,
// fraction and films on its stencil (halo current), contact and total
// pressure and deformation on its nodes (film_slab.hpp; on one process all
// of them the grid's).
struct State {
  Eigen::ArrayXd s, q, fluid, theta, contact, total, deformation, film, reynolds_film;
  double offset = 0.0;
};

// The branches the step goes into, as detail::branch_consistent_step takes
// the cavitation switch's: taken at the current point alone, a contact
// spot's edge that must open keeps its closed row (h = 0) and its film on
// the floor h_R = h_b (film derivative D_j = 0), so the linear model
// sees a film that cannot open and asks for hundreds of pressure scales to
// push the inflow through h_b by Poiseuille flow; the steps crept and 128^2
// did not finish (docs/development-log.md, 2026-11-29). Here a closed row
// that the step `step` releases (q + dq <= (h + dh) / H) opens (p_c = 0),
// and a node below 1.5 h_b that the step lifts above it takes D_j = 1.
// Branches change only that way, so the passes end; near the solution no
// node crosses and the Jacobian is the film's own. `film_change` is dh =
// K (dp_f + dp_c) + dh0 of the step. Returns whether a branch changed (the
// step is then solved again).
// On a slab (film_slab.hpp) the own nodes' from the stencil node `first`;
// the caller agrees on the answer.
bool take_step_branches(const State& x, std::size_t first, double hb, double H, bool smoothed,
                        const Eigen::VectorXd& step, const Eigen::VectorXd& film_change, std::vector<char>& closed,
                        std::vector<double>& film_slope) {
  const Eigen::Index ni = x.q.size();
  bool flipped = false;
  const auto take = [&](char& branch, bool wanted) {
    if (branch != static_cast<char>(wanted)) {
      branch = static_cast<char>(wanted);
      flipped = true;
    }
  };
  for (Eigen::Index j = 0; j < ni; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    const std::size_t at = first + jj;
    const double film = x.film[static_cast<Eigen::Index>(at)] + film_change[j];
    if (!smoothed && closed[jj] != 0 && !(x.q[j] + step[ni + j] > film / H)) take(closed[jj], false);
    if (film_slope[at] < 1.0 && reynolds_film_slope(film, hb) == 1.0) {
      film_slope[at] = 1.0;
      flipped = true;
    }
  }
  return flipped;
}

// Whether the look-ahead's branches (take_step_branches, from an earlier
// pass's step) hold for the final step `step` with film change
// `film_change`: every row it released ends open (q + dq <= (h + dh) / H)
// and every film it lifted ends above 1.5 h_b. Each pass solves the step
// again, and the last step can undo what an earlier one promised; a
// released node whose film then falls keeps h < 0 with its row on q, and
// no step along such a direction lowered the residual (the 64^2 level of a
// measured map stalled; docs/development-log.md, 2026-11-30).
bool look_ahead_holds(const State& x, std::size_t first, double hb, double H, bool smoothed,
                      const Eigen::VectorXd& step, const Eigen::VectorXd& film_change, const std::vector<char>& closed,
                      const std::vector<double>& film_slope) {
  const Eigen::Index ni = x.q.size();
  for (Eigen::Index j = 0; j < ni; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    const auto at = static_cast<Eigen::Index>(first) + j;
    const double film = x.film[at] + film_change[j];
    const bool released = !smoothed && closed[jj] == 0 && x.film[at] / H < x.q[j];
    if (released && x.q[j] + step[ni + j] > film / H) return false;
    const bool lifted = film_slope[first + jj] > reynolds_film_slope(x.film[at], hb);
    if (lifted && reynolds_film_slope(film, hb) < 1.0) return false;
  }
  return true;
}

// The contact rows' residuals on the branches `closed`: h / H (closed) or q
// (the smoothed rows have no branches).
void contact_residuals(const State& x, std::size_t first, double H, bool smoothed, const std::vector<char>& closed,
                       Eigen::VectorXd& residual) {
  if (smoothed) return;
  const Eigen::Index ni = x.q.size();
  for (Eigen::Index j = 0; j < ni; ++j) {
    residual[ni + j] =
        closed[static_cast<std::size_t>(j)] != 0 ? x.film[static_cast<Eigen::Index>(first) + j] / H : x.q[j];
  }
}

}  // namespace

namespace {

// One Newton solve from `start` or the standard starts, with the contact
// rows smoothed by `smoothing` (mu) where it is > 0.
MixedFilm newton_solve(InfluenceOperator& op, const Eigen::ArrayXd& gap, detail::MixedFilmKeep& keep,
                       const FlowConditions& conditions, const LubricantLaws& laws, const MixedFilmOptions& options,
                       const MixedFilm* start, detail::MixedStartUse use = detail::MixedStartUse::solve_only,
                       double smoothing = 0.0) {
  const bool smoothed = smoothing > 0.0;
  const bool only_trying = use == detail::MixedStartUse::try_only || use == detail::MixedStartUse::try_until_short ||
                           use == detail::MixedStartUse::try_as_start;
  const auto started = std::chrono::steady_clock::now();
  const Grid& grid = op.grid();
  conditions.validate(grid);
  laws.validate(conditions.viscosity);
  options.validate();
  const bool second_order = options.couette_scheme == CouetteScheme::second_order;
  // This process's rows and the halo the stencil reaches (film_slab.hpp):
  // on one process the whole grid.
  const detail::FilmSlab slab(grid, conditions, op.local_size(), op.communicator(), second_order ? 2 : 1);
  const std::size_t n = slab.own_nodes();
  const std::size_t first = slab.own_first();
  const bool spread = slab.distributed();
  if (spread && options.linear_solve == FilmLinearSolve::dense) {
    throw InputError("the mixed film's dense linear solve runs on one process: use the gmres solve on several");
  }
  detail::agree_on_input(slab.communicator(), [&] { require_mixed_film_fits(grid, options, "the mixed film", n); });
  const bool krylov = spread || takes_krylov(grid, options);
  const detail::MixedKrylovSettings krylov_settings = mixed_krylov_settings(options);
  if (!slab.all(static_cast<std::size_t>(gap.size()) == n && gap.allFinite())) {
    throw InputError(fmt::format("mixed film gap has {} values, the {} grid has {} cells{}; every value must be finite",
                                 gap.size(), grid.shape_string(), grid.size(),
                                 spread ? fmt::format(" ({} on this process)", n) : ""));
  }
  const auto ni = static_cast<Eigen::Index>(n);
  const auto own = [&](auto& field) { return field.segment(static_cast<Eigen::Index>(first), ni); };
  const auto stencil_size = static_cast<Eigen::Index>(slab.stencil_nodes());
  const ReynoldsStencil topology(slab.stencil_grid(), Eigen::ArrayXd::Ones(stencil_size), slab.stencil_conditions());
  const detail::OwnNodes own_nodes{.first = first, .count = n, .comm = spread ? &slab.communicator() : nullptr};
  if (topology.couette_x() + topology.couette_y() <= 0.0) {
    throw InputError(
        "mixed film entrainment velocity is zero: at zero speed the film carries nothing (solve the dry contact)");
  }
  const bool load_control = options.load_controlled();
  const double eta0 = conditions.viscosity;
  const double area = grid.cell_area();
  const double w = options.load;
  const double supply = conditions.boundary.supply_fluid_fraction;
  const double hb = options.boundary_film;
  // The step's branches (take_step_branches) and the clipped step on point
  // contacts, where they cut the fine Newton steps (64^2: 55 to 33) and let
  // 128^2 converge; on the rough line contacts of the tests they took 4x the
  // work (docs/development-log.md, 2026-11-29).
  const bool step_branches = grid.dimension() == 2;
  const Eigen::Index m = 2 * ni + (load_control ? 1 : 0);  // unknowns
  const Eigen::Index h0 = 2 * ni;                          // index of h0 (load control)

  MixedFilm result;
  // The dry contact (the grid's, kept in `keep`): the start and the scales P
  // (its peak pressure) and H (the largest undeformed gap inside it).
  double pressure_scale = 0.0, film_scale = 0.0, dry_offset = options.offset;
  Eigen::ArrayXd dry_pressure = Eigen::ArrayXd::Zero(ni);
  const bool given_start = slab.all(start != nullptr && start->fluid_pressure.size() == ni &&
                                    start->contact_pressure.size() == ni && start->fluid_fraction.size() == ni);
  if (load_control || !given_start) {
    const solvers::Loading loading =
        load_control ? solvers::Loading::force(w) : solvers::Loading::approach(std::max(-options.offset, 0.0));
    if (load_control || -options.offset > 0.0) {
      const solvers::SolveResult& contact = keep.dry.solve(op, gap, loading);
      if (!contact.converged()) {
        result.message =
            fmt::format("the dry contact that starts the mixed solve did not converge: {}", contact.message);
        return result;
      }
      dry_pressure = contact.pressure;
      pressure_scale = contact.max_pressure;
      if (load_control) dry_offset = -contact.approach;
    }
  }
  for (Eigen::Index k = 0; k < ni; ++k) {
    if (dry_pressure[k] > 0.0) film_scale = std::max(film_scale, gap[k]);
  }
  film_scale = slab.max(film_scale);
  if (!(film_scale > 0.0)) {
    film_scale =
        std::max(slab.max(ni > 0 ? gap.maxCoeff() : -INFINITY) - slab.min(ni > 0 ? gap.minCoeff() : INFINITY), 1e-9);
  }
  // The dense path's K; the GMRES path's solver (which reads K_00).
  const Eigen::MatrixXd k_matrix = krylov ? Eigen::MatrixXd() : influence_matrix(op);
  std::optional<detail::MixedKrylovSolver> krylov_solver;
  if (krylov) krylov_solver.emplace(op, topology, krylov_settings, load_control, slab, &keep.arnoldi);
  const double self_influence = krylov ? krylov_solver->self_influence() : k_matrix(0, 0);
  if (given_start) {
    pressure_scale = std::max(
        pressure_scale, slab.max(ni > 0 ? (start->fluid_pressure + start->contact_pressure).maxCoeff() : -INFINITY));
  }
  if (!(pressure_scale > 0.0)) pressure_scale = 1e-3 * film_scale / self_influence;
  if (load_control) pressure_scale = std::max(pressure_scale, w / grid.domain_area());
  const double P = pressure_scale;
  const double H = film_scale;

  State x;
  for (Eigen::ArrayXd* field : {&x.s, &x.q, &x.contact, &x.total, &x.deformation}) field->resize(ni);
  for (Eigen::ArrayXd* field : {&x.fluid, &x.theta, &x.film, &x.reynolds_film}) field->setZero(stencil_size);
  const auto set_start = [&](Start kind) {
    if (kind == Start::dry_contact) {
      x.s.setZero();
      x.q = dry_pressure / P;
      x.offset = dry_offset;
    } else {
      x.s = dry_pressure / P;
      x.q.setZero();
      x.offset = dry_offset + (kind == Start::thin_film ? kThinFilm : kThickFilm) * H;
    }
  };
  if (given_start) {
    for (Eigen::Index k = 0; k < ni; ++k) {
      x.s[k] = start->fluid_pressure[k] > 0.0 ? start->fluid_pressure[k] / P : start->fluid_fraction[k] - 1.0;
    }
    x.q = start->contact_pressure / P;
    x.offset = load_control ? start->offset : options.offset;
  } else {
    set_start(load_control ? kStarts[0] : Start::dry_contact);
  }
  if (!load_control) x.offset = options.offset;

  // The fields of s, q and h0 on this process's nodes, then the halo; false
  // (on every process) if a film is not finite.
  const auto evaluate = [&](State& state) {
    detail::set_pressure_and_fraction(topology, P, supply, state.s, state.fluid, state.theta, first);
    state.contact = P * state.q;
    state.total = own(state.fluid) + state.contact;
    op.apply({state.total.data(), n}, {state.deformation.data(), n});
    own(state.film) = state.offset + gap + state.deformation;
    if (!slab.all(own(state.film).allFinite())) return false;
    for (Eigen::ArrayXd* field : {&state.fluid, &state.theta, &state.film}) slab.exchange(field->data());
    // In place: evaluate runs at every line-search trial.
    state.reynolds_film = state.film.unaryExpr([hb](double h) { return reynolds_film(h, hb); });
    return true;
  };

  NodeCoefficients coefficients;
  std::vector<LocalTerm> terms;
  terms.reserve(16);
  Eigen::VectorXd residual(m), step(m), trial_residual(m), clipped(m), pressure_change(ni);
  const Eigen::Index dense_size = krylov ? 0 : m;
  Eigen::MatrixXd jacobian_t(dense_size, dense_size);  // J transposed: row r's derivatives in column r
  Eigen::PartialPivLU<Eigen::MatrixXd> lu(dense_size);
  detail::MixedRows rows;
  if (krylov) {
    rows.start.resize(n + 1);
    rows.terms.reserve(16 * n);
  }
  rows.film_slope.resize(slab.stencil_nodes());  // D_j, the floor's slopes (both paths; on the stencil)
  if (smoothed) {
    rows.contact_by_q.resize(n);
    rows.contact_by_film.resize(n);
  }
  Eigen::VectorXd film_change(ni);
  std::vector<char> branch_full(n, 1);
  std::vector<char> closed(n, 0);  // contact rows on the h branch
  double mass_scale = 1.0;

  const auto measure = [&](const State& state, Eigen::VectorXd& out, bool linearise_too) {
    coefficients.update(laws, eta0, state.fluid, state.reynolds_film);
    detail::FilmMeasure result_measure;
    const bool dense_too = linearise_too && !krylov;
    if (dense_too) jacobian_t.setZero();
    // Per unit pressure: the local d/dp_f in the s block, the film's d/dp
    // (through K, for p_f and p_c alike) in the q block.
    result_measure.mass = detail::mass_rows(
        topology, coefficients, state.fluid, state.theta, state.reynolds_film, second_order, mass_scale, terms, out,
        linearise_too && krylov ? &rows : nullptr,
        [&](std::size_t k, const std::vector<LocalTerm>& row_terms) {
          if (!dense_too) return;
          auto column = jacobian_t.col(static_cast<Eigen::Index>(k));
          double by_offset = 0.0;
          for (const LocalTerm& t : row_terms) {
            const auto node = static_cast<Eigen::Index>(t.node);
            column[node] += t.by_pressure / mass_scale;
            const double by_film = t.by_film * rows.film_slope[t.node];
            if (by_film != 0.0) {
              column.segment(ni, ni) += (by_film / mass_scale) * k_matrix.col(node);
              by_offset += by_film;
            }
          }
          if (load_control) column[h0] = by_offset / mass_scale;
        },
        own_nodes);
    double contact = 0.0;
    for (Eigen::Index k = 0; k < ni; ++k) {
      const double f = state.film[static_cast<Eigen::Index>(first) + k] / H;
      const double row = smoothed ? smoothed_contact_row(state.q[k], f, smoothing) : std::min(state.q[k], f);
      out[ni + k] = row;
      contact = std::max(contact, std::abs(row));
    }
    const double load = slab.sum((own(state.fluid) + state.contact).sum()) * area;
    if (load_control) out[h0] = (load - w) / w;
    result_measure.load = load_control ? std::abs(load - w) / w : 0.0;
    result_measure.contact = slab.max(contact);
    result_measure.norm = slab.norm(out, load_control ? 1 : 0);
    if (!dense_too) return result_measure;
    // Rows of J^T are the unknowns: s_j from the pressure rows (zero where
    // s_j is cavitated or the node fixed), q_j = P times the film block.
    for (std::size_t j = 0; j < n; ++j) {
      const auto jj = static_cast<Eigen::Index>(j);
      if (topology.fixed(j)) {
        jacobian_t.row(jj).setZero();
        jacobian_t(jj, jj) = 1.0;
      } else {
        const double scale = branch_full[j] != 0 ? P : 0.0;
        jacobian_t.row(jj) = (jacobian_t.row(jj) + jacobian_t.row(ni + jj)) * scale;
      }
      jacobian_t.row(ni + jj) *= P;
    }
    detail::add_fraction_columns(topology, coefficients, state.fluid, state.theta, state.reynolds_film, second_order,
                                 mass_scale, branch_full, terms, jacobian_t);
    // The contact rows: open ones fix q, closed ones the film; smoothed
    // ones weigh both.
    for (std::size_t k = 0; k < n; ++k) {
      const auto kk = static_cast<Eigen::Index>(k);
      auto column = jacobian_t.col(ni + kk);
      if (!smoothed && closed[k] == 0) {
        column[ni + kk] = 1.0;
        continue;
      }
      const double by_film = smoothed ? rows.contact_by_film[k] : 1.0;
      for (std::size_t j = 0; j < n; ++j) {
        const auto jj = static_cast<Eigen::Index>(j);
        const double by_pressure = by_film * k_matrix(kk, jj) * P / H;
        column[ni + jj] = by_pressure;
        column[jj] = !topology.fixed(j) && branch_full[j] != 0 ? by_pressure : 0.0;
      }
      if (smoothed) column[ni + kk] += rows.contact_by_q[k];
      if (load_control) column[h0] = by_film / H;
    }
    if (load_control) {
      auto column = jacobian_t.col(h0);
      for (std::size_t j = 0; j < n; ++j) {
        const auto jj = static_cast<Eigen::Index>(j);
        column[jj] = !topology.fixed(j) && branch_full[j] != 0 ? P * area / w : 0.0;
        column[ni + jj] = P * area / w;
      }
    }
    return result_measure;
  };

  const auto scale_masses = [&] { mass_scale = detail::largest_couette_outflow(topology, x.reynolds_film, own_nodes); };

  evaluate(x);
  scale_masses();
  State trial = x;
  // On the GMRES path (point contacts) only the thin-film start is tried
  // cold, with a quarter of the steps: where it fails the dry and thick
  // starts failed too on the rough point contacts measured (32^2, 64^2:
  // 134 steps spent), and the speed continuation from a faster film is the
  // cheaper way on (solve_mixed_film). Each start but the last gets an
  // equal share of the steps.
  const std::size_t attempts = given_start || !load_control || krylov ? 1 : kStarts.size();
  const int cold_budget = krylov && !given_start && load_control
                              ? std::max(1, options.max_iterations / kKrylovColdShare)
                              : options.max_iterations;
  // The film's differences from the EHL film's Newton iteration: the
  // contact rows' tolerance, Eisenstat & Walker's forcing term, a refused
  // step counted (the continuations add the steps of every solve), up to
  // three starts with the limit on the last, the step's branches and the
  // clipped step on point contacts, and a start's norm rule where the film
  // is only the next solve's start.
  detail::FilmNewton newton;
  newton.rules = {.words = {.solver = "the mixed film's", .film = "the mixed film", .krylov_step = "the mixed film's "},
                  .tolerances = {.mass = options.tolerance,
                                 .load = options.load_tolerance,
                                 .contact = options.contact_tolerance,
                                 .start_norm_share = use == detail::MixedStartUse::solve_as_start ||
                                                             use == detail::MixedStartUse::try_as_start
                                                         ? std::optional<double>(detail::kStartNormShare)
                                                         : std::nullopt},
                  .forcing = detail::FilmForcing::eisenstat_walker,
                  .krylov = krylov,
                  .krylov_tolerance = options.krylov_tolerance,
                  .counts_refused_steps = true,
                  .starts = attempts,
                  .share = std::max(1, options.max_iterations / static_cast<int>(attempts)),
                  .limit = cold_budget,
                  .limit_on_each_start = false};
  if (use == detail::MixedStartUse::try_only) {
    newton.rules.stagnation_steps = kStagnationSteps;
    newton.rules.stagnation_share = kStagnationShare;
  } else {
    newton.rules.watchdog_steps = kWatchdogSteps;
  }
  newton.measure = [&] { return measure(x, residual, false); };
  newton.lay_start = [&](std::size_t attempt) {
    set_start(kStarts[attempt]);
    evaluate(x);
    scale_masses();
    return true;
  };
  // A branch pass's GMRES (and the tight solve's) goes on from the last
  // solve's step of this Newton step: they differ in a few rows.
  bool warm = false;
  // The branches the step was last solved on (the passes flip branch_full
  // after each solve, the last one's too): the trial path's.
  std::vector<char> solved_full(n, 1);
  newton.solve = [&](const detail::FilmMeasure& current, double forcing, bool tight) {
    detail::FilmNewtonSolve outcome;
    if (!tight) warm = false;
    const auto branches_at_x = [&] {
      // The floor's slopes on the whole stencil (its halo's films are
      // current), the branches on this process's nodes.
      for (Eigen::Index k = 0; k < stencil_size; ++k) {
        rows.film_slope[static_cast<std::size_t>(k)] = reynolds_film_slope(x.film[k], hb);
      }
      for (std::size_t j = 0; j < n; ++j) {
        const auto jj = static_cast<Eigen::Index>(j);
        const double film = x.film[static_cast<Eigen::Index>(first + j)];
        branch_full[j] = x.s[jj] >= 0.0 ? 1 : 0;
        closed[j] = film / H < x.q[jj] ? 1 : 0;
        if (smoothed) {
          // The preconditioner takes the row's larger weight as its branch.
          const double q = x.q[jj], f = film / H, root = std::sqrt(q * q + f * f + 2.0 * smoothing);
          rows.contact_by_q[j] = 1.0 - q / root;
          rows.contact_by_film[j] = 1.0 - f / root;
          closed[j] = rows.contact_by_film[j] > rows.contact_by_q[j] ? 1 : 0;
        }
      }
    };
    // The tight retry keeps the branches and the linearisation the loose
    // passes ended with: from the current point's branches it ran all its
    // passes again, and at 1024^2 none of those retries led to a step; from
    // the loose passes' branches the stalls of the measured window's
    // continuation steps were passed without the watchdog (0.0113 m/s: 697
    // -> 545 GMRES iterations; docs/development-log.md, 2026-12-03,
    // thirty-eighth session).
    if (!tight) {
      branches_at_x();
      // On the GMRES path the rows do not depend on the branches: linearised
      // once, then one GMRES solve per branch pass; the dense path's J is
      // formed again per pass.
      if (krylov) measure(x, residual, true);
    }
    const detail::MixedScales scales{P, H, mass_scale, load_control ? area / w : 0.0, load_control};
    // A try (only_trying) takes none: it gives up where GMRES stops short.
    const bool short_steps_taken = current.norm >= detail::kLargestForcing && !only_trying;
    const auto gmres_solve = [&] {
      const detail::KrylovOutcome solved =
          krylov_solver->solve(rows, branch_full, closed, scales, forcing, residual, step, warm);
      warm = solved.converged;
      solved_full = branch_full;
      outcome.krylov_iterations += solved.iterations;
      outcome.krylov_message = solved.message;
      return solved.converged || (short_steps_taken && solved.relative_residual <= kLoosestLinearResidual);
    };
    const auto linearise_rows = [&] {
      solved_full = branch_full;
      measure(x, residual, true);
      contact_residuals(x, first, H, smoothed, closed, residual);
    };
    const auto solve_step = [&] {
      return krylov ? detail::branch_consistent_step_on(
                          gmres_solve, topology, first, x.s, step, branch_full, detail::kSwitchBand,
                          [&](bool flipped) { return !slab.all(!flipped); }, kKrylovSwitchPasses)
                    : detail::branch_consistent_step(linearise_rows, topology, x.s, jacobian_t, residual, lu, step,
                                                     branch_full);
    };
    // dh = K (dp_f + dp_c) + dh0 of the step.
    const auto step_film_change = [&] {
      if (krylov) {
        krylov_solver->film_change(step, film_change);
        return;
      }
      pressure_change = P * step.segment(ni, ni);
      for (std::size_t j = 0; j < n; ++j) {
        const auto jj = static_cast<Eigen::Index>(j);
        if (!topology.fixed(j) && branch_full[j] != 0) pressure_change[jj] += P * step[jj];
      }
      film_change.noalias() = k_matrix * pressure_change;
      if (load_control) film_change.array() += step[h0];
    };
    bool looked_ahead = false;
    for (int pass = 0; pass < detail::kBranchPasses; ++pass) {
      outcome.solved = solve_step();
      if (!outcome.solved || pass + 1 == detail::kBranchPasses || !step_branches) break;
      step_film_change();
      // Agreed: the next pass is collective. A lifted film's slope reaches
      // the neighbours' halo.
      if (slab.all(!take_step_branches(x, first, hb, H, smoothed, step, film_change, closed, rows.film_slope))) break;
      slab.exchange(rows.film_slope.data());
      looked_ahead = true;
      if (krylov) contact_residuals(x, first, H, smoothed, closed, residual);
    }
    if (outcome.solved && looked_ahead && options.checked_step_branches) {
      step_film_change();
      if (!slab.all(look_ahead_holds(x, first, hb, H, smoothed, step, film_change, closed, rows.film_slope))) {
        // The step on the current point's branches (a generalised Jacobian
        // of the residual there).
        branches_at_x();
        if (krylov) contact_residuals(x, first, H, smoothed, closed, residual);
        outcome.solved = solve_step();
      }
    }
    return outcome;
  };
  // s and q by at most kLargestStep, h0 by at most kLargestStep times the
  // thinnest film.
  const auto offset_cap = [&] {
    const double thickest = slab.max(ni > 0 ? own(x.film).maxCoeff() : -INFINITY);
    const double thinnest = slab.min(ni > 0 ? own(x.reynolds_film).minCoeff() : INFINITY);
    return kLargestStep * std::max(thickest > 0.0 ? thinnest : 0.0, kFilmFloorShare * H);
  };
  newton.trust_region = [&] {
    const double largest_change = slab.max(ni > 0 ? step.head(2 * ni).cwiseAbs().maxCoeff() : 0.0);
    const double lambda = std::min(1.0, kLargestStep / std::max(largest_change, 1e-300));
    return load_control ? std::min(lambda, offset_cap() / std::max(std::abs(step[h0]), 1e-300)) : lambda;
  };
  // Where the trust region would shorten the whole step for a few entries
  // (contact cells, whose fluid pressure the h_b film barely constrains,
  // asking for tens of pressure scales), first the step with each entry
  // clipped to the trust region, the rest whole, and its halves.
  newton.clip = [&](double lambda) {
    if (!(lambda < 1.0 && step_branches)) return false;
    clipped.head(2 * ni) = step.head(2 * ni).cwiseMax(-kLargestStep).cwiseMin(kLargestStep);
    if (load_control) clipped[h0] = std::clamp(step[h0], -offset_cap(), offset_cap());
    return true;
  };
  // The trial point on the bent path (detail::bent_trial_path). On the
  // straight path the line search cut the step to 3e-5 for a few
  // pressurised nodes at s = 1e-4 to 1e-2: 256^2 crept for 45 minutes and
  // did not converge (docs/development-log.md, 2026-11-30).
  // A node on the switch that the step moves to the side other than the
  // branch it was solved on stays on it (detail::stays_on_switch): where
  // the branch passes end before the branches agree with the step, that
  // side's derivative is not the model's, and a thick film's mass row sees
  // a pressure through h^3 far more than a fraction: at 1024^2 the
  // residual's norm rose along such a direction 50 times faster than it
  // fell (docs/development-log.md, 2026-12-04).
  newton.try_step = [&](double scale, bool clip) -> std::optional<detail::FilmMeasure> {
    const Eigen::VectorXd& along = clip ? clipped : step;
    detail::bent_trial_path(topology, first, x.s, along, scale, solved_full, trial.s);
    trial.q = x.q + scale * along.segment(ni, ni).array();
    trial.offset = load_control ? x.offset + scale * along[h0] : x.offset;
    if (!evaluate(trial)) return std::nullopt;
    return measure(trial, trial_residual, false);
  };
  // The smoothed iteration's kinks are the cavitation switch's alone (its
  // contact rows are smooth): the step to the first one just past it, where
  // the bent path holds the node at s = 0. Without it the smoothed rows
  // stalled on 2 or 3 processes where one converged (17^2 rough balls,
  // MpiSlabMixedFilm); the plain iteration keeps its halving (the 128^2
  // measured window took 62 Newton steps with the kink's step against 45).
  if (smoothed) {
    newton.first_kink = [&](double longest) {
      double nearest = INFINITY;
      for (Eigen::Index k = 0; k < ni; ++k) {
        if (topology.fixed(first + static_cast<std::size_t>(k)) || x.s[k] == 0.0) continue;
        if ((x.s[k] > 0.0) == (step[k] > 0.0) || step[k] == 0.0) continue;
        const double at = -x.s[k] / step[k] * (1.0 + 1e-12);
        if (at < longest) nearest = std::min(nearest, at);
      }
      return slab.min(nearest);
    };
  }
  newton.accept = [&] { std::swap(x, trial); };
  State saved;
  newton.save = [&] { saved = x; };
  newton.restore = [&] { x = saved; };
  detail::run_film_newton(newton, result);
  result.used_krylov = krylov;
  result.entrainment_speed = std::hypot(conditions.entrainment_velocity[0], conditions.entrainment_velocity[1]);

  // The result, with the contact pressure's rounding clipped (q below 0 by
  // the contact tolerance, and on open cells, h / H >= q, q within the
  // tolerance of 0: the dense LU's step sets it to 0 exactly, the inexact
  // GMRES step only to its residual; a smoothed film keeps all of it, q h /
  // H = mu on every cell) and the check made apart from the iteration.
  // This process's rows of the fields; the scalars of the whole film.
  result.fluid_pressure = own(x.fluid);
  if (smoothed) {
    result.contact_pressure = x.contact.max(0.0);
  } else {
    result.contact_pressure = (own(x.film) / H < x.q).select(x.contact.max(0.0), 0.0);
  }
  result.pressure = result.fluid_pressure + result.contact_pressure;
  result.fluid_fraction = own(x.theta);
  result.offset = x.offset;
  result.deformation.resize(ni);
  op.apply({result.pressure.data(), n}, {result.deformation.data(), n});
  result.film = x.offset + gap + result.deformation;
  result.fluid_load = slab.sum(result.fluid_pressure.sum()) * area;
  result.contact_load = slab.sum(result.contact_pressure.sum()) * area;
  result.load = result.fluid_load + result.contact_load;
  result.contact_load_fraction = result.load > 0.0 ? result.contact_load / result.load : 0.0;
  const double whole_nodes = static_cast<double>(grid.size());
  const double in_contact = slab.sum(static_cast<double>((result.contact_pressure > 0.0).count()));
  result.contact_area = in_contact * area;
  result.contact_area_fraction = in_contact / whole_nodes;
  // The contact's centre: the first node of the smallest undeformed gap.
  const Eigen::Index centre = slab.centre_node(gap);
  result.max_pressure = slab.max(ni > 0 ? result.pressure.maxCoeff() : -INFINITY);
  result.cavitated_fraction =
      slab.sum(static_cast<double>(((result.fluid_fraction < 1.0) && (result.contact_pressure <= 0.0)).count())) /
      whole_nodes;
  // The flux-form check on the stencil: the final film (K of the clipped
  // pressure) with its halo.
  Eigen::ArrayXd seen_film = Eigen::ArrayXd::Zero(stencil_size);
  own(seen_film) = result.film;
  slab.exchange(seen_film.data());
  seen_film = reynolds_film(seen_film, hb);
  result.relative_residual =
      detail::film_flux_residual(slab, topology, conditions, laws, seen_film, x.fluid, x.theta, options.couette_scheme);
  result.load_error = load_control ? std::abs(result.load - w) / w : 0.0;
  double complementarity = 0.0;
  for (Eigen::Index k = 0; k < ni; ++k) {
    const double h = result.film[k] / H;
    const double pc = x.contact[k] / P;
    // A smoothed film's own rows: h > 0, p_c > 0, h p_c / (H P) = mu.
    const double row = smoothed ? smoothed_contact_row(pc, h, smoothing) : std::min(h, pc);
    complementarity = std::max({complementarity, -h, -pc, std::abs(row)});
  }
  result.complementarity_error = slab.max(complementarity);
  // The film on contact cells is 0 to the rounding of h0 + g + K p (h0 may be
  // 1e4 times the film); the check above saw the film as computed.
  for (Eigen::Index k = 0; k < ni; ++k) {
    if (result.contact_pressure[k] > 0.0 || result.film[k] < 0.0) result.film[k] = 0.0;
  }
  result.central_film_thickness = slab.max(centre >= 0 ? result.film[centre] : -INFINITY);
  result.minimum_film_thickness = slab.min(ni > 0 ? result.film.minCoeff() : INFINITY);
  detail::check_after_newton(newton.rules, result.complementarity_error,
                             slab.all(satisfies_complementarity(result.fluid_pressure, result.fluid_fraction)), result);
  if (spread) {
    const detail::FilmSlabRows rows_view(slab);
    add_mixed_friction(grid, conditions, laws, options.friction, hb, result, &rows_view);
  } else {
    add_mixed_friction(grid, conditions, laws, options.friction, hb, result);
  }
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

// newton_solve, traced (MixedFilmOptions::trace).
MixedFilm solve_once(InfluenceOperator& op, const Eigen::ArrayXd& gap, detail::MixedFilmKeep& keep,
                     const FlowConditions& conditions, const LubricantLaws& laws, const MixedFilmOptions& options,
                     const MixedFilm* start, detail::MixedStartUse use = detail::MixedStartUse::solve_only,
                     double smoothing = 0.0) {
  const auto started = std::chrono::steady_clock::now();
  MixedFilm film = newton_solve(op, gap, keep, conditions, laws, options, start, use, smoothing);
  if (options.trace) {
    const Grid& grid = op.grid();
    options.trace(MixedSolveRecord{
        .nx = grid.nx(),
        .ny = grid.dimension() == 2 ? grid.ny() : 1,
        .entrainment_speed = std::hypot(conditions.entrainment_velocity[0], conditions.entrainment_velocity[1]),
        .smoothing = smoothing,
        .warm = start != nullptr,
        .checked_step_branches = options.checked_step_branches,
        .status = film.status,
        .newton_steps = film.iterations,
        .krylov_iterations = film.krylov_iterations,
        .most_krylov_per_step = film.max_krylov_iterations_per_step,
        .line_search_halvings = film.line_search_halvings,
        .watchdog_steps = film.watchdog_steps,
        .relative_residual = film.relative_residual,
        .contact_load_fraction = film.contact_load_fraction,
        .wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(),
    });
  }
  return film;
}

// The contact rows' smoothing (solve_mixed_film_smoothed): from mu =
// kFirstSmoothing down by kSmoothingFactor per solve to kLastSmoothing,
// then the film itself (mu = 0). mu is q h / H on contact cells in the
// units of the pressure and film scales, so 1e-2 spreads the contact
// pressure over films of a hundredth of H. On the measured map's 64^2
// window at 4e-4 m/s it went from the 8e-4 m/s film (contact share 0.07)
// to the film (0.71) where the halving had stalled at 7.8e-4 m/s
// (docs/development-log.md, 2026-12-02, thirtieth session). Tried on
// every failed step instead of at a stall it cost 3.5x at 128^2.
constexpr double kFirstSmoothing = 1e-2;
constexpr double kSmoothingFactor = 0.1;
constexpr double kLastSmoothing = 1e-12;

// The Newton and GMRES work of a continuation's solves (every solve counts,
// the films between are discarded).
struct Work {
  int steps = 0, solves = 0, krylov = 0, most_krylov = 0, rescues = 0;

  void add(const MixedFilm& film, int solve = 1) {
    steps += film.iterations;
    solves += solve;
    krylov += film.krylov_iterations;
    most_krylov = std::max(most_krylov, film.max_krylov_iterations_per_step);
  }
  // `film` with the work as its counts.
  MixedFilm into(MixedFilm film) const {
    film.iterations = steps;
    film.krylov_iterations = krylov;
    film.max_krylov_iterations_per_step = most_krylov;
    film.smoothed_rescues = rescues;
    return film;
  }
};

}  // namespace

MixedFilm detail::solve_mixed_film_smoothed(InfluenceOperator& op, const Eigen::ArrayXd& gap,
                                            detail::MixedFilmKeep& keep, const FlowConditions& conditions,
                                            const LubricantLaws& laws, const MixedFilmOptions& options,
                                            const MixedFilm& start) {
  Work work;
  MixedFilm from = start;
  for (double mu = kFirstSmoothing;; mu *= kSmoothingFactor) {
    const bool last = mu < kLastSmoothing;
    // A smoothed film is only the next one's start: its contact rows are
    // solved to 2 sqrt(mu), what min(q, h / H) is at q h / H = mu (tighter
    // rows, a 1e-2 mu, made the levels harder on the measured map's 64^2
    // window and one failed), the last film's to the options' tolerance.
    MixedFilmOptions at = options;
    if (!last) at.contact_tolerance = std::clamp(2.0 * std::sqrt(mu), options.contact_tolerance, 0.5);
    MixedFilm film = solve_once(op, gap, keep, conditions, laws, at, &from, MixedStartUse::solve_only, last ? 0.0 : mu);
    work.add(film, 0);
    if (!film.converged()) {
      film.message =
          fmt::format("the contact rows' smoothing stopped at mu = {:.3g}: {}", last ? 0.0 : mu, film.message);
      return work.into(std::move(film));
    }
    if (last) return work.into(std::move(film));
    from = std::move(film);
  }
}

MixedFilmOptions detail::full_film_start_options(const MixedFilmOptions& options) {
  MixedFilmOptions start = options;
  start.tolerance = std::max(options.tolerance, kFullFilmStartTolerance);
  start.load_tolerance = std::max(options.load_tolerance, kFullFilmStartTolerance);
  start.contact_tolerance = std::max(options.contact_tolerance, 1e-2 * kFullFilmStartTolerance);
  return start;
}

FlowConditions detail::at_speed_factor(const FlowConditions& conditions, double factor) {
  FlowConditions scaled = conditions;
  for (int axis = 0; axis < 2; ++axis) {
    scaled.entrainment_velocity[axis] *= factor;
    scaled.sliding_velocity[axis] *= factor;
  }
  return scaled;
}

namespace {
using detail::at_speed_factor;
using detail::kFullFilmStartTolerance;

// Continuation in the speed: from a film solved at `factor` times the
// velocities down (or up) to the velocities themselves, in steps of at most
// kContinuationRatio (in full film kFullFilmRatio, the last step
// kAnswerStartRatio), each warm-started from the last; a step that fails is
// halved (in log speed) down to kSmallestRatio. The films between are
// discarded; the steps are counted into the result's iterations.
constexpr double kContinuationRatio = 2.0;
constexpr double kFullFilmRatio = 2.0;
constexpr double kAnswerStartRatio = std::numbers::sqrt2;
constexpr double kSmallestRatio = 1.02;
constexpr int kContinuationSolves = 60;
constexpr double kRatioAfterSmoothing = 1.1;

MixedFilm continue_in_speed(InfluenceOperator& op, const Eigen::ArrayXd& gap, detail::MixedFilmKeep& keep,
                            const FlowConditions& conditions, const LubricantLaws& laws,
                            const MixedFilmOptions& options, MixedFilm film, double factor, Work& work) {
  // In full film (no contact load in the last film) the ratio that failed
  // is not tried again: the films thin smoothly as the speed falls, and on
  // the measured window at 1024^2 every step of 2 failed then (451 to 611 s
  // each) where steps of sqrt(2) converged. In the mixed regime the ratio
  // comes back to kContinuationRatio: there a small step can meet a kink a
  // larger one steps over (a 17^2 rough point contact stalled with the
  // ratio held; docs/development-log.md, 2026-12-03, thirty-fifth,
  // thirty-seventh and thirty-eighth sessions). Since the films between are
  // only starts, that window's steps of 2 take 1 Newton step each; the last
  // step in full film, to the velocities, is at most kAnswerStartRatio: the
  // answer from the film at 2 times the speed took 852 GMRES iterations,
  // from the one at sqrt(2) times 578-695 (docs/development-log.md,
  // 2026-12-04, forty-eighth session).
  const auto ceiling_after = [](const MixedFilm& last, double ceiling) {
    return last.contact_load_fraction > 0.0 ? kContinuationRatio : std::min(ceiling, kFullFilmRatio);
  };
  // A film between, in full film: only a start (kFullFilmStartTolerance,
  // kStartNormShare).
  const MixedFilmOptions full_film_start = detail::full_film_start_options(options);
  double ceiling = ceiling_after(film, kContinuationRatio);
  double ratio = ceiling;
  // The ratio after a step that converged.
  const auto grown_ratio = [&] { return std::min(ratio * 1.5, ceiling); };
  while (factor != 1.0 && work.solves < kContinuationSolves) {
    const double log_factor = std::abs(std::log(factor));
    const bool in_full_film = film.contact_load_fraction == 0.0;
    const double last_step = std::log(kAnswerStartRatio);  // in full film
    double log_step = std::min(log_factor, std::log(ratio));
    // In full film a step that would reach the velocities from farther than
    // kAnswerStartRatio stops that far short of them.
    if (in_full_film && log_step >= log_factor && log_factor > last_step + std::log(kSmallestRatio)) {
      log_step = log_factor - last_step;
    }
    const double next = log_factor <= log_step ? 1.0 : factor * std::exp(factor > 1.0 ? -log_step : log_step);
    // The film before the last (the step after it reaches the velocities)
    // is the answer's start: solved to the start tolerance without the norm
    // rule (from a start a Newton step worse the 1024^2 answer took 439 s
    // instead of 287 s; docs/development-log.md, 2026-12-03, forty-first
    // session).
    const bool only_a_start = next != 1.0 && in_full_film;
    const bool answers_start =
        std::abs(std::log(next)) <= std::min(std::log(grown_ratio()), in_full_film ? last_step : INFINITY) + 1e-12;
    MixedFilm trial = solve_once(
        op, gap, keep, at_speed_factor(conditions, next), laws, only_a_start ? full_film_start : options, &film,
        only_a_start && !answers_start ? detail::MixedStartUse::solve_as_start : detail::MixedStartUse::solve_only);
    work.add(trial);
    if (trial.converged()) {
      film = std::move(trial);
      factor = next;
      ceiling = ceiling_after(film, ceiling);
      ratio = grown_ratio();
      continue;
    }
    // Half the step that failed (in log speed): the last step to the
    // velocities can be shorter than the ratio allowed, and halving the
    // ratio alone tried it again as it was (a measured 512^2 window spent
    // 150 s on the same failed solve twice; docs/development-log.md,
    // 2026-12-02, thirty-third session).
    ratio = std::exp(0.5 * log_step);
    if (film.contact_load_fraction == 0.0) ceiling = std::min(ceiling, ratio);
    if (ratio >= kSmallestRatio) continue;
    // Stalled. On point contacts the last resort: the contact rows
    // smoothed, from the last film straight to the velocities, else to the
    // step that stalled (and on from there).
    bool rescued = false;
    std::string smoothed_failure;  // the last smoothed solve's message, for the stall's
    if (op.grid().dimension() == 2 && options.smoothed_rescue) {
      for (const double target : {1.0, next}) {
        MixedFilm smoothed =
            detail::solve_mixed_film_smoothed(op, gap, keep, at_speed_factor(conditions, target), laws, options, film);
        work.add(smoothed, 0);
        smoothed_failure = smoothed.message;
        if (smoothed.converged()) {
          film = std::move(smoothed);
          factor = target;
          ratio = kRatioAfterSmoothing;
          rescued = true;
          ++work.rescues;
          break;
        }
        if (next == 1.0) break;
      }
    }
    if (!rescued) {
      trial.message =
          fmt::format("speed continuation stalled at {:.4g} times the velocities: {}{}{}", next, trial.message,
                      smoothed_failure.empty() ? "" : "; with smoothed contact rows: ", smoothed_failure);
      return trial;
    }
  }
  if (factor != 1.0) {
    film.status = FilmStatus::iteration_limit;
    film.message =
        fmt::format("speed continuation stopped after {} solves at {:.4g} times the velocities", work.solves, factor);
  }
  return film;
}

}  // namespace

namespace {

// Separation control where the Newton iteration fails from its start: from
// the given film, or else from the load-controlled film at the load of the
// dry contact at the approach -h0, walk h0 to the target in steps halved
// where one fails.
constexpr int kOffsetSolves = 40;
constexpr double kSmallestOffsetStep = 1.0 / 256.0;

MixedFilm continue_in_offset(InfluenceOperator& op, const Eigen::ArrayXd& gap, detail::MixedFilmKeep& keep,
                             const FlowConditions& conditions, const LubricantLaws& laws,
                             const MixedFilmOptions& options, const MixedFilm* start, MixedFilm failed) {
  MixedFilm from;
  Work work;
  work.add(failed);
  // On several processes each holds its rows (agreed).
  if (op.communicator().min(
          start != nullptr && start->converged() && start->fluid_pressure.size() == gap.size() ? 1.0 : 0.0) > 0.5) {
    from = *start;
  } else {
    if (!(-options.offset > 0.0)) return failed;
    const solvers::SolveResult& contact = keep.dry.solve(op, gap, solvers::Loading::approach(-options.offset));
    if (!contact.converged() || !(contact.total_force > 0.0)) return failed;
    MixedFilmOptions by_load = options;
    by_load.load = contact.total_force;
    from = detail::solve_mixed_film(op, gap, keep, conditions, laws, by_load);
    work.add(from);
    if (!from.converged()) return failed;
  }
  const double first = from.offset;
  double done = 0.0, step = 1.0;
  while (done < 1.0 && work.solves < kOffsetSolves) {
    const double next = std::min(1.0, done + step);
    const double taken = next - done;
    MixedFilmOptions at = options;
    at.offset = first + next * (options.offset - first);
    MixedFilm trial = solve_once(op, gap, keep, conditions, laws, at, &from);
    work.add(trial);
    if (!trial.converged() && taken * 0.5 < kSmallestOffsetStep && op.grid().dimension() == 2 &&
        options.smoothed_rescue) {
      // Stalled: as in the speed continuation, the smoothed contact rows.
      MixedFilm smoothed = detail::solve_mixed_film_smoothed(op, gap, keep, conditions, laws, at, from);
      work.add(smoothed, 0);
      if (smoothed.converged()) {
        trial = std::move(smoothed);
        ++work.rescues;
      } else {
        trial.message += fmt::format("; with smoothed contact rows: {}", smoothed.message);
      }
    }
    if (trial.converged()) {
      from = std::move(trial);
      done = next;
      step = std::min(2.0 * step, 1.0);
      continue;
    }
    step = 0.5 * taken;  // of the step that failed, as the speed continuation's
    if (step < kSmallestOffsetStep) {
      trial.message = fmt::format("separation continuation stalled at h0 = {:.6g} m: {}", at.offset, trial.message);
      return work.into(std::move(trial));
    }
  }
  if (done < 1.0) {
    from.status = FilmStatus::iteration_limit;
    from.message = fmt::format("separation continuation stopped after {} solves at h0 = {:.6g} m", work.solves,
                               first + done * (options.offset - first));
  }
  return work.into(std::move(from));
}

}  // namespace

MixedFilm detail::solve_mixed_film_on_grid(InfluenceOperator& op, const Eigen::ArrayXd& gap,
                                           detail::MixedFilmKeep& keep, const FlowConditions& conditions,
                                           const LubricantLaws& laws, const MixedFilmOptions& options,
                                           const MixedFilm* start, MixedStartUse use) {
  const auto started = std::chrono::steady_clock::now();
  MixedFilm film;
  if (use != MixedStartUse::continue_only) {
    film = solve_once(op, gap, keep, conditions, laws, options, start, use);
    if (film.converged() || use != MixedStartUse::solve_then_continue) return film;
  }
  if (!options.load_controlled()) {
    MixedFilm continued = continue_in_offset(op, gap, keep, conditions, laws, options, start, std::move(film));
    continued.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return continued;
  }
  // Where the film does not converge from its starts (the mixed regime, with
  // contacts coming and going), continue in the speed: from the given film's
  // speed if it has one, else from a faster film that converges.
  Work work;
  work.add(film, use == MixedStartUse::continue_only ? 0 : 1);
  MixedFilm from;
  double factor = 0.0;
  const double speed = std::hypot(conditions.entrainment_velocity[0], conditions.entrainment_velocity[1]);
  if (start != nullptr && start->converged() && start->entrainment_speed > 0.0 && start->entrainment_speed != speed) {
    from = *start;
    factor = start->entrainment_speed / speed;
  }
  for (double faster = 4.0; factor == 0.0 && faster <= 1e4; faster *= 4.0) {
    MixedFilm trial = solve_once(op, gap, keep, at_speed_factor(conditions, faster), laws, options, nullptr);
    work.add(trial);
    if (trial.converged()) {
      from = std::move(trial);
      factor = faster;
    }
  }
  if (factor == 0.0) return work.into(std::move(film));
  MixedFilm continued =
      work.into(continue_in_speed(op, gap, keep, conditions, laws, options, std::move(from), factor, work));
  continued.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return continued;
}

}  // namespace halfspace::lubrication
