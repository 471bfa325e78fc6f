// The tangential compliance of two elastic bodies as an operator: the
// relative tangential surface displacement u = C t of the traction t =
// (t_x, t_y) per cell, matrix-free by FFT like the normal FftInfluenceOperator
// (plans and symbols made once): periodic grids multiply each mode by the 2x2
// symbol of kernels/tangential_fourier.hpp; free grids convolve with
// Cerruti's rectangle (2D) or the tangential strip (1D) coefficients by zero
// padding (DC-FFT, PaddedRealFft). Built from the ElasticPair, because E*
// alone does not fix the tangential compliance. For elastically dissimilar
// bodies (Dundurs' beta != 0) it also applies the normal-tangential coupling
// (kernels/coupling_coefficients.hpp): the tangential displacement of a
// pressure and the normal displacement of a traction, by the same transforms
// (coupling_fourier, coupling_rectangle, coupling_strip). A coated body
// (ElasticPair::coated) takes its symbols per mode from the pair; on free
// 2D grids the layer's closed forms plus a remainder added per mode, as the
// normal coated kernel (docs/theory.md, "Tangential compliance of a coated
// half-space").
#pragma once

#include <memory>
#include <span>
#include <string>

#include "halfspace/elastic_pair.hpp"
#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/kernels/tangential_coefficients.hpp"
#include "halfspace/linalg/communicator.hpp"
#include "halfspace/operators/spectral_transforms.hpp"

namespace halfspace::operators {

// Why the pair's tangential compliance is not built on `grid`, or empty: a
// coated body on a free 1D grid, or on a free 2D grid whose shorter side is
// less than 8 split heights (NormalKernel::spectral_remainder: the remainder
// goes in by DFT only there).
std::string coated_free_grid_refusal(const Grid& grid, const ElasticPair& pair);

class TangentialOperator {
 public:
  // Throws InputError with coated_free_grid_refusal's reason, if any.
  TangentialOperator(const Grid& grid, const ElasticPair& pair, FftPlanning planning = FftPlanning::estimate);
  // The same on `transforms` (a distributed layout's slab transforms of
  // `grid`): fields hold this process's cells, reductions go over its
  // communicator. Collective.
  TangentialOperator(const Grid& grid, const ElasticPair& pair, std::unique_ptr<SpectralTransforms> transforms);
  ~TangentialOperator();
  TangentialOperator(const TangentialOperator&) = delete;
  TangentialOperator& operator=(const TangentialOperator&) = delete;

  const Grid& grid() const;
  const ElasticPair& pair() const;
  // The cells held here (all of the grid's serially) and the processes the
  // fields are spread over.
  std::size_t local_size() const;
  const linalg::Communicator& communicator() const;

  // (u_x, u_y) = C (t_x, t_y): the relative tangential displacement (m) of
  // the surfaces under the traction (Pa) body 1 exerts on body 2. Each span
  // has local_size() entries; the outputs may be the inputs (in place) but
  // must not overlap otherwise. Periodic grids: the mean mode of u is zero.
  // Allocates nothing.
  void apply(std::span<const double> traction_x, std::span<const double> traction_y, std::span<double> displacement_x,
             std::span<double> displacement_y);

  // (t_x, t_y) = M (u_x, u_y): an approximate inverse of C for
  // preconditioning, each mode of the operator's own (padded) transform
  // multiplied by the inverse of its 2x2 symbol (periodic grids: the exact
  // inverse, q (delta_ab + B/(A - B) n_a n_b)/A of tangential_fourier.hpp,
  // outside the mean mode). Modes whose eigenvalue is zero or negative (the
  // periodic mean mode, a padded circulant's) take the largest instead, so M
  // is symmetric positive definite. Same spans and aliasing rules as
  // apply(); shares its transforms, so the two must not run at once.
  // Allocates nothing.
  void apply_approximate_inverse(std::span<const double> displacement_x, std::span<const double> displacement_y,
                                 std::span<double> traction_x, std::span<double> traction_y);

  // apply() and apply_approximate_inverse() with single-precision
  // transforms, where single_precision(): the fields stay double, the
  // spectra are float (in the double ones' memory, so nothing is added to
  // the operator's size) and the product's relative error is about 1e-7;
  // elsewhere the double products themselves. For the inner products of
  // an iteration whose errors exact products correct (the tangential
  // step's conjugate gradients, TangentialOptions::precision). Allocates
  // nothing; shares the transforms with the double products.
  bool single_precision() const;  // a serial periodic 2D grid
  void apply_in_single_precision(std::span<const double> traction_x, std::span<const double> traction_y,
                                 std::span<double> displacement_x, std::span<double> displacement_y);
  void apply_approximate_inverse_in_single_precision(std::span<const double> displacement_x,
                                                     std::span<const double> displacement_y,
                                                     std::span<double> traction_x, std::span<double> traction_y);

  // Whether the pair couples the normal and tangential problems (Dundurs'
  // beta != 0, ElasticPair::similar() false). The coupling products below
  // are exactly zero otherwise.
  bool coupled() const;

  // (v_x, v_y) = K p: the relative tangential displacement (m) of the
  // surfaces under the pressure p (Pa). Same span rules as apply(); the
  // outputs must not overlap the input. Periodic grids: no mean mode (the
  // kernel is odd). Allocates nothing.
  void apply_pressure_coupling(std::span<const double> pressure, std::span<double> displacement_x,
                               std::span<double> displacement_y);
  // w = K^T (t_x, t_y): the normal displacement (m, positive into the
  // half-space as the normal operator's K p) under the traction (Pa); the
  // transpose, so that the 3x3 compliance of (p, t) is symmetric (Betti).
  // The output must not overlap the inputs. Allocates nothing.
  void apply_traction_coupling(std::span<const double> traction_x, std::span<const double> traction_y,
                               std::span<double> normal_displacement);

  // The block C_ii (m/Pa) of a cell under unit traction on itself alone, the
  // same for every cell (xy is zero: the cell is symmetric).
  kernels::TangentialCoefficients self_influence() const;
  // An upper bound (m/Pa) on the largest eigenvalue of C: the largest
  // eigenvalue of the 2x2 symbol over the modes of its (padded) circulant.
  double largest_eigenvalue_bound() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace halfspace::operators

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using operators::TangentialOperator;
}  // namespace halfspace
