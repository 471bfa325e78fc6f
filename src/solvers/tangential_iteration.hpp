// The state and the shared passes of one tangential load step's iteration
// (tangential_solver.hpp): the problem's data, step 0 (the start), step 1
// (ds, the approach and the duality gap), the stop, the exact product u = C q
// and the exact projection onto the force. The two methods step it:
// ConjugateGradientMethod (tangential_conjugate_gradient.hpp, the default)
// and ProjectedGradientMethod (tangential_projected_gradient.hpp), as
// TangentialSolver::solve drives them. Internal to src/solvers.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>

#include "halfspace/linalg/parallel.hpp"
#include "halfspace/operators/tangential_operator.hpp"
#include "halfspace/solvers/tangential_result.hpp"
#include "halfspace/solvers/tangential_solver.hpp"

namespace halfspace::solvers::tangential {

using linalg::for_each_index;
using linalg::sums;

// Conjugate gradients: u = C q exactly at least every this many steps (the
// linear update misses the circles' second-order pull; 1, 4 and 10 gave
// 17, 17 and 20 iterations on the rough test contact).
inline constexpr int kConjugateUpdatesBetweenExactProducts = 4;
// Conjugate gradients that do not halve the gap in this many steps stall
// (sets swinging back and forth): projected gradients take over for a while
// (tangential_solver.cpp). After a coarse-grid start the sets are already
// near their final size, so a swing is caught sooner; from the fine start
// the sets are still forming and the short window hands over too early
// (measurements: docs/development-log.md, 2026-11-30, fric29h).
inline constexpr int kStalledConjugateSteps = 100;
inline constexpr int kStalledConjugateStepsAfterCoarseStart = 20;
// Projected-gradient steps after a stall before conjugate gradients resume,
// and the stall after which projected gradients go on to the end.
inline constexpr int kProjectedStepsAfterStall = 20;
inline constexpr int kConjugateStalls = 4;
// Slip increments below this fraction of the previous step's largest
// displacement are rounding of the products, not motion (the residual's
// scale is kept above it).
inline constexpr double kResolvedMotion = 1e-9;
// A traction within this relative distance of mu p is at the limit (a
// projected traction lies on the circle to rounding).
inline constexpr double kAtLimit = 1e-12;
// Passes of restore_force that give the force clipped stick cells lost to the
// stick cells left before the exact projection takes over.
inline constexpr int kForceRestoringPasses = 8;
// A force within this relative distance of mu P is gross sliding.
inline constexpr double kSlidingForce = 1e-9;

// |(x, y)|: hypot's overflow guard is not needed at tractions in Pa.
inline double magnitude(double x, double y) {
  return std::sqrt(x * x + y * y);
}

// sums<K>, sums_and_range<K> and for_each_index over the cells of
// `contact` (Problem::contact): term(i) and body(i) get the cell's index.
template <std::size_t K, class Term>
std::array<double, K> contact_sums(const linalg::Communicator& comm, std::span<const std::size_t> contact,
                                   Term&& term) {
  return sums<K>(comm, contact.size(), [&](std::size_t k) HALFSPACE_INLINE_TERM { return term(contact[k]); });
}
template <std::size_t K, class Term>
linalg::SumsAndRange<K> contact_sums_and_range(const linalg::Communicator& comm, std::span<const std::size_t> contact,
                                               Term&& term) {
  return linalg::sums_and_range<K>(comm, contact.size(),
                                   [&](std::size_t k) HALFSPACE_INLINE_TERM { return term(contact[k]); });
}
template <class Body>
void for_each_contact(std::span<const std::size_t> contact, Body&& body) {
  for_each_index(contact.size(), [&](std::size_t k) HALFSPACE_INLINE_TERM { body(contact[k]); });
}

inline bool at_limit(double qx, double qy, double radius) {
  return radius > 0.0 && magnitude(qx, qy) >= radius * (1.0 - kAtLimit);
}

// The nearest point of the disc |q| <= radius.
inline std::pair<double, double> clipped(double x, double y, double radius) {
  const double m = magnitude(x, y);
  if (m <= radius) return {x, y};
  if (!(radius > 0.0)) return {0.0, 0.0};
  const double f = radius / m;
  return {f * x, f * y};
}

struct Problem {
  const double* radius = nullptr;  // mu p
  // The cells with mu p > 0, ascending. The passes of every iteration run
  // over these alone: a rough contact holds a few percent of the grid, and
  // the passes over the whole grid took more than a quarter of a 1024^2
  // step (docs/development-log.md). Outside them q and the direction r stay
  // zero and g, t, u hold values nothing reads until the next exact product.
  std::span<const std::size_t> contact;
  const TangentialState* previous = nullptr;
  // The previous displacement less the step's fixed part (the pressure's
  // coupling displacement; the previous one itself without coupling).
  const double* previous_x = nullptr;
  const double* previous_y = nullptr;
  bool force_controlled = false;
  double target_x = 0.0;  // sum of q under force control (Q / A_cell)
  double target_y = 0.0;
  double delta_x = 0.0;  // delta - delta_prev under displacement control
  double delta_y = 0.0;
  double capacity = 0.0;  // sum of mu p
  double contact_cells = 0.0;
  double cell_area = 0.0;
};

struct Fields {
  double* qx;
  double* qy;
  double* ux;
  double* uy;
  double* gx;
  double* gy;
  double* tx;
  double* ty;
  double* rx;
  double* ry;
  // Conjugate gradients only: each contact cell's set within a step, while
  // gx, gy hold C d (tangential_conjugate_gradient.cpp); unused outside
  // the contact.
  std::uint8_t* kind;
};

// A 2-vector and a symmetric 2x2 matrix.
struct Pair {
  double x = 0.0;
  double y = 0.0;
};
struct Symmetric {
  double xx = 0.0;
  double xy = 0.0;
  double yy = 0.0;
};

// The pseudo-inverse of s applied to v: s's eigenvalues below 1e-12 of its
// trace count as zero (the force's constraint is degenerate when every cell
// slips along one line).
inline Pair solve_pseudo(const Symmetric& s, const Pair& v) {
  const double mean = 0.5 * (s.xx + s.yy);
  const double half_difference = 0.5 * (s.xx - s.yy);
  const double spread = std::hypot(half_difference, s.xy);
  const double floor = 1e-12 * 2.0 * std::abs(mean);
  auto inverse = [&](double e) { return e > floor ? 1.0 / e : 0.0; };
  const double upper = inverse(mean + spread);
  const double lower = inverse(mean - spread);
  const double along = 0.5 * (upper + lower);
  const double across = spread > 0.0 ? 0.5 * (upper - lower) / spread : 0.0;
  return {(along + across * half_difference) * v.x + across * s.xy * v.y,
          across * s.xy * v.x + (along - across * half_difference) * v.y};
}

class TangentialIteration {
 public:
  TangentialIteration(TangentialOperator& op, const TangentialOptions& options, const Problem& problem,
                      TangentialResult& result, Fields f)
      : op_(op),
        options_(options),
        problem_(problem),
        result_(result),
        comm_(op.communicator()),
        n_(op.local_size()),
        f_(f),
        up_x_(problem.previous_x),
        up_y_(problem.previous_y),
        radius_(problem.radius),
        contact_(problem.contact) {}

