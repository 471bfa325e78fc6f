// The adhesive contact energy minimised by preconditioned conjugate
// gradients (the default) or spectral projected gradients, and the load
// control around them (adhesive_contact_solver.hpp). SPG costs one product
// with the stiffness S (one FFT pair) per iteration: the trial energies of
// its line search reuse S v and S d, since the elastic energy is quadratic
// along a line; the conjugate gradients two or three.
#include "halfspace/solvers/adhesive_contact_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/material.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/solvers/approach_search.hpp"
#include "halfspace/solvers/interface_law.hpp"
#include "halfspace/solvers/loading.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::solvers {
namespace {

// Non-monotone line search of SPG (Grippo, Lampariello & Lucidi 1986): a
// step is accepted against the largest of the last kMemory energies, which
// lets the Barzilai-Borwein steps through the narrow valleys of an
// ill-conditioned energy.
constexpr std::size_t kMemory = 10;
constexpr double kSufficientDecrease = 1e-4;
constexpr int kMaxBacktracks = 40;
// The rounding of an energy change summed cell by cell, in units of
// machine epsilon times the energies' magnitudes (the elastic energy and
// the sum of the cells' |interaction energies|): within it a change cannot
// be told from zero. Near the tolerance the true decrease falls below it
// and the line search can only fail; after a failure has recomputed the
// state, the next search accepts a change within this noise.
constexpr double kEnergyRounding = 16.0;
// S v is updated along the steps (S v += lambda S d); it is recomputed from v
// this often, so rounding does not accumulate.
constexpr int kRefreshEvery = 50;
// The cohesive zone (AdhesionLaw::cohesive_zone_length) against the cell
// length: below kUnresolvedZone of a cell the grid cannot represent the law
// at a contact edge (its answer would be the grid's, not the law's), and the
// law is refused; below kUnderresolvedZone a result with a contact edge
// carries a warning.
constexpr double kUnresolvedZone = 0.01;
constexpr double kUnderresolvedZone = 0.1;

}  // namespace

void AdhesiveSolverOptions::validate() const {
  const auto text = [](auto value) { return fmt::format("{}", value); };
  if (!(std::isfinite(law.work) && law.work > 0.0)) {
    throw SolverOptionError("law.work", text(law.work), "is invalid: must be positive and finite (J/m^2)");
  }
  if (!(std::isfinite(law.range) && law.range > 0.0)) {
    throw SolverOptionError("law.range", text(law.range), "is invalid: must be positive and finite (m)");
  }
  if (!std::isnormal(law.stress()) || !std::isfinite(law.stress())) {
    throw SolverOptionError("law.range", text(law.range),
                            fmt::format("is invalid with law.work = {}: the stress work / range = {} Pa must be "
                                        "finite and normal",
                                        law.work, law.stress()));
  }
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw SolverOptionError("tolerance", text(tolerance), "is invalid: allowed range is (0, 1)");
  }
  if (!(force_tolerance > 0.0 && force_tolerance < 1.0)) {
    throw SolverOptionError("force_tolerance", text(force_tolerance), "is invalid: allowed range is (0, 1)");
  }
  if (max_iterations < 1) {
    throw SolverOptionError("max_iterations", text(max_iterations), "is invalid: must be at least 1");
  }
  if (max_load_steps < 1) {
    throw SolverOptionError("max_load_steps", text(max_load_steps), "is invalid: must be at least 1");
  }
}

double cell_length(const Grid& grid) {
  return grid.dimension() == 1 ? grid.dx() : std::max(grid.dx(), grid.dy());
}

// The law on this body and grid: its cohesive zone resolved (see
// kUnresolvedZone) and its largest force over the domain finite.
void check_law_on_grid(const AdhesionLaw& law, double e_star, const Grid& grid) {
  const double zone = law.cohesive_zone_length(e_star);
  const double cell = cell_length(grid);
  if (!(zone >= kUnresolvedZone * cell)) {
    throw InputError(fmt::format(
        "adhesion-range = {:.6g} m (adhesion stress {:.6g} Pa, work-of-adhesion {:.6g} J/m^2) is invalid on this grid: "
        "its cohesive zone at a contact edge, pi E* w / (4 sigma0^2) = {:.3g} m at E* = {:.6g} Pa, is {:.3g} of the "
        "cell length {:.6g} m (at least {} needed), so the grid cannot represent the law; use a longer range (a "
        "smaller stress) or a finer grid",
        law.range, law.stress(), law.work, zone, e_star, zone / cell, cell, kUnresolvedZone));
  }
  // The sums of the solve: the law's stress over every cell (a pull on the
  // whole domain) and its work.
  const double cells = static_cast<double>(grid.size());
  if (!(std::isfinite(4.0 * law.stress() * cells * std::max(1.0, grid.cell_area())) &&
        std::isfinite(4.0 * law.work * cells * std::max(1.0, grid.cell_area())))) {
    throw InputError(fmt::format(
        "work-of-adhesion = {:.6g} J/m^2 with adhesion-range = {:.6g} m is invalid on this grid: the adhesive stress "
        "{:.6g} Pa over its {} cells overflows the total force",
        law.work, law.range, law.stress(), grid.size()));
  }
}

