// The block-deflation coarse correction (block_deflation.hpp derives it): the
// kernel pair sums of b x b blocks, the coarse matrix A = Z^T K Z kept up to
// date as the contact set changes, and its projected CG solve.
#include "halfspace/solvers/block_deflation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <cmath>

#include "halfspace/error.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::solvers {
namespace {

// See BlockDeflation::covers.
constexpr std::size_t kMinBlocksPerAxis = 3;
// Larger blocks leave too few coarse unknowns to help, and their pair sums
// grow as b^4.
constexpr std::size_t kMaxBlock = 256;

// Neighbour index of offset (dy, dx) in {-1, 0, 1}^2.
constexpr std::size_t neighbour(int dy, int dx) {
  return static_cast<std::size_t>((dy + 1) * 3 + dx + 1);
}

std::size_t wrapped(std::size_t index, int offset, std::size_t count) {
  return (index + count + static_cast<std::size_t>(offset + static_cast<int>(count))) % count;
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double total = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) total += a[i] * b[i];
  return total;
}

}  // namespace

void BlockDeflationOptions::validate() const {
  if (block < 1 || block > kMaxBlock) {
    throw SolverOptionError("deflation.block", fmt::format("{}", block),
                            fmt::format("is invalid: allowed range is 1 to {} cells", kMaxBlock));
  }
  if (!(max_pair_terms > 0.0)) {
    throw SolverOptionError("deflation.max_pair_terms", fmt::format("{}", max_pair_terms),
                            "is invalid: must be positive");
  }
  if (!(coarse_tolerance > 0.0 && coarse_tolerance < 1.0)) {
    throw SolverOptionError("deflation.coarse_tolerance", fmt::format("{}", coarse_tolerance),
                            "is invalid: allowed range is (0, 1)");
  }
  if (coarse_max_iterations < 1) {
    throw SolverOptionError("deflation.coarse_max_iterations", fmt::format("{}", coarse_max_iterations),
                            "is invalid: must be at least 1");
  }
}

bool BlockDeflation::covers(const Grid& grid, std::size_t block) {
  return grid.dimension() == 2 && block > 0 && grid.nx() % block == 0 && grid.ny() % block == 0 &&
         grid.nx() >= kMinBlocksPerAxis * block && grid.ny() >= kMinBlocksPerAxis * block;
}

bool BlockDeflation::neighbour_block(std::size_t I, int dy, int dx, std::size_t& J) const {
  const std::size_t iy = I / blocks_x_;
  const std::size_t ix = I % blocks_x_;
  if (grid_.periodic()) {
    J = wrapped(iy, dy, blocks_y_) * blocks_x_ + wrapped(ix, dx, blocks_x_);
    return true;
  }
  const auto jy = static_cast<std::ptrdiff_t>(iy) + dy;
  const auto jx = static_cast<std::ptrdiff_t>(ix) + dx;
  if (jy < 0 || jx < 0 || jy >= static_cast<std::ptrdiff_t>(blocks_y_) ||
      jx >= static_cast<std::ptrdiff_t>(blocks_x_)) {
    return false;
  }
  J = static_cast<std::size_t>(jy) * blocks_x_ + static_cast<std::size_t>(jx);
  return true;
}

void BlockDeflation::require_covers(const Grid& grid, std::size_t block) {
  if (grid.dimension() != 2) {
    throw SolverOptionError("deflation.block", fmt::format("{}", block),
                            fmt::format("does not apply to the {} {}D grid: block deflation needs a 2D grid",
                                        to_string(grid.boundary()), grid.dimension()));
  }
  if (!covers(grid, block)) {
    throw SolverOptionError("deflation.block", fmt::format("{}", block),
                            fmt::format("is invalid for the {} grid: it must divide nx and ny and leave at least {} "
                                        "blocks per axis",
                                        grid.shape_string(), kMinBlocksPerAxis));
  }
}

BlockDeflation::BlockDeflation(const Grid& grid, BlockDeflationOptions options)
    : BlockDeflation(grid, options, 0, grid.ny(), linalg::serial_communicator()) {}

