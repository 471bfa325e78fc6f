// The active-set phase of tangential_active_set.hpp. Per inner iteration
// one product C d and one preconditioner product and four passes over the
// cells (the update of q and u fused with the next gradient's sums); per
// outer iteration one exact product after the set update.
#include "tangential_active_set.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace halfspace::solvers::tangential {

TangentialActiveSet::Frame TangentialActiveSet::frame(std::size_t i) const {
  Frame c;
  const std::uint8_t kind = f_.kind[i];
  if (kind == kOutside) return c;
  c.contact = true;
  if (kind == kStick) return c;
  c.slip = true;
  // q = r e + tau J e with J the quarter turn, so e = (r - tau J) q / (r^2 + tau^2).
  const double r = radius_[i];
  const double tau = tau_[i];
  const double qx = f_.qx[i];
  const double qy = f_.qy[i];
  const double inverse = 1.0 / (r * r + tau * tau);
  c.ex = (r * qx + tau * qy) * inverse;
  c.ey = (r * qy - tau * qx) * inverse;
  c.kappa = kappa_[i];
  c.scale = std::sqrt(self_ / (self_ + c.kappa));
  return c;
}

Pair TangentialActiveSet::reduced_gradient(std::size_t i, const Frame& c) const {
  const Pair g = slip_increment(i);
  if (!c.slip) return g;
  const double along = c.along(g.x, g.y) + c.kappa * tau_[i];
  return {-along * c.ey, along * c.ex};
}

void TangentialActiveSet::prepare() {
  const bool force = problem_.force_controlled;
  // The restriction's Gram matrix and the force the tractions carry.
  const auto [gxx, gxy, gyy, sum_x, sum_y] = sums<5>(comm_, n_, [&](std::size_t i) {
    tau_[i] = 0.0F;
    kappa_[i] = 0.0F;
    const Frame c = frame(i);
    if (!c.contact) return std::array<double, 5>{};
    if (!c.slip) return std::array<double, 5>{1.0, 0.0, 1.0, f_.qx[i], f_.qy[i]};
    return std::array<double, 5>{c.ey * c.ey, -c.ex * c.ey, c.ex * c.ex, f_.qx[i], f_.qy[i]};
  });
  gram_ = {gxx, gxy, gyy};
  if (force) {
    // The missing force given back through the frames (stick cells alike,
    // slipping ones along their tangents): the least change that restores it.
    const Pair b = solve_pseudo(gram_, {problem_.target_x - sum_x, problem_.target_y - sum_y});
    if (b.x != 0.0 || b.y != 0.0) {
      for_each_index(n_, [&](std::size_t i) {
        const Frame c = frame(i);
        if (!c.contact) return;
        const Pair v = c.restrict(b.x, b.y);
        if (c.slip) tau_[i] = static_cast<float>(c.along(b.x, b.y));
        f_.qx[i] += v.x;
        f_.qy[i] += v.y;
      });
    }
  }
  it_.exact_displacement();
  // Each slipping cell's multiplier lambda = -(ds - a) . e, the approach a
  // under force control estimated as the model's multiplier with no
  // curvature yet (the least-squares fit of ds by the restricted shifts).
  Pair a{};
  if (force) {
    const auto [rx, ry] = sums<2>(comm_, n_, [&](std::size_t i) {
      const Frame c = frame(i);
      if (!c.contact) return std::array<double, 2>{};
      const Pair g = slip_increment(i);
      const Pair v = c.restrict(g.x, g.y);
      return std::array<double, 2>{v.x, v.y};
    });
    a = solve_pseudo(gram_, {rx, ry});
  }
  for_each_index(n_, [&](std::size_t i) {
    if (f_.kind[i] != kSlip) return;
    const Frame c = frame(i);
    const Pair g = slip_increment(i);
    const double lambda = -((g.x - a.x) * c.ex + (g.y - a.y) * c.ey);
    kappa_[i] = static_cast<float>(std::max(lambda, 0.0) / radius_[i]);
  });
}

