// The unpadded real transform of a grid's own shape, which the periodic
// operator and the Fourier preconditioner use (and may share): nx values in
// 1D, (ny, nx) in 2D, the inverse overwriting the input (FftOutput::
// overwrite_input: one real array less; nothing needs the input afterwards).
// In 2D the spectrum is transposed (FftLayout::transposed, kx-major): the
// faster transform at large sizes, and the slab transforms' layout, which
// every operator on the transforms already handles.
#pragma once

#include <complex>
#include <memory>
#include <span>
#include <string_view>

#include "halfspace/fft/real_fft.hpp"
#include "halfspace/grid.hpp"

namespace halfspace::fft {

std::shared_ptr<RealFft> make_grid_transform(const Grid& grid, FftPlanning planning);
// The same over `workspace`, memory idle while it runs (RealFft's workspace
// constructor); throws InputError if it is smaller than
// RealFft::workspace_size of the grid's shape.
std::shared_ptr<RealFft> make_grid_transform(const Grid& grid, FftPlanning planning,
                                             std::span<std::complex<double>> workspace);

// The grid's transform in single precision (a mixed-precision solve's inner
// products), over `workspace`: idle double-precision memory such as another
// transform's spectrum, read as floats (it holds twice as many); throws
// InputError if it is smaller than SingleRealFft::workspace_size.
std::shared_ptr<SingleRealFft> make_single_grid_transform(const Grid& grid, FftPlanning planning,
                                                          std::span<std::complex<double>> workspace);

// Returns `transform` if it has the grid's shape; throws InputError naming
// `user` (the class receiving it) and both shapes otherwise, or if it is null.
template <class Real>
std::shared_ptr<BasicRealFft<Real>> checked_grid_transform(const Grid& grid,
                                                           std::shared_ptr<BasicRealFft<Real>> transform,
                                                           std::string_view user);

}  // namespace halfspace::fft

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using fft::make_grid_transform;
using fft::make_single_grid_transform;
}  // namespace halfspace
