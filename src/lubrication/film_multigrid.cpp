// The EHL multigrid preconditioner (film_multigrid.hpp). One V-cycle from a
// zero guess is a fixed linear map, as GMRES's right preconditioning needs:
// a forward line Gauss–Seidel sweep, the residual restricted by P^T, the
// coarse correction prolongated by P, a backward sweep (the sweeps in
// opposite orders so that flow across the lines, whichever its sign, is
// met downstream once). The coarse operators are Galerkin's, P^T A P
// (Wesseling 1992, "An Introduction to Multigrid Methods"; Trottenberg,
// Oosterlee & Schüller 2001, "Multigrid", on cell-centred transfers): they need
// nothing of the physics, so cavitated rows, fixed-pressure edges and the
// elastic diagonal coarsen alike.
#include "film_multigrid.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <span>

#include "banded_lu.hpp"
#include "csr_rows_in_runs.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::lubrication::detail {

namespace {

// Line Gauss–Seidel sweeps before and after the coarse correction.
constexpr int kPreSweeps = 1;
constexpr int kPostSweeps = 1;
// Entries of a row within this many nodes along its line go into the
// line's band (the stencil's reach: 2 upstream at second order, more with
// a preconditioner neighbourhood); farther ones are relaxed, not solved.
constexpr int kMaxBand = 4;
// Line sweeps on a coarsest grid too large for the direct solve.
constexpr int kCoarsestSweeps = 8;
// The lines' factorisations and the levels' other loops are shared out
// among the threads from this many nodes, as the rows built in runs are
// (kRowsInRunsFrom): a row costs tens of nanoseconds, waking the team tens
// of microseconds.
constexpr std::size_t kParallelNodes = 4096;
// The sweeps' chains of consecutive lines (chain_lines), on levels of at
// least kChainedNodes nodes; a smaller level is swept as one chain, line
// after line, as on one thread: there the wake-ups cost what the second
// thread saves, and the mixed film's Newton path (which any change of the
// smoother moves) stays as it was on the grids its continuation runs on.
constexpr long kLinesPerChain = 32;
constexpr std::size_t kChainedNodes = 65536;

// The fine-to-coarse transfer of one axis of n nodes: halved if coarsened.
bool coarsens(std::size_t n, bool periodic) {
  return n > FilmMultigrid::kMinCoarsenedCells && (!periodic || n % 2 == 0);
}

// The signed offset from a to b on an axis of n nodes (the nearest image
// on a periodic one).
long offset(long a, long b, long n, bool periodic) {
  long d = b - a;
  if (periodic) {
    d = ((d % n) + n) % n;
    if (d > n / 2) d -= n;
  }
  return d;
}

}  // namespace

void CsrMatrix::residual(const Eigen::VectorXd& b, const Eigen::VectorXd& x, Eigen::VectorXd& out) const {
  linalg::for_each_index(rows, [&](std::size_t i) {
    double sum = b[static_cast<Eigen::Index>(i)];
    for (int e = start[i]; e < start[i + 1]; ++e) sum -= value[e] * x[column[e]];
    out[static_cast<Eigen::Index>(i)] = sum;
  });
}