struct AdhesiveContactSolver::Impl {
  Impl(std::unique_ptr<InfluenceOperator> own, InfluenceOperator& o, double modulus, AdhesiveSolverOptions opts,
       std::optional<double> cap)
      : owned(std::move(own)),
        op(o),
        grid((check_law_on_grid(opts.law, checked_composite_modulus(modulus), o.grid()), o.grid())),
        e_star(checked_composite_modulus(modulus)),
        options(std::move(opts)),
        form(op.circulant_form()),
        comm(op.communicator()),
        padded(form.padded()),
        capped(cap.has_value()),
        hardness(cap.value_or(std::numeric_limits<double>::infinity())),
        cells(op.local_size()),
        stride(form.row_stride()),
        total(static_cast<double>(form.size())) {
    const std::size_t m = size();
    for (Eigen::ArrayXd* a : {&x, &sx, &gradient, &trial, &direction, &s_direction, &offset, &lower}) a->resize(m);
    if (options.precondition) {
      scaled.resize(m);
      old_gradient.resize(m);
    }
    physical.assign(m, 0);
    below.assign(m, 0);
    for (std::size_t k = 0; k < cells; ++k) physical[index(k)] = 1;
    // K_ii as the form's products give it: op.self_influence() to rounding,
    // but the steps and the residual are scaled by it, and the iteration
    // near its rounding limit (capped, tolerance 1e-8) follows its last bits.
    trial.setZero();
    if (comm.rank() == 0) trial[0] = 1.0;
    compliance_times(trial, direction);
    compliance = linalg::global_sum(comm, std::array<double, 1>{comm.rank() == 0 ? direction[0] : 0.0})[0];
  }

  // sum_k f(values[k]) over every process's cells in cell order (this
  // process's in order, then the processes in rank order): the sums load
  // control decides on (forces, the mean gap), whose last bits can change
  // which branch a search closes on, in the order the serial solver always
  // summed them.
  template <class F>
  double in_cell_order(std::span<const double> values, F&& f) const {
    double local = 0.0;
    for (const double v : values) local += f(v);
    return linalg::global_sum(comm, std::array<double, 1>{local})[0];
  }

  // Index in the variable's array of this process's grid cell k ((rows,
  // nx) row-major).
  std::size_t index(std::size_t k) const { return padded ? (k / grid.nx()) * stride + k % grid.nx() : k; }
  std::size_t size() const { return form.local_size(); }

  // out = K in, out = S in on the variable's grid (the operator's circulant form).
  void compliance_times(const Eigen::ArrayXd& in, Eigen::ArrayXd& out) {
    form.apply({in.data(), size()}, {out.data(), size()});
  }
  void stiffness_times(const Eigen::ArrayXd& in, Eigen::ArrayXd& out) {
    form.apply_inverse({in.data(), size()}, {out.data(), size()});
  }

  // The shift tau of the projection of y onto {v >= lower} and (periodic)
  // mean v = 0: P(y) = max(lower, y - tau), with tau the root of the
  // convex, decreasing, piecewise linear mean, found by Newton's method from
  // the left, exact once a step clips no new cell; 0 on free grids. y(i)
  // gives y's entries (an array, or an expression such as v - c G that is
  // never stored). Empty if no feasible point exists.
  template <class Y>
  std::optional<double> projection_shift(Y&& y) const {
    if (padded) return 0.0;
    if (capped) return capped_projection_shift(y);
    const std::size_t m = size();
    const auto sum_and_free = [&](double tau) {
      return linalg::sums<2>(comm, m, [&](std::size_t i) {
        const double v = y(i) - tau;
        return v > lower[i] ? std::array<double, 2>{v, 1.0} : std::array<double, 2>{lower[i], 0.0};
      });
    };
    double tau = linalg::sum(comm, m, [&](std::size_t i) { return y(i); }) / total;
    std::array<double, 2> s = sum_and_free(tau);
    for (int k = 0; k < 1000; ++k) {
      if (s[1] == 0.0) return std::nullopt;
      tau += s[0] / s[1];
      const std::array<double, 2> next = sum_and_free(tau);
      const bool exact = next[1] == s[1];
      s = next;
      if (exact) break;
    }
    return tau;
  }

  // With a hardness cap: y - tau moved onto cell i's side of the kink
  // (below: g <= 0, above: g >= 0); without, max(lower, y - tau).
  double onto_side(std::size_t i, double shifted) const {
    return below[i] ? std::min(lower[i], shifted) : std::max(lower[i], shifted);
  }

  // projection_shift with a cap: the sum of the projection onto the sides
  // is still decreasing, continuous and piecewise linear in tau, but neither
  // convex nor concave, so Newton's steps are kept inside a bracket of the
  // root and replaced by bisection where they leave it, until the sum is
  // zero to rounding (relative to the sum of |P(y)|).
  template <class Y>
  std::optional<double> capped_projection_shift(Y&& y) const {
    const std::size_t m = size();
    // The sum of P(y), its count of unclipped cells and the sum of |P(y)|.
    const auto sums_at = [&](double tau) {
      return linalg::sums<3>(comm, m, [&](std::size_t i) {
        const double shifted = y(i) - tau;
        const double z = onto_side(i, shifted);
        return std::array<double, 3>{z, z == shifted ? 1.0 : 0.0, std::abs(z)};
      });
    };
    double tau = linalg::sum(comm, m, [&](std::size_t i) { return y(i); }) / total;
    double low = -std::numeric_limits<double>::infinity();  // sum above 0
    double high = std::numeric_limits<double>::infinity();  // sum below 0
    std::array<double, 3> s = sums_at(tau);
    double scale = std::abs(tau);
    for (int k = 0; k < 400; ++k) {
      if (!std::isfinite(s[0])) return std::nullopt;
      if (std::abs(s[0]) <= 1e-14 * s[2]) return tau;
      (s[0] > 0.0 ? low : high) = tau;
      if (std::isfinite(low) && std::isfinite(high) && !(high - low > 1e-15 * (std::abs(low) + std::abs(high)))) {
        return tau;
      }
      double next = s[1] > 0.0 ? tau + s[0] / s[1] : std::numeric_limits<double>::quiet_NaN();
      if (!(next > low && next < high)) {
        if (std::isfinite(low) && std::isfinite(high)) {
          next = 0.5 * (low + high);
        } else {
          // No slope and no bracket yet: double the step outwards.
          scale = 2.0 * scale + s[2] / total;
          next = tau + (s[0] > 0.0 ? scale : -scale);
        }
      }
      tau = next;
      s = sums_at(tau);
    }
    return std::nullopt;
  }