BlockDeflation::BlockDeflation(const Grid& grid, BlockDeflationOptions options, std::size_t first_row, std::size_t rows,
                               const linalg::Communicator& comm)
    : grid_(grid), options_(options), first_row_(first_row), rows_(rows), comm_(&comm) {
  options_.validate();
  // One process holds every row; several hold slabs.
  if (first_row_ + rows_ > grid_.ny() || (comm_->size() == 1 && (first_row_ != 0 || rows_ != grid_.ny()))) {
    throw InputError(fmt::format("block deflation: rows {} to {} of the {} grid do not suit {} process(es)", first_row_,
                                 first_row_ + rows_, grid_.shape_string(), comm_->size()));
  }
  require_covers(grid_, options_.block);
  const std::size_t b = options_.block;
  blocks_x_ = grid_.nx() / b;
  blocks_y_ = grid_.ny() / b;
  const std::size_t m = coarse_size();
  // Owned block rows: those whose first row is held here. Held: one more
  // each side, which also covers the block rows of this slab's own rows.
  owned_first_ = (first_row_ + b - 1) / b;
  owned_end_ = (first_row_ + rows_ + b - 1) / b;
  if (rows_ > 0) {
    auto low = static_cast<std::ptrdiff_t>(owned_first_) - 1;
    auto high = static_cast<std::ptrdiff_t>(owned_end_) + 1;
    const auto count = static_cast<std::ptrdiff_t>(blocks_y_);
    if (!grid_.periodic()) {
      low = std::max<std::ptrdiff_t>(low, 0);
      high = std::min(high, count);
    } else if (high - low >= count) {
      low = 0;
      high = count;
    }
    held_first_ = static_cast<std::size_t>((low + count) % count);
    held_block_rows_ = static_cast<std::size_t>(high - low);
  }
  const std::size_t held_cells = held_block_rows_ * b * grid_.nx();
  if (comm_->size() > 1) {
    local_set_.assign(local_size(), 0);
    fetched_.assign(held_cells, 0);
  }
  set_.assign(held_cells, 0);
  counts_.assign(m, 0.0);
  block_counts_.assign(m, 0.0);
  near_.assign(9 * m, 0.0);
  const std::size_t held_blocks = held_block_rows_ * blocks_x_;
  cell_start_.assign(held_blocks + 1, 0);
  previous_start_.assign(held_blocks + 1, 0);
  changed_start_.assign(held_blocks + 1, 0);
  // A free grid's far field is a linear convolution: zero-padded to twice
  // the blocks per axis.
  const std::size_t pad = grid_.periodic() ? 1 : 2;
  coarse_fft_ = std::make_unique<RealFft>(pad * blocks_y_, pad * blocks_x_, FftPlanning::estimate);
  for (auto* v : {&rhs_, &y_, &first_, &inverse_diagonal_, &residual_, &direction_, &image_, &scaled_})
    v->assign(m, 0.0);
}

BlockDeflation::~BlockDeflation() = default;

void BlockDeflation::set_kernel(std::span<const double> unit_response) {
  set_kernel_from(unit_response);
}

void BlockDeflation::set_kernel(std::span<const float> unit_response) {
  set_kernel_from(unit_response);
}

