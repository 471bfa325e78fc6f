// The pieces of a Newton iteration on the piezoviscous, compressible p–theta
// Reynolds equation that the EHL film (elastic_film.cpp) and the mixed film
// (mixed_film.cpp) share: the nodes' coefficients, one node's balance with
// its local derivatives, and the dense influence matrix. Private to the
// library.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "halfspace/linalg/communicator.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/lubrication/lubricant.hpp"
#include "halfspace/lubrication/reynolds_stencil.hpp"
#include "halfspace/operators/influence_operator.hpp"

namespace halfspace::lubrication::detail {

// Nodes within this of the switch s = 0 take the branch their step goes
// into; the passes that may take. Only nodes exactly on it (the dry
// start's unloaded nodes, a node a bent trial path stopped on) choose:
// every other node takes the branch of its side, whose derivative is exact
// for short steps, so that the Newton direction descends. A band of 1e-9
// in s is 1e-9 of the pressure scale on the pressure side, which a thick
// film's mass row sees through h^3 far more strongly than 1e-9 of theta:
// nodes at p ~ 5e-10 of the scale given the cavitated branch stalled the
// EHL film's 1024^2 point contact at a mass residual of 6.65e-6 and the
// mixed film's 512^2 measured window below 1.4e-3 m/s
// (docs/development-log.md, 2026-11-29 and 2026-12-02).
inline constexpr double kSwitchBand = 0.0;
inline constexpr int kBranchPasses = 4;

// One semi-smooth Newton step on the generalised Jacobian's branches
// (`branch_full[j]`: 1 for the full-film branch of node j): `linearise()`
// fills `jacobian_t` (J transposed) and `residual` for the current
// branches; a node at the switch (|s| <= switch_band, as the start's
// unloaded nodes and an inlet's vanishing pressures) takes the branch the
// step moves it into, found by re-solving (the directional derivative;
// Qi & Sun 1993). Returns false when the step is not finite (J singular).
// The same with any linear solve: `solve()` fills `step` for the current
// branches and returns false when it cannot (reported by the caller).
// On several processes (film_slab.hpp) `s`, `step` and `branch_full` are
// this process's nodes, the first of them the stencil's node `first`, and
// `any` agrees on whether a branch flipped anywhere (the next pass is
// collective). At most `passes` solves.
template <class Solve, class Any>
bool branch_consistent_step_on(Solve&& solve, const ReynoldsStencil& topology, std::size_t first,
                               const Eigen::ArrayXd& s, const Eigen::VectorXd& step, std::vector<char>& branch_full,
                               double switch_band, Any&& any, int passes = kBranchPasses) {
  for (int pass = 0; pass < passes; ++pass) {
    if (!solve()) return false;
    bool flipped = false;
    for (std::size_t j = 0; j < branch_full.size(); ++j) {
      const auto jj = static_cast<Eigen::Index>(j);
      if (topology.fixed(first + j) || std::abs(s[jj]) > switch_band) continue;
      const char wanted = step[jj] >= 0.0 ? 1 : 0;
      if (wanted != branch_full[j]) {
        branch_full[j] = wanted;
        flipped = true;
      }
    }
    if (!any(flipped)) break;
  }
  return true;
}

// Whether a node at `s` on the switch (|s| <= kSwitchBand) stays on it
// along a step of `change` in s solved on the full-film branch (`solved_full`)
// or the cavitated one: where the branch passes end before
// every node's branch agrees with its step, the other side's derivative is
// not the linear model's, and the trial path keeps the node at s = 0, where
// the model's error is its change on the solved branch alone rather than the
// jump between the branches.
inline bool stays_on_switch(double s, double change, bool solved_full) {
  return std::abs(s) <= kSwitchBand && change != 0.0 && (change > 0.0) != solved_full;
}

// The trial point on a bent path, s + scale * along with every node the
// step carries across the cavitation switch (from off it) stopped on it,
// s = 0, as a projected Newton method's path stops at its bounds
// (Bertsekas 1982), and every node on the switch that stays_on_switch holds;
// the next step's branch passes choose its side from the direction. On the
// straight path the linear model, exact on a node's own branch, is wrong past
// the switch, and the line search cuts the whole step for a few nodes
// (docs/development-log.md, 2026-11-30 and 2026-12-04). `s` and
// `solved_full` are this process's nodes, the first the stencil's `first`.
inline void bent_trial_path(const ReynoldsStencil& topology, std::size_t first, const Eigen::ArrayXd& s,
                            const Eigen::VectorXd& along, double scale, const std::vector<char>& solved_full,
                            Eigen::ArrayXd& trial_s) {
  const Eigen::Index n = s.size();
  trial_s = s + scale * along.head(n).array();
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    if (topology.fixed(first + kk)) continue;
    const bool crossed = (s[k] > 0.0) != (trial_s[k] > 0.0);
    if ((crossed && std::abs(s[k]) > kSwitchBand) || stays_on_switch(s[k], along[k], solved_full[kk] != 0)) {
      trial_s[k] = 0.0;
    }
  }
}

