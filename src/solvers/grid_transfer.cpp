#include "halfspace/solvers/grid_transfer.hpp"

#include <cassert>

#include "halfspace/linalg/parallel.hpp"

namespace halfspace::solvers {

std::optional<Grid> coarser_grid(const Grid& fine, std::size_t min_cells_per_axis) {
  const bool line = fine.dimension() == 1;
  if (fine.nx() % 2 != 0 || fine.nx() / 2 < min_cells_per_axis) return std::nullopt;
  if (line) return Grid::line(fine.nx() / 2, 2.0 * fine.dx(), fine.boundary());
  if (fine.ny() % 2 != 0 || fine.ny() / 2 < min_cells_per_axis) return std::nullopt;
  return Grid::plane(fine.nx() / 2, fine.ny() / 2, 2.0 * fine.dx(), 2.0 * fine.dy(), fine.boundary());
}

void restrict_by_average(const Grid& fine, std::span<const double> fine_values, std::span<double> coarse_values) {
  const std::size_t nx = fine.nx();
  const std::size_t cx = nx / 2;
  assert(fine_values.size() == fine.size() && coarse_values.size() * (fine.dimension() == 1 ? 2 : 4) == fine.size());
  if (fine.dimension() == 1) {
    linalg::for_each_index(
        cx, [&](std::size_t i) { coarse_values[i] = 0.5 * (fine_values[2 * i] + fine_values[2 * i + 1]); });
    return;
  }
  linalg::for_each_row(fine.ny() / 2, nx, [&](std::size_t jc) {
    const double* top = fine_values.data() + 2 * jc * nx;
    const double* bottom = top + nx;
    for (std::size_t i = 0; i < cx; ++i) {
      coarse_values[jc * cx + i] = 0.25 * ((top[2 * i] + top[2 * i + 1]) + (bottom[2 * i] + bottom[2 * i + 1]));
    }
  });
}

void prolong_constant(const Grid& fine, std::span<const double> coarse_values, std::span<double> fine_values) {
  const std::size_t nx = fine.nx();
  const std::size_t cx = nx / 2;
  assert(fine_values.size() == fine.size() && coarse_values.size() * (fine.dimension() == 1 ? 2 : 4) == fine.size());
  if (fine.dimension() == 1) {
    linalg::for_each_index(nx, [&](std::size_t i) { fine_values[i] = coarse_values[i / 2]; });
    return;
  }
  linalg::for_each_row(fine.ny(), nx, [&](std::size_t j) {
    const double* coarse_row = coarse_values.data() + (j / 2) * cx;
    double* fine_row = fine_values.data() + j * nx;
    for (std::size_t i = 0; i < nx; ++i) fine_row[i] = coarse_row[i / 2];
  });
}

}  // namespace halfspace::solvers