template <class T>
void BlockDeflation::set_kernel_from(std::span<const T> local_response) {
  assert(local_response.size() == local_size());
  // k at offset (dy, dx) cells: read from K e_0 across the period on a
  // periodic grid; on a free one K e_0 holds the offsets >= 0 and k is even
  // in each (Love's rectangle coefficients). On several processes each reads
  // the rows it holds and 0 elsewhere; the near field and the block-centre
  // offsets are then summed over the processes, which is exact (every entry
  // comes from one process), so no process holds the whole K e_0.
  const std::size_t nx = grid_.nx();
  const std::size_t ny = grid_.ny();
  const bool periodic = grid_.periodic();
  const bool distributed = comm_->size() > 1;
  auto kernel = [&](std::ptrdiff_t dy, std::ptrdiff_t dx) {
    const std::size_t row = periodic ? wrapped(0, static_cast<int>(dy), ny) : static_cast<std::size_t>(std::abs(dy));
    const std::size_t column = periodic ? wrapped(0, static_cast<int>(dx), nx) : static_cast<std::size_t>(std::abs(dx));
    if (row < first_row_ || row >= first_row_ + rows_) return 0.0;
    return static_cast<double>(local_response[(row - first_row_) * nx + column]);
  };
  const auto b = static_cast<std::ptrdiff_t>(options_.block);
  const std::ptrdiff_t reach = 2 * b - 1;
  const auto side = static_cast<std::size_t>(2 * reach + 1);
  near_kernel_.assign(side * side, 0.0);
  for (std::ptrdiff_t dy = -reach; dy <= reach; ++dy) {
    for (std::ptrdiff_t dx = -reach; dx <= reach; ++dx) {
      near_kernel_[static_cast<std::size_t>(dy + reach) * side + static_cast<std::size_t>(dx + reach)] = kernel(dy, dx);
    }
  }
  if (distributed) comm_->sum(near_kernel_);
  // Point loads between block centres beyond the neighbours, at the coarse
  // offsets (jy, jx) of the (padded) coarse grid; the coarse transform is
  // unnormalised, so 1/size goes into the symbol.
  const std::size_t rows = coarse_fft_->rows();
  const std::size_t cols = coarse_fft_->cols();
  auto signed_offset = [](std::size_t j, std::size_t count) {
    return j <= count / 2 ? static_cast<std::ptrdiff_t>(j)
                          : static_cast<std::ptrdiff_t>(j) - static_cast<std::ptrdiff_t>(count);
  };
  std::vector<double> far(rows * cols);
  for (std::size_t jy = 0; jy < rows; ++jy) {
    for (std::size_t jx = 0; jx < cols; ++jx) {
      const std::ptrdiff_t sy = signed_offset(jy, rows);
      const std::ptrdiff_t sx = signed_offset(jx, cols);
      const bool near = std::abs(sy) <= 1 && std::abs(sx) <= 1;
      // Padding: offsets of a whole grid or more do not occur.
      const bool reachable = periodic || (std::abs(sy) < static_cast<std::ptrdiff_t>(blocks_y_) &&
                                          std::abs(sx) < static_cast<std::ptrdiff_t>(blocks_x_));
      far[jy * cols + jx] = near || !reachable ? 0.0 : kernel(sy * b, sx * b);
    }
  }
  if (distributed) comm_->sum(far);
  std::copy(far.begin(), far.end(), coarse_fft_->input().begin());
  coarse_fft_->forward();
  const std::span<const std::complex<double>> spectrum = coarse_fft_->spectrum();
  const double scale = 1.0 / static_cast<double>(rows * cols);
  far_symbol_.resize(spectrum.size());
  for (std::size_t k = 0; k < spectrum.size(); ++k) far_symbol_[k] = spectrum[k] * scale;
  // apply_coarse writes the blocks only: a free grid's padding stays zero.
  std::fill(coarse_fft_->input().begin(), coarse_fft_->input().end(), 0.0);
}

