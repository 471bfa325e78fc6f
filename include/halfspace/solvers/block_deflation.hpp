// A coarse-grid correction for preconditioned Polonsky-Keer on 2D grids,
// periodic or free: deflation by b x b blocks of the contact cells.
//
// On a large rough contact the Fourier preconditioner M^-1 overestimates the
// response to smooth pressure modulations spread across many small spots, so
// the condition number on the contact set grows with the domain
// (docs/development-log.md, "Why a growing domain costs more"). The coarse space
// Z, one column per block holding 1 on the block's cells in the coarse set
// (the solver passes the contact cells), captures those modulations. With
// the Galerkin matrix A = Z^T K Z and Q = Z A^-1 Z^T, the balancing
// preconditioner (Mandel 1993; Tang, Nabben, Vuik & Erlangga 2009)
//
//   B r = Q r + (I - Q K) M^-1 (I - K Q) r
//
// is symmetric positive definite; pre_correction and post_correction are
// its two halves around M^-1 (two more products K per application). A is
// assembled from the kernel in real space: exactly between each block and
// its eight neighbours (sums over cell pairs), and as point loads between
// block centres, n_I n_J k(c_I - c_J), beyond them, which the coarse grid
// applies by FFT. When the set changes, the pair sums are updated from the
// changed cells alone (a stale A costs many iterations), or rebuilt when most
// of the set changed. A is solved by Jacobi-preconditioned CG, under a fixed
// load projected onto corrections that move no load (docs/theory.md, "Block
// deflation").
#pragma once

#include <algorithm>
#include <array>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "halfspace/fft/real_fft.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/solvers/block_deflation_options.hpp"

namespace halfspace::solvers {

// Counters of the coarse work, for reports and benchmarks.
struct BlockDeflationStats {
  int rebuilds = 0;                   // A assembled from all pair sums
  int declined = 0;                   // full builds not made: too many pair terms
  int updates = 0;                    // A updated by the changed cells
  long coarse_iterations = 0;         // CG iterations of all coarse solves
  int unconverged_coarse_solves = 0;  // stopped at coarse_max_iterations
};

class BlockDeflation {
 public:
  // Whether blocks of `block` cells cover `grid`: 2D, periodic or free, the
  // block dividing nx and ny and leaving at least 3 blocks per axis (fewer,
  // and on a periodic grid the 3 x 3 neighbourhood would meet itself across
  // the period).
  static bool covers(const Grid& grid, std::size_t block);
  // Throws InputError (SolverOptionError for the block) unless covers(grid, block).
  static void require_covers(const Grid& grid, std::size_t block);
  // Throws InputError unless covers(grid, options.block).
  BlockDeflation(const Grid& grid, BlockDeflationOptions options = {});
  // On a grid spread over the processes of `comm` in slabs of rows (which
  // must outlive this object): the fields given to and returned by the
  // correction, and the set, hold this process's `rows` rows from
  // `first_row` on. Each process keeps the set and its cells only on the
  // block rows whose first row it holds and one block row each side (the
  // neighbours of the near field), computes those blocks' coarse entries,
  // and shares them; every process then solves the (small) coarse problem
  // redundantly, its right-hand sides summed over the processes. Throws
  // InputError unless covers(grid, options.block).
  BlockDeflation(const Grid& grid, BlockDeflationOptions options, std::size_t first_row, std::size_t rows,
                 const linalg::Communicator& comm);
  ~BlockDeflation();

  const Grid& grid() const { return grid_; }
  std::size_t block() const { return options_.block; }
  // The cells held here (rows x nx), and whether cell 0 is among them.
  std::size_t local_size() const { return rows_ * grid_.nx(); }
  bool holds_first_cell() const { return first_row_ == 0 && rows_ > 0; }

  // The kernel in real space: `unit_response` = K e_0, the displacement of
  // every cell under unit pressure on cell 0 (this process's rows).
  // Collective; must be called before update(). In single precision (a
  // mixed-precision solve's float work vectors) its rounding, about 1e-7
  // of k(0), only perturbs the preconditioner: the coarse matrix is summed
  // in double either way.
  void set_kernel(std::span<const double> unit_response);
  void set_kernel(std::span<const float> unit_response);

