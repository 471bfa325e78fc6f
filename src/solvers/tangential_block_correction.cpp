// The tangential coarse correction of tangential_block_correction.hpp: three
// scalar block deflations (C_xx, C_xy, C_yy) on one coarse set, their 2 x 2
// coarse system solved by block-Jacobi conjugate gradients.
#include "tangential_block_correction.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "halfspace/error.hpp"

namespace halfspace::solvers::tangential {
namespace {

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double total = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) total += a[i] * b[i];
  return total;
}

// The inverse of the symmetric 2 x 2 (xx, xy, yy), zero if it is not
// positive definite (an empty block).
std::array<double, 3> inverse(double xx, double xy, double yy) {
  const double det = xx * yy - xy * xy;
  if (!(xx > 0.0 && det > 1e-14 * xx * yy)) return {};
  return {yy / det, -xy / det, xx / det};
}

}  // namespace

bool TangentialBlockCorrection::applies(const TangentialOperator& op, std::size_t block) {
  return op.communicator().size() == 1 && op.grid().periodic() && BlockDeflation::covers(op.grid(), block);
}

TangentialBlockCorrection::TangentialBlockCorrection(TangentialOperator& op, std::size_t block, double coarse_tolerance)
    : grid_(op.grid()), block_(block), coarse_tolerance_(coarse_tolerance) {
  if (!applies(op, block)) {
    throw InputError(fmt::format(
        "coarse_correction_block = {} is invalid for the {} {} grid: the tangential coarse correction needs one "
        "process and a 2D periodic grid whose sides the block divides into at least 3 blocks",
        block, to_string(grid_.boundary()), grid_.shape_string()));
  }
  const std::size_t n = grid_.size();
  BlockDeflationOptions options;
  options.block = block;
  xx_ = std::make_unique<BlockDeflation>(grid_, options);
  xy_ = std::make_unique<BlockDeflation>(grid_, options);
  yy_ = std::make_unique<BlockDeflation>(grid_, options);
  // C e_0 for unit tractions along x and y on cell 0: (C_xx, C_yx) and
  // (C_xy, C_yy); C_xy = C_yx (C symmetric and even).
  std::vector<double> tx(n, 0.0), ty(n, 0.0), ux(n), uy(n);
  tx[0] = 1.0;
  op.apply(tx, ty, ux, uy);
  xx_->set_kernel(std::span<const double>(ux));
  tx[0] = 0.0;
  ty[0] = 1.0;
  op.apply(tx, ty, ux, uy);
  xy_->set_kernel(std::span<const double>(ux));
  yy_->set_kernel(std::span<const double>(uy));
  set_.assign(n, 0);
  blocks_x_ = grid_.nx() / block;
  const std::size_t m = coarse_size();
  inverse_diagonal_.assign(3 * m, 0.0);
  counts_.assign(m, 0.0);
  for (auto* v : {&rhs_, &y_, &residual_, &direction_, &image_, &scaled_}) v->assign(2 * m, 0.0);
  part_.assign(m, 0.0);
}

TangentialBlockCorrection::~TangentialBlockCorrection() = default;

std::size_t TangentialBlockCorrection::coarse_size() const {
  return xx_->coarse_size();
}

bool TangentialBlockCorrection::ready() const {
  return xx_->ready() && xy_->ready() && yy_->ready();
}

void TangentialBlockCorrection::update_components() {
  auto member = [this](std::size_t i) { return set_[i] != 0; };
  xx_->update(member);
  xy_->update(member);
  yy_->update(member);
  if (!ready()) return;
  const std::size_t m = coarse_size();
  std::array<double, 3> load{};  // N^T D^-1 N
  for (std::size_t I = 0; I < m; ++I) {
    counts_[I] = xx_->block_cells(I);
    const std::array<double, 3> d = inverse(xx_->coarse_diagonal(I), xy_->coarse_diagonal(I), yy_->coarse_diagonal(I));
    std::copy(d.begin(), d.end(), inverse_diagonal_.begin() + static_cast<std::ptrdiff_t>(3 * I));
    const double n2 = counts_[I] * counts_[I];
    for (std::size_t k = 0; k < 3; ++k) load[k] += n2 * d[k];
  }
  load_inverse_ = inverse(load[0], load[1], load[2]);
}

