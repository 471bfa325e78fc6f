// Adhesive frictionless normal contact: the hard wall gap >= 0 plus a
// cohesive law (adhesion_law.hpp), solved under displacement control as the
// bound-constrained minimisation of the total energy over the surface
// displacement, by preconditioned conjugate gradients (the default, see
// Preconditioning below) or by spectral projected gradients (SPG:
// Barzilai-Borwein steps with a non-monotone line search, Birgin, Martinez &
// Raydan 2000, SIAM J. Optim. 10, 1196): the energy formulation of Pastewka
// & Robbins (2014, PNAS 111, 3298) and their ContactMechanics code, with
// other minimisers. Load control wraps it in a search on the approach along
// the stable branch the warm start follows.
//
// The problem. With v the displacement (m), S = K^-1 the stiffness, h the
// initial gap and delta the approach, the energy per cell area
//
//   E(v) = 1/2 v.S v + sum_i phi(h_i + v_i - delta),   v_i >= delta - h_i,
//
// (phi the law's energy) has the gradient S v - t(g) (t the law's traction),
// so its constrained stationary points are the equilibria: p = S v equals
// t(g) where g > 0 and p >= t(0) where g = 0. The energy is not convex (phi
// is not), so which equilibrium a solve reaches depends on its start: a warm
// start from the previous step of a sweep follows a branch, which is how
// loading and unloading differ (hysteresis, jump-in, pull-off).
//
// Grids. Periodic: S is diagonal in Fourier space, E*|q|/2, and the mean
// displacement is held at 0 (the convention of the operator: the mean gap
// is mean(h) - delta), so the approach must stay below mean(h); the mean
// pressure is the multiplier of that constraint. Free: v lives on the
// zero-padded (2ny, 2nx) grid of the DC-FFT convolution, S is the inverse of
// its circulant kernel, and the padding carries no interaction, so at a
// stationary point its pressure vanishes and v on the grid is K p exactly
// (ContactMechanics' free-boundary half-space does the same).
//
// Preconditioning (the default; precondition = false runs SPG). The plain
// gradient's Hessian is S, whose symbol grows like |q|, so SPG's iterations
// grow with the grid. The default runs preconditioned non-linear conjugate
// gradients instead
// (Polak-Ribiere+) on the cells the wall does not hold: the gradient there
// is scaled by the compliance K = S^-1 (its principal block on those cells,
// a two-metric projection in the sense of Bertsekas 1982, SIAM J. Control
// Optim. 20, 221), which flattens the elastic spectrum; the cells the wall
// holds stay put. The step minimises the elastic energy along the
// direction, is clipped onto the wall and halved until the energy falls
// (Armijo); a clipped step restarts the conjugation (a change of the held
// set alone does not: Polak-Ribiere+ resets itself where needed).
// Where the conjugate direction does not descend, the iteration takes the
// plain projected gradient step. Two or three FFT pairs per iteration
// against SPG's one.
//
// Hardness cap (optional). An elastic-perfectly plastic surface carries at
// most H: the wall becomes the kink of the energy term H max(-g, 0) (the
// plastic work of a rigid surface penetrating by -g), so
//
//   E(v) = 1/2 v.S v + sum_i psi(h_i + v_i - delta),
//   psi(g) = phi(g) for g >= 0,  phi(0) - H g for g < 0,
//
// unconstrained but for the periodic mean. Its stationary points: p = t(g)
// where g > 0, p = H where g < 0 (plastic), t(0) <= p <= H where g = 0.
// The kink is a breakpoint both ways, handled as the wall is (an
// orthant-wise projection in the sense of Andrew & Gao 2007, ICML, for the
// L1 kink): every cell has a side, above (g >= 0) or below (g <= 0) the
// kink, fixed for one iteration; steps are projected onto the sides, so a
// cell crossing the kink stops on it. A cell on the kink is held while
// t(0) <= p <= H (less the periodic multiplier), released below when p > H
// (its gradient there is S v - H) and above when p < t(0). Without a cap
// every cell is above, and the iteration is the one described here.
//
// Stopping. residual = max_i |P(v - c G) - v|_i / (c p_ref), with G the
// gradient, P the projection onto the constraints, c = K_ii (the cell's
// self-compliance, m/Pa) and p_ref the largest pressure of the state (|S v|,
// and the law's traction off the wall), at least min(w / range, range / c):
// the largest pressure error of the projected gradient step relative to the
// pressures of the contact (not to the law's stress, which a short range
// makes larger than all of them). Zero exactly at a constrained stationary
// point. With a cap, P projects onto the sides, with the gradient of the
// side a cell on the kink is released to: zero exactly at a stationary
// point of the capped energy. A cell the projected step puts on the wall is
// reported on it (its pressure S v).
//
// Resolution. The law acts at a contact edge over its cohesive zone, about
// pi E* w / (4 sigma0^2) (AdhesionLaw::cohesive_zone_length); a zone below
// 1 % of the cell length is refused (InputError with both lengths), one
// below 10 % is warned about in results with a contact edge.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string_view>