FilmMultigrid::FilmMultigrid(const Grid& grid, int line_axis, bool scale_columns)
    : periodic_(grid.periodic()), scale_columns_(scale_columns), line_axis_(grid.dimension() == 1 ? 0 : line_axis) {
  std::size_t nx = grid.nx();
  std::size_t ny = grid.dimension() == 1 ? 1 : grid.ny();
  const auto make_axis = [&](std::size_t n) {
    Axis axis;
    axis.fine = n;
    const bool halve = coarsens(n, periodic_);
    axis.coarse = halve ? (n + 1) / 2 : n;
    axis.parents.resize(n);
    axis.children.resize(axis.coarse);
    for (std::size_t i = 0; i < n; ++i) {
      Parents& p = axis.parents[i];
      if (!halve) {
        p = {1, {static_cast<int>(i), 0}, {1.0, 0.0}};
      } else {
        const long own = static_cast<long>(i / 2);
        long other = i % 2 == 0 ? own - 1 : own + 1;
        const auto nc = static_cast<long>(axis.coarse);
        if (periodic_) other = (other + nc) % nc;
        if (other < 0 || other >= nc) {
          p = {1, {static_cast<int>(own), 0}, {1.0, 0.0}};
        } else {
          p = {2, {static_cast<int>(own), static_cast<int>(other)}, {0.75, 0.25}};
        }
      }
      for (int k = 0; k < p.count; ++k) {
        Children& c = axis.children[static_cast<std::size_t>(p.index[k])];
        c.index[c.count] = static_cast<int>(i);
        c.weight[c.count] = p.weight[k];
        ++c.count;
      }
    }
    return axis;
  };
  for (;;) {
    Level level;
    level.nx = nx;
    level.ny = ny;
    const std::size_t n = nx * ny;
    level.x.resize(static_cast<Eigen::Index>(n));
    level.b.resize(static_cast<Eigen::Index>(n));
    level.r.resize(static_cast<Eigen::Index>(n));
    const bool coarser = n > kDirectNodes && (coarsens(nx, periodic_) || coarsens(ny, periodic_));
    if (coarser) {
      level.to_coarse_x = make_axis(nx);
      level.to_coarse_y = make_axis(ny);
      level.node_x.resize(n);
      level.node_y.resize(n);
      for (std::size_t i = 0; i < n; ++i) {
        level.node_x[i] = static_cast<int>(i % nx);
        level.node_y[i] = static_cast<int>(i / nx);
      }
      nx = level.to_coarse_x.coarse;
      ny = level.to_coarse_y.coarse;
    }
    direct_coarsest_ = n <= kDirectNodes;
    levels_.push_back(std::move(level));
    if (!coarser) break;
  }
}

std::size_t FilmMultigrid::line_count(const Level& level) const {
  return line_axis_ == 0 ? level.ny : level.nx;
}
std::size_t FilmMultigrid::line_length(const Level& level) const {
  return line_axis_ == 0 ? level.nx : level.ny;
}
std::size_t FilmMultigrid::node(const Level& level, std::size_t line, std::size_t t) const {
  return line_axis_ == 0 ? line * level.nx + t : t * level.nx + line;
}

bool FilmMultigrid::split_lines(Level& level, std::string& message) {
  const CsrMatrix& a = *level.matrix;
  const auto nx = static_cast<long>(level.nx);
  const auto line_of = [&](long j) { return line_axis_ == 0 ? j / nx : j % nx; };
  const auto position = [&](long j) { return line_axis_ == 0 ? j % nx : j / nx; };
  const auto rows = static_cast<std::ptrdiff_t>(a.rows);
  const bool threaded = a.rows > kParallelNodes;
  // The bands' width from the pattern.
  int kl = 0, ku = 0;
#pragma omp parallel for schedule(static) reduction(max : kl, ku) if (threaded)
  for (std::ptrdiff_t i = 0; i < rows; ++i) {
    for (int e = a.start[static_cast<std::size_t>(i)]; e < a.start[static_cast<std::size_t>(i) + 1]; ++e) {
      const long j = a.column[e];
      const long d = position(j) - position(i);
      if (line_of(j) != line_of(i) || std::abs(d) > kMaxBand) continue;
      kl = std::max(kl, static_cast<int>(-d));
      ku = std::max(ku, static_cast<int>(d));
    }
  }
  level.kl = kl;
  level.ku = ku;
  const std::size_t stride = banded_lu_stride(kl, ku);
  const std::size_t length = line_length(level);
  const auto lines = static_cast<std::ptrdiff_t>(line_count(level));
  level.band.resize(a.rows * stride);
  level.pivots.resize(a.rows);
#pragma omp parallel for schedule(static) if (threaded)
  for (std::ptrdiff_t line = 0; line < lines; ++line) {
    const auto at = static_cast<std::size_t>(line) * length * stride;
    std::fill_n(level.band.begin() + static_cast<std::ptrdiff_t>(at), length * stride, 0.0);
  }
  // Each row's in-band entries into its line's band (rows write apart), the
  // others into the off-band matrix, rows in runs (csr_rows_in_runs.hpp).
  CsrMatrix& off = level.off_band;
  off.rows = a.rows;
  build_rows_in_runs(off, row_run_team(a.rows), off_band_runs_, row_count_,
                     [&](GatheredRowRun&, std::size_t i, std::vector<int>& column, std::vector<double>& value) {
                       const auto ii = static_cast<long>(i);
                       const std::size_t line = static_cast<std::size_t>(line_of(ii));
                       const auto t = static_cast<std::size_t>(position(ii));
                       std::span<double> band(level.band.data() + line * length * stride, length * stride);
                       for (int e = a.start[i]; e < a.start[i + 1]; ++e) {
                         const long j = a.column[e];
                         const long d = position(j) - position(ii);
                         if (line_of(j) == line_of(ii) && d >= -kl && d <= ku) {
                           band[banded_index(kl, ku, t, static_cast<std::size_t>(position(j)))] += a.value[e];
                         } else {
                           column.push_back(static_cast<int>(j));
                           value.push_back(a.value[e]);
                         }
                       }
                     });
  std::ptrdiff_t singular = lines;  // the first singular line, if any
#pragma omp parallel for schedule(static) reduction(min : singular) if (a.rows > kParallelNodes)
  for (std::ptrdiff_t line = 0; line < lines; ++line) {
    const auto at = static_cast<std::size_t>(line) * length;
    if (!banded_lu_factorise(std::span<double>(level.band.data() + at * stride, length * stride),
                             std::span<int>(level.pivots.data() + at, length), kl, ku)) {
      singular = std::min(singular, line);
    }
  }
  if (singular < lines) {
    message = fmt::format("the EHL multigrid preconditioner's line {} of the {} x {} grid is singular", singular,
                          level.nx, level.ny);
    return false;
  }
  chain_lines(level);
  return true;
}

