// The partial-slip problem of tangential_solver.hpp. Each iteration
// evaluates the slip increment ds (the gradient) and the approach, measures
// the duality gap, steps, projects onto the discs (and the force) and makes
// u = C q exactly.
//
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
// development-log.md). Polak-Ribiere momentum, which restarts
// whenever a set changes, and under force control the directions are kept
// orthogonal to the force's constraint. Three FFT products per iteration
// (C d, the preconditioner, C q).
//
// Projected gradients (TangentialMethod::projected_gradient): accelerated
// (Nesterov 1983; Beck & Teboulle 2009, FISTA) with adaptive restart
// (O'Donoghue & Candes 2015): a step 1/L from the extrapolated point, one
// product per iteration, iterations growing with the grid.
#include "halfspace/solvers/tangential_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::solvers {
namespace {

using linalg::for_each_index;
using linalg::sums;

// Conjugate gradients: u = C q exactly at least every this many steps (the
// linear update misses the circles' second-order pull; 1, 4 and 10 gave
// 17, 17 and 20 iterations on the rough test contact).
constexpr int kConjugateUpdatesBetweenExactProducts = 4;
// Conjugate gradients that do not halve the gap in this many steps stall
// (sets swinging back and forth): projected gradients take over.
constexpr int kStalledConjugateSteps = 100;
// Slip increments below this fraction of the previous step's largest
// displacement are rounding of the products, not motion (the residual's
// scale is kept above it).
constexpr double kResolvedMotion = 1e-9;
// A traction within this relative distance of mu p is at the limit (a
// projected traction lies on the circle to rounding).
constexpr double kAtLimit = 1e-12;
// A force within this relative distance of mu P is gross sliding.
constexpr double kSlidingForce = 1e-9;

// |(x, y)|: hypot's overflow guard is not needed at tractions in Pa.
double magnitude(double x, double y) {
  return std::sqrt(x * x + y * y);
}

bool at_limit(double qx, double qy, double radius) {
  return radius > 0.0 && magnitude(qx, qy) >= radius * (1.0 - kAtLimit);
}

// The nearest point of the disc |q| <= radius.
std::pair<double, double> clipped(double x, double y, double radius) {
  const double m = magnitude(x, y);
  if (m <= radius) return {x, y};
  if (!(radius > 0.0)) return {0.0, 0.0};
  const double f = radius / m;
  return {f * x, f * y};
}

struct Problem {
  const double* radius = nullptr;  // mu p
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
  double* wx;  // conjugate gradients only
  double* wy;
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
Pair solve_pseudo(const Symmetric& s, const Pair& v) {
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

class Iteration {
 public:
  Iteration(TangentialOperator& op, const TangentialOptions& options, const Problem& problem, TangentialResult& result,
            Fields f)
      : op_(op),
        options_(options),
        problem_(problem),
        result_(result),
        comm_(op.communicator()),
        n_(op.local_size()),
        f_(f),
        up_x_(problem.previous_x),
        up_y_(problem.previous_y),
        radius_(problem.radius) {}

  // Step 0: the previous traction, clipped to the new discs and, under
  // force control, projected onto the force.
  void start() {
    const double* px = problem_.previous->shear_x.data();
    const double* py = problem_.previous->shear_y.data();
    if (problem_.force_controlled) {
      const auto [sx, sy] = force_shift([&](std::size_t i) { return std::pair{px[i], py[i]}; });
      for_each_index(
          n_, [&](std::size_t i) { std::tie(f_.qx[i], f_.qy[i]) = clipped(px[i] + sx, py[i] + sy, radius_[i]); });
    } else {
      for_each_index(n_, [&](std::size_t i) { std::tie(f_.qx[i], f_.qy[i]) = clipped(px[i], py[i], radius_[i]); });
    }
    exact_displacement();
    // The slip the products resolve: motion below this fraction of the
    // previous displacement is rounding (a step repeating the previous load
    // moves nothing, and the residual would compare rounding with rounding).
    const auto previous = linalg::sums_and_range<1>(comm_, n_, [&](std::size_t i) {
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
    if (options_.progress) options_.progress(iteration, residual_);
  }

  bool finished(int iteration) {
    const std::optional<SolveStatus> status =
        stopping_status(residual_, options_.tolerance, iteration, options_.max_iterations, &result_.message);
    if (status) result_.status = *status;
    return status.has_value();
  }

  // One accelerated projected-gradient step (Nesterov; Beck & Teboulle's
  // FISTA) with step 1/L, L >= the largest eigenvalue of C, from the
  // extrapolated point y = q + beta (q - q_old) (u = C y by linearity):
  // q = P(y - (C y - u_prev - delta)/L), then u = C q exactly. The momentum
  // restarts when the step turns against the previous one (O'Donoghue &
  // Candes 2015's gradient test). t and r hold q_old and u_old.
  void accelerate(double inverse_lipschitz) {
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
      std::tie(sx, sy) = force_shift([&](std::size_t i) { return std::pair{f_.gx[i], f_.gy[i]}; });
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
    exact_displacement();
  }

  // One preconditioned conjugate-gradient step on the stick/slip sets (the
  // file comment); g holds ds from evaluate(), t the last preconditioned
  // gradient z, r the last direction d, w is C d.
  void conjugate() {
    const bool force = problem_.force_controlled;
    // The reduced gradient R g (pass A), and the projector onto the force's
    // constraint: sum over stick cells of v plus over slipping cells of
    // their tangent part vanishes; Pi v = v - R a with a = Gram^-1 (sum R v).
    const auto [released, g_dot_z_old, gram_xx, gram_xy, gram_yy, sum_x, sum_y] =
        sums<7>(comm_, n_, [&](std::size_t i) {
          const Cell c = cell(i);
          if (!c.contact) return std::array<double, 7>{};
          const Pair g = c.tangent(f_.gx[i], f_.gy[i]);
          return std::array<double, 7>{c.released ? 1.0 : 0.0,
                                       g.x * f_.tx[i] + g.y * f_.ty[i],
                                       c.slip ? 1.0 - c.nx * c.nx : 1.0,
                                       c.slip ? -c.nx * c.ny : 0.0,
                                       c.slip ? 1.0 - c.ny * c.ny : 1.0,
                                       g.x,
                                       g.y};
        });
    const Symmetric gram{gram_xx, gram_xy, gram_yy};
    const Pair shift_g = force ? solve_pseudo(gram, {sum_x, sum_y}) : Pair{};
    // Pass B: Pi R g into t, then z = M t in place.
    for_each_index(n_, [&](std::size_t i) {
      const Pair g = projected_gradient(i, shift_g);
      const double scale = cell(i).scale;
      f_.tx[i] = scale * g.x;
      f_.ty[i] = scale * g.y;
    });
    op_.apply_approximate_inverse({f_.tx, n_}, {f_.ty, n_}, {f_.tx, n_}, {f_.ty, n_});
    ++result_.preconditioner_applications;
    // Pass C: z = Pi R M Pi R g.
    const auto [zx, zy] = sums<2>(comm_, n_, [&](std::size_t i) {
      const Cell c = cell(i);
      if (!c.contact) return std::array<double, 2>{};
      const Pair z = c.restrict(f_.tx[i], f_.ty[i]);
      return std::array<double, 2>{z.x, z.y};
    });
    const Pair shift_z = force ? solve_pseudo(gram, {zx, zy}) : Pair{};
    const auto [rho, g_dot_d_old] = sums<2>(comm_, n_, [&](std::size_t i) {
      const Cell c = cell(i);
      if (!c.contact) {
        f_.tx[i] = 0.0;
        f_.ty[i] = 0.0;
        return std::array<double, 2>{};
      }
      const Pair z = c.restrict(f_.tx[i], f_.ty[i]);
      const Pair a = c.tangent(shift_z.x, shift_z.y);
      f_.tx[i] = z.x - a.x;
      f_.ty[i] = z.y - a.y;
      const Pair g = projected_gradient(i, shift_g);
      const Pair d = c.tangent(f_.rx[i], f_.ry[i]);
      return std::array<double, 2>{g.x * f_.tx[i] + g.y * f_.ty[i], g.x * d.x + g.y * d.y};
    });
    // Polak-Ribiere's momentum (with the changing restriction the flexible
    // form), none after a set changed or if the direction would not descend.
    double beta = 0.0;
    if (sets_unchanged_ && released == 0.0 && rho_old_ > 0.0) {
      beta = std::max(0.0, (rho - g_dot_z_old) / rho_old_);
      if (!(rho + beta * g_dot_d_old > 0.0)) beta = 0.0;
    }
    rho_old_ = rho;
    if (!(rho > 0.0)) {
      sets_unchanged_ = false;
      return;  // the reduced gradient vanishes: only the sets can move
    }
    // Pass D: d = z + beta R d_old.
    for_each_index(n_, [&](std::size_t i) {
      const Cell c = cell(i);
      const Pair d = c.contact ? c.tangent(f_.rx[i], f_.ry[i]) : Pair{};
      f_.rx[i] = f_.tx[i] + beta * d.x;
      f_.ry[i] = f_.ty[i] + beta * d.y;
    });
    op_.apply({f_.rx, n_}, {f_.ry, n_}, {f_.wx, n_}, {f_.wy, n_});
    ++result_.operator_applications;
    // The step minimising the quadratic model along d (curvature included).
    const auto [descent, model] = sums<2>(comm_, n_, [&](std::size_t i) {
      const Cell c = cell(i);
      if (!c.contact) return std::array<double, 2>{};
      const Pair g = projected_gradient(i, shift_g);
      const double dx = f_.rx[i];
      const double dy = f_.ry[i];
      return std::array<double, 2>{g.x * dx + g.y * dy,
                                   dx * f_.wx[i] + dy * f_.wy[i] + c.curvature * (dx * dx + dy * dy)};
    });
    if (!(descent > 0.0 && model > 0.0)) {
      sets_unchanged_ = false;
      return;
    }
    const double alpha = descent / model;
    // Pass E: q -= alpha d, slipping cells back onto their circles, stick
    // cells over their discs clipped onto them.
    const auto [clipped_cells, stick_cells, sum_qx, sum_qy] = sums<4>(comm_, n_, [&](std::size_t i) {
      const Cell c = cell(i);
      if (!c.contact) return std::array<double, 4>{};
      const double x = f_.qx[i] - alpha * f_.rx[i];
      const double y = f_.qy[i] - alpha * f_.ry[i];
      const double radius = radius_[i];
      const double m = magnitude(x, y);
      if (c.slip || m > radius) {
        const double scale = m > 0.0 ? radius / m : 0.0;
        f_.qx[i] = scale * x;
        f_.qy[i] = scale * y;
        return std::array<double, 4>{c.slip ? 0.0 : 1.0, 0.0, f_.qx[i], f_.qy[i]};
      }
      f_.qx[i] = x;
      f_.qy[i] = y;
      return std::array<double, 4>{0.0, 1.0, x, y};
    });
    sets_unchanged_ = clipped_cells == 0.0 && released == 0.0;
    bool linear = clipped_cells == 0.0;
    if (force) {
      // The directions keep the force; what the circles and clips moved is
      // given back by the stick cells alike, or, if that pushes one over its
      // disc, by the exact projection onto the force and the discs.
      const double ex = problem_.target_x - sum_qx;
      const double ey = problem_.target_y - sum_qy;
      bool exact = stick_cells == 0.0;
      if (!exact && (ex != 0.0 || ey != 0.0)) {
        const double sx = ex / stick_cells;
        const double sy = ey / stick_cells;
        const auto [over] = sums<1>(comm_, n_, [&](std::size_t i) {
          const double radius = radius_[i];
          if (!(radius > 0.0) || at_limit(f_.qx[i], f_.qy[i], radius)) return std::array<double, 1>{};
          f_.qx[i] += sx;
          f_.qy[i] += sy;
          return std::array<double, 1>{magnitude(f_.qx[i], f_.qy[i]) > radius ? 1.0 : 0.0};
        });
        exact = over > 0.0;
      }
      if (exact) {
        const auto [sx, sy] = force_shift([&](std::size_t i) { return std::pair{f_.qx[i], f_.qy[i]}; });
        for_each_index(n_, [&](std::size_t i) {
          std::tie(f_.qx[i], f_.qy[i]) = clipped(f_.qx[i] + sx, f_.qy[i] + sy, radius_[i]);
        });
        linear = false;
        sets_unchanged_ = false;
      }
    }
    // u follows q by the product C d already made, up to the circles'
    // second-order pull, while no cell was clipped; exactly every few steps
    // and always before the stop (evaluate()).
    if (linear && updates_since_exact_ + 1 < kConjugateUpdatesBetweenExactProducts) {
      for_each_index(n_, [&](std::size_t i) {
        f_.ux[i] -= alpha * f_.wx[i];
        f_.uy[i] -= alpha * f_.wy[i];
      });
      ++updates_since_exact_;
    } else {
      exact_displacement();
    }
  }

  // Hands over from conjugate gradients to projected gradients at the
  // current iterate (no momentum; t and r hold q and u = C q).
  void begin_projected_gradient() {
    exact_displacement();
    for_each_index(n_, [&](std::size_t i) {
      f_.tx[i] = f_.qx[i];
      f_.ty[i] = f_.qy[i];
      f_.rx[i] = f_.ux[i];
      f_.ry[i] = f_.uy[i];
    });
    momentum_ = 0.0;
  }

  double approach_x() const { return delta_x_; }
  double approach_y() const { return delta_y_; }
  double residual() const { return residual_; }

 private:
  // The uniform shift s with sum_i clip_i(y_i + s) = target (Newton's
  // method on this monotone map, each step halved until the mismatch
  // shrinks; a few passes).
  template <class Moved>
  std::pair<double, double> force_shift(Moved&& moved) const {
    auto mismatch = [&](double sx, double sy) {
      return sums<5>(comm_, n_, [&](std::size_t i) {
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
    if (lambda < 0.0) {
      c.released = true;
      return c;
    }
    c.slip = true;
    c.nx = nx;
    c.ny = ny;
    c.curvature = lambda / radius;
    c.scale = std::sqrt(self_ / (self_ + c.curvature));
    return c;
  }

  // Pi R g at cell i (zero out of contact).
  Pair projected_gradient(std::size_t i, const Pair& shift) const {
    const Cell c = cell(i);
    if (!c.contact) return {};
    const Pair g = c.tangent(f_.gx[i], f_.gy[i]);
    const Pair a = c.tangent(shift.x, shift.y);
    return {g.x - a.x, g.y - a.y};
  }

  void exact_displacement() {
    op_.apply({f_.qx, n_}, {f_.qy, n_}, {f_.ux, n_}, {f_.uy, n_});
    ++result_.operator_applications;
    updates_since_exact_ = 0;
  }

  // Step 1's passes: the approach (under force control the mean of u - u_prev
  // over the stick cells, where ds vanishes at the solution; over the
  // contact if none sticks), then ds and the residual's sums.
  void measure() {
    if (problem_.force_controlled) {
      const auto [stick_x, stick_y, stick_cells, contact_x, contact_y] = sums<5>(comm_, n_, [&](std::size_t i) {
        if (!(radius_[i] > 0.0)) return std::array<double, 5>{};
        const double dx = f_.ux[i] - up_x_[i];
        const double dy = f_.uy[i] - up_y_[i];
        const double stick = at_limit(f_.qx[i], f_.qy[i], radius_[i]) ? 0.0 : 1.0;
        return std::array<double, 5>{stick * dx, stick * dy, stick, dx, dy};
      });
      const double cells = stick_cells > 0.0 ? stick_cells : problem_.contact_cells;
      delta_x_ = (stick_cells > 0.0 ? stick_x : contact_x) / cells;
      delta_y_ = (stick_cells > 0.0 ? stick_y : contact_y) / cells;
    } else {
      delta_x_ = problem_.delta_x;
      delta_y_ = problem_.delta_y;
    }
    const double delta_x = delta_x_;
    const double delta_y = delta_y_;
    const auto settled = linalg::sums_and_range<2>(comm_, n_, [&](std::size_t i) {
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

  const double self_ = op_.self_influence().xx;
  int updates_since_exact_ = 0;
  double delta_x_ = 0.0;  // the approach's increment over the step
  double delta_y_ = 0.0;
  double residual_ = 0.0;
  double motion_floor_ = 0.0;  // m, see start()
  double momentum_ = 0.0;
  double rho_old_ = 0.0;         // conjugate gradients: the last z . Pi R g
  bool sets_unchanged_ = false;  // no cell changed set in the last step
};

void check_size(std::string_view what, std::size_t got, std::size_t expected) {
  if (got != expected) {
    throw InputError(fmt::format("{} has {} entries, but the grid has {} cells", what, got, expected));
  }
}

}  // namespace

std::string_view to_string(TangentialControl control) {
  return control == TangentialControl::force ? "tangential force" : "tangential displacement";
}

void TangentialLoading::validate() const {
  if (!std::isfinite(x) || !std::isfinite(y)) {
    throw InputError(fmt::format("{} ({}, {}) is invalid: both components must be finite", to_string(control), x, y));
  }
}

TangentialState TangentialState::unloaded(std::size_t cells) {
  const auto n = static_cast<Eigen::Index>(cells);
  TangentialState state;
  for (Eigen::ArrayXd* field :
       {&state.shear_x, &state.shear_y, &state.displacement_x, &state.displacement_y, &state.slip_x, &state.slip_y}) {
    field->setZero(n);
  }
  return state;
}

void TangentialOptions::validate() const {
  if (!(std::isfinite(friction_coefficient) && friction_coefficient >= 0.0)) {
    throw InputError(
        fmt::format("friction coefficient mu = {} is invalid: must be finite and non-negative", friction_coefficient));
  }
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw InputError(fmt::format("tolerance = {} is invalid: allowed range is (0, 1)", tolerance));
  }
  if (max_iterations < 1) {
    throw InputError(fmt::format("max_iterations = {} is invalid: must be at least 1", max_iterations));
  }
  if (method != TangentialMethod::conjugate_gradient && method != TangentialMethod::projected_gradient) {
    throw InputError(
        fmt::format("tangential method {} is invalid: allowed are conjugate_gradient (0) and "
                    "projected_gradient (1)",
                    static_cast<int>(method)));
  }
}

TangentialSolver::TangentialSolver(TangentialOperator& op, TangentialOptions options)
    : op_(op), options_(std::move(options)) {
  options_.validate();
  const auto n = static_cast<Eigen::Index>(op_.local_size());
  radius_.setZero(n);
  for (Eigen::ArrayXd* field : {&gx_, &gy_, &tx_, &ty_, &rx_, &ry_}) field->setZero(n);
  if (options_.method == TangentialMethod::conjugate_gradient) {
    wx_.setZero(n);
    wy_.setZero(n);
  }
}

TangentialResult TangentialSolver::solve(std::span<const double> pressure, const TangentialLoading& loading,
                                         const TangentialState& previous) {
  return solve(pressure, loading, previous, {}, {});
}

TangentialResult TangentialSolver::solve(std::span<const double> pressure, const TangentialLoading& loading,
                                         const TangentialState& previous, std::span<const double> fixed_x,
                                         std::span<const double> fixed_y) {
  const auto start_time = std::chrono::steady_clock::now();
  const std::size_t n = op_.local_size();
  const Grid& grid = op_.grid();
  const linalg::Communicator& comm = op_.communicator();
  check_size("pressure", pressure.size(), n);
  for (const Eigen::ArrayXd* field : {&previous.shear_x, &previous.shear_y, &previous.displacement_x,
                                      &previous.displacement_y, &previous.slip_x, &previous.slip_y}) {
    check_size("previous tangential state", static_cast<std::size_t>(field->size()), n);
  }
  loading.validate();
  const double mu = options_.friction_coefficient;
  const auto [pressure_sum, contact_cells, bad] = sums<3>(comm, n, [&](std::size_t i) {
    const double p = pressure[i];
    return std::array<double, 3>{std::isfinite(p) ? p : 0.0, p > 0.0 ? 1.0 : 0.0,
                                 std::isfinite(p) && p >= 0.0 ? 0.0 : 1.0};
  });
  if (bad > 0.0) throw InputError("pressure holds a negative or non-finite value: friction needs a contact pressure");
  for_each_index(n, [&](std::size_t i) { radius_[static_cast<Eigen::Index>(i)] = mu * pressure[i]; });

  const double area = grid.cell_area();
  Problem problem;
  problem.radius = radius_.data();
  problem.previous = &previous;
  const bool fixed = !fixed_x.empty() || !fixed_y.empty();
  if (fixed) {
    check_size("fixed tangential displacement x", fixed_x.size(), n);
    check_size("fixed tangential displacement y", fixed_y.size(), n);
    if (fx_.size() != static_cast<Eigen::Index>(n)) {
      fx_.setZero(static_cast<Eigen::Index>(n));
      fy_.setZero(static_cast<Eigen::Index>(n));
    }
    for_each_index(n, [&](std::size_t i) {
      const auto j = static_cast<Eigen::Index>(i);
      fx_[j] = previous.displacement_x[j] - fixed_x[i];
      fy_[j] = previous.displacement_y[j] - fixed_y[i];
    });
    problem.previous_x = fx_.data();
    problem.previous_y = fy_.data();
  } else {
    problem.previous_x = previous.displacement_x.data();
    problem.previous_y = previous.displacement_y.data();
  }
  problem.force_controlled = loading.control == TangentialControl::force;
  problem.capacity = mu * pressure_sum;
  problem.contact_cells = contact_cells;
  problem.cell_area = area;
  const double limit = problem.capacity * area;  // mu P
  bool sliding = false;
  if (problem.force_controlled) {
    problem.target_x = loading.x / area;
    problem.target_y = loading.y / area;
    const double force = std::hypot(loading.x, loading.y);
    if (force > limit * (1.0 + kSlidingForce)) {
      throw InputError(fmt::format(
          "tangential force {:.6g} exceeds the friction limit mu P = {:.6g} (mu = {}, P = {:.6g}): the contact slides; "
          "impose a tangential displacement to follow sliding",
          force, limit, mu, pressure_sum * area));
    }
    sliding = force > 0.0 && force >= limit * (1.0 - kSlidingForce);
  } else {
    problem.delta_x = loading.x - previous.approach_x;
    problem.delta_y = loading.y - previous.approach_y;
  }

  TangentialResult result;
  result.friction_coefficient = mu;
  result.dundurs_beta = op_.pair().dundurs_beta();
  result.tolerance = options_.tolerance;
  result.normal_force = pressure_sum * area;
  result.residual_history.reserve(static_cast<std::size_t>(std::min(options_.max_iterations, 1024)) + 1);
  TangentialState& state = result.state;
  state = TangentialState::unloaded(n);
  Fields fields{state.shear_x.data(),
                state.shear_y.data(),
                state.displacement_x.data(),
                state.displacement_y.data(),
                gx_.data(),
                gy_.data(),
                tx_.data(),
                ty_.data(),
                rx_.data(),
                ry_.data(),
                wx_.data(),
                wy_.data()};
  for (Eigen::ArrayXd* field : {&tx_, &ty_, &rx_, &ry_}) field->setZero();
  Iteration it(op_, options_, problem, result, fields);
  const double inverse_lipschitz = 1.0 / op_.largest_eigenvalue_bound();
  double delta_x = 0.0;
  double delta_y = 0.0;
  int k = 0;
  if (sliding) {
    // Gross sliding: every contact cell at mu p along Q; the approach the
    // smallest at which every cell slips forward along Q.
    const double force = std::hypot(loading.x, loading.y);
    const double ex = loading.x / force;
    const double ey = loading.y / force;
    for_each_index(n, [&](std::size_t i) {
      const auto j = static_cast<Eigen::Index>(i);
      state.shear_x[j] = radius_[j] * ex;
      state.shear_y[j] = radius_[j] * ey;
    });
    op_.apply({fields.qx, n}, {fields.qy, n}, {fields.ux, n}, {fields.uy, n});
    ++result.operator_applications;
    const double along = linalg::max_of(comm, n, [&](std::size_t i) {
      const auto j = static_cast<Eigen::Index>(i);
      return radius_[j] > 0.0 ? (state.displacement_x[j] - problem.previous_x[i]) * ex +
                                    (state.displacement_y[j] - problem.previous_y[i]) * ey
                              : -std::numeric_limits<double>::infinity();
    });
    delta_x = along * ex;
    delta_y = along * ey;
    for_each_index(n, [&](std::size_t i) {
      const auto j = static_cast<Eigen::Index>(i);
      const bool contact = radius_[j] > 0.0;
      gx_[j] = contact ? state.displacement_x[j] - problem.previous_x[i] - delta_x : 0.0;
      gy_[j] = contact ? state.displacement_y[j] - problem.previous_y[i] - delta_y : 0.0;
    });
    result.status = SolveStatus::converged;
    result.message = "gross sliding: the tangential force equals mu P";
  } else {
    it.start();
    bool conjugate = options_.method == TangentialMethod::conjugate_gradient;
    double best = std::numeric_limits<double>::infinity();
    int best_at = 0;
    for (;; ++k) {
      it.evaluate(k);
      if (it.finished(k)) break;
      if (conjugate) {
        // A stall (the gap not halved in kStalledConjugateSteps steps) hands
        // over to projected gradients, which converge whatever the sets do.
        if (it.residual() < 0.5 * best) {
          best = it.residual();
          best_at = k;
        } else if (k - best_at > kStalledConjugateSteps) {
          conjugate = false;
          it.begin_projected_gradient();
        }
      }
      if (conjugate) {
        it.conjugate();
      } else {
        it.accelerate(inverse_lipschitz);
      }
    }
    delta_x = it.approach_x();
    delta_y = it.approach_y();
    result.residual = it.residual();
  }
  result.iterations = k;

  // The state and the step's integrals.
  if (fixed) {
    // The state's displacement is the whole: C q and the fixed part.
    for_each_index(n, [&](std::size_t i) {
      const auto j = static_cast<Eigen::Index>(i);
      state.displacement_x[j] += fixed_x[i];
      state.displacement_y[j] += fixed_y[i];
    });
  }
  state.approach_x = previous.approach_x + delta_x;
  state.approach_y = previous.approach_y + delta_y;
  result.stick.setZero(static_cast<Eigen::Index>(n));
  const auto [qx_sum, qy_sum, stick_cells, dissipated] = sums<4>(comm, n, [&](std::size_t i) {
    const auto j = static_cast<Eigen::Index>(i);
    if (!(radius_[j] > 0.0)) {
      state.slip_x[j] = 0.0;
      state.slip_y[j] = 0.0;
      return std::array<double, 4>{};
    }
    const double qx = state.shear_x[j];
    const double qy = state.shear_y[j];
    const bool stick = !at_limit(qx, qy, radius_[j]);
    result.stick[j] = stick ? 1.0 : 0.0;
    state.slip_x[j] = previous.slip_x[j] + gx_[j];
    state.slip_y[j] = previous.slip_y[j] + gy_[j];
    return std::array<double, 4>{qx, qy, stick ? 1.0 : 0.0, -(qx * gx_[j] + qy * gy_[j])};
  });
  result.force_x = qx_sum * area;
  result.force_y = qy_sum * area;
  result.stick_fraction = contact_cells > 0.0 ? stick_cells / contact_cells : 0.0;
  result.slip_fraction = contact_cells > 0.0 ? 1.0 - result.stick_fraction : 0.0;
  result.gross_sliding = contact_cells > 0.0 && stick_cells == 0.0;
  result.dissipated_energy = dissipated * area;
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return result;
}

}  // namespace halfspace::solvers
