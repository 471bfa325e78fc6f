#include "halfspace/solvers/grid_transfer.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

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

namespace {

// The two coarse indices and the weight of the second for a fine index
// `i` on an axis of `coarse_count` coarse nodes.
struct Bracket {
  std::size_t low = 0, high = 0;
  double weight = 0.0;
};

Bracket bracket(std::size_t i, std::size_t coarse_count, bool periodic) {
  const double t = 0.5 * static_cast<double>(i) - 0.25;
  if (coarse_count == 1) return {};
  if (periodic) {
    const double low = std::floor(t);
    const auto n = static_cast<long>(coarse_count);
    const long l = ((static_cast<long>(low) % n) + n) % n;
    return {static_cast<std::size_t>(l), static_cast<std::size_t>((l + 1) % n), t - low};
  }
  const double clamped = std::clamp(t, 0.0, static_cast<double>(coarse_count - 1));
  const auto low = std::min(static_cast<std::size_t>(clamped), coarse_count - 2);
  return {low, low + 1, clamped - static_cast<double>(low)};
}

}  // namespace

void prolong_bilinear(const Grid& fine, std::span<const double> coarse_values, std::span<double> fine_values) {
  prolong_bilinear_rows(fine, coarse_values, 0, fine_values);
}

void prolong_bilinear_rows(const Grid& fine, std::span<const double> coarse_values, std::size_t first_row,
                           std::span<double> fine_rows) {
  const bool line = fine.dimension() == 1;
  const std::size_t nx = fine.nx(), ny = line ? 1 : fine.ny();
  const std::size_t cx = nx / 2, cy = line ? 1 : ny / 2;
  const std::size_t rows = fine_rows.size() / nx;
  assert(fine_rows.size() == nx * rows && first_row + rows <= ny && coarse_values.size() == cx * cy);
  const bool periodic = fine.periodic();
  for (std::size_t r = 0; r < rows; ++r) {
    const std::size_t j = first_row + r;
    const Bracket y = line ? Bracket{} : bracket(j, cy, periodic);
    for (std::size_t i = 0; i < nx; ++i) {
      const Bracket x = bracket(i, cx, periodic);
      const auto at = [&](std::size_t row, std::size_t column) { return coarse_values[row * cx + column]; };
      const double low = (1.0 - x.weight) * at(y.low, x.low) + x.weight * at(y.low, x.high);
      const double high = (1.0 - x.weight) * at(y.high, x.low) + x.weight * at(y.high, x.high);
      fine_rows[r * nx + i] = (1.0 - y.weight) * low + y.weight * high;
    }
  }
}

void restrict_rows_by_average(const Grid& fine, std::span<const double> fine_rows, std::size_t first_row,
                              std::span<double> coarse_values, const linalg::Communicator& comm) {
  if (comm.size() == 1) return restrict_by_average(fine, fine_rows, coarse_values);
  const std::size_t nx = fine.nx();
  const std::size_t cx = nx / 2;
  const std::size_t rows = fine_rows.size() / nx;
  assert(fine.dimension() == 2 && coarse_values.size() * 4 == fine.size() && first_row + rows <= fine.ny());
  std::fill(coarse_values.begin(), coarse_values.end(), 0.0);
  // Each process its rows' halves of the averages; a pair of rows split
  // between two processes is completed by the sum.
  for (std::size_t r = 0; r < rows; ++r) {
    const double* row = fine_rows.data() + r * nx;
    double* coarse_row = coarse_values.data() + ((first_row + r) / 2) * cx;
    for (std::size_t i = 0; i < cx; ++i) coarse_row[i] += 0.25 * (row[2 * i] + row[2 * i + 1]);
  }
  comm.sum(coarse_values);
}

}  // namespace halfspace::solvers