void FilmMultigrid::chain_lines(Level& level) const {
  // Chains at least one line longer than the lines' reach across one
  // another through the off-band entries (the nearest image's on a periodic
  // grid), coloured alternately (an even number of them on a periodic grid,
  // where the last chain meets the first), touch none of their colour. A
  // level below kChainedNodes is one chain, and its reach is not needed.
  const auto lines = static_cast<long>(line_count(level));
  long count = 1;
  if (level.nx * level.ny >= kChainedNodes) {
    const CsrMatrix& off = level.off_band;
    const auto nx = static_cast<long>(level.nx);
    const auto line_of = [&](long j) { return line_axis_ == 0 ? j / nx : j % nx; };
    long reach = 0;
    for (std::size_t i = 0; i < off.rows; ++i) {
      const long own = line_of(static_cast<long>(i));
      for (int e = off.start[i]; e < off.start[i + 1]; ++e) {
        reach = std::max(reach, std::abs(offset(own, line_of(off.column[e]), lines, periodic_)));
      }
    }
    count = std::max(1L, lines / std::max(kLinesPerChain, reach + 1));
    if (periodic_ && count % 2 == 1) count = std::max(1L, count - 1);
  }
  level.chains.clear();
  level.colour_start.assign(count > 1 ? 3 : 2, 0);
  for (long colour = 0; colour < (count > 1 ? 2 : 1); ++colour) {
    for (long k = colour; k < count; k += 2) {
      const long first = lines * k / count, next = lines * (k + 1) / count;
      level.chains.emplace_back(static_cast<std::size_t>(first), static_cast<std::size_t>(next - first));
    }
    level.colour_start[static_cast<std::size_t>(colour) + 1] = level.chains.size();
  }
}

void FilmMultigrid::find_fixed(Level& level) {
  const CsrMatrix& a = *level.matrix;
  level.fixed.resize(a.rows);
  linalg::for_each_index(a.rows, [&](std::size_t i) {
    level.fixed[i] = a.start[i + 1] - a.start[i] == 1 && a.column[a.start[i]] == static_cast<int>(i) ? 1 : 0;
  });
}

