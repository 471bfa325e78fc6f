// Newton's method on the whole EHL problem (elastic_film.hpp). Per node the
// mass balance of the control volume (reynolds_stencil.hpp's finite volumes,
// with the face conductance the mean of the two nodes' eps = rho h^3 /
// (12 eta), as Venner & Lubrecht 2000, ch. 8, discretise the piezoviscous
// equation) depends on the pressures, fluid fractions and films of the node
// and its neighbours; every film depends on every pressure through K and on
// h0. The Jacobian is therefore
//
//   J = (A_p + A_h K) diag(dp/ds) + A_theta diag(dtheta/ds),
//
// A_* the sparse local derivatives, plus the h0 column (the row sums of A_h)
// and the load row. K is read off one product of the operator with a unit
// pressure (it is translation invariant), so free and periodic grids and
// coated half-spaces all use the operator the contact solvers use. A
// backtracking line search on the scaled residual's norm (film_newton.hpp,
// the iteration the mixed film shares) keeps the films positive and the
// semi-smooth steps (a node switching full/cavitated) from diverging. Each step's linear system is solved by the
// dense LU of J, or on larger grids by GMRES with K applied by the
// operator (film_krylov_solver.hpp), which never forms K.
#include "halfspace/lubrication/elastic_film.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <optional>
#include <vector>

#include "dry_contact_memo.hpp"
#include "film_grid_sequence.hpp"
#include "film_krylov_solver.hpp"
#include "film_newton.hpp"
#include "film_slab.hpp"
#include "halfspace/error.hpp"
#include "halfspace/lubrication/cavitation_solver.hpp"
#include "halfspace/lubrication/reynolds_stencil.hpp"
#include "halfspace/memory_estimate.hpp"
#include "reynolds_linearisation.hpp"

namespace halfspace::lubrication {

std::string_view to_string(CouetteScheme scheme) {
  return scheme == CouetteScheme::second_order ? "second-order" : "first-order";
}

CouetteScheme parse_couette_scheme(std::string_view text) {
  if (text == "first-order") return CouetteScheme::first_order;
  if (text == "second-order") return CouetteScheme::second_order;
  throw InputError(fmt::format("Couette scheme '{}' is invalid: allowed are first-order, second-order", text));
}

std::string_view to_string(FilmLinearSolve solve) {
  switch (solve) {
    case FilmLinearSolve::dense:
      return "dense";
    case FilmLinearSolve::gmres:
      return "gmres";
    default:
      return "automatic";
  }
}

FilmLinearSolve parse_film_linear_solve(std::string_view text) {
  if (text == "automatic") return FilmLinearSolve::automatic;
  if (text == "dense") return FilmLinearSolve::dense;
  if (text == "gmres") return FilmLinearSolve::gmres;
  throw InputError(fmt::format("EHL linear solve '{}' is invalid: allowed are automatic, dense, gmres", text));
}

std::string_view to_string(KrylovPreconditioner preconditioner) {
  return preconditioner == KrylovPreconditioner::sparse_lu ? "sparse-lu" : "multigrid";
}

KrylovPreconditioner parse_krylov_preconditioner(std::string_view text) {
  if (text == "multigrid") return KrylovPreconditioner::multigrid;
  if (text == "sparse-lu") return KrylovPreconditioner::sparse_lu;
  throw InputError(fmt::format("EHL preconditioner '{}' is invalid: allowed are multigrid, sparse-lu", text));
}

void ElasticFilmOptions::validate() const {
  if (!(std::isfinite(load) && load > 0.0)) {
    throw OptionError("load", format_number(load), "is invalid: the EHL load must be positive and finite");
  }
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw OptionError("tolerance", format_number(tolerance), "is invalid: the EHL tolerance must be in (0, 1)");
  }
  if (!(load_tolerance > 0.0 && load_tolerance < 1.0)) {
    throw OptionError("load_tolerance", format_number(load_tolerance),
                      "is invalid: allowed range is 0 < tolerance < 1");
  }
  if (max_iterations < 1) {
    throw OptionError("max_iterations", fmt::format("{}", max_iterations), "is invalid: at least 1 Newton step");
  }
  detail::film_krylov_settings(*this).validate();
  if (preconditioner != KrylovPreconditioner::multigrid && preconditioner != KrylovPreconditioner::sparse_lu) {
    throw OptionError("preconditioner", fmt::format("{}", static_cast<int>(preconditioner)),
                      "is invalid: allowed are multigrid, sparse-lu");
  }
}