  // z = the projection of y (see projection_shift); false if no feasible
  // point exists.
  bool project(const Eigen::ArrayXd& y, Eigen::ArrayXd& z) const {
    const std::optional<double> tau = projection_shift([&](std::size_t i) { return y[i]; });
    if (!tau) return false;
    if (capped) {
      linalg::for_each_index(size(), [&](std::size_t i) { z[i] = onto_side(i, y[i] - *tau); });
    } else {
      linalg::for_each_index(size(), [&](std::size_t i) { z[i] = std::max(lower[i], y[i] - *tau); });
    }
    return true;
  }

  // The stopping residual (see Stopping in the header): the largest entry of
  // P(v - c G) - v over c p_ref, without storing the step. p_ref is the
  // largest pressure of the state: |S v| anywhere and the law's traction on
  // the cells off the wall; not the law's stress, which may exceed every
  // pressure of the contact by orders of magnitude (a short range) and so
  // would call any start converged. Its floor, for states without pressure
  // (surfaces apart, v -> 0), is the smaller of the stress and the pressure
  // that moves a cell by the law's range (range / c): below it a step
  // changes no cell's gap by more than the tolerance times the range.
  double residual_of_step(double c) const {
    const auto y = [&](std::size_t i) { return x[i] - c * gradient[i]; };
    const double tau = projection_shift(y).value_or(std::numeric_limits<double>::quiet_NaN());
    const AdhesionLaw& law = options.law;
    // The two maxima and the count of non-finite entries (which std::max
    // would drop).
    using Maxima = std::array<double, 3>;
    Maxima largest = linalg::reduce_in_blocks(
        size(), Maxima{0.0, 0.0, 0.0},
        [&](Maxima& acc, std::size_t i) {
          const double step = std::abs((capped ? onto_side(i, y(i) - tau) : std::max(lower[i], y(i) - tau)) - x[i]);
          acc[0] = std::max(acc[0], step);
          acc[2] += std::isfinite(step) ? 0.0 : 1.0;
          acc[1] = std::max(acc[1], std::abs(sx[i]));
          if (physical[i] && off_wall(i)) acc[1] = std::max(acc[1], std::abs(cell_traction(law, offset[i] + x[i])));
        },
        [](Maxima& all, const Maxima& part) {
          all[0] = std::max(all[0], part[0]);
          all[1] = std::max(all[1], part[1]);
          all[2] += part[2];
        });
    largest = {comm.max(largest[0]), comm.max(largest[1]),
               linalg::global_sum(comm, std::array<double, 1>{largest[2]})[0]};
    if (!std::isfinite(tau) || largest[2] > 0.0) return std::numeric_limits<double>::quiet_NaN();
    const double floor = std::min(options.law.stress(), options.law.range / c);
    return largest[0] / (c * std::max(largest[1], floor));
  }

  // The interaction energy sum_i phi(g_i + step * d_i) over the grid cells.
  double interaction_energy(const Eigen::ArrayXd& v, const Eigen::ArrayXd* d, double step) const {
    const AdhesionLaw& law = options.law;
    return linalg::sum(comm, size(), [&](std::size_t i) {
      if (!physical[i]) return 0.0;
      const double g = offset[i] + v[i] + (d ? step * (*d)[i] : 0.0);
      return cell_energy(law, g);
    });
  }

  // The interaction energy per area at gap g, with the cap's plastic work
  // below the kink (see Hardness cap in the header).
  double cell_energy(const AdhesionLaw& law, double g) const {
    return capped && g < 0.0 ? law.energy(0.0) - hardness * g : law.energy(std::max(g, 0.0));
  }
  // The pressure the interface exerts at gap g: H below the kink (the
  // traction above it at g = 0, the side settle() may change).
  double cell_traction(const AdhesionLaw& law, double g) const {
    return capped && g < 0.0 ? hardness : law.traction(std::max(g, 0.0));
  }
  // Whether cell i is off the wall (the kink): its gradient vanishes there
  // at the solution, so it measures the periodic multiplier.
  bool off_wall(std::size_t i) const { return capped ? x[i] != lower[i] : x[i] > lower[i]; }

  // With a cap: the side of every cell for the next step, and the gradient
  // of the cells on the kink: released below (gradient S v - H) when their
  // pressure, less the periodic multiplier `shift`, exceeds H; otherwise
  // above (S v - t(0), held or released as without a cap).
  void settle(double shift) {
    if (!capped) return;
    const double jump = hardness - options.law.traction(0.0);
    linalg::for_each_index(size(), [&](std::size_t i) {
      if (x[i] == lower[i]) {
        const bool flows = gradient[i] - jump - shift > 0.0;
        if (flows) gradient[i] -= jump;
        below[i] = flows ? 1 : 0;
      } else {
        below[i] = x[i] < lower[i] ? 1 : 0;
      }
    });
  }

  // gradient = S v - t(g) on the grid, S v on the padding (with a cap,
  // the sides settled).
  void make_gradient() {
    const AdhesionLaw& law = options.law;
    linalg::for_each_index(size(), [&](std::size_t i) {
      gradient[i] = physical[i] ? sx[i] - cell_traction(law, offset[i] + x[i]) : sx[i];
    });
    if (capped) settle(mean_shift());
  }

  // Whether cell i is held by the wall: at its bound with the gradient,
  // less the multiplier `shift` of the periodic mean constraint, pushing
  // into the wall.
  // With a cap, only a cell on the kink above it (settle()).
  bool binding(std::size_t i, double shift) const {
    if (capped) return x[i] == lower[i] && !below[i] && gradient[i] - shift > 0.0;
    return x[i] <= lower[i] && gradient[i] - shift > 0.0;
  }

