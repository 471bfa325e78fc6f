#include "halfspace/mpi/slab_level_transfer.hpp"

#include <fmt/format.h>

#include <Eigen/Core>
#include <algorithm>
#include <cassert>
#include <optional>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/solvers/grid_transfer.hpp"

namespace halfspace::mpi {

RowRanges SlabLevelTransfer::Level::held() const {
  return gathered ? RowRanges::all(static_cast<int>(slab_rows.first.size()), ny) : slab_rows;
}

SlabLevelTransfer::SlabLevelTransfer(const Grid& fine, std::size_t min_cells_per_axis, const MpiCommunicator& comm,
                                     std::size_t gather_below_cells)
    : comm_(comm) {
  if (fine.dimension() != 2) throw InputError("a distributed multilevel solve needs a 2D grid");
  for (std::optional<Grid> grid = fine; grid; grid = solvers::coarser_grid(*grid, min_cells_per_axis)) {
    Level level;
    level.nx = grid->nx();
    level.ny = grid->ny();
    level.slab = slab_layout(level.nx, level.ny, comm_);
    level.slab_rows = RowRanges::gather(comm_, level.slab.first_row, level.slab.rows);
    const bool empty_slab = *std::min_element(level.slab_rows.rows.begin(), level.slab_rows.rows.end()) == 0;
    // The fine level is the caller's slab; once one level is gathered, all
    // coarser ones are.
    level.gathered = !levels_.empty() && (levels_.back().gathered || grid->size() < gather_below_cells || empty_slab);
    level.fine_rows = level.slab_rows;
    for (std::size_t p = 0; p < level.fine_rows.first.size(); ++p) {
      level.fine_rows.first[p] *= 2;
      level.fine_rows.rows[p] *= 2;
    }
    if (!levels_.empty()) {
      // The finer level prolongs from this one: fine row j takes coarse row j / 2.
      Level& finer = levels_.back();
      finer.coarse_rows = finer.slab_rows;
      for (std::size_t p = 0; p < finer.coarse_rows.first.size(); ++p) {
        const std::size_t first = finer.slab_rows.first[p];
        const std::size_t rows = finer.slab_rows.rows[p];
        finer.coarse_rows.first[p] = first / 2;
        finer.coarse_rows.rows[p] = rows > 0 ? (first + rows - 1) / 2 + 1 - first / 2 : 0;
      }
    }
    levels_.push_back(std::move(level));
  }
}

const SlabLevelTransfer::Level& SlabLevelTransfer::level(const Grid& grid) const {
  for (const Level& level : levels_) {
    if (level.nx == grid.nx() && level.ny == grid.ny()) return level;
  }
  throw InputError(fmt::format("the {} grid is not a level of this multilevel solve", grid.shape_string()));
}

const SlabLevelTransfer::Level& SlabLevelTransfer::coarser(const Level& fine) const {
  const auto index = static_cast<std::size_t>(&fine - levels_.data());
  assert(index + 1 < levels_.size());
  return levels_[index + 1];
}

std::size_t SlabLevelTransfer::local_size(const Grid& grid) const {
  const Level& found = level(grid);
  return found.gathered ? grid.size() : found.slab.local_size();
}

const linalg::Communicator& SlabLevelTransfer::communicator(const Grid& grid) const {
  if (level(grid).gathered) return linalg::serial_communicator();
  return comm_;
}

void SlabLevelTransfer::restrict_to_coarse(const Grid& fine, std::span<const double> fine_values,
                                           std::span<double> coarse_values) {
  const Level& f = level(fine);
  const Level& c = coarser(f);
  if (f.gathered) {
    solvers::restrict_by_average(fine, fine_values, coarse_values);
    return;
  }
  // The two fine rows of each coarse row of this process's slab of the
  // coarse grid, then their block averages.
  const std::size_t rows = c.slab.rows;
  Eigen::ArrayXd fine_rows(static_cast<Eigen::Index>(2 * rows * f.nx));
  fetch_rows(comm_, f.nx, f.slab_rows, fine_values, c.fine_rows, {fine_rows.data(), 2 * rows * f.nx});
  Eigen::ArrayXd slab(static_cast<Eigen::Index>(c.gathered ? rows * c.nx : 0));
  const std::span<double> coarse_slab =
      c.gathered ? std::span<double>(slab.data(), rows * c.nx) : coarse_values.first(rows * c.nx);
  if (rows > 0) {
    const Grid block = Grid::plane(f.nx, 2 * rows, fine.dx(), fine.dy(), fine.boundary());
    solvers::restrict_by_average(block, {fine_rows.data(), 2 * rows * f.nx}, coarse_slab);
  }
  // A gathered coarse level: every process's coarse rows to every process.
  if (c.gathered) fetch_rows(comm_, c.nx, c.slab_rows, coarse_slab, c.held(), coarse_values);
}

void SlabLevelTransfer::prolong_to_fine(const Grid& fine, std::span<const double> coarse_values,
                                        std::span<double> fine_values) {
  const Level& f = level(fine);
  const Level& c = coarser(f);
  if (f.gathered) {
    solvers::prolong_constant(fine, coarse_values, fine_values);
    return;
  }
  const auto me = static_cast<std::size_t>(comm_.rank());
  const std::size_t first = f.slab.first_row;
  const std::size_t first_coarse = f.coarse_rows.first[me];
  const std::size_t coarse_rows = f.coarse_rows.rows[me];
  Eigen::ArrayXd rows(static_cast<Eigen::Index>(coarse_rows * c.nx));
  fetch_rows(comm_, c.nx, c.held(), coarse_values, f.coarse_rows, {rows.data(), coarse_rows * c.nx});
  const std::size_t nx = f.nx;
  const std::size_t cx = c.nx;
  linalg::for_each_row(f.slab.rows, nx, [&](std::size_t j) {
    const double* coarse_row = rows.data() + ((first + j) / 2 - first_coarse) * cx;
    double* fine_row = fine_values.data() + j * nx;
    for (std::size_t i = 0; i < nx; ++i) fine_row[i] = coarse_row[i / 2];
  });
}

}  // namespace halfspace::mpi
