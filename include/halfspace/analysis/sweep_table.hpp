// The summary table of a load sweep: one row per step, one column per
// quantity, written as HDF5 /sweep/<name> and as the sweep's CSV
// (docs/file-format.md#sweep-results).
#pragma once

#include <span>
#include <string_view>

#include "halfspace/analysis/load_sweep.hpp"

namespace halfspace::analysis {

// One column of the sweep's summary table (HDF5 /sweep/<name> and the CSV):
// its name, unit ("" when dimensionless; "force" stands for N in 2D, N/m in
// 1D) and how a step gives its value.
struct SummaryColumn {
  std::string_view name;
  std::string_view unit;
  std::string_view meaning;
  double (*value)(const SweepStep& step);
};

// The columns in file order: load, mean_pressure, total_force, approach,
// contact_fraction, plastic_fraction, mean_gap, rms_gap, free_volume, max_pressure, clusters,
// iterations, residual, seconds, converged.
std::span<const SummaryColumn> summary_columns();

}  // namespace halfspace::analysis
