// The active-set phase of a tangential step (TangentialOptions::
// active_set_updates): a semi-smooth Newton outer loop in the manner of
// Hintermueller, Ito & Kunisch (2002), carried from p >= 0 to the discs
// |q| <= mu p. Each outer iteration freezes the stick set S, the slip set L,
// each slipping cell's direction e_i and its curvature kappa_i = lambda_i /
// (mu p_i) (lambda_i = -ds_i . e_i its multiplier); what remains is the
// Newton step, a linear problem: stick cells free in both components,
// slipping cells moving along the tangent of their circle only (q_i = mu p_i
// e_i + tau_i t_i, t_i = e_i turned by 90 degrees), minimising the quadratic
// model 1/2 q.C q - q.b + sum_L kappa_i tau_i^2 / 2 (and, under force
// control, sum q = Q, the approach its multiplier). Preconditioned conjugate
// gradients solve it loosely (the inverse of C's symbol restricted to the
// frozen sets with the curvature scaling of tangential_conjugate_gradient.hpp;
// no clipping, no set change inside, so the momentum is never cut). Then the
// slipping tractions are put back onto their circles and every cell is
// classified anew by the semi-smooth Newton form of Coulomb's law
// q = proj_disc(q - c ds) (Alart & Curnier 1991; c = 1/C_ii): a cell slips
// along q - c ds where that lies outside its disc, else sticks. The loop
// stops once no cell changes set and no direction turns by more than
// kSettledTurn, or after the given number of updates, and leaves an
// admissible traction from which the conjugate gradients of
// tangential_conjugate_gradient.hpp finish the step, as the normal
// solver's active-set phase hands over to Polonsky & Keer
// (active_set_start.hpp): the duality gap, checked on an exact product,
// still decides convergence. Internal to src/solvers.
//
// Freezing the directions without the tangential motion (q_i = mu p_i e_i
// held, e_i <- -ds_i/|ds_i| between solves) was tried first: that update is
// a Jacobi iteration on the slipping cells' angles under the non-local C,
// and on the rough benchmark contact it diverged (directions turning by up
// to 90 degrees per update; docs/development-log.md).
#pragma once

#include <cstdint>
#include <span>

#include "tangential_iteration.hpp"

namespace halfspace::solvers::tangential {

struct ActiveSetPhase {
  int updates = 0;     // outer iterations (set updates) made
  int iterations = 0;  // inner conjugate-gradient iterations, all outer iterations
  bool settled = false;
};

class TangentialActiveSet : IterationMethod {
 public:
  // tau and kappa: one entry per cell (the slipping cells' tangential
  // motion and curvature within an outer iteration); single precision,
  // since they only shape the Newton step, which the finishing conjugate
  // gradients correct.
  TangentialActiveSet(TangentialIteration& it, std::span<float> tau, std::span<float> kappa)
      : IterationMethod(it), tau_(tau.data()), kappa_(kappa.data()) {}

  // From the admissible q of TangentialIteration::start() (u = C q exact):
  // at most max_updates outer iterations, each of at most kMaxInnerSteps
  // inner ones, at most max_iterations inner ones in all; leaves q admissible (the caller then projects it onto the
  // force and makes u = C q). Uses t, r and g as workspace and
  // Fields::kind for the sets.
  ActiveSetPhase run(int max_updates, int max_iterations);

  // The inner solve stops once the square norm of the scaled, projected
  // gradient falls below this fraction of its value at the outer
  // iteration's start (on the 256^2 to 1024^2 benchmark contacts 1e-1 let
  // the sets cycle, 1e-3 and 1e-4 spent more iterations per update than
  // the sets were worth).
  static constexpr double kInnerReduction = 1e-2;
  static constexpr int kMaxInnerSteps = 60;
  // A direction that turns by less than this (|e' - e|) counts as settled.
  static constexpr double kSettledTurn = 1e-3;

 private:
  static constexpr std::uint8_t kOutside = 0;
  static constexpr std::uint8_t kStick = 1;
  static constexpr std::uint8_t kSlip = 2;

  // A contact cell's frozen frame: its set, and for a slipping cell the
  // direction e (recovered from q = mu p e + tau t) and the preconditioner's
  // scaling sqrt(C_ii / (C_ii + kappa)).
  struct Frame {
    bool contact = false;
    bool slip = false;
    double ex = 0.0;
    double ey = 0.0;
    double scale = 1.0;
    double kappa = 0.0;
    // v restricted: itself on a stick cell, its tangential part on a
    // slipping one.
    Pair restrict(double x, double y) const {
      if (!slip) return {x, y};
      const double along = -x * ey + y * ex;
      return {-along * ey, along * ex};
    }
    double along(double x, double y) const { return -x * ey + y * ex; }
  };

  Frame frame(std::size_t i) const;
  // ds without the approach under force control (the projection removes
  // it), with the prescribed one under displacement control.
  Pair slip_increment(std::size_t i) const { return {f_.ux[i] - up_x_[i] - fixed_.x, f_.uy[i] - up_y_[i] - fixed_.y}; }
  // The model's gradient restricted to the cell's frame.
  Pair reduced_gradient(std::size_t i, const Frame& c) const;

  // After a set update: the force restored through the frozen frames (the
  // Gram matrix of the restriction), u = C q, and each slipping cell's
  // curvature from its multiplier.
  void prepare();
  // The Newton step: conjugate gradients on the frozen sets, at most
  // `budget` iterations; returns the iterations made.
  int solve_frozen(int budget);
  // q back onto the circles, the sets and directions updated; counts the
  // cells that changed set and the largest turn.
  std::pair<double, double> update();

  float* tau_;
  float* kappa_;
  const double self_ = op_.self_influence().xx;  // C_ii
  Pair fixed_;                                   // the prescribed approach increment (displacement control)
  Symmetric gram_;                               // sum over the cells of the restriction (force control)
};

}  // namespace halfspace::solvers::tangential
