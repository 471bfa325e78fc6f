// The sweep's summary table: its columns, their order and what each reads
// from a step.
#include "halfspace/analysis/sweep_table.hpp"

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

namespace halfspace::analysis {
namespace {

using analysis::SweepStep;

TEST(SweepTableTest, SummaryColumnsAreTheDocumentedOnes) {
  std::vector<std::string> names;
  for (const SummaryColumn& column : summary_columns()) names.emplace_back(column.name);
  EXPECT_EQ(names, (std::vector<std::string>{"load", "mean_pressure", "total_force", "approach", "contact_fraction",
                                             "plastic_fraction", "mean_gap", "rms_gap", "free_volume", "max_pressure",
                                             "clusters", "iterations", "residual", "seconds", "converged"}));
  SweepStep step;
  step.loading = Loading::approach(2e-6);
  step.result.status = SolveStatus::converged;
  step.result.iterations = 7;
  step.statistics.cluster_sizes = {5, 3, 1};
  step.statistics.free_volume = 4.5;
  const auto value = [&](std::string_view name) {
    for (const SummaryColumn& column : summary_columns()) {
      if (column.name == name) return column.value(step);
    }
    return -1.0;
  };
  EXPECT_EQ(value("load"), 2e-6);
  EXPECT_EQ(value("clusters"), 3.0);
  EXPECT_EQ(value("iterations"), 7.0);
  EXPECT_EQ(value("free_volume"), 4.5);
  EXPECT_EQ(value("converged"), 1.0);
}

// The contact fraction is the solver's, as in a single result: with
// adhesion the cells at the wall, which the pressure's sign does not tell
// (attraction holds the rim of a JKR-like contact at the wall). It once read
// the statistics' count of cells with p > 0.
TEST(SweepTableTest, ContactFractionIsTheSolversCount) {
  SweepStep step;
  step.result.contact_fraction = 0.25;       // at the wall
  step.statistics.contact_fraction = 0.125;  // p > 0
  for (const SummaryColumn& column : summary_columns()) {
    if (column.name == "contact_fraction") {
      EXPECT_EQ(column.value(step), 0.25);
    }
  }
}

}  // namespace
}  // namespace halfspace::analysis
