// Polonsky-Keer constrained conjugate-gradient solver for frictionless normal
// contact (Polonsky & Keer 1999, Wear 231, 206-219), under load control (total
// force or mean pressure) or displacement control (imposed approach).
//
// Stopping criterion. With gap g = initial_gap + K p - approach, contact set
// C = {i : p_i > 0}, mean pressure pbar = (1/N) sum_i p_i and gap scale
// g_ref = ptp(initial_gap) + max(ptp(K p), pbar ptp(K 1)) (ptp = max - min
// over the grid), the residual of iterate p is
//
//   residual = ( sum_i (p_i / pbar) |g_i| + sum_i max(-g_i, 0) ) / (N g_ref),
//
// a pressure-weighted mean gap on the contact set plus the mean interpenetration
// elsewhere, both relative to the gap scale (the first sum is dropped when
// pbar = 0). It is zero exactly at the solution of the linear complementarity
// problem. The floor pbar ptp(K 1), the displacement range of the same load
// spread uniformly (zero on a periodic grid), keeps g_ref from vanishing where
// the first two do: a flat punch in full contact has ptp(initial_gap) = 0 and
// ptp(K p) -> 0 at its solution, so without it the residual stalled at O(1)
// or became 0/0. It costs one product K 1 per solver, on its first solve; on
// other contacts ptp(K p) is the larger term. The iteration stops when
// residual <= tolerance, checked on the final (p, K p) pair, so the returned
// fields are mutually consistent. Under load control the force equals the
// target to rounding at every iterate.
//
// Preconditioning. Given a Preconditioner M^-1 (e.g. FourierPreconditioner),
// the conjugate directions are built from z = M^-1 g restricted to the
// search set (see SearchSet) instead of g itself, which cuts the iteration
// count on rough surfaces at the price of one more transform per iteration.
// A BlockDeflation adds a coarse-grid correction to M^-1 (two more products
// per iteration) once the contact set has nearly settled, which keeps the
// iterations from growing with the domain (docs/performance.md).
#pragma once

#include <functional>
#include <span>
#include <string_view>

#include "halfspace/operators/influence_operator.hpp"
#include "halfspace/solvers/block_deflation.hpp"
#include "halfspace/solvers/contact_solver.hpp"
#include "halfspace/solvers/preconditioner.hpp"

namespace halfspace::solvers {

// Polonsky & Keer restart the conjugate directions whenever a cell enters the
// contact set. On large rough contacts a few cells enter in almost every
// iteration, which turns the method into (preconditioned) steepest descent.
// The Powell-style rule restarts only when the new gap is no longer nearly
// orthogonal to the previous direction on the contact set,
// |sum_C g t_old| > 0.2 sum_C g z (Powell 1977, Math. Programming 12, 241),
// which is what conjugacy needs, or when more than 1% of the contact cells
// enter at once (measured in docs/performance.md).
enum class ConjugacyRestart { on_entry, powell };

// The cells the search direction covers. Polonsky & Keer build it on the
// contact set C = {p > 0}; a cell out of contact that interpenetrates
// (g < 0) enters only after the step, with pressure -tau g, and joins the
// direction one iteration later. The projected-gradient set adds those cells
// at once, C + {p = 0, g < 0}, as bound-constrained CG does (Vollebregt 2014,
// J. Comput. Phys. 257, 333): the step itself gives them pressure, which
// saves iterations while the contact set still moves (docs/performance.md).
enum class SearchSet { contact, contact_and_overlap };

struct PolonskyKeerOptions {
  double tolerance = 1e-10;    // relative residual, see the stopping criterion above
  int max_iterations = 10000;  // status iteration_limit when reached
  // When the conjugate directions restart (step 3 with beta = 0).
  ConjugacyRestart restart = ConjugacyRestart::on_entry;
  // Which cells the conjugate directions cover.
  SearchSet search_set = SearchSet::contact;
  // Called once per iteration with (iteration, residual); may be empty. It
  // runs on the calling thread between iterations, so it may print.
  std::function<void(int, double)> progress;

  // Throws InputError naming the option unless 0 < tolerance < 1 and
  // max_iterations >= 1.
  void validate() const;
};

class PolonskyKeer final : public ContactSolver {
 public:
  // Keeps a reference to `op` (which must outlive the solver) and allocates
  // the workspace once; solve() then allocates nothing inside its loop but
  // the deflation's field, once per solver when it first joins.
  // `preconditioner`, if given, must outlive the solver too, and so must
  // `deflation`, which needs a preconditioner and the operator's grid.
  explicit PolonskyKeer(InfluenceOperator& op, PolonskyKeerOptions options = {},
                        Preconditioner* preconditioner = nullptr, BlockDeflation* deflation = nullptr);

  std::string_view name() const override {
    if (deflation_) return "deflated-polonsky-keer";
    return preconditioner_ ? "preconditioned-polonsky-keer" : "polonsky-keer";
  }

  SolveResult solve(std::span<const double> initial_gap, const Loading& loading,
                    std::span<const double> initial_pressure = {}) override;
  // Iterates in `start` itself (it becomes the result's pressure).
  SolveResult solve_from(std::span<const double> initial_gap, const Loading& loading, Eigen::ArrayXd&& start) override;

 private:
  // The iteration from `pressure`: a warm start if `warm`, else any values
  // (step 0 chooses the start).
  SolveResult run(std::span<const double> initial_gap, const Loading& loading, Eigen::ArrayXd pressure, bool warm);
  // Step 2 with deflation: direction_image_ = B g on the search set
  // (in_search(i)), B the balancing preconditioner of block_deflation.hpp
  // around M^-1; under load control on the set's mean-free fields. Counts
  // its products in `result`, whose gap it reads.
  template <class InSearch>
  void apply_balancing(bool load_controlled, InSearch&& in_search, SolveResult& result);

  InfluenceOperator& op_;
  PolonskyKeerOptions options_;
  Preconditioner* preconditioner_;
  BlockDeflation* deflation_;
  bool kernel_known_ = false;  // deflation_ has the kernel (one product, when first deflating)
  // Workspace, one entry per cell.
  Eigen::ArrayXd direction_;        // conjugate direction t
  Eigen::ArrayXd direction_image_;  // K t, and M^-1 g before it is needed
  // With deflation only, made when it first joins: the coarse correction
  // Z y as a field, then K of it, then K of M^-1's output (apply_balancing).
  Eigen::ArrayXd coarse_field_;
  // ptp(K 1), the displacement range of a unit uniform pressure (the gap
  // scale's floor); negative until the first solve computes it.
  double uniform_response_range_ = -1.0;
};

}  // namespace halfspace::solvers