  // With a cap: a cell on the kink released to one side whose conjugate
  // direction points to the other (the compliance mixes the cells) would be
  // clipped back by every step, and stay on the kink with its pressure
  // beyond the bounds; its component is the diagonally scaled gradient
  // -c (G - shift) instead, which points to its side (the two-metric
  // projection's diagonal near a bound, Bertsekas 1982), and the direction
  // is made mean-free again on the free cells (periodic). Returns the slope
  // G.d.
  double keep_released_sides(double shift) {
    const std::size_t m = size();
    const double c = compliance;
    // sum of d and count over the free cells, G.d, sum of G over them
    const std::array<double, 4> parts = linalg::sums<4>(comm, m, [&](std::size_t i) {
      if (binding(i, shift)) return std::array<double, 4>{};
      if (x[i] == lower[i] && (below[i] ? direction[i] > 0.0 : direction[i] < 0.0)) {
        direction[i] = -c * (gradient[i] - shift);
      }
      return std::array<double, 4>{direction[i], 1.0, gradient[i] * direction[i], gradient[i]};
    });
    return mean_free_on_free_cells(parts, shift);
  }

  // The direction made mean-free on the cells the wall does not hold
  // (periodic: mean v = 0 then holds along the line), from the sums over
  // those cells {sum d, count, G.d, sum G}; returns the slope G.d of the
  // result. Free grids have no mean constraint.
  double mean_free_on_free_cells(const std::array<double, 4>& parts, double shift) {
    if (padded || !(parts[1] > 0.0)) return parts[2];
    const double mu = parts[0] / parts[1];
    linalg::for_each_index(size(), [&](std::size_t i) {
      if (!binding(i, shift)) direction[i] -= mu;
    });
    return parts[2] - mu * parts[3];
  }

  // The periodic grid's multiplier of mean v = 0: the mean gradient over the
  // cells off the wall (0 on free grids, which have no such constraint).
  double mean_shift() const {
    if (padded) return 0.0;
    const std::array<double, 2> free_part = linalg::sums<2>(comm, size(), [&](std::size_t i) {
      return off_wall(i) ? std::array<double, 2>{gradient[i], 1.0} : std::array<double, 2>{0.0, 0.0};
    });
    return free_part[1] > 0.0 ? free_part[0] / free_part[1] : 0.0;
  }

  double dot(const Eigen::ArrayXd& a, const Eigen::ArrayXd& b) const {
    return linalg::sum(comm, size(), [&](std::size_t i) { return a[i] * b[i]; });
  }

  // What the iterations carry from one step to the next: the energy and
  // the last kMemory energies (the non-monotone line searches), the
  // periodic multiplier, the restart flag and rho = (G - shift).D(G -
  // shift) of the conjugate gradients, and SPG's Barzilai-Borwein step.
  // Conjugate gradients restart after a step the wall clipped (or a plain
  // projected gradient step); a change of the held set alone does not
  // restart (Polak-Ribiere+ resets itself where the new gradient
  // contradicts the old direction, and restarting there cost 10-35 % more
  // iterations on the rough benchmark).
  struct Walk {  // the steps bind its members in this order
    SolveResult& result;
    double energy = 0.0;
    std::array<double, kMemory> recent{};
    double free_shift = 0.0;
    bool restart = true;
    double rho_old = 0.0;
    double alpha = 0.0;
    bool recomputed = false;  // the last step failed its line search and recomputed the state
  };
  // The state recomputed from v alone, as at the start: S v by its product
  // (the steps update it and the energy by increments, which drift by
  // rounding), the gradient, the periodic multiplier and the energy; the
  // conjugate directions restart.
  void recompute(Walk& walk) {
    stiffness_times(x, sx);
    ++walk.result.operator_applications;
    make_gradient();
    walk.free_shift = mean_shift();
    walk.energy = 0.5 * dot(x, sx) + interaction_energy(x, nullptr, 0.0);
    walk.recent.fill(walk.energy);
    walk.restart = true;
  }
  // A line search that found no decrease: once, the state is recomputed and
  // the walk goes on from there (true); a second time in a row it breaks
  // down (false, the result says why).
  bool after_failed_line_search(Walk& walk, int iteration, double residual) {
    if (!walk.recomputed) {
      recompute(walk);
      walk.recomputed = true;
      return true;
    }
    walk.result.status = SolveStatus::breakdown;
    walk.result.message =
        fmt::format("the line search found no decrease at iteration {} (residual {:.3g})", iteration, residual);
    return false;
  }
  // One iteration of either minimiser from the state in x, sx and gradient
  // at `residual`: true if it moved, false if it broke down (the result's
  // status and message then say why).
  bool conjugate_gradient_step(Walk& walk, int iteration, double residual);
  bool spectral_gradient_step(Walk& walk, int iteration, double residual);
  SolveResult solve_displacement(std::span<const double> initial_gap, double approach,
                                 std::span<const double> initial_pressure, bool start_from_last);
  SolveResult solve_force(std::span<const double> initial_gap, double target, std::span<const double> initial_pressure);
  // What load control drives: displacement-controlled solves from x, and
  // x kept at and restored from the bracket's ends.
  class Driven final : public ApproachDriven {
   public:
    Driven(Impl& solver, std::span<const double> initial_gap) : m_(solver), initial_gap_(initial_gap) {
      m_.saved_low.resize(static_cast<Eigen::Index>(m_.size()));
      m_.saved_high.resize(static_cast<Eigen::Index>(m_.size()));
    }
    SolveResult solve_at(double approach) override { return m_.solve_displacement(initial_gap_, approach, {}, true); }
    void keep(bool above) override { (above ? m_.saved_high : m_.saved_low) = m_.x; }
    void restore(bool above) override { m_.x = above ? m_.saved_high : m_.saved_low; }
    // The inner solve's residual bounds each active cell's pressure error
    // by tolerance times the largest pressure.
    double undetermined_force(const SolveResult& r) const override {
      const double largest = linalg::max_of(
          m_.comm, m_.cells, [&](std::size_t k) { return std::abs(r.pressure[static_cast<Eigen::Index>(k)]); });
      const double active = std::max(r.adhesion.interaction_fraction, r.contact_fraction) * m_.grid.domain_area();
      return m_.options.tolerance * largest * active;
    }

   private:
    Impl& m_;
    std::span<const double> initial_gap_;
  };
  void fill_result(SolveResult& result, std::span<const double> initial_gap, double approach);