  // Step 0: the previous traction, clipped to the new discs and, under
  // force control, the force's missing part spread over the contact in
  // proportion to mu p, then projected onto the force. (A uniform shift
  // puts the whole edge of every spot at its limit at once; spread by mu p,
  // the first step of the 1024^2 benchmark took 69 iterations instead of
  // 104, 512^2 42 instead of 37, 256^2 25 instead of 24: docs/
  // development-log.md.)
  // From `given`, the traction already in q (the coarse-grid start), in
  // place of the previous one.
  void start(bool given = false) {
    const double* px = given ? f_.qx : problem_.previous->shear_x.data();
    const double* py = given ? f_.qy : problem_.previous->shear_y.data();
    if (problem_.force_controlled) {
      const auto [held_x, held_y] = sums<2>(comm_, n_, [&](std::size_t i) {
        return radius_[i] > 0.0 ? std::array<double, 2>{px[i], py[i]} : std::array<double, 2>{};
      });
      const double spread_x = problem_.capacity > 0.0 ? (problem_.target_x - held_x) / problem_.capacity : 0.0;
      const double spread_y = problem_.capacity > 0.0 ? (problem_.target_y - held_y) / problem_.capacity : 0.0;
      auto spread = [&](std::size_t i) {
        return std::pair{px[i] + spread_x * radius_[i], py[i] + spread_y * radius_[i]};
      };
      const auto [sx, sy] = force_shift(spread);
      for_each_index(n_, [&](std::size_t i) {
        const auto [x, y] = spread(i);
        std::tie(f_.qx[i], f_.qy[i]) = clipped(x + sx, y + sy, radius_[i]);
      });
    } else {
      for_each_index(n_, [&](std::size_t i) { std::tie(f_.qx[i], f_.qy[i]) = clipped(px[i], py[i], radius_[i]); });
    }
    exact_displacement();
    set_motion_floor();
  }

