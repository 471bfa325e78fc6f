// The pull-off force of an adhesive loading-unloading sweep under
// displacement control.
#pragma once

#include <span>

#include "halfspace/analysis/load_sweep.hpp"

namespace halfspace::analysis {

// The most negative total force (N, N/m in 1D) on the unloading branch: the
// steps after the one of largest approach. NaN when there is no such step
// (the sweep only loads) or the sweep was not under displacement control.
// Under displacement control the force passes through its minimum stably,
// so on a fine enough list of approaches this is the pull-off force (for
// JKR's sphere, -3/2 pi w R).
double pull_off_force(std::span<const SweepStep> steps);

}  // namespace halfspace::analysis
