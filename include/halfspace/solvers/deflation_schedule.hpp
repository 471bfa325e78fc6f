// When the block-deflation coarse correction joins a Polonsky-Keer solve,
// declines or leaves it: the policy of BalancingPreconditioner, from what
// each iteration reports (residuals, clipped cells, search-set size).
//
// The correction joins once the iteration is both settled and slow:
//  - settled: the last step clipped at most kDeflateBelowClipped of the
//    search set. While the contact set still moves by many cells, the
//    correction's block-wide pressure changes clip more cells than they
//    settle, and large solves then fail to converge;
//  - slow: over kRateSteps consecutive settled steps without it, the
//    residual fell by less than kDeflateAboveRate per step. A deflated
//    iteration costs about twice the products of an undeflated one and
//    converges at about 0.3 per iteration, which pays against a rate above
//    0.3^(1/2) = 0.55. Rough contacts run well above it, Hertz-like ones
//    below (docs/solvers.md, "Block deflation").
// The rate is measured after every run of kRateSteps settled steps until it
// is found slow; from then on the correction applies whenever the last step
// was settled, and leaves while steps clip too much. A solve whose contact
// is too dense for the coarse matrix (BlockDeflation::ready) declines it for
// good.
#pragma once

#include <limits>
#include <span>

namespace halfspace::solvers {

class DeflationSchedule {
 public:
  static constexpr double kDeflateBelowClipped = 0.01;
  static constexpr double kDeflateAboveRate = 0.55;
  static constexpr int kRateSteps = 2;

  // Forgets the previous solve.
  void begin_solve() { *this = DeflationSchedule(); }
  // Whether the correction should apply in this iteration, given the
  // residuals of the solve so far (the current one last).
  bool wants(std::span<const double> residuals);
  // The correction cannot serve this solve (too dense a contact).
  void decline() { declined_ = true; }
  bool declined() const { return declined_; }
  // After each step: whether the correction applied in it, the cells it
  // clipped and the search set's size.
  void observe_step(bool deflated, double clipped, double searched);
  // The last measured rate per iteration while it kept the correction out,
  // or 0 if it was never measured or the correction pays.
  double fast_rate() const { return fast_rate_; }

 private:
  double clipped_ = std::numeric_limits<double>::infinity();  // the last step's clipped cells
  double searched_ = 0.0;                                     // and its search set
  int settled_steps_ = 0;                                     // consecutive undeflated steps that clipped little
  bool pays_ = false;                                         // their rate was slow
  bool declined_ = false;
  double fast_rate_ = 0.0;
};

}  // namespace halfspace::solvers
