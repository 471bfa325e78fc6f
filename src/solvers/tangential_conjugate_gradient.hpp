// One preconditioned conjugate-gradient step on the stick/slip sets of a
// tangential step (tangential_solver.hpp, TangentialMethod::
// conjugate_gradient): Polonsky & Keer's (1999) active-set conjugate
// gradients carried from the half-plane p >= 0 to the discs |q| <= mu p, as
// a Riemannian conjugate gradient on the product of the stick cells' planes
// and the slipping cells' circles (the file comment of
// tangential_conjugate_gradient.cpp). Internal to src/solvers.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "tangential_iteration.hpp"

namespace halfspace::solvers::tangential {

class ConjugateGradientMethod : IterationMethod {
 public:
  explicit ConjugateGradientMethod(TangentialIteration& it) : IterationMethod(it) {}

  // One preconditioned conjugate-gradient step on the stick/slip sets (the
  // file comment); g holds ds from evaluate(), t the last preconditioned
  // gradient z, r the last direction d; g holds C d within the step.
  void step();

  // Whether a slipping cell whose multiplier turned negative leaves its
  // circle in this step (released to the stick set). Held (false), the
  // sets change only by clips: the inner loop of an active-set outer loop
  // on frozen releases (tangential_solver.cpp).
  void allow_release(bool allowed) { release_ = allowed; }

  // The next step a steepest-descent one (no momentum), as after other
  // steps moved q (projected gradients after a stall, which leave their own
  // values in r: the direction is zero outside the contact again).
  void restart() {
    momentum_ = false;
    for_each_index(n_, [&](std::size_t i) {
      f_.rx[i] = 0.0;
      f_.ry[i] = 0.0;
    });
  }

 private:
  // Fields::kind's values.
  static constexpr std::uint8_t kStick = 1;  // stick or released
  static constexpr std::uint8_t kSlip = 2;

  // A contact cell's part in the reduced problem: stick (both components
  // free; also a cell at the limit whose slip points outward, `released`) or
  // slip (only the tangent to its circle free, curvature lambda/r).
  struct Cell {
    bool contact = false;
    bool slip = false;
    bool released = false;
    double nx = 0.0;
    double ny = 0.0;
    double curvature = 0.0;
    double scale = 1.0;  // the diagonal scaling of the preconditioner (sqrt)
    // The cell's restriction of a vector: itself, or its tangent part.
    Pair restrict(double x, double y) const {
      if (!slip) return {x, y};
      const double along = scale * (x * nx + y * ny);
      return {scale * x - along * nx, scale * y - along * ny};
    }
    Pair tangent(double x, double y) const {
      if (!slip) return {x, y};
      const double along = x * nx + y * ny;
      return {x - along * nx, y - along * ny};
    }
  };

  Cell cell(std::size_t i) const {
    const double radius = radius_[i];
    Cell c;
    if (!(radius > 0.0)) return c;
    c.contact = true;
    const double qx = f_.qx[i];
    const double qy = f_.qy[i];
    if (!at_limit(qx, qy, radius)) return c;
    const double m = magnitude(qx, qy);
    const double nx = qx / m;
    const double ny = qy / m;
    const double lambda = -(f_.gx[i] * nx + f_.gy[i] * ny);
    if (lambda < 0.0 && release_) {
      c.released = true;
      c.nx = nx;
      c.ny = ny;
      return c;
    }
    c.slip = true;
    c.nx = nx;
    c.ny = ny;
    c.curvature = std::max(lambda, 0.0) / radius;
    c.scale = std::sqrt(self_ / (self_ + c.curvature));
    return c;
  }

  // Pi R g at cell i, c its cell(i) (zero out of contact).
  Pair projected_gradient(std::size_t i, const Cell& c, const Pair& shift) const {
    if (!c.contact) return {};
    const Pair g = c.tangent(f_.gx[i], f_.gy[i]);
    const Pair a = c.tangent(shift.x, shift.y);
    return {g.x - a.x, g.y - a.y};
  }

  const double self_ = op_.self_influence().xx;
  // TangentialOptions::precision mixed: C d and M in single precision.
  const bool single_ = options_.precision == Precision::mixed;
  double rho_old_ = 0.0;   // the last z . Pi R g
  bool momentum_ = false;  // the last step was taken: its direction may carry over
  bool release_ = true;    // allow_release()
};

}  // namespace halfspace::solvers::tangential
