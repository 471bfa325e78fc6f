// A coarse-grid correction for the preconditioner of a tangential step
// (TangentialOptions::coarse_correction_block): block deflation's coarse
// space (block_deflation.hpp) carried to the two traction components. On a
// rough contact of many small spots the inverse of C's Fourier symbol, made
// for the whole plane, misjudges the response to smooth modulations of the
// traction spread over many spots (their eigenvalues in the preconditioned
// operator scale with the contact fraction), as it does for the normal
// problem. The coarse space Z has two columns per b x b block, holding 1 on
// the block's cells in the coarse set (the stick cells: a slipping cell's
// motion is along its circle, where the curvature dominates) in x and in y.
// The Galerkin matrix A = Z^T C Z is 2 x 2 per block pair, its entries the
// block pair sums of the Cerruti kernel's components C_xx, C_xy and C_yy,
// each assembled by one scalar BlockDeflation from the real-space response
// C e_0 (exact between neighbouring blocks, point loads at block centres by
// a coarse FFT beyond them). The correction is additive, z = M r + Z A^-1
// Z^T r (Tang, Nabben, Vuik & Erlangga 2009's coarse correction without the
// projections): no fine product more per iteration, only the coarse solve,
// and symmetric positive definite, so the conjugate gradients keep their
// form. Under force control the coarse solve is projected onto corrections
// that move no force. Serial 2D periodic grids (the cross term is odd in
// each axis, which a free grid's one-quadrant response cannot give).
// Internal to src/solvers.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "halfspace/linalg/parallel.hpp"
#include "halfspace/operators/tangential_operator.hpp"
#include "halfspace/solvers/block_deflation.hpp"

namespace halfspace::solvers::tangential {

class TangentialBlockCorrection {
 public:
  // Whether the correction applies to the operator's grid with this block:
  // one process, a 2D periodic grid the block covers (BlockDeflation::covers).
  static bool applies(const TangentialOperator& op, std::size_t block);
  // Makes C e_0 by two products (the only fine work outside the solves).
  // Throws InputError unless applies(op, block).
  TangentialBlockCorrection(TangentialOperator& op, std::size_t block, double coarse_tolerance = kCoarseTolerance);
  ~TangentialBlockCorrection();

  // Records the coarse set in_set(i) and brings A up to date (from the
  // changed cells' pair sums when few changed).
  template <class InSet>
  void update(InSet&& in_set) {
    linalg::for_each_index(set_.size(), [&](std::size_t i) { set_[i] = in_set(i) ? 1 : 0; });
    update_components();
  }
  // Whether A is built for the last set (a dense contact's build is
  // declined, BlockDeflation::update).
  bool ready() const;

  // y = A^-1 Z^T r (r on the cells; under a fixed load projected onto
  // corrections that move no load), kept for add().
  void solve(std::span<const double> rx, std::span<const double> ry, bool fixed_load);
  // z += Z y.
  void add(std::span<double> zx, std::span<double> zy) const;

  // out = A y, the coarse vectors' x parts first (coarse_size() each), then
  // their y parts. Exposed for tests.
  void apply_coarse(std::span<const double> y, std::span<double> out);
  std::size_t coarse_size() const;
  // The last solve's coarse vector (x parts, then y parts).
  std::span<const double> coarse_solution() const { return y_; }

  long coarse_iterations() const { return coarse_iterations_; }
  int unconverged_solves() const { return unconverged_solves_; }

  // Of the coarse conjugate gradients, relative in the preconditioned norm:
  // an inexact coarse solve only perturbs the preconditioner.
  static constexpr double kCoarseTolerance = 1e-3;
  static constexpr int kCoarseMaxIterations = 200;

 private:
  void update_components();
  // D^-1 r with D the 2 x 2 block diagonal of A, r first projected off the
  // load's directions under a fixed load.
  void precondition(std::vector<double>& r, std::vector<double>& out, bool fixed_load) const;

  const Grid& grid_;
  std::size_t block_;
  double coarse_tolerance_;
  std::size_t blocks_x_ = 0;
  std::vector<std::uint8_t> set_;
  // The scalar coarse matrices of C_xx, C_xy, C_yy on the one set.
  std::unique_ptr<BlockDeflation> xx_, xy_, yy_;
  // Per block: the inverse of its 2 x 2 diagonal block (xx, xy, yy), its
  // cells, and (fixed load) the inverse of N^T D^-1 N.
  std::vector<double> inverse_diagonal_;
  std::vector<double> counts_;
  std::array<double, 3> load_inverse_{};
  std::vector<double> rhs_, y_, residual_, direction_, image_, scaled_, part_;
  long coarse_iterations_ = 0;
  int unconverged_solves_ = 0;
};

}  // namespace halfspace::solvers::tangential