  // From an admissible traction already in q that holds the force but for
  // a remainder (the active-set phase's): the remainder given back (nothing
  // spread by mu p, since the traction is near the solution), and u = C q.
  void resume() {
    if (problem_.force_controlled) {
      // Given back by the stick cells alike (a shift of every cell would
      // move the slipping ones off their circles by a hair, and the
      // approach, measured over the stick cells, with them).
      const auto [held_x, held_y, stick_cells] = contact_sums<3>(comm_, contact_, [&](std::size_t i) {
        if (!(radius_[i] > 0.0)) return std::array<double, 3>{};
        return std::array<double, 3>{f_.qx[i], f_.qy[i], at_limit(f_.qx[i], f_.qy[i], radius_[i]) ? 0.0 : 1.0};
      });
      restore_force(held_x, held_y, stick_cells);
    }
    exact_displacement();
  }

  // Gives q the force it lacks, target - (held_x, held_y), through its
  // `stick_cells` alike: a stick cell the shift pushes over its disc is
  // clipped onto its circle and the force the clip took is given again by
  // the stick cells left, until no cell is clipped. Slipping cells stay on
  // their circles. Only if no stick cell is left, or the clipped force does
  // not settle in kForceRestoringPasses, is the force restored by the exact
  // projection onto the force and the discs, which shifts the slipping cells
  // too: taken on every step, it moved thousands of them off their circles
  // and back each time, and a free 256^2 sphere's step stalled on
  // rounding-level changes of the input (docs/development-log.md,
  // 2026-11-30). Returns whether a cell was clipped or the projection taken.
  bool restore_force(double held_x, double held_y, double stick_cells) {
    double ex = problem_.target_x - held_x;
    double ey = problem_.target_y - held_y;
    bool changed = false;
    for (int pass = 0; pass < kForceRestoringPasses && stick_cells > 0.0 && (ex != 0.0 || ey != 0.0); ++pass) {
      const double sx = ex / stick_cells;
      const double sy = ey / stick_cells;
      const auto [clipped_cells, lost_x, lost_y] = contact_sums<3>(comm_, contact_, [&](std::size_t i) {
        const double radius = radius_[i];
        if (!(radius > 0.0) || at_limit(f_.qx[i], f_.qy[i], radius)) return std::array<double, 3>{};
        const double x = f_.qx[i] + sx;
        const double y = f_.qy[i] + sy;
        std::tie(f_.qx[i], f_.qy[i]) = clipped(x, y, radius);
        if (magnitude(x, y) <= radius) return std::array<double, 3>{};
        return std::array<double, 3>{1.0, x - f_.qx[i], y - f_.qy[i]};
      });
      if (clipped_cells == 0.0) return changed;
      changed = true;
      ex = lost_x;
      ey = lost_y;
      stick_cells -= clipped_cells;
    }
    if (ex == 0.0 && ey == 0.0) return changed;
    const auto [sx, sy] = force_shift([&](std::size_t i) { return std::pair{f_.qx[i], f_.qy[i]}; });
    for_each_index(
        n_, [&](std::size_t i) { std::tie(f_.qx[i], f_.qy[i]) = clipped(f_.qx[i] + sx, f_.qy[i] + sy, radius_[i]); });
    return true;
  }

  // The slip the products resolve: motion below this fraction of the
  // previous displacement is rounding (a step repeating the previous load
  // moves nothing, and the residual would compare rounding with rounding).
  void set_motion_floor() {
    const auto previous = contact_sums_and_range<1>(comm_, contact_, [&](std::size_t i) {
      return std::pair{std::array<double, 1>{}, radius_[i] > 0.0 ? magnitude(up_x_[i], up_y_[i]) : 0.0};
    });
    motion_floor_ = kResolvedMotion * std::max(previous.max, 0.0);
  }

  // Step 1: ds, the approach, the residual (from an exact product whenever
  // it would stop).
  void evaluate(int iteration) {
    measure();
    if (residual_ <= options_.tolerance && updates_since_exact_ > 0) {
      exact_displacement();
      measure();
    }
    result_.residual_history.push_back(residual_);
    stop_ = stop_requested(options_.progress, iteration, residual_);
  }

