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
// or became 0/0. It costs one product K 1 per solver, on its first solve, on
// free grids (on a periodic grid it is zero by the operator's contract, no
// product); on other contacts ptp(K p) is the larger term. The iteration stops when
// residual <= tolerance, checked on the final (p, K p) pair, so the returned
// fields are mutually consistent. Under load control the force equals the
// target to rounding at every iterate: the paper restores it by scaling the
// pressure after each step; when the residual has not fallen by a tenth in
// 100 iterations, the rest of the solve shifts the contact pressures by
// one amount instead (a few one-cell spikes of a measured map, which must
// carry hundreds of times the mean pressure, made the scaling cycle).
//
// The method comes in two forms (PolonskyKeerForm).
//  - paper: the conjugate directions cover the contact set C; a cell out of
//    contact that interpenetrates (g < 0) enters after the step with
//    pressure -tau g, and any entry restarts the conjugate directions.
//  - projected: the directions cover the projected-gradient search set
//    C + {p = 0, g < 0}, as bound-constrained CG does (Vollebregt 2014, J.
//    Comput. Phys. 257, 333): the step itself gives interpenetrating cells
//    pressure. With a Preconditioner M^-1 (e.g. FourierPreconditioner; only
//    this form takes one) they are built from z = M^-1 g instead of g,
//    which cuts the iteration count on rough surfaces at the price of one
//    more transform per iteration. On large rough contacts a few cells
//    enter in almost every iteration, so restarting at every entry would
//    turn the method into steepest descent; Powell's rule restarts only
//    when the new gap is no longer nearly orthogonal to the previous
//    direction on the search set, |sum g t_old| > 0.2 sum g z (Powell 1977,
//    Math. Programming 12, 241), or when more than 1 % of the contact cells
//    enter at once. A preconditioner that adapts to the active set
//    (BalancingPreconditioner, the coarse-grid correction) restarts them
//    when it changes.
// docs/solvers.md says what each form costs and saves.
//
// Mixed precision. Given an `inner` operator (K in single precision,
// single_precision_fft_operator.hpp), the step's images K t and the
// projection's corrections K c come from it; given SinglePrecisionProducts
// instead, the direction, its image and the correction are themselves
// single-precision vectors (half the bytes stored and moved per pass),
// while the pressure and the displacement (and the gap made from them) stay double. Either way the displacement K p is
// recomputed with the exact operator every 50 updates, whenever the
// residual has fallen 100-fold since the last exact product, and before
// the residual may stop the iteration; the independent check uses the
// exact operator too. The residual, the contact set and "converged" are so
// judged in double: iterative refinement, the inner corrections in single
// precision (Higham 2002, Accuracy and Stability of Numerical Algorithms,
// ch. 12), in the manner of inexact Krylov methods, whose products may be
// as inexact as the step is small against the residual (Simoncini & Szyld
// 2003, SIAM J. Sci. Comput. 25, 454). A tolerance the inner products
// cannot resolve costs iterations, or ends in a reported iteration limit,
// never in a false "converged".
//
// Hardness cap. With PressureBounds' upper bound H (interface_law.hpp) the
// problem is the bound-constrained one, 0 <= p <= H, whose conditions at a
// cell at the cap are g <= 0: the rigid surface penetrates the elastic one
// there, and the overlap is the plastic flow (docs/theory.md, "Hardness
// cap"). Cells at the cap leave the search set as cells out of contact do,
// with the opposite sign test: a cell at p = H stays out while g <= 0 and
// joins while g > 0 says its pressure should fall (the projected-gradient
// set of bound-constrained CG, Vollebregt 2014). The approach under load
// control is the mean gap over the contact cells below the cap (when every
// contact cell is at the cap, midway between the highest of them and the
// lowest cell out of contact, so that misplaced cells can trade places),
// and the load is restored by the capped scaling min(H, s p). The residual then
// weighs a cell's overlap by (H - p)/H and takes the positive part of the
// gap in the pressure-weighted sum, so that it again vanishes exactly at the
// solution. A load above H times the domain area is refused (InputError).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <span>
#include <string>
#include <string_view>

