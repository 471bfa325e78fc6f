// Accelerated projected gradients for a tangential step
// (tangential_solver.hpp, TangentialMethod::projected_gradient, and the
// fallback when the conjugate gradients stall): Nesterov (1983), Beck &
// Teboulle (2009, FISTA) with adaptive restart (O'Donoghue & Candes 2015),
// a step 1/L from the extrapolated point, one product per iteration.
// Internal to src/solvers.
#pragma once

#include "tangential_iteration.hpp"

namespace halfspace::solvers::tangential {

class ProjectedGradientMethod : IterationMethod {
 public:
  explicit ProjectedGradientMethod(TangentialIteration& it) : IterationMethod(it) {}

  // Hands over from conjugate gradients to projected gradients at the
  // current iterate (no momentum; t and r hold q and u = C q).
  void begin();
  // One accelerated projected-gradient step (Nesterov; Beck & Teboulle's
  // FISTA) with step 1/L, L >= the largest eigenvalue of C, from the
  // extrapolated point y = q + beta (q - q_old) (u = C y by linearity):
  // q = P(y - (C y - u_prev - delta)/L), then u = C q exactly. The momentum
  // restarts when the step turns against the previous one (O'Donoghue &
  // Candes 2015's gradient test). t and r hold q_old and u_old.
  void step(double inverse_lipschitz);

 private:
  double momentum_ = 0.0;
};

}  // namespace halfspace::solvers::tangential