void TangentialBlockCorrection::apply_coarse(std::span<const double> y, std::span<double> out) {
  const std::size_t m = coarse_size();
  const std::span<const double> yx = y.first(m);
  const std::span<const double> yy = y.subspan(m, m);
  const std::span<double> out_x = out.first(m);
  const std::span<double> out_y = out.subspan(m, m);
  xx_->apply_coarse(yx, out_x);
  xy_->apply_coarse(yy, part_);
  for (std::size_t I = 0; I < m; ++I) out_x[I] += part_[I];
  yy_->apply_coarse(yy, out_y);
  xy_->apply_coarse(yx, part_);
  for (std::size_t I = 0; I < m; ++I) out_y[I] += part_[I];
}

void TangentialBlockCorrection::precondition(std::vector<double>& r, std::vector<double>& out, bool fixed_load) const {
  const std::size_t m = coarse_size();
  const double* d = inverse_diagonal_.data();
  if (fixed_load) {
    // r less its part along the load's directions N (n per component),
    // r - N lambda with N^T D^-1 (r - N lambda) = 0, so that D^-1 r moves
    // no load (as BlockDeflation's scalar solve).
    double wx = 0.0;
    double wy = 0.0;
    for (std::size_t I = 0; I < m; ++I) {
      const double* e = d + 3 * I;
      wx += counts_[I] * (e[0] * r[I] + e[1] * r[m + I]);
      wy += counts_[I] * (e[1] * r[I] + e[2] * r[m + I]);
    }
    const double lx = load_inverse_[0] * wx + load_inverse_[1] * wy;
    const double ly = load_inverse_[1] * wx + load_inverse_[2] * wy;
    for (std::size_t I = 0; I < m; ++I) {
      r[I] -= counts_[I] * lx;
      r[m + I] -= counts_[I] * ly;
    }
  }
  for (std::size_t I = 0; I < m; ++I) {
    const double* e = d + 3 * I;
    out[I] = e[0] * r[I] + e[1] * r[m + I];
    out[m + I] = e[1] * r[I] + e[2] * r[m + I];
  }
}

void TangentialBlockCorrection::solve(std::span<const double> rx, std::span<const double> ry, bool fixed_load) {
  const std::size_t m = coarse_size();
  const std::size_t b = block_;
  const std::size_t nx = grid_.nx();
  // rhs = Z^T r: each block's sums over its cells in the set.
  linalg::for_each_row(grid_.ny() / b, b * nx, [&](std::size_t by) {
    for (std::size_t bx = 0; bx < blocks_x_; ++bx) {
      double sx = 0.0;
      double sy = 0.0;
      for (std::size_t row = by * b; row < (by + 1) * b; ++row) {
        const std::size_t begin = row * nx + bx * b;
        for (std::size_t i = begin; i < begin + b; ++i) {
          if (set_[i] == 0) continue;
          sx += rx[i];
          sy += ry[i];
        }
      }
      rhs_[by * blocks_x_ + bx] = sx;
      rhs_[m + by * blocks_x_ + bx] = sy;
    }
  });
  std::fill(y_.begin(), y_.end(), 0.0);
  residual_ = rhs_;
  precondition(residual_, direction_, fixed_load);
  double rz = dot(residual_, direction_);
  const double target = coarse_tolerance_ * coarse_tolerance_ * rz;
  for (int iteration = 0;; ++iteration) {
    if (!(rz > target)) return;
    if (iteration == kCoarseMaxIterations) break;
    apply_coarse(direction_, image_);
    const double curvature = dot(direction_, image_);
    if (!(curvature > 0.0)) break;
    const double alpha = rz / curvature;
    for (std::size_t k = 0; k < 2 * m; ++k) {
      y_[k] += alpha * direction_[k];
      residual_[k] -= alpha * image_[k];
    }
    ++coarse_iterations_;
    precondition(residual_, scaled_, fixed_load);
    const double rz_next = dot(residual_, scaled_);
    const double beta = rz_next / rz;
    rz = rz_next;
    for (std::size_t k = 0; k < 2 * m; ++k) direction_[k] = scaled_[k] + beta * direction_[k];
  }
  ++unconverged_solves_;
}

void TangentialBlockCorrection::add(std::span<double> zx, std::span<double> zy) const {
  const std::size_t m = coarse_size();
  const std::size_t b = block_;
  const std::size_t nx = grid_.nx();
  linalg::for_each_row(grid_.ny(), nx, [&](std::size_t row) {
    const std::size_t first_block = (row / b) * blocks_x_;
    for (std::size_t bx = 0; bx < blocks_x_; ++bx) {
      const double vx = y_[first_block + bx];
      const double vy = y_[m + first_block + bx];
      const std::size_t begin = row * nx + bx * b;
      for (std::size_t i = begin; i < begin + b; ++i) {
        if (set_[i] == 0) continue;
        zx[i] += vx;
        zy[i] += vy;
      }
    }
  });
}

}  // namespace halfspace::solvers::tangential
