// R K P as a convolution on the coarse grid
// (coarsened_influence_operator.hpp).
#include "halfspace/operators/coarsened_influence_operator.hpp"

#include <cassert>
#include <complex>
#include <utility>
#include <vector>

#include "halfspace/solvers/grid_transfer.hpp"

namespace halfspace::operators {

CoarsenedInfluenceOperator::CoarsenedInfluenceOperator(InfluenceOperator& fine, const Grid& coarse)
    : CoarsenedInfluenceOperator(fine, coarse, fine.transforms_for(coarse)) {}

CoarsenedInfluenceOperator::CoarsenedInfluenceOperator(InfluenceOperator& fine, const Grid& coarse,
                                                       std::unique_ptr<SpectralTransforms> transforms)
    : coarse_(coarse), transforms_(std::move(transforms)) {
  const Grid& fine_grid = fine.grid();
  const std::size_t local = fine.local_size();
  const linalg::Communicator& comm = fine.communicator();
  const std::size_t nx = coarse_.nx();
  const std::size_t rows = coarse_.dimension() == 1 ? 1 : coarse_.ny();
  // R K P's coefficients: the coarse displacement under a unit pressure on
  // coarse cell 0, at every offset (0 .. n-1 per axis; on periodic grids
  // the wrapped offsets too). A distributed fine operator takes the product
  // on its slabs, and every process gets the coefficients whole.
  std::vector<double> coefficients(coarse_.size(), 0.0);
  std::vector<double> fine_pressure(local, 0.0), fine_displacement(local);
  // P of the unit pressure: 1 on the fine cells of coarse cell 0 (rows 0
  // and 1 of a plane, columns 0 and 1), on this process's rows.
  const std::size_t fine_nx = fine_grid.nx();
  const std::size_t first_row = linalg::first_row_held(comm, local / fine_nx);
  const std::size_t covered_rows = fine_grid.dimension() == 1 ? 1 : 2;
  for (std::size_t k = 0; k < local; ++k) {
    if (first_row + k / fine_nx < covered_rows && k % fine_nx < 2) fine_pressure[k] = 1.0;
  }
  fine.apply(fine_pressure, fine_displacement);
  solvers::restrict_rows_by_average(fine_grid, fine_displacement, first_row, coefficients, comm);
  self_influence_ = coefficients[0];
  // Periodic grids: the coefficients' own spectrum. Free grids: the
  // coefficients laid out on the (2 ny, 2 nx) wrap-around grid of the
  // DC-FFT (offset -d at 2n - d, nothing at n). Either is real up to
  // rounding, the coefficients being even in each offset.
  const auto folded = [](std::size_t index, std::size_t n) {
    return index < n ? index : (index == n ? n : 2 * n - index);  // n: the unused middle
  };
  // On slabs of the coarse rows a periodic grid's forward transform takes
  // this process's rows of the coefficients (every process has them whole).
  const std::size_t coarse_local = transforms_->local_size();
  const std::size_t coarse_first = linalg::first_row_held(transforms_->communicator(), coarse_local / nx) * nx;
  const std::span<const std::complex<double>> spectrum =
      coarse_.periodic()
          ? transforms_->forward(0, std::span<const double>(coefficients).subspan(coarse_first, coarse_local))
          : transforms_->transform_wraparound([&](std::size_t r, std::size_t c) {
              const std::size_t dy = rows == 1 ? 0 : folded(r, rows);
              const std::size_t dx = folded(c, nx);
              return dy == rows || dx == nx ? 0.0 : coefficients[dy * nx + dx];
            });
  const double inverse_n = 1.0 / transforms_->transform_size();
  kernel_ = held_symbol(*transforms_, [&](std::size_t k, SpectrumMode) { return spectrum[k].real() * inverse_n; });
}

CoarsenedInfluenceOperator::~CoarsenedInfluenceOperator() = default;

void CoarsenedInfluenceOperator::apply(std::span<const double> pressure, std::span<double> displacement) {
  assert(pressure.size() == local_size() && displacement.size() == local_size());
  apply_symbol(*transforms_, 0, kernel_, pressure, displacement);
}

}  // namespace halfspace::operators