namespace {

// The start's films over the dry contact, in units of the gap at the dry
// contact's edge, tried in turn while the Newton iteration fails: a thin
// one converges fastest at high loads, where a thick one takes up to 5x
// the steps; at low loads the thin one may stall and the thick one
// converges (bench/ehl/ehl_validation.cpp).
constexpr std::array<double, 2> kStartFilms{0.5, 8.0};
// The trust region of a Newton step, in units of the pressure scale (the
// dry contact's peak) and of the thinnest film.
constexpr double kLargestStep = 0.5;
// A start but the last stagnates (and the next takes over) where the
// residual's norm has not fallen below kStagnationShare of its value
// kStagnationSteps steps before: on the bent trial path a failing thin
// start crept at relative decreases of 1e-6 for ten steps, where the
// straight path stalled at once (bench/ehl/ehl_validation.cpp;
// docs/development-log.md, 2026-12-04, forty-fourth session).
constexpr int kStagnationSteps = 5;
constexpr double kStagnationShare = 0.99;

// The state of the Newton iteration: s and h0, and what follows from them.
struct State {
  Eigen::ArrayXd s, pressure, theta, deformation, film;
  double offset = 0.0;
};

}  // namespace

using detail::FilmSlab;
using detail::influence_matrix;
using detail::linearise;
using detail::LocalTerm;
using detail::NodeCoefficients;

double detail::film_flux_residual(const FilmSlab& slab, const ReynoldsStencil& topology,
                                  const FlowConditions& conditions, const LubricantLaws& laws,
                                  const Eigen::ArrayXd& film, const Eigen::ArrayXd& pressure,
                                  const Eigen::ArrayXd& fluid_fraction, CouetteScheme scheme) {
  // Face by face: each face's flux leaves one control volume and enters the
  // other (the flux form, written apart from the Newton's node form). On
  // a slab every face of this process's nodes lies in the stencil.
  const Grid& grid = slab.stencil_grid();
  const std::size_t n = grid.size();
  const std::size_t first = slab.own_first();
  const std::size_t end = first + slab.own_nodes();
  const double eta0 = conditions.viscosity;
  Eigen::ArrayXd eps(static_cast<Eigen::Index>(n)), mass(static_cast<Eigen::Index>(n));
  double couette = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double pk = std::max(pressure[k], 0.0);
    mass[k] = laws.density_ratio(pk) * film[k] * fluid_fraction[k];
    if (k >= first && k < end && !topology.fixed(k)) {
      couette = std::max(couette, (topology.couette_x() + topology.couette_y()) * laws.density_ratio(pk) * film[k]);
    }
    eps[k] = laws.density_ratio(pk) * std::pow(film[k], 3) / (12.0 * eta0 * laws.viscosity_ratio(pk, eta0));
  }
  Eigen::ArrayXd balance = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(n));
  const double ux = conditions.entrainment_velocity[0];
  const double uy = conditions.entrainment_velocity[1];
  // The upwinded mass flux density through the face downstream of `up`.
  const auto carried = [&](std::size_t up, std::size_t up_up) {
    if (up_up == Neighbours::kNone || scheme == CouetteScheme::first_order) return mass[up];
    return std::max(1.5 * mass[up] - 0.5 * mass[up_up], 0.5 * mass[up]);  // limited as the Newton rows are
  };
  for (std::size_t k = 0; k < n; ++k) {
    const Neighbours nb = topology.neighbours(k);
    if (nb.east != Neighbours::kNone) {
      const std::size_t e = nb.east;
      const std::size_t up = ux >= 0.0 ? k : e;
      const std::size_t up_up = ux >= 0.0 ? nb.west : topology.neighbours(e).east;
      const double flux = -0.5 * (eps[k] + eps[e]) * (pressure[e] - pressure[k]) / (grid.dx() * grid.dx()) +
                          ux / grid.dx() * carried(up, up_up);
      balance[k] += flux;
      balance[e] -= flux;
    }
    if (nb.north != Neighbours::kNone) {
      const std::size_t o = nb.north;
      const std::size_t up = uy >= 0.0 ? k : o;
      const std::size_t up_up = uy >= 0.0 ? nb.south : topology.neighbours(o).north;
      const double flux = -0.5 * (eps[k] + eps[o]) * (pressure[o] - pressure[k]) / (grid.dy() * grid.dy()) +
                          uy / grid.dy() * carried(up, up_up);
      balance[k] += flux;
      balance[o] -= flux;
    }
  }
  double largest = 0.0;
  for (std::size_t k = first; k < end; ++k) {
    if (!topology.fixed(k)) largest = std::max(largest, std::abs(balance[k]));
  }
  largest = slab.max(largest);
  couette = slab.max(couette);
  return largest / (couette > 0.0 ? couette : 1.0);
}