  std::unique_ptr<InfluenceOperator> owned;  // the operator, when the solver made it
  InfluenceOperator& op;
  const Grid& grid;
  double e_star;  // the contact's modulus (the cohesive zone's)
  AdhesiveSolverOptions options;
  operators::CirculantForm& form;    // K and S on the variable's grid
  const linalg::Communicator& comm;  // the processes the fields are spread over
  bool padded;
  bool capped;        // a hardness cap is set
  double hardness;    // H (Pa), infinite without a cap
  std::size_t cells;  // the grid's cells on this process
  std::size_t stride;
  double total;                         // the variable's cells on every process
  double compliance = 0.0;              // K_ii (m/Pa)
  std::vector<unsigned char> physical;  // 1 on the grid's cells, 0 on the padding
  std::vector<unsigned char> below;     // with a cap: 1 where the cell's side is below the kink (settle())
  // Workspace over the variable's array: v, S v, the gradient, the trial
  // point P(v - alpha G), the step d, S d, the offset h - delta (gap =
  // offset + v) and the bound delta - h (-inf on the padding).
  Eigen::ArrayXd x, sx, gradient, trial, direction, s_direction, offset, lower;
  Eigen::ArrayXd scaled, old_gradient;   // preconditioned solves only: D G (or S of a trial point), the last G
  Eigen::ArrayXd saved_low, saved_high;  // load control: the displacements of the bracket's ends
  bool have_last = false;                // x holds the last solve's displacement
  double last_approach = 0.0;
};

