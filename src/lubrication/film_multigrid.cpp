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

#include <algorithm>
#include <cmath>
#include <span>

#include "banded_lu.hpp"

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
  for (std::size_t i = 0; i < rows; ++i) {
    double sum = b[static_cast<Eigen::Index>(i)];
    for (int e = start[i]; e < start[i + 1]; ++e) sum -= value[e] * x[column[e]];
    out[static_cast<Eigen::Index>(i)] = sum;
  }
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
      nx = level.to_coarse_x.coarse;
      ny = level.to_coarse_y.coarse;
    }
    direct_coarsest_ = n <= kDirectNodes;
    levels_.push_back(std::move(level));
    if (!coarser) break;
  }
  line_rhs_.resize(std::max(levels_[0].nx, levels_[0].ny));
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
  // The bands' width from the pattern.
  level.kl = 0;
  level.ku = 0;
  for (std::size_t i = 0; i < a.rows; ++i) {
    const auto ii = static_cast<long>(i);
    for (int e = a.start[i]; e < a.start[i + 1]; ++e) {
      const long j = a.column[e];
      const long d = position(j) - position(ii);
      if (line_of(j) != line_of(ii) || std::abs(d) > kMaxBand) continue;
      level.kl = std::max(level.kl, static_cast<int>(-d));
      level.ku = std::max(level.ku, static_cast<int>(d));
    }
  }
  const int kl = level.kl, ku = level.ku;
  const std::size_t stride = banded_lu_stride(kl, ku);
  const std::size_t length = line_length(level);
  level.band.assign(a.rows * stride, 0.0);
  level.pivots.resize(a.rows);
  CsrMatrix& off = level.off_band;
  off.rows = a.rows;
  off.start.resize(a.rows + 1);
  off.column.clear();
  off.value.clear();
  for (std::size_t i = 0; i < a.rows; ++i) {
    const auto ii = static_cast<long>(i);
    off.start[i] = static_cast<int>(off.column.size());
    const std::size_t line = static_cast<std::size_t>(line_of(ii));
    const auto t = static_cast<std::size_t>(position(ii));
    std::span<double> band(level.band.data() + line * length * stride, length * stride);
    for (int e = a.start[i]; e < a.start[i + 1]; ++e) {
      const long j = a.column[e];
      const long d = position(j) - position(ii);
      if (line_of(j) == line_of(ii) && d >= -kl && d <= ku) {
        band[banded_index(kl, ku, t, static_cast<std::size_t>(position(j)))] += a.value[e];
      } else {
        off.column.push_back(static_cast<int>(j));
        off.value.push_back(a.value[e]);
      }
    }
  }
  off.start[a.rows] = static_cast<int>(off.column.size());
  for (std::size_t line = 0; line < line_count(level); ++line) {
    std::span<double> band(level.band.data() + line * length * stride, length * stride);
    std::span<int> pivots(level.pivots.data() + line * length, length);
    if (!banded_lu_factorise(band, pivots, kl, ku)) {
      message = fmt::format("the EHL multigrid preconditioner's line {} of the {} x {} grid is singular", line,
                            level.nx, level.ny);
      return false;
    }
  }
  return true;
}

void FilmMultigrid::find_fixed(Level& level) {
  const CsrMatrix& a = *level.matrix;
  level.fixed.assign(a.rows, 0);
  for (std::size_t i = 0; i < a.rows; ++i) {
    level.fixed[i] = a.start[i + 1] - a.start[i] == 1 && a.column[a.start[i]] == static_cast<int>(i) ? 1 : 0;
  }
}