int TangentialActiveSet::solve_frozen(int budget) {
  const bool force = problem_.force_controlled;
  // The projection onto sum R v = 0 (force control): Pi v = v - R a with
  // a = Gram^-1 sum R v, orthogonal within the restriction's range.
  auto gradient_sums = [&]() {
    const auto [x, y] = sums<2>(comm_, n_, [&](std::size_t i) {
      const Frame c = frame(i);
      if (!c.contact) return std::array<double, 2>{};
      const Pair g = reduced_gradient(i, c);
      return std::array<double, 2>{g.x, g.y};
    });
    return force ? solve_pseudo(gram_, {x, y}) : Pair{};
  };
  Pair a_g = gradient_sums();
  double* const wx = f_.gx;  // C d
  double* const wy = f_.gy;
  double norm_start = 0.0;
  double rho_old = 0.0;
  int j = 0;
  for (;; ++j) {
    // t = D Pi R g (D the curvature scaling), its square norm deciding the
    // stop (before the preconditioner's product, which a stop would waste).
    const auto [gg] = sums<1>(comm_, n_, [&](std::size_t i) {
      const Frame c = frame(i);
      if (!c.contact) {
        f_.tx[i] = 0.0;
        f_.ty[i] = 0.0;
        return std::array<double, 1>{};
      }
      const Pair g = reduced_gradient(i, c);
      const Pair shift = c.restrict(a_g.x, a_g.y);
      f_.tx[i] = c.scale * (g.x - shift.x);
      f_.ty[i] = c.scale * (g.y - shift.y);
      return std::array<double, 1>{f_.tx[i] * f_.tx[i] + f_.ty[i] * f_.ty[i]};
    });
    if (j == 0) norm_start = gg;
    if (!(gg > kInnerReduction * norm_start) || j >= std::min(kMaxInnerSteps, budget)) break;
    op_.apply_approximate_inverse({f_.tx, n_}, {f_.ty, n_}, {f_.tx, n_}, {f_.ty, n_});
    ++result_.preconditioner_applications;
    // rho = Pi R g . Pi R D M t = Pi R g . R D M t (Pi R g is orthogonal to
    // the range of the shifts R a), and sum R D M t for its projection.
    const auto [rho, zx, zy] = sums<3>(comm_, n_, [&](std::size_t i) {
      const Frame c = frame(i);
      if (!c.contact) return std::array<double, 3>{};
      const Pair g = reduced_gradient(i, c);
      const Pair shift = c.restrict(a_g.x, a_g.y);
      const Pair z = c.restrict(c.scale * f_.tx[i], c.scale * f_.ty[i]);
      return std::array<double, 3>{(g.x - shift.x) * z.x + (g.y - shift.y) * z.y, z.x, z.y};
    });
    if (!(rho > 0.0)) break;
    const Pair a_z = force ? solve_pseudo(gram_, {zx, zy}) : Pair{};
    const double beta = j > 0 ? rho / rho_old : 0.0;
    rho_old = rho;
    // d = Pi R D M t + beta d (the old d lies in the frozen range already),
    // and the model's curvature along it but for C d.
    const auto [bending] = sums<1>(comm_, n_, [&](std::size_t i) {
      const Frame c = frame(i);
      if (!c.contact) {
        f_.rx[i] = 0.0;
        f_.ry[i] = 0.0;
        return std::array<double, 1>{};
      }
      const Pair z = c.restrict(c.scale * f_.tx[i], c.scale * f_.ty[i]);
      const Pair shift = c.restrict(a_z.x, a_z.y);
      const double dx = z.x - shift.x + beta * f_.rx[i];
      const double dy = z.y - shift.y + beta * f_.ry[i];
      f_.rx[i] = dx;
      f_.ry[i] = dy;
      return std::array<double, 1>{c.kappa * (dx * dx + dy * dy)};
    });
    op_.apply({f_.rx, n_}, {f_.ry, n_}, {wx, n_}, {wy, n_});
    ++result_.operator_applications;
    const auto [stiffness] =
        sums<1>(comm_, n_, [&](std::size_t i) { return std::array<double, 1>{f_.rx[i] * wx[i] + f_.ry[i] * wy[i]}; });
    const double model = stiffness + bending;
    if (!(model > 0.0)) break;
    const double alpha = rho / model;
    // q -= alpha d (slipping cells along their tangent, tau following),
    // u -= alpha C d (exact: nothing is clipped), and the next gradient's
    // sums in the same pass.
    const auto [sx, sy] = sums<2>(comm_, n_, [&](std::size_t i) {
      f_.ux[i] -= alpha * wx[i];
      f_.uy[i] -= alpha * wy[i];
      const Frame c = frame(i);
      if (!c.contact) return std::array<double, 2>{};
      if (c.slip) tau_[i] = static_cast<float>(tau_[i] - alpha * c.along(f_.rx[i], f_.ry[i]));
      f_.qx[i] -= alpha * f_.rx[i];
      f_.qy[i] -= alpha * f_.ry[i];
      const Pair g = reduced_gradient(i, c);
      return std::array<double, 2>{g.x, g.y};
    });
    a_g = force ? solve_pseudo(gram_, {sx, sy}) : Pair{};
  }
  return j;
}