// P^T A P in two products: A P (fine rows, coarse columns), then P^T (A P).
// Each fine row's A P is made once per thread, where the product row by
// row would make it again for each of the up to 4 coarse rows the node is
// a child of (docs/development-log.md, 2026-12-03). A P is held a few fine
// lines at a time: a coarse line's rows need the 4 fine lines around it.
void FilmMultigrid::galerkin(const Level& fine, Level& coarse) {
  const CsrMatrix& a = *fine.matrix;
  const auto fnx = static_cast<long>(fine.nx), fny = static_cast<long>(fine.ny);
  const auto cnx = static_cast<long>(coarse.nx), cny = static_cast<long>(coarse.ny);
  // The fine stencil's reach sets the coarse one's: children lie within
  // 1.5 fine cells of their coarse cell's centre, parents likewise.
  long reach = 0;
  const auto fine_rows = static_cast<std::ptrdiff_t>(a.rows);
#pragma omp parallel for schedule(static) reduction(max : reach) if (a.rows > kParallelNodes)
  for (std::ptrdiff_t i = 0; i < fine_rows; ++i) {
    const long xi = fine.node_x[static_cast<std::size_t>(i)], yi = fine.node_y[static_cast<std::size_t>(i)];
    for (int e = a.start[static_cast<std::size_t>(i)]; e < a.start[static_cast<std::size_t>(i) + 1]; ++e) {
      const auto j = static_cast<std::size_t>(a.column[e]);
      reach = std::max({reach, std::abs(offset(xi, fine.node_x[j], fnx, periodic_)),
                        std::abs(offset(yi, fine.node_y[j], fny, periodic_))});
    }
  }
  // A P's row i spans the parents of the nodes within `reach` of i: within
  // (reach + 1) / 2 + 2 coarse cells of i's first parent.
  const long w_ap = (reach + 1) / 2 + 2;
  const long side_ap = 2 * w_ap + 1;
  const long w = (reach + 3) / 2;
  const long side = 2 * w + 1;
  const int team = row_run_team(a.rows);
  if (galerkin_scratch_.size() < static_cast<std::size_t>(team))
    galerkin_scratch_.resize(static_cast<std::size_t>(team));
  for (int t = 0; t < team; ++t) {
    GalerkinScratch& scratch = galerkin_scratch_[static_cast<std::size_t>(t)];
    scratch.window.assign(static_cast<std::size_t>(side * side), 0.0);
    scratch.touched.assign(static_cast<std::size_t>(side * side), 0);
    scratch.ap_window.assign(static_cast<std::size_t>(side_ap * side_ap), 0.0);
    scratch.ap_touched.assign(static_cast<std::size_t>(side_ap * side_ap), 0);
    for (ProductLine& line : scratch.lines) line.y = -1;
  }
  const Axis& ax = fine.to_coarse_x;
  const Axis& ay = fine.to_coarse_y;
  // The window's entries around (cx, cy), half-width `half`, appended to
  // `columns` and `values` (in slot order, by column on periodic grids),
  // the window cleared.
  const auto flush = [&](GalerkinScratch& scratch, std::vector<double>& window, std::vector<char>& touched, long cx,
                         long cy, long half, std::vector<int>& columns, std::vector<double>& values) {
    const long width = 2 * half + 1;
    std::vector<std::pair<int, double>>& row_entries = scratch.row_entries;
    row_entries.clear();
    for (long dy = 0; dy < width; ++dy) {
      for (long dx = 0; dx < width; ++dx) {
        const auto slot = static_cast<std::size_t>(dy * width + dx);
        if (!touched[slot]) continue;
        long jx = cx + dx - half, jy = cy + dy - half;
        if (periodic_) {
          jx = (jx + cnx) % cnx;
          jy = (jy + cny) % cny;
        }
        row_entries.emplace_back(static_cast<int>(jy * cnx + jx), window[slot]);
        window[slot] = 0.0;
        touched[slot] = 0;
      }
    }
    if (periodic_) std::sort(row_entries.begin(), row_entries.end());
    for (const auto& [column, value] : row_entries) {
      columns.push_back(column);
      values.push_back(value);
    }
  };
  // A P on fine line y, in the thread's line cache: row i's entries a_ij
  // spread over j's coarse parents (none on fixed rows and columns, which
  // the transfers leave out).
  const auto product_line = [&](GalerkinScratch& scratch, long y) -> const ProductLine& {
    ProductLine& line = scratch.lines[static_cast<std::size_t>(y) % scratch.lines.size()];
    if (line.y == y) return line;
    line.y = y;
    line.start.resize(static_cast<std::size_t>(fnx) + 1);
    line.column.clear();
    line.value.clear();
    line.start[0] = 0;
    const long hy = ay.parents[static_cast<std::size_t>(y)].index[0];
    for (long x = 0; x < fnx; ++x) {
      const auto i = static_cast<std::size_t>(y * fnx + x);
      if (!fine.fixed[i]) {
        const long hx = ax.parents[static_cast<std::size_t>(x)].index[0];
        for (int e = a.start[i]; e < a.start[i + 1]; ++e) {
          const auto j = static_cast<std::size_t>(a.column[e]);
          if (fine.fixed[j]) continue;
          const Parents& px = ax.parents[static_cast<std::size_t>(fine.node_x[j])];
          const Parents& py = ay.parents[static_cast<std::size_t>(fine.node_y[j])];
          for (int qy = 0; qy < py.count; ++qy) {
            const long dy = offset(hy, py.index[qy], cny, periodic_) + w_ap;
            const double vy = a.value[e] * py.weight[qy];
            for (int qx = 0; qx < px.count; ++qx) {
              const long dx = offset(hx, px.index[qx], cnx, periodic_) + w_ap;
              const auto slot = static_cast<std::size_t>(dy * side_ap + dx);
              scratch.ap_window[slot] += vy * px.weight[qx];
              scratch.ap_touched[slot] = 1;
            }
          }
        }
        flush(scratch, scratch.ap_window, scratch.ap_touched, hx, hy, w_ap, line.column, line.value);
      }
      line.start[static_cast<std::size_t>(x) + 1] = static_cast<int>(line.column.size());
    }
    return line;
  };
  // P^T (A P), coarse row (cx, cy): its children's rows of A P, weighted.
  CsrMatrix& c = coarse.own;
  c.rows = coarse.nx * coarse.ny;
  build_rows_in_runs(
      c, team, galerkin_scratch_, row_count_,
      [&](GalerkinScratch& scratch, std::size_t row, std::vector<int>& columns, std::vector<double>& values) {
        const auto cx = static_cast<long>(row) % cnx, cy = static_cast<long>(row) / cnx;
        const Children& kids_y = ay.children[static_cast<std::size_t>(cy)];
        const Children& kids_x = ax.children[static_cast<std::size_t>(cx)];
        for (int ky = 0; ky < kids_y.count; ++ky) {
          const ProductLine& line = product_line(scratch, kids_y.index[ky]);
          for (int kx = 0; kx < kids_x.count; ++kx) {
            const auto x = static_cast<std::size_t>(kids_x.index[kx]);
            const double wi = kids_y.weight[ky] * kids_x.weight[kx];
            for (int e = line.start[x]; e < line.start[x + 1]; ++e) {
              const long column = line.column[static_cast<std::size_t>(e)];
              const long dy = offset(cy, column / cnx, cny, periodic_) + w;
              const long dx = offset(cx, column % cnx, cnx, periodic_) + w;
              const auto slot = static_cast<std::size_t>(dy * side + dx);
              scratch.window[slot] += wi * line.value[static_cast<std::size_t>(e)];
              scratch.touched[slot] = 1;
            }
          }
        }
        const std::size_t before = columns.size();
        flush(scratch, scratch.window, scratch.touched, cx, cy, w, columns, values);
        // A coarse node whose children are all fixed is fixed itself.
        if (columns.size() == before) {
          columns.push_back(static_cast<int>(row));
          values.push_back(1.0);
        }
      });
}