  // Records the coarse set, in_set(i) for each cell, and brings A up to
  // date if the set changed since A was last (or A was never built): from
  // the changed cells' pair sums, or from all pairs when more than half of
  // the set changed. A full build whose pair
  // sums would exceed max_pair_terms per cell is not made: ready() is then
  // false (dense contacts, where the correction would cost more than it
  // saves), and the next update tries again.
  // Collective on several processes.
  template <class InSet>
  void update(InSet&& in_set) {
    if (comm_->size() > 1) {
      linalg::for_each_index(local_size(), [&](std::size_t i) { local_set_[i] = in_set(i) ? 1 : 0; });
      const auto [changed, size] = share_set();
      if (built_ && changed == 0.0) return;
      refresh(changed > 0.5 * size);
      return;
    }
    const auto [changed, size] = linalg::sums<2>(grid_.size(), [&](std::size_t i) {
      const std::uint8_t now = in_set(i) ? 1 : 0;
      const std::uint8_t built = set_[i] >> 1;
      set_[i] = static_cast<std::uint8_t>((built << 1) | now);
      return std::array<double, 2>{now != built ? 1.0 : 0.0, static_cast<double>(now)};
    });
    if (built_ && changed == 0.0) return;
    refresh(changed > 0.5 * size);
  }
  // Whether A is built for the last update's set.
  bool ready() const { return built_; }

  // Whether a full build of A for the set in_set(i) would be declined (see
  // update), counted as declined if so: one pass over the cells, no kernel
  // needed, so that a caller can skip making the kernel for a dense contact.
  // Collective on several processes.
  template <class InSet>
  bool decline_if_dense(InSet&& in_set) {
    const std::size_t b = options_.block;
    const std::size_t nx = grid_.nx();
    // Each process counts its rows of each block; the counts are whole
    // numbers, so their sum over the processes is exact.
    std::fill(block_counts_.begin(), block_counts_.end(), 0.0);
    const std::size_t end_row = first_row_ + rows_;
    linalg::for_each_row(blocks_y_, b * nx, [&](std::size_t by) {
      const std::size_t first = std::max(by * b, first_row_);
      const std::size_t last = std::min((by + 1) * b, end_row);
      for (std::size_t bx = 0; bx < blocks_x_; ++bx) {
        std::size_t in = 0;
        for (std::size_t row = first; row < last; ++row) {
          const std::size_t begin = (row - first_row_) * nx + bx * b;
          for (std::size_t i = begin; i < begin + b; ++i) in += in_set(i) ? 1 : 0;
        }
        block_counts_[by * blocks_x_ + bx] = static_cast<double>(in);
      }
    });
    comm_->sum(block_counts_);
    if (!too_many_pair_terms(block_counts_)) return false;
    ++stats_.declined;
    return true;
  }

  // The balancing form, z = Q r + (I - Q K) M^-1 (I - K Q) r with Q = Z A^-1
  // Z^T, in two halves around M^-1: pre_correction solves y1 = A^-1 Z^T r
  // and writes Z y1 into `field` (zero off the set), whose image K Z y1 the
  // caller subtracts from r before M^-1; post_correction, given K v of the
  // result v, solves y2 = A^-1 Z^T K v and adds Z (y1 - y2) to z = v.
  // Fields hold this process's rows; collective on several processes.
  // The float forms serve single-precision work vectors (mixed precision):
  // the fields are read and written in float, the block sums and the small
  // coarse solve stay double.
  void pre_correction(std::span<const double> r, std::span<double> field, bool fixed_load);
  void post_correction(std::span<const double> image, std::span<double> z, bool fixed_load);
  void pre_correction(std::span<const float> r, std::span<float> field, bool fixed_load);
  void post_correction(std::span<const float> image, std::span<float> z, bool fixed_load);

  const BlockDeflationStats& stats() const { return stats_; }

  // The coarse matrix applied to y (one entry per block, row-major blocks):
  // out = A y. Exposed for tests.
  void apply_coarse(std::span<const double> y, std::span<double> out);
  std::size_t coarse_size() const { return blocks_x_ * blocks_y_; }

