// Conjugate gradients (the default): Polonsky & Keer's (1999) active-set
// conjugate gradients carried from the half-plane p >= 0 to the discs
// |q| <= mu p, as a Riemannian conjugate gradient on the product of the
// stick cells' planes and the slipping cells' circles: a slipping cell moves
// along its circle only, where the objective's second derivative gains the
// curvature term lambda/r (lambda = -ds.q/r >= 0 its multiplier); it
// returns to the stick set once ds points outward (lambda < 0) and a stick
// cell pushed over its disc is clipped onto the circle. The gradient is
// preconditioned by the inverse of C's Fourier symbol restricted to the
// sets (as pk-fourier does for the normal problem), scaled on both sides on
// each slipping cell by sqrt(C_ii / (C_ii + lambda/r)): the curvature, which
// the symbol does not see, dominates on cells of small mu p, and without
// the scaling a rough contact takes ten times the iterations (docs/
// development-log.md). Polak-Ribiere momentum, kept (restricted) when a
// set changes, and under force control the directions are kept
// orthogonal to the force's constraint. Three FFT products per iteration
// (C d, the preconditioner, C q). C d is kept in the slip increment's
// fields (made again from u at the next iteration's start), each cell's set
// in a byte: the solver holds 56 B per point, not 72.
#include "tangential_conjugate_gradient.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace halfspace::solvers::tangential {