double elastic_film_residual(const Grid& grid, const FlowConditions& conditions, const LubricantLaws& laws,
                             const Eigen::ArrayXd& film, const Eigen::ArrayXd& pressure,
                             const Eigen::ArrayXd& fluid_fraction, CouetteScheme scheme) {
  const detail::FilmSlab whole(grid, conditions, grid.size(), linalg::serial_communicator(), 0);
  const ReynoldsStencil topology(grid, Eigen::ArrayXd::Ones(static_cast<Eigen::Index>(grid.size())), conditions);
  return detail::film_flux_residual(whole, topology, conditions, laws, film, pressure, fluid_fraction, scheme);
}

detail::FilmKrylovSettings detail::film_krylov_settings(const ElasticFilmOptions& options) {
  return {.restart = options.krylov_restart,
          .max_iterations = options.krylov_max_iterations,
          .tolerance = options.krylov_tolerance,
          .neighbourhood = options.preconditioner_neighbourhood,
          .preconditioner = options.preconditioner};
}

void detail::require_film_memory(const Grid& grid, const ElasticFilmOptions& options, std::size_t nodes) {
  const double needed = detail::film_krylov_memory_estimate(nodes, film_krylov_settings(options));
  const auto available = available_memory();
  if (available && needed > available->bytes) {
    throw InputError(fmt::format("the EHL solve on the {} grid needs about {}, more than the {} available ({})",
                                 grid.shape_string(), format_bytes(needed), format_bytes(available->bytes),
                                 available->source));
  }
}

