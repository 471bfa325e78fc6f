// A Newton step's linear solve J step = -residual on a matrix-free
// Jacobian, shared by the EHL film (film_krylov_solver.hpp) and the mixed
// film (mixed_film_krylov.hpp): restarted GMRES (restarted_gmres.hpp)
// right-preconditioned by a preconditioner kept across solves, the residual
// measured afterwards with the operator. Private to the library.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <functional>
#include <string>
#include <utility>

#include "restarted_gmres.hpp"

namespace halfspace::lubrication::detail {

// A Newton iteration's preconditioner kept from one linear solve to the
// next (a lagged preconditioner; Knoll & Keyes 2004, J. Comput. Phys. 193,
// 357): an earlier factorisation serves while GMRES converges with it in
// few iterations, as the Jacobian changes little between late Newton steps
// and between a step's branch passes (a few rows). Refactorised when the
// caller asks (`refactorise`), when the last solve took more than
// kRefactoriseAfter iterations, or when GMRES with the old one does not
// converge within twice that (then solved again with the new one).
class LaggedPreconditioner {
 public:
  static constexpr int kRefactoriseAfter = 15;

  struct Run {
    bool factorised = true;  // false: `factorise` failed (its message is the caller's)
    int iterations = 0;      // GMRES products, every attempt
    int factorisations = 0;
  };

  // `factorise()` returns whether it succeeded; `gmres(max_iterations,
  // retry)` solves (retry: the second attempt, with a new factorisation)
  // and returns {iterations, whether its step is finite}.
  template <class Factorise, class Gmres>
  Run solve(bool refactorise, int max_iterations, Factorise&& factorise, Gmres&& gmres) {
    Run run;
    bool fresh = false;
    if (!factorised_ || refactorise || last_iterations_ > kRefactoriseAfter) {
      factorised_ = factorise();
      ++run.factorisations;
      if (!factorised_) return {false, 0, run.factorisations};
      fresh = true;
    }
    const int stale_limit = std::min(max_iterations, 2 * kRefactoriseAfter);
    auto [iterations, finite] = gmres(fresh ? max_iterations : stale_limit, false);
    run.iterations = iterations;
    if (!fresh && !(finite && iterations < stale_limit)) {
      factorised_ = factorise();
      ++run.factorisations;
      if (!factorised_) return {false, run.iterations, run.factorisations};
      iterations = gmres(max_iterations, true).first;
      run.iterations += iterations;
    }
    last_iterations_ = iterations;
    return run;
  }

 private:
  bool factorised_ = false;
  int last_iterations_ = 0;
};

// GMRES with a lagged preconditioner on one Newton step; what the films'
// solves differ in is a Rule.
class KrylovNewtonStep {
 public:
  struct Rule {
    double tolerance = 0.0;    // on GMRES's estimate of ||J step + residual|| / ||residual||
    double allowance = 1.0;    // converged when the measured residual is at most allowance * tolerance
    bool refactorise = false;  // the kept preconditioner no longer fits the system
    bool warm = false;         // from `step` as given, else from 0
    bool retry_warm = false;   // the retry after a stale preconditioner goes on from where it stopped
    const char* failure = "";  // fmt message: {0} the measured residual, {1} the iterations, {2} the tolerance
  };

  // Workspace for systems of `size` unknowns and a GMRES(restart) basis.
  void resize(Eigen::Index size, int restart);

  // Solves J step = -residual (step = 0 for a zero residual) within
  // `max_iterations` products per attempt; `factorise(message)` makes the
  // preconditioner that `precondition` applies. Returns the factorisation's
  // failure (relative residual infinite) or GMRES's.
  KrylovOutcome solve(const RestartedGmres::Apply& jacobian, const RestartedGmres::Apply& precondition,
                      const std::function<bool(std::string&)>& factorise, const Eigen::VectorXd& residual,
                      int max_iterations, const Rule& rule, Eigen::VectorXd& step);

 private:
  RestartedGmres gmres_;
  LaggedPreconditioner lagged_;
  Eigen::VectorXd work_;
};

}  // namespace halfspace::lubrication::detail