void ConjugateGradientMethod::step() {
  const bool force = problem_.force_controlled;
  // The reduced gradient R g (pass A), and the projector onto the force's
  // constraint: sum over stick cells of v plus over slipping cells of
  // their tangent part vanishes; Pi v = v - R a with a = Gram^-1 (sum R v).
  const auto [g_dot_z_old, gram_xx, gram_xy, gram_yy, sum_x, sum_y] =
      contact_sums<6>(comm_, contact_, [&](std::size_t i) {
        const Cell c = cell(i);
        if (!c.contact) return std::array<double, 6>{};
        const Pair g = c.tangent(f_.gx[i], f_.gy[i]);
        return std::array<double, 6>{g.x * f_.tx[i] + g.y * f_.ty[i],
                                     c.slip ? 1.0 - c.nx * c.nx : 1.0,
                                     c.slip ? -c.nx * c.ny : 0.0,
                                     c.slip ? 1.0 - c.ny * c.ny : 1.0,
                                     g.x,
                                     g.y};
      });
  const Symmetric gram{gram_xx, gram_xy, gram_yy};
  const Pair shift_g = force ? solve_pseudo(gram, {sum_x, sum_y}) : Pair{};
  // Pass B: Pi R g into t (zero outside the contact, where the last M t
  // left its values), then z = M t in place.
  for_each_index(n_, [&](std::size_t i) {
    f_.tx[i] = 0.0;
    f_.ty[i] = 0.0;
  });
  for_each_contact(contact_, [&](std::size_t i) {
    const Cell c = cell(i);
    const Pair g = projected_gradient(i, c, shift_g);
    f_.tx[i] = c.scale * g.x;
    f_.ty[i] = c.scale * g.y;
  });
  if (single_) {
    op_.apply_approximate_inverse_in_single_precision({f_.tx, n_}, {f_.ty, n_}, {f_.tx, n_}, {f_.ty, n_});
  } else {
    op_.apply_approximate_inverse({f_.tx, n_}, {f_.ty, n_}, {f_.tx, n_}, {f_.ty, n_});
  }
  ++result_.preconditioner_applications;
  // Pass C: z = Pi R M Pi R g.
  const auto [zx, zy] = contact_sums<2>(comm_, contact_, [&](std::size_t i) {
    const Pair z = cell(i).restrict(f_.tx[i], f_.ty[i]);
    return std::array<double, 2>{z.x, z.y};
  });
  const Pair shift_z = force ? solve_pseudo(gram, {zx, zy}) : Pair{};
  const auto [rho, g_dot_d_old] = contact_sums<2>(comm_, contact_, [&](std::size_t i) {
    const Cell c = cell(i);
    const Pair z = c.restrict(f_.tx[i], f_.ty[i]);
    const Pair a = c.tangent(shift_z.x, shift_z.y);
    f_.tx[i] = z.x - a.x;
    f_.ty[i] = z.y - a.y;
    const Pair g = projected_gradient(i, c, shift_g);
    const Pair d = c.tangent(f_.rx[i], f_.ry[i]);
    return std::array<double, 2>{g.x * f_.tx[i] + g.y * f_.ty[i], g.x * d.x + g.y * d.y};
  });
  // Polak-Ribiere's momentum (with the changing restriction the flexible
  // form), carried through set changes restricted to the new sets; none
  // after a step that was not taken or if the direction would not descend.
  // Restarting on every change (as Polonsky & Keer do on cells entering)
  // left a rough contact's step near steepest descent, since some spot
  // changes set in almost every iteration: 149 iterations at 1024^2 and a
  // stall at 512^2, against 104 and 37 carried (docs/development-log.md).
  double beta = 0.0;
  if (momentum_ && rho_old_ > 0.0) {
    beta = std::max(0.0, (rho - g_dot_z_old) / rho_old_);
    if (!(rho + beta * g_dot_d_old > 0.0)) beta = 0.0;
  }
  rho_old_ = rho;
  if (!(rho > 0.0)) {
    momentum_ = false;
    return;  // the reduced gradient vanishes: only the sets can move
  }
  // Pass D: d = z + beta R d_old, with the step's model along it but for
  // C d: the descent Pi R g . d and the circles' curvature term; each
  // cell's set is kept, since C d then overwrites g (one field pair less).
  const auto [descent, bending] = contact_sums<2>(comm_, contact_, [&](std::size_t i) {
    const Cell c = cell(i);
    f_.kind[i] = c.slip ? kSlip : kStick;
    const Pair d = c.tangent(f_.rx[i], f_.ry[i]);
    double dx = f_.tx[i] + beta * d.x;
    double dy = f_.ty[i] + beta * d.y;
    // A released cell the direction would push outward stays on its circle
    // (moving along it only) for this step: the preconditioner's reach
    // pushes many released cells straight back out, to be clipped again
    // (docs/development-log.md, "the tangential step at 2048^2").
    const double outward = c.released ? -(dx * c.nx + dy * c.ny) : 0.0;
    if (outward > 0.0) {
      dx += outward * c.nx;
      dy += outward * c.ny;
      f_.kind[i] = kSlip;
    }
    f_.rx[i] = dx;
    f_.ry[i] = dy;
    const Pair g = projected_gradient(i, c, shift_g);
    return std::array<double, 2>{g.x * dx + g.y * dy, c.curvature * (dx * dx + dy * dy)};
  });
  // w = C d into g's fields.
  double* const wx = f_.gx;
  double* const wy = f_.gy;
  if (single_) {
    op_.apply_in_single_precision({f_.rx, n_}, {f_.ry, n_}, {wx, n_}, {wy, n_});
  } else {
    op_.apply({f_.rx, n_}, {f_.ry, n_}, {wx, n_}, {wy, n_});
  }
  ++result_.operator_applications;
  // The step minimising the quadratic model along d (curvature included).
  const auto [stiffness] = contact_sums<1>(
      comm_, contact_, [&](std::size_t i) { return std::array<double, 1>{f_.rx[i] * wx[i] + f_.ry[i] * wy[i]}; });
  const double model = stiffness + bending;
  if (!(descent > 0.0 && model > 0.0)) {
    // Not taken (the next evaluate() makes g again from u).
    momentum_ = false;
    return;
  }
  const double alpha = descent / model;
  // Pass E: q -= alpha d, slipping cells back onto their circles, stick
  // cells over their discs clipped onto them; u -= alpha C d in the same
  // pass (replaced below by the exact product where that is due).
  const auto [clipped_cells, stick_cells, sum_qx, sum_qy] = contact_sums<4>(comm_, contact_, [&](std::size_t i) {
    f_.ux[i] -= alpha * wx[i];
    f_.uy[i] -= alpha * wy[i];
    const bool slip = f_.kind[i] == kSlip;
    const double x = f_.qx[i] - alpha * f_.rx[i];
    const double y = f_.qy[i] - alpha * f_.ry[i];
    const double radius = radius_[i];
    const double m = magnitude(x, y);
    if (slip || m > radius) {
      const double scale = m > 0.0 ? radius / m : 0.0;
      f_.qx[i] = scale * x;
      f_.qy[i] = scale * y;
      return std::array<double, 4>{slip ? 0.0 : 1.0, 0.0, f_.qx[i], f_.qy[i]};
    }
    f_.qx[i] = x;
    f_.qy[i] = y;
    return std::array<double, 4>{0.0, 1.0, x, y};
  });
  momentum_ = true;
  bool linear = clipped_cells == 0.0;
  if (force) {
    // The directions keep the force; what the circles and clips moved is
    // given back by the stick cells alike (restore_force).
    if (it_.restore_force(sum_qx, sum_qy, stick_cells)) linear = false;
  }
  // u follows q by the product C d already made, up to the circles'
  // second-order pull, while no cell was clipped; exactly every few steps
  // and always before the stop (evaluate()).
  if (linear && updates_since_exact_ + 1 < kConjugateUpdatesBetweenExactProducts) {
    ++updates_since_exact_;  // u followed in pass E
  } else {
    it_.exact_displacement();
  }
}

}  // namespace halfspace::solvers::tangential
