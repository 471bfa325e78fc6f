// The accelerated projected-gradient step (tangential_projected_gradient.hpp).
#include "tangential_projected_gradient.hpp"

#include <array>
#include <tuple>

namespace halfspace::solvers::tangential {

void ProjectedGradientMethod::begin() {
  it_.exact_displacement();
  for_each_index(n_, [&](std::size_t i) {
    f_.tx[i] = f_.qx[i];
    f_.ty[i] = f_.qy[i];
    f_.rx[i] = f_.ux[i];
    f_.ry[i] = f_.uy[i];
  });
  momentum_ = 0.0;
}

void ProjectedGradientMethod::step(double inverse_lipschitz) {
  const double beta = momentum_ / (momentum_ + 3.0);
  const double dx = problem_.force_controlled ? 0.0 : problem_.delta_x;
  const double dy = problem_.force_controlled ? 0.0 : problem_.delta_y;
  for_each_index(n_, [&](std::size_t i) {
    const double yx = f_.qx[i] + beta * (f_.qx[i] - f_.tx[i]);
    const double yy = f_.qy[i] + beta * (f_.qy[i] - f_.ty[i]);
    const double vx = f_.ux[i] + beta * (f_.ux[i] - f_.rx[i]);
    const double vy = f_.uy[i] + beta * (f_.uy[i] - f_.ry[i]);
    f_.tx[i] = f_.qx[i];
    f_.ty[i] = f_.qy[i];
    f_.rx[i] = f_.ux[i];
    f_.ry[i] = f_.uy[i];
    // The step's target, held in g until projected.
    f_.gx[i] = yx - inverse_lipschitz * (vx - up_x_[i] - dx);
    f_.gy[i] = yy - inverse_lipschitz * (vy - up_y_[i] - dy);
  });
  double sx = 0.0;
  double sy = 0.0;
  if (problem_.force_controlled) {
    std::tie(sx, sy) = it_.force_shift([&](std::size_t i) { return std::pair{f_.gx[i], f_.gy[i]}; });
  }
  const auto [against] = sums<1>(comm_, n_, [&](std::size_t i) {
    const auto [qx, qy] = clipped(f_.gx[i] + sx, f_.gy[i] + sy, radius_[i]);
    f_.qx[i] = qx;
    f_.qy[i] = qy;
    // (y - q_new) . (q_new - q_old) > 0: the gradient step points back.
    const double stepx = qx - f_.tx[i];
    const double stepy = qy - f_.ty[i];
    return std::array<double, 1>{(f_.gx[i] - qx) * stepx + (f_.gy[i] - qy) * stepy};
  });
  momentum_ = against < 0.0 ? 0.0 : momentum_ + 1.0;
  it_.exact_displacement();
}

}  // namespace halfspace::solvers::tangential