void BlockDeflation::list_cells() {
  const std::size_t b = options_.block;
  const std::size_t nx = grid_.nx();
  const std::size_t held = held_block_rows_ * blocks_x_;
  const auto side = static_cast<std::uint32_t>(4 * b - 1);
  std::swap(cells_, previous_cells_);
  std::swap(cell_start_, previous_start_);
  cell_start_.resize(held + 1);
  changed_start_.resize(held + 1);
  // Count, then fill: each held block's cells in row-major order.
  linalg::for_each_row(held_block_rows_, b * nx, [&](std::size_t slot) {
    for (std::size_t bx = 0; bx < blocks_x_; ++bx) {
      std::size_t in_set = 0;
      std::size_t changed = 0;
      for (std::size_t r = 0; r < b; ++r) {
        const std::uint8_t* cell = set_.data() + (slot * b + r) * nx + bx * b;
        for (std::size_t c = 0; c < b; ++c) {
          in_set += cell[c] & 1U;
          changed += (cell[c] & 1U) != (cell[c] >> 1) ? 1 : 0;
        }
      }
      cell_start_[slot * blocks_x_ + bx + 1] = in_set;
      changed_start_[slot * blocks_x_ + bx + 1] = changed;
    }
  });
  cell_start_[0] = 0;
  changed_start_[0] = 0;
  for (std::size_t k = 0; k < held; ++k) {
    cell_start_[k + 1] += cell_start_[k];
    changed_start_[k + 1] += changed_start_[k];
  }
  cells_.resize(cell_start_[held]);
  changed_cells_.resize(changed_start_[held]);
  linalg::for_each_row(held_block_rows_, b * nx, [&](std::size_t slot) {
    const std::size_t by = (held_first_ + slot) % blocks_y_;
    for (std::size_t bx = 0; bx < blocks_x_; ++bx) {
      const std::size_t block = slot * blocks_x_ + bx;
      std::size_t next = cell_start_[block];
      std::size_t next_changed = changed_start_[block];
      for (std::size_t r = 0; r < b; ++r) {
        const std::size_t begin = (slot * b + r) * nx + bx * b;
        std::uint8_t* cell = set_.data() + begin;
        for (std::size_t c = 0; c < b; ++c) {
          const std::uint8_t now = cell[c] & 1U;
          const auto offset = static_cast<std::uint32_t>(r * side + c);
          if (now) cells_[next++] = ListedCell{offset, 1.0F};
          if (now != (cell[c] >> 1)) changed_cells_[next_changed++] = ListedCell{offset, now ? 1.0F : -1.0F};
          cell[c] = static_cast<std::uint8_t>((now << 1) | now);
        }
      }
      counts_[by * blocks_x_ + bx] = static_cast<double>(cell_start_[block + 1] - cell_start_[block]);
    }
  });
  share_owned(counts_, 1);
}

std::array<double, 2> BlockDeflation::share_set() {
  // The held rows in at most two runs of grid rows: up to the period, then
  // on from row 0.
  const std::size_t b = options_.block;
  const std::size_t nx = grid_.nx();
  const std::size_t first_run = std::min(held_block_rows_, blocks_y_ - held_first_);
  const std::span<const std::byte> mine = std::as_bytes(std::span<const std::uint8_t>(local_set_));
  const std::span<std::byte> fetched = std::as_writable_bytes(std::span<std::uint8_t>(fetched_));
  comm_->fetch_rows(mine, first_row_, held_first_ * b, fetched.first(first_run * b * nx), nx);
  comm_->fetch_rows(mine, first_row_, 0, fetched.subspan(first_run * b * nx), nx);
  linalg::for_each_index(set_.size(),
                         [&](std::size_t i) { set_[i] = static_cast<std::uint8_t>((set_[i] & 2U) | fetched_[i]); });
  // Changed and set cells counted on this process's rows only.
  const std::size_t base = rows_ > 0 ? held_row(first_row_) * nx : 0;
  std::array<double, 2> totals = linalg::sums<2>(local_size(), [&](std::size_t i) {
    const std::uint8_t cell = set_[base + i];
    return std::array<double, 2>{(cell & 1U) != (cell >> 1) ? 1.0 : 0.0, static_cast<double>(cell & 1U)};
  });
  comm_->sum(totals);
  return totals;
}

void BlockDeflation::share_owned(std::vector<double>& values, std::size_t per_block) {
  if (comm_->size() == 1) return;
  const std::size_t row = blocks_x_ * per_block;
  owned_.assign(values.begin() + static_cast<std::ptrdiff_t>(owned_first_ * row),
                values.begin() + static_cast<std::ptrdiff_t>(owned_end_ * row));
  comm_->concatenate(std::as_bytes(std::span<const double>(owned_)), std::as_writable_bytes(std::span<double>(values)),
                     row * sizeof(double));
}

double BlockDeflation::pair_sum(const ListedCell* first, const ListedCell* first_end, const ListedCell* second,
                                const ListedCell* second_end, int dy, int dx) const {
  // x_a - x_c = local_a - local_c - b (dy, dx): from the table entry of
  // local_a - b (dy, dx), step back by each local_c.
  const auto b = static_cast<std::ptrdiff_t>(options_.block);
  const std::ptrdiff_t reach = 2 * b - 1;
  const std::ptrdiff_t side = 2 * reach + 1;
  const double* centre = near_kernel_.data() + (reach - dy * b) * side + (reach - dx * b);
  double total = 0.0;
  for (const ListedCell* a = first; a != first_end; ++a) {
    const double* origin = centre + a->offset;
    double row = 0.0;
    for (const ListedCell* c = second; c != second_end; ++c) {
      row += static_cast<double>(c->sign) * origin[-static_cast<std::ptrdiff_t>(c->offset)];
    }
    total += static_cast<double>(a->sign) * row;
  }
  return total;
}

