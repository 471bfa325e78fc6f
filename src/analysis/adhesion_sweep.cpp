// Pull-off force of a displacement-controlled adhesive sweep.
#include "halfspace/analysis/adhesion_sweep.hpp"

#include <algorithm>
#include <limits>

namespace halfspace::analysis {

double pull_off_force(std::span<const SweepStep> steps) {
  const double none = std::numeric_limits<double>::quiet_NaN();
  if (steps.empty() || steps.front().loading.mode != ControlMode::approach) return none;
  std::size_t deepest = 0;
  for (std::size_t k = 1; k < steps.size(); ++k) {
    if (steps[k].loading.value > steps[deepest].loading.value) deepest = k;
  }
  if (deepest + 1 >= steps.size()) return none;
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t k = deepest + 1; k < steps.size(); ++k) least = std::min(least, steps[k].result.total_force);
  return least;
}

}  // namespace halfspace::analysis
