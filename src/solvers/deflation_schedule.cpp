#include "halfspace/solvers/deflation_schedule.hpp"

#include <cmath>

namespace halfspace::solvers {

bool DeflationSchedule::wants(std::span<const double> residuals) {
  if (!pays_ && settled_steps_ >= kRateSteps && residuals.size() > static_cast<std::size_t>(kRateSteps)) {
    const double ratio = residuals.back() / residuals[residuals.size() - 1 - kRateSteps];
    const double rate = std::pow(ratio, 1.0 / kRateSteps);
    pays_ = rate > kDeflateAboveRate;
    fast_rate_ = pays_ ? 0.0 : rate;
  }
  return pays_ && !declined_ && clipped_ <= kDeflateBelowClipped * searched_;
}

void DeflationSchedule::observe_step(bool deflated, double clipped, double searched) {
  clipped_ = clipped;
  searched_ = searched;
  settled_steps_ = !deflated && clipped <= kDeflateBelowClipped * searched ? settled_steps_ + 1 : 0;
}

}  // namespace halfspace::solvers
