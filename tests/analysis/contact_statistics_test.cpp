// Tests of the contact statistics: contact clusters on hand-drawn patterns
// (4-connectivity, wrap-around only on periodic grids) and the gap moments of
// a known field.
#include "halfspace/analysis/contact_statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace halfspace::analysis {
namespace {

// Closed forms evaluated with a few operations per cell, summed over <= 10^4 cells.
constexpr double kTolerance = 1e-12;

using Sizes = std::vector<std::int64_t>;

// A pressure field from a picture: '#' is in contact (p = 1), '.' is not.
std::vector<double> picture(const std::vector<std::string>& rows) {
  std::vector<double> p;
  for (const std::string& row : rows) {
    for (char c : row) p.push_back(c == '#' ? 1.0 : 0.0);
  }
  return p;
}

TEST(ContactStatisticsTest, ClustersUseEdgeNeighboursOnly) {
  // Diagonal neighbours are separate clusters (4-connectivity).
  const Grid grid = Grid::plane(5, 4, 1.0, 1.0, Boundary::free);
  const std::vector<double> p = picture({
      "##...",
      "##.#.",
      "..#..",
      ".....",
  });
  EXPECT_EQ(contact_cluster_sizes(grid, p), (Sizes{4, 1, 1}));
}

TEST(ContactStatisticsTest, PeriodicClustersWrapAroundEdges) {
  const std::vector<double> p = picture({
      "#...#",
      ".....",
      ".##..",
      "#...#",
  });
  // Free: the four corners and the pair are separate.
  EXPECT_EQ(contact_cluster_sizes(Grid::plane(5, 4, 1.0, 1.0, Boundary::free), p), (Sizes{2, 1, 1, 1, 1}));
  // Periodic: the corners touch across both edges and form one cluster.
  EXPECT_EQ(contact_cluster_sizes(Grid::plane(5, 4, 1.0, 1.0, Boundary::periodic), p), (Sizes{4, 2}));
}

TEST(ContactStatisticsTest, ClustersOnProfile) {
  const std::vector<double> p = picture({"##..###..#"});
  EXPECT_EQ(contact_cluster_sizes(Grid::line(10, 1.0, Boundary::free), p), (Sizes{3, 2, 1}));
  EXPECT_EQ(contact_cluster_sizes(Grid::line(10, 1.0, Boundary::periodic), p), (Sizes{3, 3}));
  EXPECT_TRUE(contact_cluster_sizes(Grid::line(10, 1.0, Boundary::periodic), std::vector<double>(10, 0.0)).empty());
  EXPECT_EQ(contact_cluster_sizes(Grid::line(10, 1.0, Boundary::periodic), std::vector<double>(10, 1.0)), (Sizes{10}));
}

TEST(ContactStatisticsTest, ContactStatisticsOfKnownFields) {
  const Grid grid = Grid::plane(4, 2, 2.0, 3.0, Boundary::periodic);
  const std::vector<double> pressure{1, 2, 0, 0, 0, 0, 0, 5};
  // Contact cells carry rounding-level gaps, one negative: clipped to 0.
  const std::vector<double> gap{-1e-20, 1e-20, 1, 2, 3, 4, 5, 0};
  const ContactStatistics s = contact_statistics(grid, pressure, gap);
  EXPECT_DOUBLE_EQ(s.contact_fraction, 3.0 / 8.0);
  EXPECT_NEAR(s.mean_gap, 15.0 / 8.0, kTolerance);
  EXPECT_NEAR(s.rms_gap, std::sqrt(55.0 / 8.0), kTolerance);
  EXPECT_NEAR(s.free_volume, 15.0 * 6.0, 1e-10);
  // (0,0) and (1,0) touch; (3,1) wraps onto (0,1) and (3,0), both out of
  // contact, so it stays alone.
  EXPECT_EQ(s.cluster_sizes, (Sizes{2, 1}));
  EXPECT_EQ(s.clusters(), 2);
}

}  // namespace
}  // namespace halfspace::analysis
