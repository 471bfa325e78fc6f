// A CsrMatrix's rows (film_preconditioner.hpp) built on several threads:
// each thread builds a contiguous run of rows into its own arrays, and the
// runs are joined in order, so the matrix is the same whatever the thread
// count. The first run goes straight into the matrix (it starts at 0): one
// thread holds no second copy. The preconditioners' matrices are rebuilt at
// every factorisation, a million rows at 1024^2, and one thread building
// them left the other idle (docs/development-log.md, 2026-12-04,
// forty-sixth session). Private to the library.
#pragma once

#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "film_preconditioner.hpp"

namespace halfspace::lubrication::detail {

// Rows are shared out among the threads from this many: a row costs tens of
// nanoseconds, waking the team tens of microseconds.
inline constexpr std::size_t kRowsInRunsFrom = 4096;

// The threads that build `rows` rows.
inline int row_run_team(std::size_t rows) {
  return rows > kRowsInRunsFrom ? omp_get_max_threads() : 1;
}

// A thread's scratch for rows gathered entry by entry: the entries of the
// row being built, and the thread's run of rows (but the first thread's).
struct GatheredRowRun {
  std::vector<std::pair<int, double>> entries;
  std::vector<int> column;
  std::vector<double> value;
};

// Rows [0, out.rows) of `out` made by row(scratch, r, columns, values),
// which appends row r's entries (columns ascending) to `columns` and
// `values`, on `team` threads with scratches[0 .. team).
template <class Scratch, class Row>
void build_rows_in_runs(CsrMatrix& out, int team, std::vector<Scratch>& scratches, std::vector<int>& row_count,
                        Row&& row) {
  if (scratches.size() < static_cast<std::size_t>(team)) scratches.resize(static_cast<std::size_t>(team));
  out.start.resize(out.rows + 1);
  row_count.resize(out.rows);
#pragma omp parallel num_threads(team)
  {
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    const auto threads = static_cast<std::size_t>(omp_get_num_threads());
    Scratch& scratch = scratches[t];
    std::vector<int>& column = t == 0 ? out.column : scratch.column;
    std::vector<double>& value = t == 0 ? out.value : scratch.value;
    column.clear();
    value.clear();
    const std::size_t begin = out.rows * t / threads, end = out.rows * (t + 1) / threads;
    for (std::size_t r = begin; r < end; ++r) {
      const std::size_t before = column.size();
      row(scratch, r, column, value);
      row_count[r] = static_cast<int>(column.size() - before);
    }
#pragma omp barrier
#pragma omp single
    {
      out.start[0] = 0;
      for (std::size_t r = 0; r < out.rows; ++r) out.start[r + 1] = out.start[r] + row_count[r];
      out.column.resize(static_cast<std::size_t>(out.start[out.rows]));
      out.value.resize(static_cast<std::size_t>(out.start[out.rows]));
    }
    if (t > 0) {
      std::copy(column.begin(), column.end(), out.column.begin() + out.start[begin]);
      std::copy(value.begin(), value.end(), out.value.begin() + out.start[begin]);
    }
  }
}

// build_rows_in_runs for rows gathered entry by entry: row(r, entries)
// pushes row r's entries (columns in any order, repeated ones summed, as
// CsrMatrix::append_row takes them).
template <class Row>
void gather_rows_in_runs(CsrMatrix& out, std::size_t rows, std::vector<GatheredRowRun>& scratches,
                         std::vector<int>& row_count, Row&& row) {
  out.rows = rows;
  build_rows_in_runs(out, row_run_team(rows), scratches, row_count,
                     [&](GatheredRowRun& scratch, std::size_t r, std::vector<int>& column, std::vector<double>& value) {
                       scratch.entries.clear();
                       row(r, scratch.entries);
                       append_summed(scratch.entries, column, value);
                     });
}

}  // namespace halfspace::lubrication::detail