bool BlockDeflation::too_many_pair_terms(const std::vector<double>& counts) const {
  double terms = 0.0;
  for (std::size_t I = 0; I < coarse_size(); ++I) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        std::size_t J = 0;
        if (neighbour_block(I, dy, dx, J)) terms += counts[I] * counts[J];
      }
    }
  }
  return terms > options_.max_pair_terms * static_cast<double>(grid_.size());
}

// Full: A_IJ = sum over S_I x S_J of k. Update, with chi' = chi + delta the
// new set's indicator: A'_IJ - A_IJ = sum delta_a chi'_c k + sum chi_a
// delta_c k, i.e. the changed cells of I (with the sign of the change)
// against J's new cells and I's old cells against J's changed cells. k is
// even, so A (and each update) is symmetric: only the neighbours (dy, dx)
// from (0, 0) on are summed, and A_JI is copied from A_IJ (half the pair
// sums; A exactly symmetric).
void BlockDeflation::refresh(bool full) {
  if (near_kernel_.empty()) throw std::logic_error("BlockDeflation::update before set_kernel");
  full = full || !built_;
  list_cells();
  if (full && too_many_pair_terms(counts_)) {
    built_ = false;
    ++stats_.declined;
    return;
  }
  const ListedCell* cells = cells_.data();
  const ListedCell* previous = previous_cells_.data();
  const ListedCell* changes = changed_cells_.data();
  // This process's blocks: those of the block rows it owns.
  const auto first_block = static_cast<std::ptrdiff_t>(owned_first_ * blocks_x_);
  const auto end_block = static_cast<std::ptrdiff_t>(owned_end_ * blocks_x_);
  auto held_block = [this](std::size_t block) { return held_slot(block / blocks_x_) * blocks_x_ + block % blocks_x_; };
#pragma omp parallel for schedule(dynamic, 16)
  for (std::ptrdiff_t index = first_block; index < end_block; ++index) {
    const auto I = static_cast<std::size_t>(index);
    const std::size_t i = held_block(I);
    for (int dy = 0; dy <= 1; ++dy) {
      for (int dx = dy == 0 ? 0 : -1; dx <= 1; ++dx) {
        std::size_t J = 0;
        if (!neighbour_block(I, dy, dx, J)) continue;  // beyond a free grid's edge: the entry stays zero
        const std::size_t j = held_block(J);
        double& entry = near_[I * 9 + neighbour(dy, dx)];
        const ListedCell* j_begin = cells + cell_start_[j];
        const ListedCell* j_end = cells + cell_start_[j + 1];
        if (full) {
          entry = pair_sum(cells + cell_start_[i], cells + cell_start_[i + 1], j_begin, j_end, dy, dx);
          continue;
        }
        const double delta =
            pair_sum(changes + changed_start_[i], changes + changed_start_[i + 1], j_begin, j_end, dy, dx) +
            pair_sum(previous + previous_start_[i], previous + previous_start_[i + 1], changes + changed_start_[j],
                     changes + changed_start_[j + 1], dy, dx);
        // An emptied block's entries are exactly zero, not the rounding
        // left by subtracting its sums.
        entry = counts_[I] > 0.0 && counts_[J] > 0.0 ? entry + delta : 0.0;
      }
    }
  }
  // The owners' entries are copied, not summed: the same bits as one process.
  share_owned(near_, 9);
  mirror_near();
  built_ = true;
  ++(full ? stats_.rebuilds : stats_.updates);
}

