// R K P as a convolution on the coarse grid
// (coarsened_influence_operator.hpp).
#include "halfspace/operators/coarsened_influence_operator.hpp"

#include <algorithm>
#include <cassert>
#include <complex>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/solvers/grid_transfer.hpp"

namespace halfspace::operators {

namespace {
// The spectrum's rows and columns for the coarse grid's transform.
std::size_t symbol_rows(const Grid& coarse) {
  if (coarse.dimension() == 1) return 1;
  return coarse.periodic() ? coarse.ny() : 2 * coarse.ny();
}
std::size_t symbol_cols(const Grid& coarse) {
  return coarse.periodic() ? coarse.nx() / 2 + 1 : coarse.nx() + 1;
}
}  // namespace

CoarsenedInfluenceOperator::CoarsenedInfluenceOperator(InfluenceOperator& fine, const Grid& coarse)
    : coarse_(coarse), kernel_(symbol_rows(coarse), symbol_cols(coarse)) {
  const Grid& fine_grid = fine.grid();
  if (fine.local_size() != fine_grid.size()) {
    throw InputError("the coarsened influence operator needs a serial fine operator (one process)");
  }
  const std::size_t nx = coarse_.nx();
  const std::size_t rows = coarse_.dimension() == 1 ? 1 : coarse_.ny();
  // R K P's coefficients: the coarse displacement under a unit pressure on
  // coarse cell 0, at every offset (0 .. n-1 per axis; on periodic grids
  // the wrapped offsets too).
  std::vector<double> unit(coarse_.size(), 0.0), coefficients(coarse_.size(), 0.0);
  std::vector<double> fine_pressure(fine_grid.size()), fine_displacement(fine_grid.size());
  unit[0] = 1.0;
  solvers::prolong_constant(fine_grid, unit, fine_pressure);
  fine.apply(fine_pressure, fine_displacement);
  solvers::restrict_by_average(fine_grid, fine_displacement, coefficients);
  self_influence_ = coefficients[0];
  if (coarse_.periodic()) {
    transform_ = coarse_.dimension() == 1 ? std::make_unique<RealFft>(nx, FftPlanning::estimate)
                                          : std::make_unique<RealFft>(rows, nx, FftPlanning::estimate);
    std::copy(coefficients.begin(), coefficients.end(), transform_->input().begin());
    transform_->forward();
    const double inverse_n = 1.0 / static_cast<double>(coarse_.size());
    const std::span<const std::complex<double>> spectrum = transform_->spectrum();
    for (std::size_t r = 0; r < kernel_.stored_rows(); ++r) {
      for (std::size_t c = 0; c < kernel_.cols(); ++c) {
        kernel_.at(r, c) = spectrum[r * kernel_.cols() + c].real() * inverse_n;
      }
    }
    return;
  }
  // Free grids: the coefficients laid out on the (2 ny, 2 nx) wrap-around
  // grid of the DC-FFT (offset -d at 2n - d, nothing at n), whose spectrum
  // is real up to rounding, the coefficients being even in each offset.
  padded_ = std::make_unique<PaddedRealFft>(rows, nx, FftPlanning::estimate);
  const auto folded = [](std::size_t index, std::size_t n) {
    return index < n ? index : (index == n ? n : 2 * n - index);  // n: the unused middle
  };
  for (std::size_t r = 0; r < padded_->spectrum_rows(); ++r) {
    const std::span<double> row = padded_->padded_row(r);
    const std::size_t dy = rows == 1 ? 0 : folded(r, rows);
    for (std::size_t c = 0; c < 2 * nx; ++c) {
      const std::size_t dx = folded(c, nx);
      row[c] = dy == rows || dx == nx ? 0.0 : coefficients[dy * nx + dx];
    }
  }
  padded_->forward_all_rows();
  const double inverse_n = 1.0 / static_cast<double>(padded_->padded_size());
  const std::span<const std::complex<double>> spectrum = padded_->spectrum();
  for (std::size_t r = 0; r < kernel_.stored_rows(); ++r) {
    for (std::size_t c = 0; c < kernel_.cols(); ++c)
      kernel_.at(r, c) = spectrum[r * kernel_.cols() + c].real() * inverse_n;
  }
}

CoarsenedInfluenceOperator::~CoarsenedInfluenceOperator() = default;

void CoarsenedInfluenceOperator::apply(std::span<const double> pressure, std::span<double> displacement) {
  assert(pressure.size() == coarse_.size() && displacement.size() == coarse_.size());
  if (padded_) {
    padded_->forward(pressure);
    kernel_.multiply(padded_->spectrum());
    padded_->backward(displacement);
    return;
  }
  kernel_.apply(*transform_, pressure, displacement);
}

}  // namespace halfspace::operators
