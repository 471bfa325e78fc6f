// The sweep's summary columns, in file order.
#include "halfspace/analysis/sweep_table.hpp"

#include <array>

namespace halfspace::analysis {
namespace {

// Each column reads its value with a captureless lambda (a plain function
// pointer in the table).
constexpr std::array kColumns{
    SummaryColumn{
        "load", "",
        "the controlled value of the step: force (N, N/m in 1D), mean pressure (Pa) or approach (m), as load_mode says",
        [](const SweepStep& s) { return s.loading.value; }},
    SummaryColumn{"mean_pressure", "Pa", "total force over the domain area",
                  [](const SweepStep& s) { return s.result.mean_pressure; }},
    SummaryColumn{"total_force", "force", "sum of pressure times cell area",
                  [](const SweepStep& s) { return s.result.total_force; }},
    SummaryColumn{"approach", "m", "rigid-body approach", [](const SweepStep& s) { return s.result.approach; }},
    // The solver's own count, as in a single result: with adhesion the cells
    // at the wall (gap 0, whatever their pressure's sign), not those pushed.
    SummaryColumn{"contact_fraction", "1",
                  "cells in contact over all cells: pressure > 0, or with adhesion at the wall (gap 0)",
                  [](const SweepStep& s) { return s.result.contact_fraction; }},
    SummaryColumn{"plastic_fraction", "1", "cells at the hardness cap over all cells (0 without a cap)",
                  [](const SweepStep& s) { return s.result.plastic_fraction; }},
    SummaryColumn{"mean_gap", "m", "mean gap over all cells", [](const SweepStep& s) { return s.statistics.mean_gap; }},
    SummaryColumn{"rms_gap", "m", "root mean square gap over all cells",
                  [](const SweepStep& s) { return s.statistics.rms_gap; }},
    SummaryColumn{"free_volume", "volume", "sum of gap times cell area (m^3; m^2 in 1D)",
                  [](const SweepStep& s) { return s.statistics.free_volume; }},
    SummaryColumn{"max_pressure", "Pa", "largest pressure", [](const SweepStep& s) { return s.result.max_pressure; }},
    SummaryColumn{"clusters", "1", "number of contact clusters (connected components)",
                  [](const SweepStep& s) { return static_cast<double>(s.statistics.clusters()); }},
    SummaryColumn{"iterations", "1", "solver iterations",
                  [](const SweepStep& s) { return static_cast<double>(s.result.iterations); }},
    SummaryColumn{"residual", "1", "final value of the solver's stopping measure",
                  [](const SweepStep& s) { return s.result.residual; }},
    SummaryColumn{"seconds", "s", "wall-clock time of the step's solve",
                  [](const SweepStep& s) { return s.result.wall_seconds; }},
    SummaryColumn{"converged", "1", "1 if the step converged, else 0",
                  [](const SweepStep& s) { return s.result.converged() ? 1.0 : 0.0; }},
};

}  // namespace

std::span<const SummaryColumn> summary_columns() {
  return kColumns;
}

}  // namespace halfspace::analysis