SolveResult AdhesiveContactSolver::Impl::solve_displacement(std::span<const double> initial_gap, double approach,
                                                            std::span<const double> initial_pressure,
                                                            bool start_from_last) {
  const auto started = std::chrono::steady_clock::now();
  const std::size_t m = size();
  const double inf = std::numeric_limits<double>::infinity();
  offset.setZero();
  lower.setConstant(-inf);
  for (std::size_t k = 0; k < cells; ++k) {
    offset[index(k)] = initial_gap[k] - approach;
    lower[index(k)] = approach - initial_gap[k];
  }
  const double mean_lower = padded ? 0.0 : linalg::sum(comm, m, [&](std::size_t i) { return lower[i]; }) / total;
  if (!padded && !(mean_lower < 0.0)) check_periodic_approach(approach, approach - mean_lower);
  // The start: the last solution's displacement, K p of the given pressure,
  // or 0, projected onto the constraints.
  if (!start_from_last) {
    direction.setZero();
    if (!initial_pressure.empty()) {
      for (std::size_t k = 0; k < cells; ++k) direction[index(k)] = initial_pressure[k];
      compliance_times(direction, direction);
    }
    x = direction;
  }
  SolveResult result;
  result.solver = options.precondition ? "adhesive-pcg" : "adhesive-spg";  // as name()
  result.tolerance = options.tolerance;
  // With a cap, every cell starts above the kink (the projection puts the
  // penetrating ones on it; those pressed beyond H are released below at
  // once), but for the last solve's plastic cells when continuing from it.
  if (capped) {
    linalg::for_each_index(m, [&](std::size_t i) { below[i] = start_from_last && x[i] < lower[i] ? 1 : 0; });
  }
  if (!project(x, x)) {
    result.status = SolveStatus::breakdown;
    result.message = "no displacement satisfies the constraints";
    return result;
  }
  Walk walk{result};
  recompute(walk);
  walk.alpha = compliance;
  const double c = compliance;
  result.status = SolveStatus::iteration_limit;
  for (int iteration = 0;; ++iteration) {
    // Residual: the projected gradient step of length c, in pressure.
    const double residual = residual_of_step(c);
    result.residual = residual;
    result.iterations = iteration;
    if (result.residual_history.size() < 100000) result.residual_history.push_back(residual);
    const bool stop = stop_requested(options.progress, iteration, residual);
    if (const std::optional<SolveStatus> status =
            stopping_status(residual, options.tolerance, iteration, options.max_iterations, &result.message, stop)) {
      result.status = *status;
      break;
    }
    const bool stepped = options.precondition ? conjugate_gradient_step(walk, iteration, residual)
                                              : spectral_gradient_step(walk, iteration, residual);
    if (!stepped) break;
  }
  have_last = result.converged();
  last_approach = approach;
  fill_result(result, initial_gap, approach);
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

bool AdhesiveContactSolver::Impl::conjugate_gradient_step(Walk& walk, int iteration, double residual) {
  auto& [result, energy, recent, free_shift, restart, rho_old, alpha, recomputed] = walk;
  const std::size_t m = size();
  const double c = compliance;
  // Preconditioned non-linear conjugate gradients on the free cells
  // (Polak-Ribiere+), the wall's cells held, the step the minimiser of
  // the elastic energy along d, clipped onto the wall and backtracked
  // until the energy falls (Armijo, monotone). The vector work is fused
  // into few passes: at these sizes a pass over the fields costs a
  // fair fraction of an FFT pair.
  // scaled = D (G - shift) on the cells the wall does not hold, 0 on
  // those it holds: D is the compliance K's principal block on the free
  // cells. K inverts the elastic stiffness that makes the plain gradient
  // ill-conditioned (symbol E*|q|/2). One FFT pair.
  const double shift = free_shift;
  linalg::for_each_index(m, [&](std::size_t i) { scaled[i] = binding(i, shift) ? 0.0 : gradient[i] - shift; });
  compliance_times(scaled, scaled);
  ++result.operator_applications;
  // D (G - shift) vanishes on the held cells; rho and the Polak-Ribiere
  // numerator in the same pass.
  const std::array<double, 2> sums = linalg::sums<2>(comm, m, [&](std::size_t i) {
    if (binding(i, shift)) scaled[i] = 0.0;
    return std::array<double, 2>{scaled[i] * (gradient[i] - shift),
                                 restart ? 0.0 : scaled[i] * (gradient[i] - old_gradient[i])};
  });
  double beta = 0.0;
  if (!restart && rho_old > 0.0) beta = std::max(0.0, sums[1] / rho_old);
  rho_old = sums[0];
  // d = -D G + b d on the free cells, mean-free on them (periodic: mean
  // v = 0 holds along the line); returns the slope G.d.
  const auto make_direction = [&](double b) {
    // sum of d and count over the free cells, G.d, sum of G over the free cells
    const std::array<double, 4> parts = linalg::sums<4>(comm, m, [&](std::size_t i) {
      if (binding(i, shift)) {
        direction[i] = 0.0;
        return std::array<double, 4>{0.0, 0.0, 0.0, 0.0};
      }
      direction[i] = -scaled[i] + b * direction[i];
      return std::array<double, 4>{direction[i], 1.0, gradient[i] * direction[i], gradient[i]};
    });
    return mean_free_on_free_cells(parts, shift);
  };
  double slope = make_direction(beta);
  if (!(slope < 0.0) && beta != 0.0) {
    linalg::for_each_index(m, [&](std::size_t i) { direction[i] = 0.0; });
    slope = make_direction(0.0);
  }
  if (capped) slope = keep_released_sides(shift);
  bool plain = false;
  if (!(slope < 0.0)) {
    // The plain projected gradient step always descends.
    trial = x - c * gradient;
    project(trial, trial);
    direction = trial - x;
    slope = dot(gradient, direction);
    plain = true;
  }
  if (!(slope < 0.0)) {
    result.status = SolveStatus::breakdown;
    result.message = fmt::format(
        "the conjugate direction is no descent direction at iteration {} (residual {:.3g}): rounding limits "
        "the accuracy; loosen the tolerance",
        iteration, residual);
    return false;
  }
  stiffness_times(direction, s_direction);
  ++result.operator_applications;
  // Energy changes, not energies: near the solution the change is far
  // below the rounding of the energy itself. Non-monotone as SPG's: the
  // change is measured against the largest of the last kMemory energies;
  // monotone with a cap (non-monotone steps cycled there: a rough sweep
  // alternated between two held sets for 20000 iterations).
  const double allowance = capped ? 0.0 : *std::max_element(recent.begin(), recent.end()) - energy;
  const std::array<double, 3> along = linalg::sums<3>(comm, m, [&](std::size_t i) {
    return std::array<double, 3>{direction[i] * sx[i], direction[i] * s_direction[i], x[i] * sx[i]};
  });
  const double linear = along[0];
  const double quadratic = 0.5 * along[1];
  const double elastic_energy = 0.5 * std::abs(along[2]);
  double noise = 0.0;  // the change's rounding, accepted after a recomputed state
  double step = plain || !(quadratic > 0.0) ? 1.0 : -0.5 * slope / quadratic;
  double change = 0.0;
  bool clipped = false;
  int backtracks = 0;
  const AdhesionLaw& law = options.law;
  for (;; ++backtracks) {
    // The trial point, whether the wall clips it, and (if not) the
    // interaction energy's change, in one pass.
    const std::array<double, 3> moved = linalg::sums<3>(comm, m, [&](std::size_t i) {
      trial[i] = x[i] + step * direction[i];
      const double cut = (below[i] ? trial[i] > lower[i] : trial[i] < lower[i]) ? 1.0 : 0.0;
      if (!physical[i]) return std::array<double, 3>{cut, 0.0, 0.0};
      const double g = offset[i] + x[i];
      const double before = cell_energy(law, g);
      return std::array<double, 3>{cut, cell_energy(law, g + step * direction[i]) - before, std::abs(before)};
    });
    clipped = moved[0] > 0.0;
    if (backtracks == 0 && recomputed) {
      noise = kEnergyRounding * std::numeric_limits<double>::epsilon() * (elastic_energy + moved[2]);
    }
    double decrease = step * slope;
    if (clipped) {
      project(trial, trial);
      stiffness_times(trial, scaled);  // S of the trial point
      ++result.operator_applications;
      // 1/2 t.S t - 1/2 x.S x = 1/2 (t - x).(S t + S x), and the
      // interaction energy's change.
      const std::array<double, 3> sums3 = linalg::sums<3>(comm, m, [&](std::size_t i) {
        const double s_i = trial[i] - x[i];
        const double g = offset[i] + x[i];
        const double change_i = physical[i] ? cell_energy(law, offset[i] + trial[i]) - cell_energy(law, g) : 0.0;
        return std::array<double, 3>{0.5 * s_i * (scaled[i] + sx[i]), gradient[i] * s_i, change_i};
      });
      change = sums3[0] + sums3[2];
      decrease = sums3[1];
    } else {
      change = step * linear + step * step * quadratic + moved[1];
    }
    if (change <= allowance + kSufficientDecrease * decrease + noise || backtracks >= kMaxBacktracks) break;
    step *= 0.5;
  }
  const double trial_energy = energy + change;
  if (backtracks >= kMaxBacktracks) return after_failed_line_search(walk, iteration, residual);
  recomputed = false;
  const bool refresh = !clipped && (iteration + 1) % kRefreshEvery == 0;
  if (refresh) {
    x = trial;
    stiffness_times(x, sx);
    ++result.operator_applications;
  }
  // Accept: the last gradient kept, v and S v updated, the new gradient
  // and the sums of the mean constraint's multiplier, in one pass.
  const std::array<double, 2> free_part = linalg::sums<2>(comm, m, [&](std::size_t i) {
    old_gradient[i] = gradient[i];
    x[i] = trial[i];
    if (clipped) {
      sx[i] = scaled[i];
    } else if (!refresh) {
      sx[i] += step * s_direction[i];
    }
    gradient[i] = physical[i] ? sx[i] - cell_traction(law, offset[i] + x[i]) : sx[i];
    return off_wall(i) ? std::array<double, 2>{gradient[i], 1.0} : std::array<double, 2>{0.0, 0.0};
  });
  free_shift = padded || !(free_part[1] > 0.0) ? 0.0 : free_part[0] / free_part[1];
  settle(free_shift);
  energy = trial_energy;
  recent[static_cast<std::size_t>(iteration + 1) % kMemory] = energy;
  restart = clipped || plain;
  return true;
}

bool AdhesiveContactSolver::Impl::spectral_gradient_step(Walk& walk, int iteration, double residual) {
  auto& [result, energy, recent, free_shift, restart, rho_old, alpha, recomputed] = walk;
  const std::size_t m = size();
  const double c = compliance;
  const double alpha_min = 1e-10 * c;
  const double alpha_max = 1e6 * c;
  // The spectral step and the line search along d = P(v - alpha G) - v.
  trial = x - alpha * gradient;
  project(trial, trial);
  direction = trial - x;
  const double slope = dot(gradient, direction);
  stiffness_times(direction, s_direction);
  ++result.operator_applications;
  if (!(slope < 0.0)) {
    result.status = SolveStatus::breakdown;
    result.message = fmt::format(
        "the projected gradient step is no descent direction at iteration {} (residual {:.3g}): rounding limits "
        "the accuracy; loosen the tolerance",
        iteration, residual);
    return false;
  }
  const double elastic = 0.5 * dot(x, sx);
  const double linear = dot(direction, sx);
  const double quadratic = 0.5 * dot(direction, s_direction);
  const double reference = *std::max_element(recent.begin(), recent.end());
  double step = 1.0;
  double trial_energy = 0.0;
  int backtracks = 0;
  for (;; ++backtracks) {
    trial_energy = elastic + step * linear + step * step * quadratic + interaction_energy(x, &direction, step);
    if (trial_energy <= reference + kSufficientDecrease * step * slope || backtracks >= kMaxBacktracks) break;
    // Safeguarded quadratic interpolation of the energy along the line.
    const double curvature = trial_energy - energy - step * slope;
    double next = curvature > 0.0 ? -0.5 * slope * step * step / curvature : 0.5 * step;
    step = std::clamp(next, 0.1 * step, 0.5 * step);
  }
  if (backtracks >= kMaxBacktracks) return after_failed_line_search(walk, iteration, residual);
  recomputed = false;
  // s = step d, y = G_new - G; the Barzilai-Borwein step s.s / s.y.
  if (step == 1.0) {
    x = trial;
  } else {
    x += step * direction;
  }
  if ((iteration + 1) % kRefreshEvery == 0) {
    stiffness_times(x, sx);
    ++result.operator_applications;
  } else {
    sx += step * s_direction;
  }
  trial = gradient;  // the old gradient
  make_gradient();
  const double ss = step * step * dot(direction, direction);
  const double sy = step * linalg::sum(comm, m, [&](std::size_t i) { return direction[i] * (gradient[i] - trial[i]); });
  alpha = sy > 0.0 ? std::clamp(ss / sy, alpha_min, alpha_max) : alpha_max;
  energy = trial_energy;
  recent[static_cast<std::size_t>(iteration + 1) % kMemory] = energy;
  return true;
}

void AdhesiveContactSolver::Impl::fill_result(SolveResult& result, std::span<const double> initial_gap,
                                              double approach) {
  const std::size_t n = cells;
  // A cell the projected step puts on the wall (the kink) is on it: within
  // the residual of it, it carries S v, not the law's traction at a gap of
  // rounding size (a start from the pressure K p lands cells 1e-13 m off
  // the wall, which would report -sigma0 on them). Periodic: the shift is
  // the projection's.
  {
    const double c = compliance;
    const auto y = [&](std::size_t i) { return x[i] - c * gradient[i]; };
    const std::optional<double> tau = projection_shift(y);
    if (tau) {
      linalg::for_each_index(size(), [&](std::size_t i) {
        if (physical[i] && x[i] != lower[i] && onto_side(i, y(i) - *tau) == lower[i]) x[i] = lower[i];
      });
    }
  }
  // The periodic mean pressure: the multiplier of mean v = 0, -G on the
  // cells off the wall (where the gradient vanishes at the solution).
  double mean_pressure_shift = 0.0;
  if (!padded) {
    const std::array<double, 2> free_part = linalg::sums<2>(comm, n, [&](std::size_t i) {
      return off_wall(i) ? std::array<double, 2>{gradient[i], 1.0} : std::array<double, 2>{0.0, 0.0};
    });
    if (free_part[1] > 0.0) mean_pressure_shift = -free_part[0] / free_part[1];
  }
  result.approach = approach;
  result.pressure.resize(static_cast<Eigen::Index>(n));
  result.displacement.resize(static_cast<Eigen::Index>(n));
  result.gap.resize(static_cast<Eigen::Index>(n));
  const AdhesionLaw& law = options.law;
  linalg::for_each_index(n, [&](std::size_t k) {
    const std::size_t i = index(k);
    // With a cap: on the kink (gap 0), or below it (plastic, gap < 0).
    const bool kink = capped ? x[i] == lower[i] : x[i] <= lower[i];
    const double g =
        kink ? 0.0 : (capped ? initial_gap[k] + x[i] - approach : std::max(initial_gap[k] + x[i] - approach, 0.0));
    // Off the wall the law gives the pressure exactly; S v there differs
    // from it by the residual, which would show as spurious contact. On it,
    // S v may exceed a cap by the residual: the cap holds exactly.
    result.pressure[static_cast<Eigen::Index>(k)] =
        kink ? std::min(sx[i] + mean_pressure_shift, hardness) : cell_traction(law, g);
    result.displacement[static_cast<Eigen::Index>(k)] = x[i];
    result.gap[static_cast<Eigen::Index>(k)] = g;
  });
  // The cells at the wall, in repulsive contact, interacting and plastic.
  const std::array<double, 4> counts = linalg::sums<4>(comm, n, [&](std::size_t k) {
    const double p = result.pressure[static_cast<Eigen::Index>(k)];
    const std::size_t i = index(k);
    const bool wall = x[i] <= lower[i];
    return std::array<double, 4>{wall ? 1.0 : 0.0, wall && p > 0.0 ? 1.0 : 0.0,
                                 law.interacts(std::max(result.gap[static_cast<Eigen::Index>(k)], 0.0)) ? 1.0 : 0.0,
                                 capped && p >= hardness ? 1.0 : 0.0};
  });
  const double max_pressure =
      linalg::max_of(comm, n, [&](std::size_t k) { return result.pressure[static_cast<Eigen::Index>(k)]; });
  const std::span<const double> pressure(result.pressure.data(), n);
  const double force = in_cell_order(pressure, [](double p) { return p; });
  const double adhesive = in_cell_order(pressure, [](double p) { return std::min(p, 0.0); });
  const double at_wall = counts[0];
  const double repulsive = counts[1];
  const double interacting = counts[2];
  const double plastic = counts[3];
  const double all = static_cast<double>(grid.size());
  result.total_force = force * grid.cell_area();
  result.mean_pressure = result.total_force / grid.domain_area();
  result.max_pressure = max_pressure;
  result.contact_fraction = at_wall / all;
  if (capped) result.hardness = hardness;
  result.plastic_fraction = plastic / all;
  AdhesionRecord& record = result.adhesion;
  record.law = std::string(to_string(law.type));
  record.work = law.work;
  record.range = law.range;
  record.stress = law.stress();
  record.adhesive_force = adhesive * grid.cell_area();
  record.interaction_fraction = interacting / all;
  record.repulsive_contact_fraction = repulsive / all;
  // A result is finite, or it is no answer.
  if (!(std::isfinite(result.total_force) && std::isfinite(max_pressure) && std::isfinite(record.adhesive_force))) {
    result.status = SolveStatus::breakdown;
    result.message = fmt::format("the result is not finite (total force {:g}, largest pressure {:g} Pa)",
                                 result.total_force, max_pressure);
  }
  const double zone = law.cohesive_zone_length(e_star);
  if (at_wall > 0 && at_wall < all && zone < kUnderresolvedZone * cell_length(grid)) {
    result.warnings.push_back(fmt::format(
        "the cohesive zone pi E* w / (4 sigma0^2) = {:.3g} m is {:.3g} of the cell length {:.3g} m: the contact edge "
        "is not resolved, so the result depends on the grid (refine it to at least {:.3g} m cells)",
        zone, zone / cell_length(grid), cell_length(grid), zone / kUnderresolvedZone));
  }
}

// Load control (approach_search.hpp) from the last solve's state, or from
// first touch (the least initial gap; periodic grids: the approach stays
// below the mean gap, where the force is infinite).
SolveResult AdhesiveContactSolver::Impl::solve_force(std::span<const double> initial_gap, double target,
                                                     std::span<const double> initial_pressure) {
  const auto started = std::chrono::steady_clock::now();
  const std::size_t n = initial_gap.size();
  const double mean_gap = in_cell_order(initial_gap, [](double g) { return g; }) / static_cast<double>(grid.size());
  const double min_gap = linalg::min_of(comm, n, [&](std::size_t k) { return initial_gap[k]; });
  ApproachSearch search;
  search.target = target;
  search.probe = options.law.range;
  search.ceiling = padded ? std::numeric_limits<double>::infinity() : mean_gap - 1e-9 * (mean_gap - min_gap);
  search.force_tolerance = options.force_tolerance;
  search.max_steps = options.max_load_steps;
  const bool continuing = have_last && initial_pressure.empty();
  const double approach = continuing ? last_approach : std::min(min_gap, search.ceiling);
  SolveResult first = solve_displacement(initial_gap, approach, initial_pressure, continuing);
  Driven driven(*this, initial_gap);
  SolveResult result = search_approach(driven, search, approach, std::move(first));
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

AdhesiveContactSolver::AdhesiveContactSolver(InfluenceOperator& op, double contact_modulus,
                                             AdhesiveSolverOptions options, const InterfaceLaw& law)
    : ContactSolver(op.grid(), law) {
  options.validate();
  impl_ = std::make_unique<Impl>(nullptr, op, contact_modulus, std::move(options), law.hardness);
}

AdhesiveContactSolver::AdhesiveContactSolver(std::unique_ptr<InfluenceOperator> op, double contact_modulus,
                                             AdhesiveSolverOptions options, const InterfaceLaw& law)
    : ContactSolver(op->grid(), law) {
  options.validate();
  InfluenceOperator& ref = *op;
  impl_ = std::make_unique<Impl>(std::move(op), ref, contact_modulus, std::move(options), law.hardness);
}

AdhesiveContactSolver::AdhesiveContactSolver(const Grid& grid, double e_star, AdhesiveSolverOptions options,
                                             const InterfaceLaw& law)
    : AdhesiveContactSolver(
          (options.validate(), law.validate(),
           std::make_unique<FftInfluenceOperator>(grid, checked_composite_modulus(e_star), options.fft_planning)),
          e_star, options, law) {}

AdhesiveContactSolver::~AdhesiveContactSolver() = default;

std::string_view AdhesiveContactSolver::name() const {
  return impl_->options.precondition ? "adhesive-pcg" : "adhesive-spg";
}

const AdhesiveSolverOptions& AdhesiveContactSolver::options() const {
  return impl_->options;
}

SolveResult AdhesiveContactSolver::do_solve(std::span<const double> initial_gap, const Loading& loading,
                                            std::span<const double> initial_pressure) {
  Impl& m = *impl_;
  const std::size_t n = m.cells;
  check_field_size("adhesive solve: the initial gap", initial_gap.size(), m.grid, n);
  if (!initial_pressure.empty()) {
    check_field_size("adhesive solve: the initial pressure", initial_pressure.size(), m.grid, n);
  }
  if (!std::isfinite(loading.value)) {
    throw InputError(fmt::format("{} = {} is invalid: must be finite", to_string(loading.mode), loading.value));
  }
  if (loading.mode == ControlMode::approach) {
    return m.solve_displacement(initial_gap, loading.value, initial_pressure, false);
  }
  return m.solve_force(initial_gap, loading.target_force(m.grid.domain_area()), initial_pressure);
}

}  // namespace halfspace::solvers