ElasticFilm detail::solve_film_newton(InfluenceOperator& op, const Eigen::ArrayXd& gap,
                                      const FlowConditions& conditions, const LubricantLaws& laws,
                                      const ElasticFilmOptions& options, const ElasticFilm* start) {
  const auto started = std::chrono::steady_clock::now();
  const Grid& grid = op.grid();
  conditions.validate(grid);
  laws.validate(conditions.viscosity);
  options.validate();
  const bool second_order = options.couette_scheme == CouetteScheme::second_order;
  // This process's rows and the halo the stencil reaches (two rows for the
  // second-order Couette flux's upstream extrapolation).
  const FilmSlab slab(grid, conditions, op.local_size(), op.communicator(), second_order ? 2 : 1);
  const std::size_t n = slab.own_nodes();
  const std::size_t first = slab.own_first();
  const bool spread = slab.distributed();
  if (spread && options.linear_solve == FilmLinearSolve::dense) {
    throw InputError("the EHL solver's dense linear solve runs on one process: use the gmres solve on several");
  }
  const bool krylov = spread || options.linear_solve == FilmLinearSolve::gmres ||
                      (options.linear_solve == FilmLinearSolve::automatic && n > kAutomaticKrylovNodes);
  if (!krylov && n > kMaxElasticFilmNodes) {
    throw InputError(fmt::format(
        "the {} grid has {} nodes: the EHL solver's dense linear solve allows at most {} (use the gmres solve)",
        grid.shape_string(), n, kMaxElasticFilmNodes));
  }
  const detail::FilmKrylovSettings krylov_settings = detail::film_krylov_settings(options);
  if (krylov) {
    detail::agree_on_input(slab.communicator(), [&] { detail::require_film_memory(grid, options, n); });
  }
  if (!slab.all(static_cast<std::size_t>(gap.size()) == n && gap.allFinite())) {
    throw InputError(fmt::format("EHL gap has {} values, the {} grid has {} cells{}; every value must be finite",
                                 gap.size(), grid.shape_string(), grid.size(),
                                 spread ? fmt::format(" ({} on this process)", n) : ""));
  }
  const auto ni = static_cast<Eigen::Index>(n);
  const auto own = [&](Eigen::ArrayXd& field) { return field.segment(static_cast<Eigen::Index>(first), ni); };
  const auto stencil_size = static_cast<Eigen::Index>(slab.stencil_nodes());
  const ReynoldsStencil topology(slab.stencil_grid(), Eigen::ArrayXd::Ones(stencil_size), slab.stencil_conditions());
  const detail::OwnNodes own_nodes{.first = first, .count = n, .comm = spread ? &slab.communicator() : nullptr};
  const double eta0 = conditions.viscosity;
  const double area = grid.cell_area();
  const double w = options.load;
  const double supply = conditions.boundary.supply_fluid_fraction;
  if (topology.couette_x() + topology.couette_y() <= 0.0) {
    throw InputError("EHL entrainment velocity is zero: the film needs entrainment to carry a load");
  }

  ElasticFilm result;
  State x;
  for (Eigen::ArrayXd* field : {&x.pressure, &x.theta, &x.deformation, &x.film}) field->setZero(stencil_size);
  // The start: a previous film, or the dry contact at the load with a film
  // laid over it (Newton then finds h0).
  double pressure_scale = 0.0;
  double dry_offset = 0.0, edge_gap = 0.0;
  const bool dry_start =
      !slab.all(start != nullptr && start->pressure.size() == ni && start->fluid_fraction.size() == ni);
  if (!dry_start) {
    pressure_scale = std::max(start->max_pressure, w / grid.domain_area());
    own(x.pressure) = start->pressure;
    own(x.theta) = start->fluid_fraction;
    x.offset = start->offset;
  } else {
    const solvers::SolveResult contact = detail::solve_dry_contact(op, gap, solvers::Loading::force(w));
    if (!contact.converged()) {
      result.message = fmt::format("the dry contact that starts the EHL solve did not converge: {}", contact.message);
      // Fields of the grid's size all the same, so that the failure is
      // written and reported like any other: no pressure, the undeformed
      // film, full of fluid.
      result.pressure = Eigen::ArrayXd::Zero(ni);
      result.fluid_fraction = Eigen::ArrayXd::Ones(ni);
      result.film = gap;
      result.deformation = Eigen::ArrayXd::Zero(ni);
      return result;
    }
    pressure_scale = contact.max_pressure;
    own(x.pressure) = contact.pressure;
    own(x.theta).setOnes();
    // A dry contact on nodes of imposed pressure only (a wedge touching at
    // its outlet edge) leaves the film's nodes unloaded, and the first
    // Newton step from there was singular at any load: the load spread
    // evenly over them instead.
    double free_load = 0.0;
    double free_nodes = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      if (topology.fixed(first + k)) continue;
      free_load += contact.pressure[static_cast<Eigen::Index>(k)];
      free_nodes += 1.0;
    }
    free_load = slab.sum(free_load);
    free_nodes = slab.sum(free_nodes);
    if (!(free_load > 0.0) && free_nodes > 0.0) {
      const double mean = w / (area * free_nodes);
      for (std::size_t k = 0; k < n; ++k) {
        x.pressure[static_cast<Eigen::Index>(first + k)] = topology.fixed(first + k) ? 0.0 : mean;
      }
      pressure_scale = mean;
    }
    // The undeformed gap at the dry contact's edge (b^2 / 2R for a
    // cylinder or sphere) sets the scale of the elastic film.
    for (Eigen::Index k = 0; k < ni; ++k) {
      if (contact.pressure[k] > 0.0) edge_gap = std::max(edge_gap, gap[k]);
    }
    edge_gap = slab.max(edge_gap);
    if (!(edge_gap > 0.0)) edge_gap = std::max(slab.max(ni > 0 ? gap.maxCoeff() : 0.0), 1e-9);
    dry_offset = -contact.approach;
    x.offset = dry_offset + kStartFilms[0] * edge_gap;
  }
  x.s.resize(ni);
  for (Eigen::Index k = 0; k < ni; ++k) {
    const auto at = static_cast<Eigen::Index>(first) + k;
    x.s[k] = x.pressure[at] > 0.0 ? x.pressure[at] / pressure_scale : x.theta[at] - 1.0;
  }

  // p, theta, K p and h of s and h0, on this process's nodes and then the
  // halo; false (on every process) if a film is not positive.
  const auto evaluate = [&](State& state) {
    detail::set_pressure_and_fraction(topology, pressure_scale, supply, state.s, state.pressure, state.theta, first);
    op.apply({state.pressure.data() + first, n}, {state.deformation.data() + first, n});
    own(state.film) = state.offset + gap + own(state.deformation);
    if (!slab.all((own(state.film) > 0.0).all() && own(state.film).allFinite())) return false;
    for (Eigen::ArrayXd* field : {&state.pressure, &state.theta, &state.film}) slab.exchange(field->data());
    return true;
  };
  if (!evaluate(x)) {
    result.message = "the start of the EHL solve has a film that is not positive";
    return result;
  }

  // The dense path's K, J and LU; the GMRES path's local rows and solver.
  const Eigen::MatrixXd k_matrix = krylov ? Eigen::MatrixXd() : influence_matrix(op);
  NodeCoefficients coefficients;
  std::vector<LocalTerm> terms;
  terms.reserve(16);
  Eigen::VectorXd residual(ni + 1), step(ni + 1);
  Eigen::MatrixXd jacobian_t(krylov ? 0 : ni + 1, krylov ? 0 : ni + 1);  // J transposed: row k's in column k
  Eigen::PartialPivLU<Eigen::MatrixXd> lu(krylov ? 0 : ni + 1);
  detail::LocalRows rows;
  std::optional<detail::FilmKrylovSolver> krylov_solver;
  if (krylov) {
    rows.start.resize(n + 1);
    rows.terms.reserve(16 * n);
    krylov_solver.emplace(op, topology, krylov_settings, slab);
  }
  std::vector<char> branch_full(n, 1);
  std::vector<char> solved_full(n, 1);  // the branches the step was solved on
  double mass_scale = 1.0;

  // The scaled residual (mass rows over mass_scale, the load row over w)
  // and the measured relative residuals.
  const auto measure = [&](State& state, Eigen::VectorXd& out, bool linearise_too) {
    coefficients.update(laws, eta0, state.pressure, state.film);
    const bool dense_too = linearise_too && !krylov;
    if (dense_too) jacobian_t.setZero();
    detail::FilmMeasure m;
    m.mass = detail::mass_rows(
        topology, coefficients, state.pressure, state.theta, state.film, second_order, mass_scale, terms, out,
        linearise_too && krylov ? &rows : nullptr,
        [&](std::size_t k, const std::vector<LocalTerm>& row_terms) {
          if (!dense_too) return;
          auto column = jacobian_t.col(static_cast<Eigen::Index>(k));
          double by_offset = 0.0;
          for (const LocalTerm& t : row_terms) {
            const auto node = static_cast<Eigen::Index>(t.node);
            if (t.by_film != 0.0) {
              column.head(ni) += (t.by_film / mass_scale) * k_matrix.col(node);
            }
            by_offset += t.by_film;
            column[node] += t.by_pressure / mass_scale;
          }
          column[ni] = by_offset / mass_scale;
        },
        own_nodes);
    const double load = slab.sum(own(state.pressure).sum()) * area;
    out[ni] = (load - w) / w;
    m.load = std::abs(load - w) / w;
    m.norm = slab.norm(out, 1);
    if (!dense_too) return m;
    // Columns of J are rows of J^T: scale by dp/ds, then add d theta / ds.
    for (std::size_t j = 0; j < n; ++j) {
      const auto jj = static_cast<Eigen::Index>(j);
      const bool fixed = topology.fixed(j);
      const bool full = !fixed && branch_full[j] != 0;
      if (fixed) {
        jacobian_t.row(jj).setZero();
        jacobian_t(jj, jj) = 1.0;
      } else {
        jacobian_t.row(jj) *= full ? pressure_scale : 0.0;
      }
      jacobian_t(jj, ni) = full ? pressure_scale * area / w : 0.0;
    }
    detail::add_fraction_columns(topology, coefficients, state.pressure, state.theta, state.film, second_order,
                                 mass_scale, branch_full, terms, jacobian_t);
    return m;
  };

  // The mass rows' scale: the largest Couette outflow of the start.
  const auto scale_masses = [&] { mass_scale = detail::largest_couette_outflow(topology, x.film, own_nodes); };
  scale_masses();

  const State initial = x;
  State trial = x;
  Eigen::VectorXd trial_residual(ni + 1);
  // The film's differences from the mixed film's Newton iteration: two
  // starts (a thin film with half the steps, then a thick one), steps
  // counted when taken, GMRES to min(1e-2, ||F||) (Eisenstat & Walker's
  // term, newton_forcing.hpp, took a Newton step more here at 64^2 and
  // 512^2: docs/development-log.md, 2026-11-30, branch lub30i), the trust
  // region on s and h0 alone.
  detail::FilmNewton newton;
  newton.rules = {.words = {.solver = "the EHL", .film = "the EHL film", .krylov_step = ""},
                  .tolerances = {.mass = options.tolerance,
                                 .load = options.load_tolerance,
                                 .contact = std::nullopt,
                                 .start_norm_share = std::nullopt},
                  .forcing = detail::FilmForcing::residual_norm,
                  .krylov = krylov,
                  .krylov_tolerance = options.krylov_tolerance,
                  .counts_refused_steps = false,
                  .starts = dry_start ? kStartFilms.size() : 1,
                  .share = options.max_iterations / 2,
                  .limit = options.max_iterations,
                  .limit_on_each_start = true,
                  .stagnation_steps = kStagnationSteps,
                  .stagnation_share = kStagnationShare,
                  .stagnation_ends_last_start = false};
  newton.measure = [&] { return measure(x, residual, false); };
  newton.lay_start = [&](std::size_t attempt) {
    x = initial;
    x.offset = dry_offset + kStartFilms[attempt] * edge_gap;
    if (!evaluate(x)) return false;
    scale_masses();
    return true;
  };
  newton.solve = [&](const detail::FilmMeasure&, double forcing, bool) {
    detail::FilmNewtonSolve outcome;
    // The generalised Jacobian's branch per node: full where s >= 0,
    // cavitated below (branch_consistent_step settles the nodes at s = 0).
    for (std::size_t j = 0; j < n; ++j) branch_full[j] = x.s[static_cast<Eigen::Index>(j)] >= 0.0 ? 1 : 0;
    if (!krylov) {
      const auto linearise = [&] {
        solved_full = branch_full;
        measure(x, residual, true);
      };
      outcome.solved = detail::branch_consistent_step(linearise, topology, x.s, jacobian_t, residual, lu, step,
                                                      branch_full, detail::kSwitchBand);
      return outcome;
    }
    // The linearisation does not depend on the branches: once, then one
    // GMRES solve per branch pass.
    measure(x, residual, true);
    const auto gmres_solve = [&] {
      const detail::KrylovOutcome solved =
          krylov_solver->solve(rows, branch_full, pressure_scale, mass_scale, area / w, forcing, residual, step);
      solved_full = branch_full;
      outcome.krylov_iterations += solved.iterations;
      outcome.krylov_message = solved.message;
      return solved.converged;
    };
    outcome.solved =
        detail::branch_consistent_step_on(gmres_solve, topology, first, x.s, step, branch_full, detail::kSwitchBand,
                                          [&](bool flipped) { return !slab.all(!flipped); });
    return outcome;
  };
  // No pressure changes by more than the pressure scale, h0 by no more than
  // the thinnest film.
  newton.trust_region = [&] {
    const double largest_change = slab.max(ni > 0 ? step.head(ni).cwiseAbs().maxCoeff() : 0.0);
    const double film_change = std::abs(step[ni]) / slab.min(own(x.film).minCoeff());
    return std::min(
        {1.0, kLargestStep / std::max(largest_change, 1e-300), kLargestStep / std::max(film_change, 1e-300)});
  };
  // The trial point on the bent path (detail::bent_trial_path), as the
  // mixed film's: on the straight path a few nodes carried across the
  // switch cut every other Newton step to a few thousandths, and the 1024^2
  // point contact took 13 fine Newton steps instead of 5, 75 trial points
  // instead of 5 (docs/development-log.md, 2026-12-04, forty-fourth session).
  newton.try_step = [&](double lambda, bool) -> std::optional<detail::FilmMeasure> {
    detail::bent_trial_path(topology, first, x.s, step, lambda, solved_full, trial.s);
    trial.offset = x.offset + lambda * step[ni];
    if (!evaluate(trial)) return std::nullopt;
    return measure(trial, trial_residual, false);
  };
  newton.accept = [&] { std::swap(x, trial); };
  result.tight_retries = detail::run_film_newton(newton, result);

  // This process's rows of the fields; the scalars of the whole film.
  result.used_krylov = krylov;
  result.pressure = own(x.pressure);
  result.fluid_fraction = own(x.theta);
  result.film = own(x.film);
  result.deformation = own(x.deformation);
  result.offset = x.offset;
  result.load = slab.sum(result.pressure.sum()) * area;
  // The contact's centre: the first node of the smallest undeformed gap.
  const Eigen::Index centre = slab.centre_node(gap);
  result.central_film_thickness = slab.max(centre >= 0 ? result.film[centre] : -INFINITY);
  result.minimum_film_thickness = slab.min(ni > 0 ? result.film.minCoeff() : INFINITY);
  result.max_pressure = slab.max(ni > 0 ? result.pressure.maxCoeff() : -INFINITY);
  // The check apart from the iteration: the flux-form residual, the
  // complementarity and the load.
  result.relative_residual =
      detail::film_flux_residual(slab, topology, conditions, laws, x.film, x.pressure, x.theta, options.couette_scheme);
  result.load_error = std::abs(result.load - w) / w;
  detail::check_after_newton(newton.rules, 0.0,
                             slab.all(satisfies_complementarity(result.pressure, result.fluid_fraction)), result);
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace halfspace::lubrication