template <class Solve>
bool branch_consistent_step_with(Solve&& solve, const ReynoldsStencil& topology, const Eigen::ArrayXd& s,
                                 const Eigen::VectorXd& step, std::vector<char>& branch_full,
                                 double switch_band = kSwitchBand) {
  return branch_consistent_step_on(std::forward<Solve>(solve), topology, 0, s, step, branch_full, switch_band,
                                   [](bool flipped) { return flipped; });
}

template <class Linearise>
bool branch_consistent_step(Linearise&& linearise, const ReynoldsStencil& topology, const Eigen::ArrayXd& s,
                            const Eigen::MatrixXd& jacobian_t, const Eigen::VectorXd& residual,
                            Eigen::PartialPivLU<Eigen::MatrixXd>& lu, Eigen::VectorXd& step,
                            std::vector<char>& branch_full, double switch_band = kSwitchBand) {
  const auto dense_solve = [&] {
    linearise();
    lu.compute(jacobian_t.transpose());
    step = lu.solve(-residual);
    return step.allFinite();
  };
  return branch_consistent_step_with(dense_solve, topology, s, step, branch_full, switch_band);
}

// The p-theta switch on the film's nodes (s clipped at -1, a fully
// cavitated node): p = P max(s, 0), theta = 1 + min(s, 0); on nodes of
// imposed pressure that pressure and the supply's fluid fraction.
// `s` may be a slab's own nodes, the first of them the stencil node `first`
// of `pressure` and `theta` (film_slab.hpp).
inline void set_pressure_and_fraction(const ReynoldsStencil& topology, double pressure_scale, double supply,
                                      Eigen::ArrayXd& s, Eigen::ArrayXd& pressure, Eigen::ArrayXd& theta,
                                      std::size_t first = 0) {
  for (Eigen::Index k = 0; k < s.size(); ++k) {
    const auto node = first + static_cast<std::size_t>(k);
    const auto at = static_cast<Eigen::Index>(node);
    if (topology.fixed(node)) {
      pressure[at] = topology.fixed_pressure(node);
      theta[at] = supply;
      continue;
    }
    s[k] = std::max(s[k], -1.0);
    pressure[at] = pressure_scale * std::max(s[k], 0.0);
    theta[at] = 1.0 + std::min(s[k], 0.0);
  }
}

// The nodes' pressure-dependent coefficients for a film: rho / rho0, eps =
// rho h^3 / (12 eta) and their derivatives.
struct NodeCoefficients {
  Eigen::ArrayXd rho, rho_p, eps, eps_p, eps_h;

  void update(const LubricantLaws& laws, double eta0, const Eigen::ArrayXd& p, const Eigen::ArrayXd& h) {
    const Eigen::Index n = p.size();
    rho.resize(n);
    rho_p.resize(n);
    eps.resize(n);
    eps_p.resize(n);
    eps_h.resize(n);
    // The laws' powers and exponentials are the cost: shared among the threads.
    linalg::for_each_index(static_cast<std::size_t>(n), [&](std::size_t node) {
      const auto k = static_cast<Eigen::Index>(node);
      const double pk = std::max(p[k], 0.0);
      rho[k] = laws.density_ratio(pk);
      rho_p[k] = laws.density_ratio_slope(pk);
      eps[k] = rho[k] * h[k] * h[k] * h[k] / (12.0 * eta0 * laws.viscosity_ratio(pk, eta0));
      eps_p[k] = eps[k] * (rho_p[k] / rho[k] - laws.viscosity_log_slope(pk, eta0));
      eps_h[k] = 3.0 * eps[k] / h[k];
    });
  }
};

// One local derivative of a node's balance: d/dp, d/dh, d/dtheta of `node`.
struct LocalTerm {
  std::size_t node;
  double by_pressure, by_film, by_fraction;
};

// The second-order Couette flux 1.5 m_up - 0.5 m_upup, limited to at least
// 0.5 m_up (so that no face carries mass upstream): whether the limit
// holds, i.e. the flux is 0.5 m_up.
inline bool second_order_flux_limited(double up_mass, double up_up_mass) {
  return 1.5 * up_mass - 0.5 * up_up_mass < 0.5 * up_mass;
}

