// The preconditioners' rows built on several threads
// (src/lubrication/csr_rows_in_runs.hpp): the same matrix, entry for entry,
// as the rows appended one by one, on any thread count.
#include "lubrication/csr_rows_in_runs.hpp"

#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

#include "halfspace/threads.hpp"

namespace halfspace::lubrication::detail {
namespace {

// Row r's entries: up to 40 of 30 columns in random order, many repeated
// (as the mass rows' K around each local term overlap), some rows empty.
std::vector<std::pair<int, double>> random_row(std::size_t r) {
  std::mt19937 random(static_cast<unsigned>(r) + 11u);
  std::uniform_int_distribution<int> count(0, 40);
  std::uniform_int_distribution<int> column(0, 29);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<std::pair<int, double>> row;
  const int entries = r % 97 == 0 ? 0 : count(random);
  for (int e = 0; e < entries; ++e) row.emplace_back(column(random), value(random));
  return row;
}

TEST(CsrRowsInRunsTest, ThreadedRowsAreTheRowsAppendedOneByOne) {
  const std::size_t rows = 3 * kRowsInRunsFrom + 17;  // above the threshold: the team is shared out
  CsrMatrix expected;
  expected.clear();
  std::size_t pushed = 0;
  for (std::size_t r = 0; r < rows; ++r) {
    std::vector<std::pair<int, double>> row = random_row(r);
    pushed += row.size();
    expected.append_row(row);
  }
  const int original = threads();
  for (const int count : {1, 2, 3}) {
    set_threads(count);
    CsrMatrix built;
    std::vector<GatheredRowRun> scratches;
    std::vector<int> row_count;
    gather_rows_in_runs(built, rows, scratches, row_count,
                        [&](std::size_t r, std::vector<std::pair<int, double>>& row) { row = random_row(r); });
    EXPECT_EQ(built.rows, expected.rows) << count << " threads";
    EXPECT_EQ(built.start, expected.start) << count << " threads";
    EXPECT_EQ(built.column, expected.column) << count << " threads";
    EXPECT_EQ(built.value, expected.value) << count << " threads";
    // Built again into the same matrix and scratches: nothing left over.
    gather_rows_in_runs(built, rows, scratches, row_count,
                        [&](std::size_t r, std::vector<std::pair<int, double>>& row) { row = random_row(r); });
    EXPECT_EQ(built.column, expected.column) << count << " threads, again";
    EXPECT_EQ(built.value, expected.value) << count << " threads, again";
  }
  set_threads(original);
  // Repeated columns were summed: fewer entries than pushed, ascending.
  EXPECT_LT(expected.entries(), pushed);
  for (std::size_t r = 0; r < rows; ++r) {
    for (int e = expected.start[r] + 1; e < expected.start[r + 1]; ++e) {
      ASSERT_LT(expected.column[e - 1], expected.column[e]) << "row " << r;
    }
  }
}

}  // namespace
}  // namespace halfspace::lubrication::detail
