// The transforms a TangentialOperator multiplies its symbols on: the whole
// grid on this process (the serial ones, made by its grid constructor), or
// this process's slab of rows of a grid spread over MPI processes
// (mpi/slab_tangential_transforms.hpp, made by the distributed layout). The
// operator computes its symbols and applies them once, on whichever spectrum
// entries the transforms hold here.
#pragma once

#include <complex>
#include <cstddef>
#include <functional>
#include <memory>
#include <span>

#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/linalg/communicator.hpp"

namespace halfspace::operators {

// A mode of the (padded, on free grids) spectrum: the row (ky) and the
// column (kx, 0 <= kx <= nx/2 or nx) of the whole transform.
struct SpectrumMode {
  std::size_t row = 0;
  std::size_t col = 0;
};

class TangentialTransforms {
 public:
  virtual ~TangentialTransforms() = default;

  // The field values held here, and the processes the field is spread over.
  virtual std::size_t local_size() const = 0;
  virtual const linalg::Communicator& communicator() const = 0;
  // The spectrum entries held here, as blocks x length (for parallel loops),
  // entry k standing for mode(k).
  virtual std::size_t spectrum_blocks() const = 0;
  virtual std::size_t spectrum_length() const = 0;
  virtual SpectrumMode mode(std::size_t k) const = 0;
  // The rows of the whole spectrum (the padded grid's on free grids).
  virtual std::size_t spectrum_rows() const = 0;
  // The N of backward(forward(x)) = N x.
  virtual double transform_size() const = 0;

  // The spectrum of `values` (local_size() values) in transform `k` (0 or
  // 1), valid until its backward(). Collective on a distributed grid.
  virtual std::span<std::complex<double>> forward(int k, std::span<const double> values) = 0;
  virtual std::span<std::complex<double>> spectrum(int k) = 0;
  // The unnormalised inverse of spectrum(k) into `values`. Collective.
  virtual void backward(int k, std::span<double> values) = 0;

  // Free grids: the DFT of the real wrap-around array value(row, col) on the
  // whole padded grid (spectrum_rows() x 2 nx), on the entries held here
  // (a kernel's coefficients, transformed once). Collective.
  virtual std::span<const std::complex<double>> transform_wraparound(
      const std::function<double(std::size_t row, std::size_t col)>& value) = 0;
};

// The serial transforms: the whole of `grid` on this process, two of the
// grid's own transforms (periodic) or two pruned padded ones (free; 1D or 2D).
std::unique_ptr<TangentialTransforms> make_serial_transforms(const Grid& grid, FftPlanning planning);

}  // namespace halfspace::operators