void BlockDeflation::mirror_near() {
  for (std::size_t I = 0; I < coarse_size(); ++I) {
    for (int dy = -1; dy <= 0; ++dy) {
      for (int dx = -1; dx <= (dy == 0 ? -1 : 1); ++dx) {
        std::size_t J = 0;
        if (neighbour_block(I, dy, dx, J)) near_[I * 9 + neighbour(dy, dx)] = near_[J * 9 + neighbour(-dy, -dx)];
      }
    }
  }
}

void BlockDeflation::apply_coarse(std::span<const double> y, std::span<double> out) {
  const std::size_t cols = coarse_fft_->cols();
  std::span<double> far = coarse_fft_->input();
  for (std::size_t iy = 0; iy < blocks_y_; ++iy) {
    for (std::size_t ix = 0; ix < blocks_x_; ++ix) {
      const std::size_t I = iy * blocks_x_ + ix;
      far[iy * cols + ix] = counts_[I] * y[I];
    }
  }
  coarse_fft_->forward();
  std::span<std::complex<double>> spectrum = coarse_fft_->spectrum();
  for (std::size_t k = 0; k < spectrum.size(); ++k) spectrum[k] *= far_symbol_[k];
  coarse_fft_->backward();
  const std::span<const double> response = coarse_fft_->output();
  for (std::size_t iy = 0; iy < blocks_y_; ++iy) {
    for (std::size_t ix = 0; ix < blocks_x_; ++ix) {
      const std::size_t I = iy * blocks_x_ + ix;
      double total = counts_[I] * response[iy * cols + ix];
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          std::size_t J = 0;
          if (neighbour_block(I, dy, dx, J)) total += near_[I * 9 + neighbour(dy, dx)] * y[J];
        }
      }
      out[I] = total;
    }
  }
}

// Jacobi-preconditioned CG on A y = rhs_ over the blocks with cells (the
// others keep y = 0: their rows and columns of A vanish). With a fixed load,
// projected CG on n^T y = 0 (n the blocks' cell counts): the coarse
// correction moves no load, and a multiplier absorbs the rhs along n, as
// the approach does on the fine grid. Without the constraint A's softest
// mode, a uniform pressure on the set (on a periodic grid K has no mean
// response), would take any rhs along it and amplify it.
void BlockDeflation::solve_coarse(bool fixed_load) {
  const std::size_t m = coarse_size();
  for (std::size_t k = 0; k < m; ++k) {
    const double diagonal = near_[k * 9 + neighbour(0, 0)];
    inverse_diagonal_[k] = counts_[k] > 0.0 && diagonal > 0.0 ? 1.0 / diagonal : 0.0;
  }
  double counts_norm = 0.0;  // n^T D^-1 n
  if (fixed_load) {
    for (std::size_t k = 0; k < m; ++k) counts_norm += counts_[k] * inverse_diagonal_[k] * counts_[k];
  }
  // Under a fixed load the residual less its part along n, r - lambda n
  // with n^T D^-1 (r - lambda n) = 0 (the multiplier), so that z = D^-1 r
  // moves no load. Taking it out of the residual itself, not only out of z,
  // keeps the residual as small as the iteration has made it: otherwise its
  // part along n stays and the rounding of each projection grows against
  // the shrinking rest (Gould, Hribar & Nocedal 2001).
  auto precondition = [&](std::vector<double>& r, std::vector<double>& out) {
    if (counts_norm > 0.0) {
      double along = 0.0;
      for (std::size_t k = 0; k < m; ++k) along += counts_[k] * inverse_diagonal_[k] * r[k];
      const double multiplier = along / counts_norm;
      for (std::size_t k = 0; k < m; ++k) r[k] -= multiplier * counts_[k];
    }
    for (std::size_t k = 0; k < m; ++k) out[k] = inverse_diagonal_[k] * r[k];
  };
  std::fill(y_.begin(), y_.end(), 0.0);
  for (std::size_t k = 0; k < m; ++k) rhs_[k] = counts_[k] > 0.0 ? rhs_[k] : 0.0;
  residual_ = rhs_;
  precondition(residual_, direction_);
  double rz = dot(residual_, direction_);
  // The preconditioned residual norm r^T z, which ignores the part along n.
  const double target = options_.coarse_tolerance * options_.coarse_tolerance * rz;
  for (int iteration = 0;; ++iteration) {
    if (rz <= target) return;
    if (iteration == options_.coarse_max_iterations) break;
    apply_coarse(direction_, image_);
    const double curvature = dot(direction_, image_);
    if (!(curvature > 0.0)) break;
    const double alpha = rz / curvature;
    for (std::size_t k = 0; k < m; ++k) {
      y_[k] += alpha * direction_[k];
      residual_[k] -= alpha * image_[k];
    }
    ++stats_.coarse_iterations;
    precondition(residual_, scaled_);
    const double rz_next = dot(residual_, scaled_);
    const double beta = rz_next / rz;
    rz = rz_next;
    for (std::size_t k = 0; k < m; ++k) direction_[k] = scaled_[k] + beta * direction_[k];
  }
  ++stats_.unconverged_coarse_solves;
}