bool FilmMultigrid::factorise(const CsrMatrix& matrix, std::string& message) {
  // The unknowns scaled by the diagonal (A D^-1, D = |diag A|), if asked.
  const auto n = static_cast<Eigen::Index>(matrix.rows);
  column_scale_.setOnes(n);
  if (scale_columns_) {
    linalg::for_each_index(matrix.rows, [&](std::size_t i) {
      for (int e = matrix.start[i]; e < matrix.start[i + 1]; ++e) {
        if (matrix.column[e] == static_cast<int>(i) && matrix.value[e] != 0.0) {
          column_scale_[static_cast<Eigen::Index>(i)] = std::abs(matrix.value[e]);
        }
      }
    });
  }
  CsrMatrix& scaled = levels_[0].own;
  scaled.rows = matrix.rows;
  scaled.start = matrix.start;
  scaled.column = matrix.column;
  scaled.value.resize(matrix.value.size());
  linalg::for_each_index(matrix.value.size(),
                         [&](std::size_t e) { scaled.value[e] = matrix.value[e] / column_scale_[matrix.column[e]]; });
  levels_[0].matrix = &scaled;
  for (std::size_t l = 0; l < levels_.size(); ++l) {
    Level& level = levels_[l];
    const bool coarsest = l + 1 == levels_.size();
    find_fixed(level);
    if (!(coarsest && direct_coarsest_) && !split_lines(level, message)) return false;
    if (!coarsest) {
      galerkin(level, levels_[l + 1]);
      levels_[l + 1].matrix = &levels_[l + 1].own;
    }
  }
  if (direct_coarsest_) {
    const CsrMatrix& a = *levels_.back().matrix;
    const auto n = static_cast<Eigen::Index>(a.rows);
    const Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor, int>> rows(
        n, n, static_cast<Eigen::Index>(a.entries()), a.start.data(), a.column.data(), a.value.data());
    coarsest_ = rows;
    coarsest_lu_.compute(coarsest_);  // at most kDirectNodes nodes: analysed afresh, whatever the pattern
    if (coarsest_lu_.info() != Eigen::Success) {
      message = fmt::format("the EHL multigrid preconditioner's coarsest grid ({} x {}) is singular: {}",
                            levels_.back().nx, levels_.back().ny, coarsest_lu_.lastErrorMessage());
      return false;
    }
  }
  return true;
}