  bool finished(int iteration) {
    const std::optional<SolveStatus> status =
        stopping_status(residual_, options_.tolerance, iteration, options_.max_iterations, &result_.message, stop_);
    if (!status) return false;
    result_.status = *status;
    // Stopped short: u exact everywhere (the linear updates followed it in
    // the contact alone) and the residual reported of that u.
    if (updates_since_exact_ > 0) {
      exact_displacement();
      measure();
    }
    return true;
  }

  double approach_x() const { return delta_x_; }
  double approach_y() const { return delta_y_; }
  double residual() const { return residual_; }

  // The uniform shift s with sum_i clip_i(y_i + s) = target (Newton's
  // method on this monotone map, each step halved until the mismatch
  // shrinks; a few passes).
  template <class Moved>
  std::pair<double, double> force_shift(Moved&& moved) const {
    auto mismatch = [&](double sx, double sy) {
      return contact_sums<5>(comm_, contact_, [&](std::size_t i) {
        const double radius = radius_[i];
        if (!(radius > 0.0)) return std::array<double, 5>{};
        auto [x, y] = moved(i);
        x += sx;
        y += sy;
        const double m = std::hypot(x, y);
        if (m <= radius) return std::array<double, 5>{x, y, 1.0, 0.0, 1.0};
        const double f = radius / m;
        const double nx = x / m;
        const double ny = y / m;
        return std::array<double, 5>{f * x, f * y, f * (1.0 - nx * nx), -f * nx * ny, f * (1.0 - ny * ny)};
      });
    };
    double sx = 0.0;
    double sy = 0.0;
    std::array<double, 5> v = mismatch(sx, sy);
    double fx = v[0] - problem_.target_x;
    double fy = v[1] - problem_.target_y;
    double norm = std::hypot(fx, fy);
    const double tolerance = 1e-15 * problem_.capacity;
    constexpr int kMaxNewtonSteps = 60;
    for (int pass = 0; pass < kMaxNewtonSteps && norm > tolerance; ++pass) {
      const double det = v[2] * v[4] - v[3] * v[3];
      double dx = 0.0;
      double dy = 0.0;
      if (det > 1e-12 * (v[2] + v[4]) * (v[2] + v[4])) {
        dx = -(v[4] * fx - v[3] * fy) / det;
        dy = -(-v[3] * fx + v[2] * fy) / det;
      } else {
        const double trace = std::max(v[2] + v[4], 1.0);
        dx = -fx / trace;
        dy = -fy / trace;
      }
      bool accepted = false;
      for (double step = 1.0; step > 1e-12; step *= 0.5) {
        const std::array<double, 5> trial = mismatch(sx + step * dx, sy + step * dy);
        const double tx = trial[0] - problem_.target_x;
        const double ty = trial[1] - problem_.target_y;
        if (std::hypot(tx, ty) < norm) {
          sx += step * dx;
          sy += step * dy;
          v = trial;
          fx = tx;
          fy = ty;
          norm = std::hypot(fx, fy);
          accepted = true;
          break;
        }
      }
      if (!accepted) break;
    }
    return {sx, sy};
  }

  void exact_displacement() {
    op_.apply({f_.qx, n_}, {f_.qy, n_}, {f_.ux, n_}, {f_.uy, n_});
    ++result_.operator_applications;
    updates_since_exact_ = 0;
  }

  // Step 1's passes: the approach (under force control the mean of u - u_prev
  // over the stick cells, where ds vanishes at the solution; over the
  // contact if none sticks), then ds and the residual's sums.
  // Every cell slips: the approach is the one the slip conditions fix, the
  // least-squares delta with each cell's slip increment along its traction
  // (its part across the circle's normal vanishing), i.e. the shift the
  // conjugate gradients' force projector applies. The mean displacement
  // alone is not: against it the reduced gradient vanished with the residual
  // stuck above the tolerance (a rough steel contact on a rigid body at
  // mu = 0.05, pressed: 5.7e-3 for 10000 iterations).
  void full_slip_approach() {
    const auto [xx, xy, yy, across_x, across_y] = contact_sums<5>(comm_, contact_, [&](std::size_t i) {
      const double radius = radius_[i];
      if (!(radius > 0.0)) return std::array<double, 5>{};
      const double m = magnitude(f_.qx[i], f_.qy[i]);
      const double nx = f_.qx[i] / m;
      const double ny = f_.qy[i] / m;
      const double dx = f_.ux[i] - up_x_[i] - delta_x_;
      const double dy = f_.uy[i] - up_y_[i] - delta_y_;
      const double along = dx * nx + dy * ny;
      return std::array<double, 5>{1.0 - nx * nx, -nx * ny, 1.0 - ny * ny, dx - along * nx, dy - along * ny};
    });
    const Pair shift = solve_pseudo({xx, xy, yy}, {across_x, across_y});
    delta_x_ += shift.x;
    delta_y_ += shift.y;
  }

