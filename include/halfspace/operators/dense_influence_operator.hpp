// The influence matrix K assembled explicitly, for small grids only: the
// reference the FFT operator is tested against and the matrix of the dense
// LCP solvers. Built from the same kernel functions as the FFT operator.
#pragma once

#include <Eigen/Core>

#include "halfspace/operators/influence_operator.hpp"

namespace halfspace::operators {

// Largest grid (cells) for which the dense matrix is assembled: 8 * 8192^2
// bytes = 512 MiB.
inline constexpr std::size_t kMaxDenseCells = 8192;

// K (m/Pa), size N x N with N = grid.size(): K(i, j) is the displacement of
// cell i under unit pressure on cell j. For periodic grids the mean mode of
// every column is zero, as in FftInfluenceOperator. Throws InputError naming
// the size if N > kMaxDenseCells.
Eigen::MatrixXd assemble_influence_matrix(const Grid& grid, double e_star);

class DenseInfluenceOperator final : public InfluenceOperator {
 public:
  DenseInfluenceOperator(const Grid& grid, double e_star);

  const Grid& grid() const override { return grid_; }
  void apply(std::span<const double> pressure, std::span<double> displacement) override;
  double self_influence() const override { return matrix_(0, 0); }

  const Eigen::MatrixXd& matrix() const { return matrix_; }

 private:
  Grid grid_;
  Eigen::MatrixXd matrix_;
  Eigen::VectorXd product_;  // K p when applied in place
};

}  // namespace halfspace::operators

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using operators::assemble_influence_matrix;
using operators::DenseInfluenceOperator;
using operators::kMaxDenseCells;
}  // namespace halfspace