#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/operators/influence_operator.hpp"
#include "halfspace/solvers/adhesion_law.hpp"
#include "halfspace/solvers/contact_solver.hpp"

namespace halfspace::solvers {

struct AdhesiveSolverOptions {
  AdhesionLaw law;
  double tolerance = 1e-6;     // relative residual, see Stopping above
  int max_iterations = 20000;  // per displacement-controlled solve
  FftPlanning fft_planning = FftPlanning::estimate;
  // Preconditioned conjugate gradients (see Preconditioning above; 5-15x
  // fewer operator products than SPG on rough contacts, the same pull-off
  // on a quasi-static sweep), or SPG with false.
  bool precondition = true;
  // Load control: relative force tolerance of the search on the approach,
  // and its limit of displacement-controlled solves.
  double force_tolerance = 1e-6;
  int max_load_steps = 60;
  ProgressCallback progress;  // (iteration, residual), may be empty or stop the solve

  // Throws SolverOptionError (solver_options.hpp) naming the option
  // ("law.work", "law.range", "tolerance", "force_tolerance",
  // "max_iterations", "max_load_steps") unless the law is valid
  // (AdhesionLaw::validate's rules), 0 < tolerance < 1, 0 < force_tolerance
  // < 1, max_iterations >= 1 and max_load_steps >= 1.
  void validate() const;
};

class AdhesiveContactSolver final : public ContactSolver {
 public:
  // On `op` (which must outlive the solver), through its circulant form
  // (K and S on the variable's grid, circulant_form.hpp), on one process or
  // several (the fields then hold this process's cells). contact_modulus
  // (Pa): the composite modulus at the contact edge's scale (the body's E*,
  // a coating's layer's), which sets the cohesive zone (see Resolution
  // above). `law`'s hardness, if set, caps the pressure at the wall (see
  // Hardness cap above). Throws SolverOptionError (options.validate(),
  // law.validate()) or InputError if the law's cohesive zone is below 1 % of
  // a cell or its stress over the grid overflows a force, and as
  // op.circulant_form() does (no such form, or no stiffness).
  AdhesiveContactSolver(InfluenceOperator& op, double contact_modulus, AdhesiveSolverOptions options,
                        const InterfaceLaw& law = {});
  // The same, owning `op`.
  AdhesiveContactSolver(std::unique_ptr<InfluenceOperator> op, double contact_modulus, AdhesiveSolverOptions options,
                        const InterfaceLaw& law = {});
  // The homogeneous half-space of composite modulus e_star (Pa) on `grid`:
  // on an FftInfluenceOperator of its own.
  AdhesiveContactSolver(const Grid& grid, double e_star, AdhesiveSolverOptions options, const InterfaceLaw& law = {});
  ~AdhesiveContactSolver() override;
  AdhesiveContactSolver(const AdhesiveContactSolver&) = delete;
  AdhesiveContactSolver& operator=(const AdhesiveContactSolver&) = delete;

  // "adhesive-pcg" (preconditioned conjugate gradients) or "adhesive-spg".
  std::string_view name() const override;
  const AdhesiveSolverOptions& options() const;

  // Displacement control: any finite approach (negative: the surfaces start
  // apart); on a periodic grid it must be below the mean initial gap. Load
  // control (force or mean pressure, which may be negative: a pull): a
  // search on the approach that follows one path of states (expanding
  // steps, then regula falsi in the bracket; a bracket closed on a jump of
  // the force, a snap of the contact edge, is left along the other end's
  // branch), each step a displacement-controlled solve warm-started from the
  // path's last state, to a force tolerance no tighter than the inner
  // solve's residual allows; breakdown when the pull is beyond the pull-off
  // force (the message gives the least force reached) or the target lies in
  // a jump, or (with the bracket) after max_load_steps. `initial_pressure` (Pa, signed), if given,
  // warm-starts from the displacement K p it makes. The result's pressure
  // is signed (negative: attraction); contact_fraction counts the cells at
  // the wall (gap 0; with a cap also those below it, gap < 0 at p = H);
  // result.adhesion holds the adhesive quantities, result.hardness and
  // plastic_fraction the cap's. With a cap, a load above H times the domain
  // area throws InputError (ContactSolver::solve).
 protected:
  SolveResult do_solve(std::span<const double> initial_gap, const Loading& loading,
                       std::span<const double> initial_pressure) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace halfspace::solvers