void FilmMultigrid::smooth(Level& level, bool forward) {
  const CsrMatrix& off = level.off_band;
  const std::size_t length = line_length(level);
  const std::size_t stride = banded_lu_stride(level.kl, level.ku);
  const std::size_t colours = level.colour_start.size() - 1;
  const auto threads = static_cast<std::size_t>(omp_get_max_threads());
  if (line_rhs_.size() < threads * length) line_rhs_.resize(threads * length);
  const auto relax = [&](std::size_t line, std::span<double> rhs) {
    for (std::size_t t = 0; t < length; ++t) {
      const std::size_t i = node(level, line, t);
      double sum = level.b[static_cast<Eigen::Index>(i)];
      for (int e = off.start[i]; e < off.start[i + 1]; ++e) sum -= off.value[e] * level.x[off.column[e]];
      rhs[t] = sum;
    }
    banded_lu_solve(std::span<const double>(level.band.data() + line * length * stride, length * stride),
                    std::span<const int>(level.pivots.data() + line * length, length), level.kl, level.ku, rhs);
    for (std::size_t t = 0; t < length; ++t) level.x[static_cast<Eigen::Index>(node(level, line, t))] = rhs[t];
  };
  for (std::size_t k = 0; k < colours; ++k) {
    const std::size_t colour = forward ? k : colours - 1 - k;
    const std::size_t first = level.colour_start[colour];
    const auto count = static_cast<std::ptrdiff_t>(level.colour_start[colour + 1] - first);
#pragma omp parallel for schedule(static) if (count > 1)
    for (std::ptrdiff_t q = 0; q < count; ++q) {
      const auto [start, lines] = level.chains[first + static_cast<std::size_t>(q)];
      std::span<double> rhs(line_rhs_.data() + static_cast<std::size_t>(omp_get_thread_num()) * length, length);
      for (std::size_t m = 0; m < lines; ++m) relax(forward ? start + m : start + lines - 1 - m, rhs);
    }
  }
}