  void measure() {
    if (problem_.force_controlled) {
      const auto [stick_x, stick_y, stick_cells, contact_x, contact_y] =
          contact_sums<5>(comm_, contact_, [&](std::size_t i) {
            if (!(radius_[i] > 0.0)) return std::array<double, 5>{};
            const double dx = f_.ux[i] - up_x_[i];
            const double dy = f_.uy[i] - up_y_[i];
            const double stick = at_limit(f_.qx[i], f_.qy[i], radius_[i]) ? 0.0 : 1.0;
            return std::array<double, 5>{stick * dx, stick * dy, stick, dx, dy};
          });
      const double cells = stick_cells > 0.0 ? stick_cells : problem_.contact_cells;
      delta_x_ = (stick_cells > 0.0 ? stick_x : contact_x) / cells;
      delta_y_ = (stick_cells > 0.0 ? stick_y : contact_y) / cells;
      if (stick_cells == 0.0) full_slip_approach();
    } else {
      delta_x_ = problem_.delta_x;
      delta_y_ = problem_.delta_y;
    }
    const double delta_x = delta_x_;
    const double delta_y = delta_y_;
    const auto settled = contact_sums_and_range<2>(comm_, contact_, [&](std::size_t i) {
      const double radius = radius_[i];
      if (!(radius > 0.0)) {
        f_.gx[i] = 0.0;
        f_.gy[i] = 0.0;
        return std::pair{std::array<double, 2>{}, 0.0};
      }
      const double dx = f_.ux[i] - up_x_[i];
      const double dy = f_.uy[i] - up_y_[i];
      const double gx = dx - delta_x;
      const double gy = dy - delta_y;
      f_.gx[i] = gx;
      f_.gy[i] = gy;
      const double gap = radius * magnitude(gx, gy) + f_.qx[i] * gx + f_.qy[i] * gy;
      return std::pair{std::array<double, 2>{std::max(gap, 0.0), 0.0}, magnitude(dx, dy)};
    });
    const double scale =
        problem_.capacity * std::max(std::max(settled.max, 0.0) + std::hypot(delta_x, delta_y), motion_floor_);
    residual_ = settled.sums[0] == 0.0 ? 0.0 : settled.sums[0] / scale;
  }

 private:
  friend class IterationMethod;

  // The methods step the iteration's fields and count its products.
  TangentialOperator& op_;
  const TangentialOptions& options_;
  const Problem& problem_;
  TangentialResult& result_;
  const linalg::Communicator& comm_;
  const std::size_t n_;
  Fields f_;
  const double* up_x_;  // the previous step's u
  const double* up_y_;
  const double* radius_;
  const std::span<const std::size_t> contact_;

  int updates_since_exact_ = 0;
  double delta_x_ = 0.0;  // the approach's increment over the step
  double delta_y_ = 0.0;
  double residual_ = 0.0;
  bool stop_ = false;          // the progress callback asked to stop
  double motion_floor_ = 0.0;  // m, see start()
};

// What a method that steps the iteration sees of it: the problem's data and
// the fields (ConjugateGradientMethod, TangentialActiveSet,
// ProjectedGradientMethod derive from it).
class IterationMethod {
 protected:
  explicit IterationMethod(TangentialIteration& it)
      : it_(it),
        op_(it.op_),
        options_(it.options_),
        problem_(it.problem_),
        result_(it.result_),
        comm_(it.comm_),
        n_(it.n_),
        f_(it.f_),
        up_x_(it.up_x_),
        up_y_(it.up_y_),
        radius_(it.radius_),
        contact_(it.contact_),
        updates_since_exact_(it.updates_since_exact_) {}

  TangentialIteration& it_;
  TangentialOperator& op_;
  const TangentialOptions& options_;
  const Problem& problem_;
  TangentialResult& result_;
  const linalg::Communicator& comm_;
  const std::size_t n_;
  Fields f_;
  const double* up_x_;  // the previous step's u (less the fixed part)
  const double* up_y_;
  const double* radius_;                        // mu p
  const std::span<const std::size_t> contact_;  // the cells with mu p > 0
  int& updates_since_exact_;                    // the iteration's: products since u = C q was exact
};

}  // namespace halfspace::solvers::tangential