// The balance of node k (per unit area, m/s) and its local derivatives
// (up to 5 faces + 3 Couette terms).
inline double linearise(const ReynoldsStencil& topology, std::size_t k, const NodeCoefficients& c,
                        const Eigen::ArrayXd& p, const Eigen::ArrayXd& theta, const Eigen::ArrayXd& h,
                        bool second_order, std::vector<LocalTerm>& terms) {
  terms.clear();
  const Neighbours nb = topology.neighbours(k);
  const Grid& grid = topology.grid();
  double balance = 0.0;
  double own_p = 0.0, own_h = 0.0;
  const auto face = [&](std::size_t other, double spacing) {
    if (other == Neighbours::kNone) return;
    const double w = 0.5 / (spacing * spacing);
    const double conductance = w * (c.eps[k] + c.eps[other]);
    const double drop = p[k] - p[other];
    balance += conductance * drop;
    own_p += conductance + drop * w * c.eps_p[k];
    own_h += drop * w * c.eps_h[k];
    terms.push_back({other, -conductance + drop * w * c.eps_p[other], drop * w * c.eps_h[other], 0.0});
  };
  face(nb.west, grid.dx());
  face(nb.east, grid.dx());
  face(nb.south, grid.dy());
  face(nb.north, grid.dy());
  terms.push_back({k, own_p, own_h, 0.0});
  // The Couette flux U rho h theta through a face, taken from the upstream
  // node (first order), or at second order the linear extrapolation 1.5
  // m_up - 0.5 m_upup (Venner & Lubrecht 2000's second-order upstream
  // scheme), first order where the upstream node has no upstream neighbour
  // (next to a fixed edge). The extrapolation is limited to at least 0.5
  // m_up (second_order_flux): where the film's mass flux falls by more than
  // half in a cell (its rupture behind a constriction), 1.5 m_up - 0.5
  // m_upup turns negative, and with oblique entrainment a cavitated node's
  // balance then asked for a fluid fraction below 0 (the Newton iteration
  // stalled at a mass residual of 1e-4; docs/development-log.md,
  // 2026-12-02, thirty-second session).
  const auto mass = [&](std::size_t node, double coefficient) {
    balance += coefficient * c.rho[node] * h[node] * theta[node];
    terms.push_back({node, coefficient * c.rho_p[node] * h[node] * theta[node], coefficient * c.rho[node] * theta[node],
                     coefficient * c.rho[node] * h[node]});
  };
  const auto node_mass = [&](std::size_t node) { return c.rho[node] * h[node] * theta[node]; };
  // The limited second-order flux from `up` with `up_up` behind it.
  const auto extrapolated = [&](std::size_t up, std::size_t up_up, double coefficient) {
    if (second_order_flux_limited(node_mass(up), node_mass(up_up))) {
      mass(up, 0.5 * coefficient);
    } else {
      mass(up, 1.5 * coefficient);
      mass(up_up, -0.5 * coefficient);
    }
  };
  const auto couette = [&](double coefficient, auto upstream_of) {
    if (coefficient == 0.0) return;
    const std::size_t up = upstream_of(nb);
    // Out through the downstream face.
    if (up == Neighbours::kNone) {
      mass(k, coefficient);
      return;
    }
    if (!second_order) {
      mass(k, coefficient);
      mass(up, -coefficient);
      return;
    }
    extrapolated(k, up, coefficient);
    // In through the upstream face.
    const std::size_t up_up = upstream_of(topology.neighbours(up));
    if (up_up == Neighbours::kNone) {
      mass(up, -coefficient);
    } else {
      extrapolated(up, up_up, -coefficient);
    }
  };
  couette(topology.couette_x(), [&](const Neighbours& n) { return topology.upstream_x(n); });
  couette(topology.couette_y(), [&](const Neighbours& n) { return topology.upstream_y(n); });
  return balance;
}

// The largest Couette outflow (u_x + u_y) rho h over the free nodes, the
// mass rows' scale (rho: the density ratio, or 1 at the start).
template <class Density>
double largest_couette_outflow(const ReynoldsStencil& topology, const Density& rho, const Eigen::ArrayXd& h) {
  double couette = 0.0;
  for (Eigen::Index k = 0; k < h.size(); ++k) {
    if (!topology.fixed(static_cast<std::size_t>(k))) {
      couette = std::max(couette, (topology.couette_x() + topology.couette_y()) * rho[k] * h[k]);
    }
  }
  return couette;
}

// The nodes of a stencil a Newton residual's rows are this process's
// (film_slab.hpp): `count` from `first`, the extremes reduced by `max`
// over the processes. The default: every node, one process.
struct OwnNodes {
  std::size_t first = 0;
  std::size_t count = static_cast<std::size_t>(-1);
  const linalg::Communicator* comm = nullptr;

  std::size_t end(std::size_t nodes) const { return count == static_cast<std::size_t>(-1) ? nodes : first + count; }
  double max(double local) const { return comm != nullptr ? comm->max(local) : local; }
};