void FilmMultigrid::galerkin(const Level& fine, Level& coarse) {
  const CsrMatrix& a = *fine.matrix;
  const auto fnx = static_cast<long>(fine.nx), fny = static_cast<long>(fine.ny);
  const auto cnx = static_cast<long>(coarse.nx), cny = static_cast<long>(coarse.ny);
  // The fine stencil's reach sets the coarse one's: children lie within
  // 1.5 fine cells of their coarse cell's centre, parents likewise.
  long reach = 0;
  for (std::size_t i = 0; i < a.rows; ++i) {
    const long xi = static_cast<long>(i) % fnx, yi = static_cast<long>(i) / fnx;
    for (int e = a.start[i]; e < a.start[i + 1]; ++e) {
      const long j = a.column[e];
      reach = std::max(
          {reach, std::abs(offset(xi, j % fnx, fnx, periodic_)), std::abs(offset(yi, j / fnx, fny, periodic_))});
    }
  }
  const long w = (reach + 3) / 2;
  const long side = 2 * w + 1;
  window_.assign(static_cast<std::size_t>(side * side), 0.0);
  touched_.assign(static_cast<std::size_t>(side * side), 0);
  CsrMatrix& c = coarse.own;
  c.rows = coarse.nx * coarse.ny;
  c.start.resize(c.rows + 1);
  c.column.clear();
  c.value.clear();
  const Axis& ax = fine.to_coarse_x;
  const Axis& ay = fine.to_coarse_y;
  for (long cy = 0; cy < cny; ++cy) {
    for (long cx = 0; cx < cnx; ++cx) {
      const auto row = static_cast<std::size_t>(cy * cnx + cx);
      c.start[row] = static_cast<int>(c.column.size());
      const Children& kids_y = ay.children[static_cast<std::size_t>(cy)];
      const Children& kids_x = ax.children[static_cast<std::size_t>(cx)];
      for (int ky = 0; ky < kids_y.count; ++ky) {
        for (int kx = 0; kx < kids_x.count; ++kx) {
          const auto i = static_cast<std::size_t>(kids_y.index[ky] * fnx + kids_x.index[kx]);
          if (fine.fixed[i]) continue;
          const double wi = kids_y.weight[ky] * kids_x.weight[kx];
          for (int e = a.start[i]; e < a.start[i + 1]; ++e) {
            const long j = a.column[e];
            if (fine.fixed[static_cast<std::size_t>(j)]) continue;
            const Parents& px = ax.parents[static_cast<std::size_t>(j % fnx)];
            const Parents& py = ay.parents[static_cast<std::size_t>(j / fnx)];
            const double v = wi * a.value[e];
            for (int qy = 0; qy < py.count; ++qy) {
              const long dy = offset(cy, py.index[qy], cny, periodic_) + w;
              for (int qx = 0; qx < px.count; ++qx) {
                const long dx = offset(cx, px.index[qx], cnx, periodic_) + w;
                const auto slot = static_cast<std::size_t>(dy * side + dx);
                window_[slot] += v * py.weight[qy] * px.weight[qx];
                touched_[slot] = 1;
              }
            }
          }
        }
      }
      row_entries_.clear();
      for (long dy = 0; dy < side; ++dy) {
        for (long dx = 0; dx < side; ++dx) {
          const auto slot = static_cast<std::size_t>(dy * side + dx);
          if (!touched_[slot]) continue;
          long jx = cx + dx - w, jy = cy + dy - w;
          if (periodic_) {
            jx = (jx + cnx) % cnx;
            jy = (jy + cny) % cny;
          }
          row_entries_.emplace_back(static_cast<int>(jy * cnx + jx), window_[slot]);
          window_[slot] = 0.0;
          touched_[slot] = 0;
        }
      }
      // A coarse node whose children are all fixed is fixed itself.
      if (row_entries_.empty()) row_entries_.emplace_back(static_cast<int>(row), 1.0);
      if (periodic_) std::sort(row_entries_.begin(), row_entries_.end());
      for (const auto& [column, value] : row_entries_) {
        c.column.push_back(column);
        c.value.push_back(value);
      }
    }
  }
  c.start[c.rows] = static_cast<int>(c.column.size());
}

bool FilmMultigrid::factorise(const CsrMatrix& matrix, std::string& message) {
  // The unknowns scaled by the diagonal (A D^-1, D = |diag A|), if asked.
  const auto n = static_cast<Eigen::Index>(matrix.rows);
  column_scale_.setOnes(n);
  for (std::size_t i = 0; i < matrix.rows && scale_columns_; ++i) {
    for (int e = matrix.start[i]; e < matrix.start[i + 1]; ++e) {
      if (matrix.column[e] == static_cast<int>(i) && matrix.value[e] != 0.0) {
        column_scale_[static_cast<Eigen::Index>(i)] = std::abs(matrix.value[e]);
      }
    }
  }
  CsrMatrix& scaled = levels_[0].own;
  scaled = matrix;
  for (std::size_t e = 0; e < scaled.value.size(); ++e) scaled.value[e] /= column_scale_[scaled.column[e]];
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
  const std::size_t lines = line_count(level);
  const std::size_t length = line_length(level);
  const std::size_t stride = banded_lu_stride(level.kl, level.ku);
  std::span<double> rhs(line_rhs_.data(), length);
  for (std::size_t k = 0; k < lines; ++k) {
    const std::size_t line = forward ? k : lines - 1 - k;
    for (std::size_t t = 0; t < length; ++t) {
      const std::size_t i = node(level, line, t);
      double sum = level.b[static_cast<Eigen::Index>(i)];
      for (int e = off.start[i]; e < off.start[i + 1]; ++e) sum -= off.value[e] * level.x[off.column[e]];
      rhs[t] = sum;
    }
    banded_lu_solve(std::span<const double>(level.band.data() + line * length * stride, length * stride),
                    std::span<const int>(level.pivots.data() + line * length, length), level.kl, level.ku, rhs);
    for (std::size_t t = 0; t < length; ++t) level.x[static_cast<Eigen::Index>(node(level, line, t))] = rhs[t];
  }
}

void FilmMultigrid::restrict_residual(const Level& fine, Level& coarse) const {
  const Axis& ax = fine.to_coarse_x;
  const Axis& ay = fine.to_coarse_y;
  for (std::size_t cy = 0; cy < coarse.ny; ++cy) {
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
  }
}

void FilmMultigrid::prolongate_add(const Level& coarse, Level& fine) const {
  const Axis& ax = fine.to_coarse_x;
  const Axis& ay = fine.to_coarse_y;
  for (std::size_t y = 0; y < fine.ny; ++y) {
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
  }
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
  // kMaxBand wide, pivots, four vectors (x, b, r, D); the coarse levels a
  // third of the fine nodes with Galerkin rows of up to 25 entries held
  // twice (the operator and its off-band part).
  const double band = 8.0 * static_cast<double>(banded_lu_stride(kMaxBand, kMaxBand)) + 4.0 + 4.0 * 8.0;
  const double fine = 2.0 * 12.0 * row_entries + band;
  const double coarse = (2.0 * 12.0 * 25.0 + band) / 3.0;
  return fine + coarse;
}

}  // namespace halfspace::lubrication::detail