void FilmMultigrid::restrict_residual(const Level& fine, Level& coarse) const {
  const Axis& ax = fine.to_coarse_x;
  const Axis& ay = fine.to_coarse_y;
  linalg::for_each_row(coarse.ny, coarse.nx, [&](std::size_t cy) {
    for (std::size_t cx = 0; cx < coarse.nx; ++cx) {
      const Children& kids_y = ay.children[cy];
      const Children& kids_x = ax.children[cx];
      double sum = 0.0;
      for (int ky = 0; ky < kids_y.count; ++ky) {
        for (int kx = 0; kx < kids_x.count; ++kx) {
          const std::size_t i =
              static_cast<std::size_t>(kids_y.index[ky]) * fine.nx + static_cast<std::size_t>(kids_x.index[kx]);
          if (!fine.fixed[i]) sum += kids_y.weight[ky] * kids_x.weight[kx] * fine.r[static_cast<Eigen::Index>(i)];
        }
      }
      coarse.b[static_cast<Eigen::Index>(cy * coarse.nx + cx)] = sum;
    }
  });
}

void FilmMultigrid::prolongate_add(const Level& coarse, Level& fine) const {
  const Axis& ax = fine.to_coarse_x;
  const Axis& ay = fine.to_coarse_y;
  linalg::for_each_row(fine.ny, fine.nx, [&](std::size_t y) {
    const Parents& py = ay.parents[y];
    for (std::size_t x = 0; x < fine.nx; ++x) {
      const Parents& px = ax.parents[x];
      if (fine.fixed[y * fine.nx + x]) continue;
      double sum = 0.0;
      for (int qy = 0; qy < py.count; ++qy) {
        for (int qx = 0; qx < px.count; ++qx) {
          sum += py.weight[qy] * px.weight[qx] *
                 coarse.x[static_cast<Eigen::Index>(static_cast<std::size_t>(py.index[qy]) * coarse.nx +
                                                    static_cast<std::size_t>(px.index[qx]))];
        }
      }
      fine.x[static_cast<Eigen::Index>(y * fine.nx + x)] += sum;
    }
  });
}

void FilmMultigrid::cycle(std::size_t l) {
  Level& level = levels_[l];
  if (l + 1 == levels_.size()) {
    if (direct_coarsest_) {
      level.x = coarsest_lu_.solve(level.b);
    } else {
      level.x.setZero();
      for (int s = 0; s < kCoarsestSweeps; ++s) smooth(level, s % 2 == 0);
    }
    return;
  }
  level.x.setZero();
  for (int s = 0; s < kPreSweeps; ++s) smooth(level, true);
  level.matrix->residual(level.b, level.x, level.r);
  restrict_residual(level, levels_[l + 1]);
  cycle(l + 1);
  prolongate_add(levels_[l + 1], level);
  for (int s = 0; s < kPostSweeps; ++s) smooth(level, false);
}

void FilmMultigrid::apply(const Eigen::VectorXd& in, Eigen::VectorXd& out) {
  levels_[0].b = in;
  cycle(0);
  out = levels_[0].x.cwiseQuotient(column_scale_);
}

double FilmMultigrid::bytes_per_node(double row_entries) {
  // The fine level: the scaled copy of the matrix and its off-band part
  // (at most the row's entries each), the band factors of lines up to
  // kMaxBand wide, pivots, four vectors (x, b, r, D), the nodes' column and
  // row; the coarse levels a third of the fine nodes with Galerkin rows of
  // up to 25 entries held twice (the operator and its off-band part); and
  // the threads' rows of the Galerkin product besides the first's, at most
  // the first coarse level's (a quarter of the fine nodes).
  const double band = 8.0 * static_cast<double>(banded_lu_stride(kMaxBand, kMaxBand)) + 4.0 + 4.0 * 8.0 + 2.0 * 4.0;
  const double fine = 2.0 * 12.0 * row_entries + band;
  const double coarse = (2.0 * 12.0 * 25.0 + band) / 3.0;
  const double threads_rows = 12.0 * 25.0 / 4.0;
  return fine + coarse + threads_rows;
}

}  // namespace halfspace::lubrication::detail