// The same over this process's nodes, reduced.
inline double largest_couette_outflow(const ReynoldsStencil& topology, const Eigen::ArrayXd& h, const OwnNodes& own) {
  double couette = 0.0;
  for (std::size_t k = own.first; k < own.end(static_cast<std::size_t>(h.size())); ++k) {
    if (!topology.fixed(k)) {
      couette = std::max(couette, (topology.couette_x() + topology.couette_y()) * h[static_cast<Eigen::Index>(k)]);
    }
  }
  return own.max(couette);
}

// A Newton residual's mass rows at (p, theta, h), `c` updated there: each
// free node's balance over mass_scale into `out` (0 where p is imposed);
// its local terms appended to `rows` (offsets and terms, the GMRES path's;
// null: not wanted) and handed to `dense_row(k, terms)`. Returns the
// relative mass residual: the largest balance over the largest Couette
// outflow.
template <class Rows, class DenseRow>
double mass_rows(const ReynoldsStencil& topology, const NodeCoefficients& c, const Eigen::ArrayXd& p,
                 const Eigen::ArrayXd& theta, const Eigen::ArrayXd& h, bool second_order, double mass_scale,
                 std::vector<LocalTerm>& terms, Eigen::VectorXd& out, Rows* rows, DenseRow&& dense_row,
                 const OwnNodes& own = {}) {
  // With a slab (`own`), rows, out and dense_row count from its first node.
  const std::size_t first = own.first;
  const std::size_t end = own.end(static_cast<std::size_t>(h.size()));
  if (rows != nullptr) rows->terms.clear();
  double largest = 0.0;
  double couette = 0.0;
  for (std::size_t k = first; k < end; ++k) {
    const auto kk = static_cast<Eigen::Index>(k - first);
    if (rows != nullptr) rows->start[k - first] = rows->terms.size();
    if (topology.fixed(k)) {
      out[kk] = 0.0;
      continue;
    }
    const double balance = linearise(topology, k, c, p, theta, h, second_order, terms);
    largest = std::max(largest, std::abs(balance));
    const auto at = static_cast<Eigen::Index>(k);
    couette = std::max(couette, (topology.couette_x() + topology.couette_y()) * c.rho[at] * h[at]);
    out[kk] = balance / mass_scale;
    if (rows != nullptr) rows->terms.insert(rows->terms.end(), terms.begin(), terms.end());
    dense_row(k - first, terms);
  }
  if (rows != nullptr) rows->start[end - first] = rows->terms.size();
  largest = own.max(largest);
  couette = own.max(couette);
  return largest / (couette > 0.0 ? couette : 1.0);
}

// The dense J^T's d balance / d s of the cavitated free nodes (d theta / d s
// = 1 there), added to the mass rows' columns.
inline void add_fraction_columns(const ReynoldsStencil& topology, const NodeCoefficients& c, const Eigen::ArrayXd& p,
                                 const Eigen::ArrayXd& theta, const Eigen::ArrayXd& h, bool second_order,
                                 double mass_scale, const std::vector<char>& branch_full, std::vector<LocalTerm>& terms,
                                 Eigen::MatrixXd& jacobian_t) {
  for (std::size_t k = 0; k < branch_full.size(); ++k) {
    if (topology.fixed(k)) continue;
    linearise(topology, k, c, p, theta, h, second_order, terms);
    for (const LocalTerm& t : terms) {
      if (!topology.fixed(t.node) && branch_full[t.node] == 0) {
        jacobian_t(static_cast<Eigen::Index>(t.node), static_cast<Eigen::Index>(k)) += t.by_fraction / mass_scale;
      }
    }
  }
}

// The dense K from one product: K(i, j) depends only on the offset of the
// two cells, and is even in each axis' offset on free grids.
inline Eigen::MatrixXd influence_matrix(InfluenceOperator& op) {
  const Grid& grid = op.grid();
  const std::size_t n = grid.size();
  const std::size_t nx = grid.nx();
  const std::size_t ny = grid.ny();
  std::vector<double> unit(n, 0.0), column(n, 0.0);
  unit[0] = 1.0;
  op.apply(unit, column);
  Eigen::MatrixXd k(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t xj = j % nx, yj = j / nx;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t xi = i % nx, yi = i / nx;
      std::size_t dx = 0, dy = 0;
      if (grid.periodic()) {
        dx = (xi + nx - xj) % nx;
        dy = (yi + ny - yj) % ny;
      } else {
        dx = xi > xj ? xi - xj : xj - xi;
        dy = yi > yj ? yi - yj : yj - yi;
      }
      k(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = column[dy * nx + dx];
    }
  }
  return k;
}

}  // namespace halfspace::lubrication::detail