#include "halfspace/operators/influence_operator.hpp"
#include "halfspace/solvers/contact_solver.hpp"
#include "halfspace/solvers/preconditioner.hpp"
#include "halfspace/solvers/pressure_bounds.hpp"
#include "halfspace/solvers/single_precision_products.hpp"

namespace halfspace::solvers {

enum class PolonskyKeerForm { paper, projected };

struct PolonskyKeerOptions {
  double tolerance = 1e-10;    // relative residual, see the stopping criterion above
  int max_iterations = 10000;  // status iteration_limit when reached
  PolonskyKeerForm form = PolonskyKeerForm::paper;
  // Called once per iteration with (iteration, residual); may be empty. It
  // runs on the calling thread between iterations, so it may print; its
  // IterationDecision::stop ends the solve with status `stopped`.
  ProgressCallback progress;
  // The solve is only the start of a finer one (pk-multilevel's coarse
  // levels): it ends on the residual of the updated displacement, without
  // the exact product that confirms it and without the independent check
  // of the conditions (the finer solve, whose result is reported, does
  // both). Saves two products per coarse level.
  bool start_only = false;

  // Throws InputError naming the option unless 0 < tolerance < 1 and
  // max_iterations >= 1.
  void validate() const;
};

class PolonskyKeer final : public ContactSolver {
 public:
  // Keeps a reference to `op` (which must outlive the solver). solve()
  // makes its two work vectors when it begins and gives them back when it
  // ends (the result's gap, which the iteration does not store, takes
  // their place); it allocates nothing inside its loop.
  // The pressures admitted are `law`'s bounds: [0, inf), or [0, H] with a
  // hardness cap.
  // `preconditioner`, if given, must outlive the solver too; it needs the
  // projected form (InputError otherwise). `inner`, if given, takes the
  // step's products (see "Mixed precision" above), acts on op's fields and
  // must outlive the solver too.
  // `single`, if given, takes the step's products on single-precision work
  // vectors (and then M^-1 too, for which it needs its precondition when a
  // preconditioner is given: InputError otherwise); `inner` is then unused.
  explicit PolonskyKeer(InfluenceOperator& op, PolonskyKeerOptions options = {}, const InterfaceLaw& law = {},
                        Preconditioner* preconditioner = nullptr, InfluenceOperator* inner = nullptr,
                        SinglePrecisionProducts single = {});

  std::string_view name() const override { return name_; }

  // Workspace field 0 or 1 (one entry per cell), made on the first call,
  // free until the next solve, so that a phase run before solve_from
  // (active_set_start.hpp) needs no fields of its own for them.
  std::span<double> workspace(int which);
  // The same in float for a solver with single-precision work vectors
  // (then the double ones are given back); the products on them.
  std::span<float> single_workspace(int which);
  const SinglePrecisionProducts& single_products() const { return single_; }

 protected:
  SolveResult do_solve(std::span<const double> initial_gap, const Loading& loading,
                       std::span<const double> initial_pressure) override;
  // Iterates in `start` itself (it becomes the result's pressure).
  SolveResult do_solve_from(std::span<const double> initial_gap, const Loading& loading,
                            Eigen::ArrayXd&& start) override;

 private:
  // The iteration from `pressure`: a warm start if `warm`, else any values
  // (step 0 chooses the start).
  SolveResult run(std::span<const double> initial_gap, const Loading& loading, Eigen::ArrayXd pressure, bool warm);

  InfluenceOperator& op_;
  InfluenceOperator& inner_;  // the step's products: op_ unless given
  PolonskyKeerOptions options_;
  Preconditioner* preconditioner_;
  std::string name_;
  SinglePrecisionProducts single_;
  // Workspace, one entry per cell, held during a solve (or lent to a phase
  // before one): the conjugate direction t, and the preconditioned gap z,
  // then its image K t, then the step's correction c, then K c (each
  // needed only until the next is made); in double, or in single
  // precision with single_.
  Eigen::ArrayXd direction_;
  Eigen::ArrayXd image_;
  Eigen::ArrayXf single_direction_;
  Eigen::ArrayXf single_image_;
  // ptp(K 1), the displacement range of a unit uniform pressure (the gap
  // scale's floor); negative until the first solve computes it.
  double uniform_response_range_ = -1.0;
};

}  // namespace halfspace::solvers