std::pair<double, double> TangentialActiveSet::update() {
  const bool force = problem_.force_controlled;
  // The approach for the classification: the model's multiplier.
  Pair a = fixed_;
  if (force) {
    const auto [x, y] = sums<2>(comm_, n_, [&](std::size_t i) {
      const Frame c = frame(i);
      if (!c.contact) return std::array<double, 2>{};
      const Pair g = reduced_gradient(i, c);
      return std::array<double, 2>{g.x, g.y};
    });
    const Pair shift = solve_pseudo(gram_, {x, y});
    a = {shift.x, shift.y};
  }
  // Where the Newton step left the traction: slipping cells back onto
  // their circles, then q = proj(q - c ds) decides the sets (stick cells
  // count ds as zero: the inner solve's remainder).
  const double c_scale = 1.0 / self_;
  const auto counts = linalg::sums_and_range<1>(comm_, n_, [&](std::size_t i) {
    const Frame c = frame(i);
    if (!c.contact) return std::pair{std::array<double, 1>{}, 0.0};
    const double radius = radius_[i];
    double qx = f_.qx[i];
    double qy = f_.qy[i];
    double gx = 0.0;
    double gy = 0.0;
    if (c.slip) {
      const double m = magnitude(qx, qy);
      qx *= radius / m;
      qy *= radius / m;
      gx = f_.ux[i] - up_x_[i] - a.x;
      gy = f_.uy[i] - up_y_[i] - a.y;
    }
    const double yx = qx - c_scale * gx;
    const double yy = qy - c_scale * gy;
    const double m = magnitude(yx, yy);
    if (!(m > radius)) {
      f_.kind[i] = kStick;
      f_.qx[i] = qx;
      f_.qy[i] = qy;
      return std::pair{std::array<double, 1>{c.slip ? 1.0 : 0.0}, 0.0};
    }
    const double nx = yx / m;
    const double ny = yy / m;
    f_.qx[i] = radius * nx;
    f_.qy[i] = radius * ny;
    f_.kind[i] = kSlip;
    const double turn = c.slip ? magnitude(nx - c.ex, ny - c.ey) : 0.0;
    return std::pair{std::array<double, 1>{c.slip ? 0.0 : 1.0}, turn};
  });
  // The frames are now those of q on the circles.
  for_each_index(n_, [&](std::size_t i) { tau_[i] = 0.0F; });
  return {counts.sums[0], counts.max};
}

ActiveSetPhase TangentialActiveSet::run(int max_updates, int max_iterations) {
  ActiveSetPhase phase;
  fixed_ = problem_.force_controlled ? Pair{} : Pair{problem_.delta_x, problem_.delta_y};
  // The sets of the start: cells at their limit slip along their traction.
  for_each_index(n_, [&](std::size_t i) {
    const double radius = radius_[i];
    tau_[i] = 0.0F;
    f_.kind[i] = !(radius > 0.0) ? kOutside : (at_limit(f_.qx[i], f_.qy[i], radius) ? kSlip : kStick);
  });
  prepare();
  for (int outer = 0; outer < max_updates && phase.iterations < max_iterations; ++outer) {
    phase.iterations += solve_frozen(max_iterations - phase.iterations);
    ++phase.updates;
    const auto [changed, turn] = update();
    if (changed == 0.0 && turn < kSettledTurn) {
      phase.settled = true;
      break;
    }
    if (outer + 1 < max_updates) prepare();
  }
  // An admissible traction (the force is the caller's to restore).
  for_each_index(n_, [&](std::size_t i) { std::tie(f_.qx[i], f_.qy[i]) = clipped(f_.qx[i], f_.qy[i], radius_[i]); });
  return phase;
}

}  // namespace halfspace::solvers::tangential
