// A primal-dual active-set phase before Polonsky-Keer: the contact set is
// found by whole-set updates, each from a linear solve on a fixed set, and
// Polonsky-Keer finishes from there.
//
// The frictionless contact is the LCP p >= 0, g >= 0, p g = 0 with
// g = g0 + K p - a. For a set C the linear problem
//
//   K_CC p_C = a - g0_C,   p = 0 off C   (under load control also sum p = F / cell area,
//                                         which fixes the approach a)
//
// is solved inexactly by preconditioned conjugate gradients, and the set is
// updated to C+ = {i in C : p_i > 0} | {i not in C : g_i < 0}: the
// primal-dual active-set method, a semismooth Newton method for
// min(p, g) = 0 (Hintermueller, Ito & Kunisch 2002, SIAM J. Optim. 13, 865;
// for contact: Hueeber & Wohlmuth 2005). Whatever the domain, it moves
// every edge of every spot at once, so its outer iterations do not grow with
// the number of spots; and since the set is fixed inside each linear solve,
// nothing is clipped there, so an adapting preconditioner (block deflation,
// balancing_preconditioner.hpp) serves from the first iteration, where in
// Polonsky-Keer it must wait until the set has settled
// (docs/development-log.md, "2026-11-28: issue 31, the moving-set phase").
//
// The phase stops once an update changes at most settled_changes of the
// set, when the changes stop falling (the method need not converge for a
// dense K, which is no M-matrix), or after max_outer updates; the pressure,
// max(p, 0), is then the start of the Polonsky-Keer solve, which checks the
// contact conditions as every solve does. An adapting preconditioner carries
// its verdict over (Preconditioner::continue_next_solve): whether block
// deflation pays was measured in the phase, on the same contact, so
// Polonsky-Keer does not spend undeflated iterations measuring it again. Without a start, or with a
// hardness cap, the solve is Polonsky-Keer's alone (the factory does not
// build this phase for capped contacts).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "halfspace/operators/influence_operator.hpp"
#include "halfspace/solvers/active_set_options.hpp"
#include "halfspace/solvers/contact_solver.hpp"
#include "halfspace/solvers/polonsky_keer.hpp"
#include "halfspace/solvers/preconditioner.hpp"

namespace halfspace::solvers {

// What the phase did, for reports and tests.
struct ActiveSetRecord {
  int outer = 0;                        // set updates
  int inner = 0;                        // conjugate-gradient iterations (one K t and one preconditioner each)
  int operator_applications = 0;        // K products, the preconditioner's own included
  int preconditioner_applications = 0;  // preconditioner applications
  double last_changes = 0.0;            // cells the last update changed
};

class ActiveSetStart final : public ContactSolver {
 public:
  // Keeps references to `op` and `preconditioner` (which must outlive it;
  // the preconditioner may adapt to the set, as BalancingPreconditioner
  // does) and owns `finish`, whose workspace the phase borrows.
  ActiveSetStart(InfluenceOperator& op, Preconditioner& preconditioner, std::unique_ptr<PolonskyKeer> finish,
                 ActiveSetOptions options = {});

  std::string_view name() const override { return name_; }

  // The last solve's phase.
  const ActiveSetRecord& record() const { return record_; }

 protected:
  // Without a start: Polonsky-Keer alone.
  SolveResult do_solve(std::span<const double> initial_gap, const Loading& loading,
                       std::span<const double> initial_pressure) override;
  // The phase from `start`, then Polonsky-Keer from its pressure; the
  // phase's iterations and products are added to the result's.
  SolveResult do_solve_from(std::span<const double> initial_gap, const Loading& loading,
                            Eigen::ArrayXd&& start) override;

 private:
  // The phase on `pressure` (in place): returns its record. Its work
  // vectors t and K t are those of Polonsky-Keer: float with mixed
  // precision's single-precision work vectors (K t and M^-1 then in single
  // precision; K p, the set and the approach stay double).
  ActiveSetRecord run(std::span<const double> initial_gap, const Loading& loading, Eigen::ArrayXd& pressure);
  template <class Work>
  ActiveSetRecord run_on(std::span<const double> initial_gap, const Loading& loading, Eigen::ArrayXd& pressure);

  InfluenceOperator& op_;
  Preconditioner& preconditioner_;
  std::unique_ptr<PolonskyKeer> finish_;
  ActiveSetOptions options_;
  std::string name_;
  ActiveSetRecord record_;
  std::vector<double> inner_norms_;  // per linear solve, for an adapting preconditioner's schedule
};

}  // namespace halfspace::solvers
