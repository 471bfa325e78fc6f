#include "halfspace/fft/grid_transform.hpp"

#include <fmt/format.h>

#include "halfspace/error.hpp"

namespace halfspace::fft {

std::shared_ptr<RealFft> make_grid_transform(const Grid& grid, FftPlanning planning) {
  if (grid.dimension() == 1) return std::make_shared<RealFft>(grid.nx(), planning, FftOutput::overwrite_input);
  return std::make_shared<RealFft>(grid.ny(), grid.nx(), planning, FftOutput::overwrite_input, FftLayout::transposed);
}

std::shared_ptr<RealFft> make_grid_transform(const Grid& grid, FftPlanning planning,
                                             std::span<std::complex<double>> workspace) {
  return std::make_shared<RealFft>(grid.dimension() == 1 ? 1 : grid.ny(), grid.nx(), planning, workspace,
                                   FftLayout::transposed);
}

std::shared_ptr<SingleRealFft> make_single_grid_transform(const Grid& grid, FftPlanning planning,
                                                          std::span<std::complex<double>> workspace) {
  // FFTW-aligned double memory is FFTW-aligned float memory; std::complex<float>
  // has the layout of float[2] ([complex.numbers]).
  const std::span<std::complex<float>> floats{reinterpret_cast<std::complex<float>*>(workspace.data()),
                                              2 * workspace.size()};
  return std::make_shared<SingleRealFft>(grid.dimension() == 1 ? 1 : grid.ny(), grid.nx(), planning, floats,
                                         FftLayout::transposed);
}

template <class Real>
std::shared_ptr<BasicRealFft<Real>> checked_grid_transform(const Grid& grid,
                                                           std::shared_ptr<BasicRealFft<Real>> transform,
                                                           std::string_view user) {
  const std::size_t rows = grid.dimension() == 1 ? 1 : grid.ny();
  if (!transform || transform->rows() != rows || transform->cols() != grid.nx()) {
    throw InputError(fmt::format("{}: the shared transform is {}x{} but the grid needs {}x{}", user,
                                 transform ? transform->rows() : 0, transform ? transform->cols() : 0, rows,
                                 grid.nx()));
  }
  return transform;
}

template std::shared_ptr<RealFft> checked_grid_transform(const Grid&, std::shared_ptr<RealFft>, std::string_view);
template std::shared_ptr<SingleRealFft> checked_grid_transform(const Grid&, std::shared_ptr<SingleRealFft>,
                                                               std::string_view);

}  // namespace halfspace::fft