template <class T>
void BlockDeflation::restrict_to_blocks(std::span<const T> field) {
  const std::size_t b = options_.block;
  const std::size_t nx = grid_.nx();
  // This process's rows of each block (a block may straddle two processes).
  const std::size_t end_row = first_row_ + rows_;
  linalg::for_each_row(blocks_y_, b * nx, [&](std::size_t by) {
    const std::size_t first = std::max(by * b, first_row_);
    const std::size_t last = std::min((by + 1) * b, end_row);
    for (std::size_t bx = 0; bx < blocks_x_; ++bx) {
      double total = 0.0;
      for (std::size_t row = first; row < last; ++row) {
        const std::uint8_t* set = set_.data() + held_row(row) * nx + bx * b;
        const T* values = field.data() + (row - first_row_) * nx + bx * b;
        for (std::size_t c = 0; c < b; ++c) total += (set[c] & 1U) ? static_cast<double>(values[c]) : 0.0;
      }
      rhs_[by * blocks_x_ + bx] = total;
    }
  });
  comm_->sum(rhs_);
}

template <class T>
void BlockDeflation::prolong(const std::vector<double>& y, std::span<T> z, bool add) const {
  const std::size_t b = options_.block;
  const std::size_t nx = grid_.nx();
  linalg::for_each_row(rows_, nx, [&](std::size_t local_row) {
    const std::size_t row = first_row_ + local_row;
    const std::size_t by = row / b;
    for (std::size_t bx = 0; bx < blocks_x_; ++bx) {
      const double value = y[by * blocks_x_ + bx];
      const std::uint8_t* set = set_.data() + held_row(row) * nx + bx * b;
      T* values = z.data() + local_row * nx + bx * b;
      if (add) {
        for (std::size_t c = 0; c < b; ++c) values[c] = static_cast<T>(values[c] + ((set[c] & 1U) ? value : 0.0));
      } else {
        for (std::size_t c = 0; c < b; ++c) values[c] = static_cast<T>((set[c] & 1U) ? value : 0.0);
      }
    }
  });
}

template <class T>
void BlockDeflation::pre_correction_of(std::span<const T> g, std::span<T> field, bool fixed_load) {
  restrict_to_blocks(g);
  solve_coarse(fixed_load);
  first_ = y_;
  prolong(first_, field, false);
}

template <class T>
void BlockDeflation::post_correction_of(std::span<const T> image, std::span<T> z, bool fixed_load) {
  restrict_to_blocks(image);
  solve_coarse(fixed_load);
  for (std::size_t k = 0; k < coarse_size(); ++k) y_[k] = first_[k] - y_[k];
  prolong(y_, z, true);
}

void BlockDeflation::pre_correction(std::span<const double> g, std::span<double> field, bool fixed_load) {
  pre_correction_of(g, field, fixed_load);
}

void BlockDeflation::post_correction(std::span<const double> image, std::span<double> z, bool fixed_load) {
  post_correction_of(image, z, fixed_load);
}

void BlockDeflation::pre_correction(std::span<const float> g, std::span<float> field, bool fixed_load) {
  pre_correction_of(g, field, fixed_load);
}

void BlockDeflation::post_correction(std::span<const float> image, std::span<float> z, bool fixed_load) {
  post_correction_of(image, z, fixed_load);
}

}  // namespace halfspace::solvers
