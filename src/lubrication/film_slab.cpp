// A film's slab of rows with its halo (film_slab.hpp).
#include "film_slab.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include "halfspace/error.hpp"

namespace halfspace::lubrication::detail {

FilmSlab::FilmSlab(const Grid& whole, const FlowConditions& conditions, std::size_t own_nodes,
                   const linalg::Communicator& comm, std::size_t halo)
    : whole_(whole),
      comm_(comm),
      own_nodes_(own_nodes),
      stencil_grid_(whole),
      own_grid_(whole),
      stencil_conditions_(conditions) {
  if (comm.size() == 1) {
    own_rows_ = whole.dimension() == 1 ? 1 : whole.ny();
    return;
  }
  // Agreed on every process before anything collective that needs rows.
  const bool spread_1d = whole.dimension() != 2;
  if (comm.max(spread_1d ? 1.0 : 0.0) > 0.5) {
    throw InputError(fmt::format("the film on several processes needs a 2D grid, not {}", whole.shape_string()));
  }
  const std::size_t nx = whole.nx();
  own_rows_ = own_nodes / nx;
  const double fewest = comm.min(static_cast<double>(own_rows_));
  // Each process's rows are a grid of their own (own_grid_: at least 2
  // rows) and reach the stencil's halo.
  const auto needed = std::max<std::size_t>(halo, 2);
  if (fewest < static_cast<double>(needed)) {
    throw InputError(fmt::format(
        "the {} film on {} processes leaves a process with {} row{}: each needs at least {} (a grid of its own rows, "
        "as deep as the Reynolds stencil reaches); use fewer processes",
        whole.shape_string(), comm.size(), fewest, fewest == 1.0 ? "" : "s", needed));
  }
  first_row_ = linalg::first_row_held(comm, own_rows_);
  const bool periodic = conditions.boundary.y == AxisBoundary::periodic;
  periodic_y_ = periodic;
  low_halo_ = first_row_ > 0 || periodic ? halo : 0;
  high_halo_ = first_row_ + own_rows_ < whole.ny() || periodic ? halo : 0;
  own_first_ = low_halo_ * nx;
  stencil_grid_ = Grid::plane(nx, own_rows_ + low_halo_ + high_halo_, whole.dx(), whole.dy(), whole.boundary());
  own_grid_ = Grid::plane(nx, own_rows_, whole.dx(), whole.dy(), whole.boundary());
  stencil_conditions_.boundary.y = AxisBoundary::fixed_pressure;
}

std::size_t FilmSlab::whole_node(std::size_t stencil_node) const {
  if (!distributed()) return stencil_node;
  const std::size_t nx = whole_.nx();
  const std::size_t ny = whole_.ny();
  const std::size_t row = (first_row_ + ny - low_halo_ + stencil_node / nx) % ny;
  return row * nx + stencil_node % nx;
}

std::size_t FilmSlab::stencil_node(std::size_t whole_node) const {
  if (!distributed()) return whole_node;
  const std::size_t nx = whole_.nx();
  const std::size_t ny = whole_.ny();
  const std::size_t row = (whole_node / nx + ny + low_halo_ - first_row_) % ny;
  return row < stencil_grid_.ny() ? row * nx + whole_node % nx : kOutside;
}

void FilmSlab::fetch(const double* field, std::size_t whole_first, std::size_t rows, double* into) const {
  const std::size_t nx = whole_.nx();
  const std::span<const double> mine(field + own_first_, own_nodes_);
  comm_.fetch_rows(std::as_bytes(mine), first_row_, whole_first, std::as_writable_bytes(std::span(into, rows * nx)),
                   nx * sizeof(double));
}

void FilmSlab::exchange(double* field) const {
  if (!distributed()) return;
  const std::size_t ny = whole_.ny();
  // Each halo is one range of whole rows (every process holds at least
  // `halo` rows): below, the rows before this process's (wrapped on a
  // periodic film); above, those after.
  fetch(field, (first_row_ + ny - low_halo_) % ny, low_halo_, field);
  fetch(field, (first_row_ + own_rows_) % ny, high_halo_, field + own_first_ + own_nodes_);
}

void FilmSlab::fetch_wrapping(const double* own, std::size_t first, std::size_t rows, std::size_t width,
                              double* into) const {
  const std::size_t ny = whole_.ny();
  const std::size_t unit = whole_.nx() * width;
  const std::size_t head = std::min(rows, ny - first);  // up to the last row, then from row 0
  const auto mine = std::as_bytes(std::span(own, own_rows_ * unit));
  comm_.fetch_rows(mine, first_row_, first, std::as_writable_bytes(std::span(into, head * unit)),
                   unit * sizeof(double));
  comm_.fetch_rows(mine, first_row_, 0, std::as_writable_bytes(std::span(into + head * unit, (rows - head) * unit)),
                   unit * sizeof(double));
}

std::pair<std::size_t, std::size_t> FilmSlab::rows_around_limits(std::size_t wanted) const {
  if (!distributed()) return {0, 0};
  const std::size_t ny = whole_.ny();
  if (!periodic_y_) return {std::min(wanted, first_row_), std::min(wanted, ny - first_row_ - own_rows_)};
  const std::size_t others = ny - own_rows_;
  const std::size_t below = std::min(wanted, others / 2);
  return {below, std::min(wanted, others - below)};
}

const double* FilmSlab::on_stencil(Eigen::Ref<const Eigen::VectorXd> own, Eigen::VectorXd& stencil) const {
  if (!distributed()) return own.data();
  stencil.segment(static_cast<Eigen::Index>(own_first_), static_cast<Eigen::Index>(own_nodes_)) = own;
  exchange(stencil.data());
  return stencil.data();
}

void FilmSlab::rows_around(const double* own, std::size_t below, std::size_t above, std::size_t width,
                           double* around) const {
  const std::size_t ny = whole_.ny();
  const std::size_t unit = whole_.nx() * width;
  std::copy(own, own + own_rows_ * unit, around + below * unit);
  if (!distributed()) return;
  fetch_wrapping(own, (first_row_ + ny - below) % ny, below, width, around);
  fetch_wrapping(own, (first_row_ + own_rows_) % ny, above, width, around + (below + own_rows_) * unit);
}

void FilmSlab::gather_rows(const CsrMatrix& own, std::size_t below, std::size_t above, CsrMatrix& block,
                           RowScratch& scratch) const {
  // This process's rows packed to the widest row of any process (column,
  // value; column -1 past a row's end), then the block's rows fetched from
  // their owners in the same form.
  const std::size_t nx = whole_.nx();
  const std::size_t ny = whole_.ny();
  std::size_t widest = 0;
  for (std::size_t k = 0; k < own_nodes_; ++k) {
    widest = std::max(widest, static_cast<std::size_t>(own.start[k + 1] - own.start[k]));
  }
  const auto width = static_cast<std::size_t>(max(static_cast<double>(widest)));
  scratch.packed_own.assign(own_nodes_ * 2 * width, -1.0);
  for (std::size_t k = 0; k < own_nodes_; ++k) {
    for (auto e = static_cast<std::size_t>(own.start[k]); e < static_cast<std::size_t>(own.start[k + 1]); ++e) {
      const std::size_t slot = k * 2 * width + 2 * (e - static_cast<std::size_t>(own.start[k]));
      scratch.packed_own[slot] = own.column[e];
      scratch.packed_own[slot + 1] = own.value[e];
    }
  }
  const std::size_t block_rows = own_rows_ + below + above;
  const std::size_t block_nodes = block_rows * nx;
  scratch.packed_block.resize(block_nodes * 2 * width);
  rows_around(scratch.packed_own.data(), below, above, 2 * width, scratch.packed_block.data());
  // A whole-grid node's column in the block: its row counted from the
  // block's first row, if it lies in the block.
  const std::size_t block_first = whole_row_around(0, below);
  block.clear();
  for (std::size_t k = 0; k < block_nodes; ++k) {
    for (std::size_t e = 0; e < width; ++e) {
      const double column = scratch.packed_block[k * 2 * width + 2 * e];
      if (column < 0.0) break;
      const auto node = static_cast<std::size_t>(column);
      const std::size_t row = (node / nx + ny - block_first) % ny;
      if (row >= block_rows) continue;
      scratch.row.emplace_back(static_cast<int>(row * nx + node % nx), scratch.packed_block[k * 2 * width + 2 * e + 1]);
    }
    block.append_row(scratch.row);
  }
}

Eigen::Index FilmSlab::centre_node(const Eigen::ArrayXd& gap) const {
  Eigen::Index centre = 0;
  const bool any = gap.size() > 0;
  const double smallest = min(any ? gap.minCoeff(&centre) : INFINITY);
  const bool holds = any && gap[centre] == smallest;
  const auto node = static_cast<double>(whole_node(own_first_ + static_cast<std::size_t>(centre)));
  const double first = min(holds ? node : INFINITY);
  return holds && node == first ? centre : -1;
}

double FilmSlab::sum(double local) const {
  comm_.sum(std::span(&local, 1));
  return local;
}

double FilmSlab::dot(Eigen::Ref<const Eigen::VectorXd> a, Eigen::Ref<const Eigen::VectorXd> b,
                     Eigen::Index replicated) const {
  if (!distributed()) return a.dot(b);
  const Eigen::Index own = a.size() - replicated;
  return sum(a.head(own).dot(b.head(own))) + a.tail(replicated).dot(b.tail(replicated));
}

double FilmSlab::norm(Eigen::Ref<const Eigen::VectorXd> v, Eigen::Index replicated) const {
  if (!distributed()) return v.norm();
  return std::sqrt(dot(v, v, replicated));
}

void agree_on_input(const linalg::Communicator& comm, const std::function<void()>& check) {
  if (comm.size() <= 1) return check();
  std::string message;
  try {
    check();
  } catch (const InputError& error) {
    message = error.what();
  }
  if (comm.min(message.empty() ? 1.0 : 0.0) > 0.5) return;
  if (!message.empty()) throw InputError(message);
  throw InputError("another process's share of the film does not fit (its message is that process's)");
}

void FilmSlabRows::complete(Eigen::ArrayXd& pressure, Eigen::ArrayXd& fluid_fraction) {
  slab_.exchange(pressure.data());
  slab_.exchange(fluid_fraction.data());
}

Eigen::ArrayXd FilmSlabRows::stencil_field(std::span<const double> rows) const {
  Eigen::ArrayXd field = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(slab_.stencil_nodes()));
  std::copy(rows.begin(), rows.end(), field.data() + slab_.own_first());
  slab_.exchange(field.data());
  return field;
}

bool FilmSlabRows::fixed_in_whole(std::size_t) const {
  throw std::logic_error("FilmSlabRows does not know the whole film's fixed nodes");
}

KrylovDistribution FilmSlab::krylov_distribution() const {
  if (!distributed()) return {};
  return {.sum = [this](double local) { return sum(local); }, .all = [this](bool local) { return all(local); }};
}

}  // namespace halfspace::lubrication::detail