 private:
  // On several processes: the set on the held rows from local_set_ (this
  // process's rows) and the processes holding the halo, into bit 0 of
  // set_; returns the changed cells and the set's size, summed over the
  // processes.
  std::array<double, 2> share_set();
  // The held slot of block row `by` (held_block_rows_ or more if not held), and the
  // held row of grid row `row`.
  std::size_t held_slot(std::size_t by) const { return (by + blocks_y_ - held_first_) % blocks_y_; }
  std::size_t held_row(std::size_t row) const {
    return held_slot(row / options_.block) * options_.block + row % options_.block;
  }
  // On several processes: every process's entries (`per_block` per block)
  // of the block rows it owns made whole in `values`.
  void share_owned(std::vector<double>& values, std::size_t per_block);
  // J = the block at (dy, dx) in {-1, 0, 1}^2 from block I: across the
  // period on a periodic grid; false beyond the edge of a free one.
  bool neighbour_block(std::size_t I, int dy, int dx, std::size_t& J) const;
  // Whether the pair sums of a full build with these cells per block exceed
  // max_pair_terms per cell.
  bool too_many_pair_terms(const std::vector<double>& counts) const;
  // Brings A up to date with the current set, from all pairs if `full` or
  // A was never built.
  void refresh(bool full);
  // A_IJ for the neighbours before (0, 0) from A_JI (refresh).
  void mirror_near();
  // Lists the cells of the current set and the changed cells per block;
  // the current set becomes the built one.
  void list_cells();
  // The exact sums over cell pairs of block I and neighbour (dy, dx):
  // sum_{a in first, c in second} k(x_a - x_c).
  struct ListedCell {
    std::uint32_t offset;  // local (row, col) as row * (4b - 1) + col, the offset in near_kernel_
    float sign;            // 1, or -1 for a cell that left the set (in the changed lists)
  };
  double pair_sum(const ListedCell* first, const ListedCell* first_end, const ListedCell* second,
                  const ListedCell* second_end, int dy, int dx) const;
  void solve_coarse(bool fixed_load);
  // set_kernel, pre_correction and post_correction on fields of T (double or float).
  template <class T>
  void set_kernel_from(std::span<const T> unit_response);
  template <class T>
  void pre_correction_of(std::span<const T> r, std::span<T> field, bool fixed_load);
  template <class T>
  void post_correction_of(std::span<const T> image, std::span<T> z, bool fixed_load);
  // rhs_ = Z^T field over the current set, summed (in double) over the processes.
  template <class T>
  void restrict_to_blocks(std::span<const T> field);
  // z = Z y, or z += Z y, over the current set.
  template <class T>
  void prolong(const std::vector<double>& y, std::span<T> z, bool add) const;

  Grid grid_;
  BlockDeflationOptions options_;
  std::size_t first_row_ = 0;  // this process's rows of the fields
  std::size_t rows_ = 0;
  const linalg::Communicator* comm_;
  // On several processes: this process's rows of the set, and the held rows
  // fetched (empty on one process).
  std::vector<std::uint8_t> local_set_, fetched_;
  std::size_t blocks_x_;
  std::size_t blocks_y_;
  // The block rows whose near-field entries this process computes (those
  // whose first row it holds), and the block rows it holds the set on:
  // those and one more each side (a block's 3 x 3 neighbourhood), from
  // held_first_ on across the period; every block row on one process.
  std::size_t owned_first_ = 0, owned_end_ = 0;
  std::size_t held_first_ = 0, held_block_rows_ = 0;
  bool built_ = false;
  // Per held cell: bit 0 in the current coarse set, bit 1 in the set A was
  // built on.
  std::vector<std::uint8_t> set_;
  // Kernel near field k(dy, dx) for |dx|, |dy| < 2b, row-major over dy.
  std::vector<double> near_kernel_;
  // Per block: its cells in the set, n_I, and the 3 x 3 exact block sums
  // (neighbour (dy, dx) at (dy + 1) * 3 + dx + 1).
  std::vector<double> counts_;
  std::vector<double> block_counts_;  // decline_if_dense's counts
  std::vector<double> near_;
  std::vector<double> owned_;  // this process's rows of counts_ or near_, to share
  // Per held block (row-major from held_first_), the cells of the set A was built on (current, previous) and
  // the cells that changed between the two.
  std::vector<std::size_t> cell_start_, previous_start_, changed_start_;
  std::vector<ListedCell> cells_, previous_cells_, changed_cells_;
  // Far field: point loads between block centres, as a coarse-grid symbol
  // (zero-padded to 2 x 2 times the blocks on a free grid).
  std::unique_ptr<RealFft> coarse_fft_;
  std::vector<std::complex<double>> far_symbol_;
  // Coarse CG vectors.
  std::vector<double> rhs_, y_, first_, inverse_diagonal_, residual_, direction_, image_, scaled_;
  BlockDeflationStats stats_;
};

}  // namespace halfspace::solvers
