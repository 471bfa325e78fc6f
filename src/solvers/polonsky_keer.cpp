// Polonsky-Keer constrained conjugate gradient (Polonsky & Keer 1999, Wear
// 231, 206-219). The steps below follow the paper's numbering; the stopping
// test is ours (see the header) because the paper's relative pressure change
// says little about how well the contact conditions hold.
#include "halfspace/solvers/polonsky_keer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/solvers/contact_conditions.hpp"
#include "halfspace/solvers/interface_law.hpp"
#include "halfspace/solvers/pressure_bounds.hpp"

namespace halfspace::solvers {
namespace {

using linalg::for_each_index;
using linalg::sums;

// The displacement is updated incrementally between exact products K p; an
// exact one every this many updates keeps rounding from accumulating.
constexpr int kUpdatesBetweenExactProducts = 50;
// With single-precision inner products (mixed precision) the updates also
// carry the products' rounding, about 1e-7 of each step: the large early
// steps leave an error that the later, smaller residual would not show.
// An exact product whenever the residual has fallen by this factor since
// the last one keeps that error below the residual (the outer correction
// of iterative refinement, see the header).
constexpr double kRefinementFactor = 1e-2;

// Powell's restart threshold, and the share of the contact cells that may
// enter in one step without a restart (preconditioned form, see the header).
constexpr double kPowellRestart = 0.2;
constexpr double kEntriesKept = 0.01;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A stall of load control (Iteration::evaluate): the residual has not
// fallen below this share of its least value in this many iterations.
constexpr double kStallProgress = 0.9;
constexpr int kStallIterations = 100;

struct Problem {
  std::span<const double> initial_gap;
  bool load_controlled = false;
  double target_force = 0.0;  // load control only
  double approach = 0.0;      // displacement control only
  double cell_area = 0.0;
  double initial_gap_range = 0.0;  // ptp(initial_gap)
  PressureBounds bounds;           // the interface law's admissible pressures
};

// The problem of a solve, checked.
Problem make_problem(const InfluenceOperator& op, std::span<const double> initial_gap, const Loading& loading,
                     const PressureBounds& bounds) {
  const Grid& grid = op.grid();
  const linalg::Communicator& comm = op.communicator();
  const std::size_t n = op.local_size();
  check_field_size("initial gap", initial_gap.size(), grid, n);
  loading.validate();
  const double gap_max = linalg::max_of(comm, n, [&](std::size_t i) { return initial_gap[i]; });
  const double gap_min = linalg::min_of(comm, n, [&](std::size_t i) { return initial_gap[i]; });
  if (!std::isfinite(gap_max) || !std::isfinite(gap_min)) {
    throw InputError("initial gap holds a non-finite value");
  }
  Problem problem{initial_gap, loading.load_controlled(), 0.0, 0.0, grid.cell_area(), gap_max - gap_min, bounds};
  if (problem.load_controlled) {
    problem.target_force = loading.target_force(grid.domain_area());
  } else {
    problem.approach = loading.value;
  }
  if (!problem.load_controlled && grid.periodic()) {
    // With a zero-mean displacement the mean gap is mean(g0) - approach, and
    // it cannot be negative: at mean(g0) the pressure is already infinite.
    const double mean_gap =
        linalg::sum(comm, n, [&](std::size_t i) { return initial_gap[i]; }) / static_cast<double>(grid.size());
    check_periodic_approach(problem.approach, mean_gap);
  }
  return problem;
}

// A load-restoring scale with a hardness cap (Iteration::capped_scale): the
// pressure q becomes min(H, factor q), or H where q >= H if keep_cap. The
// iteration stores stored(q) and multiplies by the factor later.
struct CappedScale {
  double factor = 1.0;
  bool keep_cap = true;

  double stored(double q, double upper) const {
    return keep_cap && q >= upper ? upper / factor : std::min(q, upper / factor);
  }
};

// One solve: the iterate and the paper's steps, each one or two passes over
// the cells. The fields live in the result (pressure p, displacement
// u = K p; the gap g = g0 + u - approach is computed where read, not
// stored: a field less, one more read per pass) and in the solver's workspace (the direction t, and one
// array that holds z = M^-1 g, then the image K t, then the step's
// correction c, then K c). Work is their precision: double, or float with
// mixed precision's SinglePrecisionProducts (see the header).
template <class Work>
class Iteration {
 public:
  static constexpr bool kSingle = std::is_same_v<Work, float>;

  Iteration(InfluenceOperator& op, InfluenceOperator& inner, const SinglePrecisionProducts& single,
            Preconditioner* preconditioner, const PolonskyKeerOptions& options, const Problem& problem,
            SolveResult& result, Work* direction, Work* image, double& uniform_response_range)
      : op_(op),
        inner_(inner),
        single_(single),
        refined_(&inner != &op || kSingle),
        preconditioner_(preconditioner),
        options_(options),
        problem_(problem),
        result_(result),
        comm_(op.communicator()),
        n_(op.local_size()),
        cells_(static_cast<double>(op.grid().size())),
        pressure_(result.pressure.data()),
        displacement_(result.displacement.data()),
        direction_(direction),
        preconditioned_gap_(image),
        image_(image),
        correction_(image),
        correction_image_(image),
        projected_(options.form == PolonskyKeerForm::projected),
        in_set_(n_, 0),
        // With a cap the paper's form searches the projected set too: its
        // entries alone stall once the cells below the cap are too few to
        // move the load among them (the mean-free direction on one cell is
        // zero), and its set holds the cells leaving the cap, whose gaps the
        // approach (the mean over the contact below the cap) does not balance.
        set_{pressure_,
             problem.initial_gap.data(),
             displacement_,
             &approach_,
             projected_ || problem.bounds.capped(),
             problem.load_controlled && (projected_ || problem.bounds.capped()),
             problem.bounds.upper,
             nullptr,
             in_set_.data()},
        bounds_(problem.bounds),
        uniform_response_range_(uniform_response_range),
        approach_(problem.approach) {
    if (uniform_response_range_ < 0.0 && op.grid().periodic()) {
      // A periodic operator is translation invariant with a mean-free
      // response (influence_operator.hpp): K 1 = 0, so no product.
      uniform_response_range_ = 0.0;
    } else if (uniform_response_range_ < 0.0) {
      // ptp(K 1) for the gap scale (see the header), once per solver; the
      // work vectors are free until the iteration starts.
      for_each_index(n_, [&](std::size_t i) { direction_[i] = 1; });
      if constexpr (kSingle) {
        single_.kernel({direction_, n_}, {image_, n_});
      } else {
        op_.apply({direction_, n_}, {image_, n_});
      }
      ++result_.operator_applications;
      uniform_response_range_ = linalg::max_of(comm_, n_, [&](std::size_t i) -> double { return image_[i]; }) -
                                linalg::min_of(comm_, n_, [&](std::size_t i) -> double { return image_[i]; });
    }
    for_each_index(n_, [&](std::size_t i) { direction_[i] = 0; });
  }

  // Step 0: the starting pressure, projected onto the bounds. Load control:
  // the warm start or a uniform pressure, scaled to the target force.
  // Displacement control: the warm start or the local-overlap guess.
  void start(bool warm) {
    for_each_index(n_, [&](std::size_t i) { pressure_[i] = warm ? bounds_.project(pressure_[i]) : 0.0; });
    if (problem_.load_controlled) {
      double force = problem_.cell_area * linalg::sum(comm_, n_, [&](std::size_t i) { return pressure_[i]; });
      if (!(force > 0.0)) {
        for_each_index(n_, [&](std::size_t i) { pressure_[i] = 1.0; });
        force = problem_.cell_area * cells_;
      }
      CappedScale scale{problem_.target_force / force, false};
      if (bounds_.capped()) {
        // Scaled and capped; a start too concentrated to carry the load
        // below the cap gives way to the uniform pressure, which does.
        const std::optional<CappedScale> capped = capped_scale([&](std::size_t i) { return pressure_[i]; });
        if (!capped) for_each_index(n_, [&](std::size_t i) { pressure_[i] = 1.0; });
        scale = capped ? *capped : CappedScale{problem_.target_force / (problem_.cell_area * cells_), false};
      }
      for_each_index(n_, [&](std::size_t i) {
        pressure_[i] = bounds_.snap(scale.stored(pressure_[i], bounds_.upper) * scale.factor);
      });
    } else if (!warm) {
      local_overlap_pressure();  // u = 0 here: g = g0 - approach
    }
    exact_displacement();
  }

  // Step 1: the gap of the current pressure, its approach under load
  // control, and the residual (see the header), from an exact product every
  // kUpdatesBetweenExactProducts updates and whenever it would stop.
  void evaluate(int iteration) {
    if (updates_since_exact_ >= kUpdatesBetweenExactProducts ||
        (refined_ && updates_since_exact_ > 0 && residual_ < kRefinementFactor * exact_residual_)) {
      exact_displacement();
    }
    measure();
    if (residual_ <= options_.tolerance && updates_since_exact_ > 0 && !options_.start_only) {
      // Convergence is judged on the exact product only.
      exact_displacement();
      measure();
    }
    if (updates_since_exact_ == 0) exact_residual_ = residual_;
    result_.residual_history.push_back(residual_);
    stop_ = stop_requested(options_.progress, iteration, residual_);
    // A load-controlled iteration without a cap whose residual has not
    // fallen by a tenth in kStallIterations restores the load by shifting
    // from then on (load_shift); the conjugate directions restart.
    if (residual_ < kStallProgress * best_residual_) {
      best_residual_ = residual_;
      best_iteration_ = iteration;
    } else if (problem_.load_controlled && !bounds_.capped() && !load_by_shift_ &&
               iteration - best_iteration_ >= kStallIterations) {
      load_by_shift_ = true;
      conjugate_ = false;
    }
  }

  // Whether the iteration ends here, with the result's status.
  bool finished(int iteration) {
    const std::optional<SolveStatus> status =
        stopping_status(residual_, options_.tolerance, iteration, options_.max_iterations, &result_.message, stop_);
    if (status) result_.status = *status;
    return status.has_value();
  }

  // Displacement control can lose every contact cell; the iteration then
  // starts again from the local overlap of the current gap.
  bool restarted_without_contact() {
    if (contact_cells_ > 0.0) return false;
    local_overlap_pressure();
    exact_displacement();
    conjugate_ = false;
    return true;
  }

  // Step 2: z = g, or z = M^-1 g, on the search set; under load control
  // mean-free there, so that the step keeps the force (on C alone g is
  // mean-free already: the approach makes it so). G = sum over the set of
  // g z. An adapting M^-1 that changed restarts the conjugate directions.
  void precondition() {
    z_is_gap_ = true;
    if (!projected_ && !set_.mean_free) {
      search_cells_ = contact_cells_;
      search_gap_sum_ = 0.0;
      z_mean_ = 0.0;
      search_norm_ = gap_norm_;
      return;
    }
    if (preconditioner_) {
      z_is_gap_ = false;  // evaluate() left g on the search set in preconditioned_gap_
      if (preconditioner_->adapt(set_, result_.residual_history)) conjugate_ = false;
      if constexpr (kSingle) {
        single_.precondition({preconditioned_gap_, n_}, {preconditioned_gap_, n_});
      } else {
        preconditioner_->apply({preconditioned_gap_, n_}, {preconditioned_gap_, n_});
      }
      ++result_.preconditioner_applications;
    }
    // The set's cells and its sum of g are measure()'s; z = g needs no pass.
    double z_sum = set_gap_sum_;
    double gz = gap_norm_;
    if (!z_is_gap_) {
      const std::uint8_t* const in_set = in_set_.data();
      const Work* const z = preconditioned_gap_;
      const std::array<double, 2> along = sums<2>(comm_, n_, [&](std::size_t i) {
        const double zi = in_set[i] ? static_cast<double>(z[i]) : 0.0;
        return std::array<double, 2>{zi, gap(i) * zi};
      });
      z_sum = along[0];
      gz = along[1];
    }
    search_cells_ = set_cells_;
    search_gap_sum_ = set_gap_sum_;
    z_mean_ = set_.mean_free ? z_sum / search_cells_ : 0.0;
    search_norm_ = gz - z_mean_ * search_gap_sum_;
  }

  // Step 3: the conjugate direction t = z + beta t on the search set, or
  // t = z when restarting.
  void conjugate() {
    if (projected_ && !(std::abs(gap_along_direction_) <= kPowellRestart * search_norm_)) conjugate_ = false;
    // The paper's form restarts whenever its set grows: cells leaving the
    // cap join it as entering cells do.
    if (!projected_ && released_cells_ > 0.0) conjugate_ = false;
    const double beta = conjugate_ ? search_norm_ / previous_norm_ : 0.0;
    const double z_mean = z_mean_;
    // Under load control the carried-over direction is made mean-free on the
    // current set too: cells that left the set took part of it with them.
    // A direction with a mean moves the load the scaling then puts back, and
    // its curvature t.Kt - mean(Kt) sum(t) can vanish or turn negative: on a
    // measured profile the solve broke down at random, by the FFT plan's
    // rounding. Not in Polonsky & Keer's paper; docs/solvers.md has the
    // iterations it saves.
    const double t_mean =
        problem_.load_controlled && beta != 0.0 && search_cells_ > 0.0 ? direction_sum_ / search_cells_ : 0.0;
    const std::uint8_t* const in_set = in_set_.data();
    with_z([&](auto z) {
      for_each_index(n_, [&](std::size_t i) {
        direction_[i] = static_cast<Work>(in_set[i] ? (z(i) - z_mean) + beta * (direction_[i] - t_mean) : 0.0);
      });
    });
    // g.t on the set from the sums at hand (t is the line above on it):
    // sum g (z - mean z) + beta sum g (t_old - t_mean).
    gap_along_new_ = search_norm_ + beta * (gap_along_direction_ - t_mean * search_gap_sum_);
    previous_norm_ = search_norm_;
  }

  // Steps 4-5: the image K t, mean-corrected on the search set under
  // load control, and the step length tau, the exact minimiser along t on
  // the current set. After a restart tau is positive; a conjugate direction
  // can give a negative one, which is still a valid step, but then no cell
  // enters and the next step restarts. False (breakdown) if t.Kt is not
  // positive: K is positive definite on directions that are mean-free on
  // the set, as conjugate() keeps them under load control (the curvature
  // t.Kt - mean(Kt) sum(t) of a direction with a mean can vanish).
  bool step_length(int iteration) {
    kernel_product(direction_, image_);
    ++result_.operator_applications;
    // t vanishes off the set: only K t's sum needs the set.
    const std::uint8_t* const in_set = in_set_.data();
    const auto [image_sum, t_sum, t_image] = sums<3>(comm_, n_, [&](std::size_t i) {
      const double ti = direction_[i];
      const double image = image_[i];
      return std::array<double, 3>{in_set[i] ? image : 0.0, ti, image * ti};
    });
    const double gt = gap_along_new_;
    const double image_mean = problem_.load_controlled && search_cells_ > 0.0 ? image_sum / search_cells_ : 0.0;
    const double curvature = t_image - image_mean * t_sum;
    tau_ = gt / curvature;
    if (curvature > 0.0 && std::isfinite(tau_)) return true;
    result_.status = SolveStatus::breakdown;
    result_.message = fmt::format("non-positive curvature t.Kt = {:.3e} at iteration {}", curvature, iteration);
    return false;
  }

  // Steps 6-9: p = P(p - tau t), P the projection onto the bounds; in the
  // paper's form, cells out of contact that interpenetrate enter with
  // pressure -tau g. The displacement follows without a new product:
  // K(p - tau t) = u - tau r, plus K c for the correction c that the
  // projection and entries add, zero once the contact set settles. The
  // load is restored by scaling (K is linear: u scales with p), or, once
  // that has stalled, by the shift of load_shift, which joins c. The
  // addition of K c and the scaling are left to the next evaluation's first
  // pass (Deferred).
  void advance() {
    if (bounds_.capped()) {
      advance_capped();
      return;
    }
    const bool entries = !projected_;
    const double tau = tau_;
    // The cell's pressure after the step, projected, or entered with -tau g
    // (read before the step moves the cell's u).
    const auto projected = [&](std::size_t i) {
      const double pi = bounds_.project(pressure_[i] - tau * direction_[i]);
      if (!entries) return pi;
      const double g = gap(i);
      return pi == 0.0 && g < 0.0 && tau > 0.0 ? -tau * g : pi;
    };
    const bool shifted = problem_.load_controlled && load_by_shift_;
    const double shift = shifted ? load_shift(projected) : 0.0;
    const auto [new_pressure_sum, entered, corrected] = sums<3>(comm_, n_, [&](std::size_t i) {
      const double moved = pressure_[i] - tau * direction_[i];
      const double q = projected(i);
      const double pi = q > 0.0 ? std::max(q + shift, 0.0) : 0.0;
      const double entry = q > 0.0 && moved <= 0.0 ? 1.0 : 0.0;
      pressure_[i] = pi;
      displacement_[i] -= tau * image_[i];
      correction_[i] = static_cast<Work>(pi - moved);
      return std::array<double, 3>{pi, entry, q != moved ? 1.0 : 0.0};
    });
    const double entries_kept = projected_ ? kEntriesKept * contact_cells_ : 0.0;
    conjugate_ = entered <= entries_kept && tau > 0.0;
    finish_step(corrected, corrected > 0.0 || shift != 0.0);
    if (problem_.load_controlled && !shifted) {
      deferred_.scale = problem_.target_force / (problem_.cell_area * new_pressure_sum);
    }
  }

  // The load restored after a step without a cap, once the scaling has
  // stalled (see evaluate): the shift mu of the pressures q_i > 0 with
  //
  //   sum over q_i > 0 of max(q_i + mu, 0)  =  target force / cell area,
  //
  // the projection of q onto the admissible pressures carrying the load
  // that keeps the contact from growing (mu <= 0 unless rounding left the
  // sum short). Polonsky & Keer's scaling, p -> s p, takes the load off
  // every cell in proportion to its pressure: on a surface with a few much
  // higher cells (instrument spikes in measured maps) whose pressure must be
  // many times the others', each scaling undid the step that had raised
  // them, and the iteration cycled between two states far from the solution
  // (sur-2's 256^2 window, every solver, at 1-5 % contact; docs/validation.md,
  // "Robustness matrix"); the shift takes the same load off every contact
  // cell and leaves them raised. It is not the default: on a stiff coating
  // over a soft substrate, whose nearly uniform pressures it clips by the
  // hundred, it can collapse the contact. The left side is convex and
  // piecewise linear in mu, so Newton's method from the shift that ignores
  // the clipping (above the root) falls monotonically onto it, exactly
  // once the cells it clips stop changing.
  template <class Pressure>
  double load_shift(Pressure&& pressure) const {
    const double target_sum = problem_.target_force / problem_.cell_area;
    const auto [sum, count] = sums<2>(comm_, n_, [&](std::size_t i) {
      const double q = pressure(i);
      return q > 0.0 ? std::array<double, 2>{q, 1.0} : std::array<double, 2>{0.0, 0.0};
    });
    if (!(count > 0.0)) return 0.0;
    double shift = (target_sum - sum) / count;
    constexpr int kMaxPasses = 100;
    for (int pass = 0; pass < kMaxPasses; ++pass) {
      const auto [force_sum, slope] = sums<2>(comm_, n_, [&](std::size_t i) {
        const double q = pressure(i);
        return q > 0.0 && q + shift > 0.0 ? std::array<double, 2>{q + shift, 1.0} : std::array<double, 2>{0.0, 0.0};
      });
      const double excess = force_sum - target_sum;
      if (excess <= 1e-15 * target_sum || !(slope > 0.0)) break;
      shift -= excess / slope;
    }
    return shift;
  }

  // Steps 6-9 with a hardness cap: p = P(p - tau t) onto [0, H], entries
  // as above. Under load control scaling alone would lift capped cells
  // above H, or pull them off the cap, so the load is restored by the
  // capped scaling of capped_scale. Its p is stored as CappedScale::stored
  // and scaled by s in the next evaluation (Deferred, which puts it back on
  // the cap exactly), so that the correction c and K c stay exact. A step
  // that leaves too few cells in contact to carry the load at the cap fills
  // the deficit into the cells out of contact with the smallest gaps and
  // restarts the conjugate directions.
  void advance_capped() {
    const bool entries = !projected_;
    const double tau = tau_;
    const double upper = bounds_.upper;
    // The gap is read before the step moves the cell's u.
    auto lower = [&](std::size_t i, double moved) {
      double pi = std::max(moved, bounds_.lower);
      if (entries && pi == 0.0 && tau > 0.0) {
        const double g = gap(i);
        if (g < 0.0) pi = -tau * g;
      }
      return pi;
    };
    CappedScale scale{1.0, true};
    double fill = 0.0;               // pressure of each filled cell
    double fill_below = -kInfinity;  // the filled cells: out of contact with a gap below this
    bool filled = false;
    if (problem_.load_controlled) {
      const double target_sum = problem_.target_force / problem_.cell_area;
      const std::optional<CappedScale> capped =
          capped_scale([&](std::size_t i) { return lower(i, pressure_[i] - tau * direction_[i]); });
      if (capped) {
        scale = *capped;
      } else {
        // The cells at the cap cannot carry the load: the next cells to
        // touch, those out of contact with the smallest gaps, take the rest.
        filled = true;
        const double positive = linalg::sum(
            comm_, n_, [&](std::size_t i) { return lower(i, pressure_[i] - tau * direction_[i]) > 0.0 ? 1.0 : 0.0; });
        const double deficit = target_sum - upper * positive;
        const auto [below, count] =
            smallest_gaps([&](std::size_t i) { return lower(i, pressure_[i] - tau * direction_[i]) == 0.0; },
                          std::ceil(deficit / upper));
        fill_below = below;
        fill = deficit / count;
      }
    }
    const auto [entered, corrected, reached_cap] = sums<3>(comm_, n_, [&](std::size_t i) {
      const double moved = pressure_[i] - tau * direction_[i];
      const double pre = lower(i, moved);
      double pi = scale.stored(pre, upper);
      if (filled) pi = pre > 0.0 ? upper : (gap(i) < fill_below ? fill : 0.0);
      const double entry = entries && moved <= 0.0 && pre > 0.0 ? 1.0 : 0.0;
      pressure_[i] = pi;
      displacement_[i] -= tau * image_[i];
      correction_[i] = static_cast<Work>(pi - moved);
      return std::array<double, 3>{entry, correction_[i] != 0.0 ? 1.0 : 0.0, pre * scale.factor >= upper ? 1.0 : 0.0};
    });
    const double entries_kept = projected_ ? kEntriesKept * contact_cells_ : 0.0;
    conjugate_ = entered <= entries_kept && tau > 0.0 && !filled && (projected_ || reached_cap == 0.0);
    finish_step(corrected, corrected > 0.0);
    deferred_.scale = scale.factor;
  }

  // The end of steps 6-9 shared by both projections: the preconditioner
  // sees how much the projection moved, and the moved part c (correction_)
  // is turned into its displacement K c in place (correction_image_), added
  // to u in the next evaluation's first pass.
  void finish_step(double corrected, bool correction) {
    if (preconditioner_) preconditioner_->observe_step({corrected, search_cells_});
    if (correction) {
      kernel_product(correction_, correction_image_);
      ++result_.operator_applications;
      deferred_.add_correction = true;
    }
    ++updates_since_exact_;
  }

  // The result's summary of the final iterate, whose displacement and gap
  // are current.
  void summarise(int iterations) {
    const auto [pressure_total, contact_total, plastic_total] = sums<3>(comm_, n_, [&](std::size_t i) {
      return std::array<double, 3>{pressure_[i], pressure_[i] > 0.0 ? 1.0 : 0.0,
                                   bounds_.at_cap(pressure_[i]) ? 1.0 : 0.0};
    });
    if (bounds_.capped()) result_.hardness = bounds_.upper;
    result_.plastic_fraction = plastic_total / cells_;
    const Grid& grid = op_.grid();
    result_.iterations = iterations;
    result_.residual = residual_;
    result_.approach = approach_;
    result_.total_force = problem_.cell_area * pressure_total;
    result_.mean_pressure = result_.total_force / grid.domain_area();
    result_.max_pressure = linalg::max_of(comm_, n_, [&](std::size_t i) { return pressure_[i]; });
    result_.contact_fraction = contact_total / cells_;
  }

 private:
  // Steps 8-9 end with work on p and u that the next evaluation does in its
  // first pass rather than in passes of their own: adding K c (held in g)
  // to u, and the load-restoring scale of p and u.
  struct Deferred {
    double scale = 1.0;
    bool add_correction = false;
  };

  // f(z), z the step's search gradient: g itself or M^-1 g (precondition()).
  template <class Function>
  auto with_z(Function&& f) const {
    if (z_is_gap_) return f([this](std::size_t i) { return gap(i); });
    const Work* z = preconditioned_gap_;
    return f([z](std::size_t i) -> double { return z[i]; });
  }

  // The gap of the cell (see the class comment).
  double gap(std::size_t i) const { return problem_.initial_gap[i] + displacement_[i] - approach_; }

  // out = K in on the work vectors, by the inner products (see the header).
  void kernel_product(const Work* in, Work* out) {
    if constexpr (kSingle) {
      single_.kernel({in, n_}, {out, n_});
    } else {
      inner_.apply({in, n_}, {out, n_});
    }
  }

  // Starting pressure from the overlap in g: each cell pushed in by the
  // local overlap alone, p = max(-g, 0) / K_ii, projected onto the bounds.
  void local_overlap_pressure() {
    const double self_influence = op_.self_influence();
    for_each_index(n_, [&](std::size_t i) { pressure_[i] = bounds_.project(std::max(-gap(i), 0.0) / self_influence); });
  }

  // The bound b such that `wanted` cells or a few more (ties) of those with
  // candidate(i) have a gap below it, by bisection over the gaps (a pass per
  // step, about 60 at most), and the number of them.
  template <class Candidate>
  std::pair<double, double> smallest_gaps(Candidate&& candidate, double wanted) const {
    auto count_below = [&](double bound) {
      return linalg::sum(comm_, n_, [&](std::size_t i) { return candidate(i) && gap(i) < bound ? 1.0 : 0.0; });
    };
    const double candidates = count_below(kInfinity);
    wanted = std::min(wanted, candidates);
    // count_below(low) < wanted <= count_below(high) = candidates.
    double low = linalg::min_of(comm_, n_, [&](std::size_t i) { return candidate(i) ? gap(i) : kInfinity; });
    double high = std::nextafter(
        linalg::max_of(comm_, n_, [&](std::size_t i) { return candidate(i) ? gap(i) : -kInfinity; }), kInfinity);
    double count = candidates;
    constexpr int kMaxPasses = 64;
    for (int pass = 0; pass < kMaxPasses && count != wanted; ++pass) {
      const double middle = 0.5 * (low + high);
      if (!(middle > low && middle < high)) break;
      const double below = count_below(middle);
      if (below >= wanted) {
        high = middle;
        count = below;
      } else {
        low = middle;
      }
    }
    return {high, count};
  }

  // The load restored by scaling, with the cap: the factor s with
  //
  //   sum over q_i >= H of H  +  sum over q_i < H of min(H, s q_i)  =  target force / cell area
  //
  // for the pressures q_i = pressure(i) >= 0 (keep_cap): cells pushed to
  // the cap stay there, the others scale. The left side is concave and
  // piecewise linear in s, so Newton's method from the factor that ignores
  // the cap for the others (below the root) rises monotonically to the root
  // and meets it exactly once the capped cells stop changing, in a few
  // passes. If the cells at the cap alone carry more than the load, all
  // cells scale (keep_cap false: s < 1 takes them off the cap). None if the
  // load exceeds H times the cells with q_i > 0.
  template <class Pressure>
  std::optional<CappedScale> capped_scale(Pressure&& pressure) const {
    const double target_sum = problem_.target_force / problem_.cell_area;
    const double upper = bounds_.upper;
    const auto [at_cap, below_sum, total_sum] = sums<3>(comm_, n_, [&](std::size_t i) {
      const double q = pressure(i);
      return q >= upper ? std::array<double, 3>{1.0, 0.0, q} : std::array<double, 3>{0.0, q, q};
    });
    const double cap_sum = upper * at_cap;
    if (!(target_sum > cap_sum)) return CappedScale{target_sum / total_sum, false};
    if (!(below_sum > 0.0)) return std::nullopt;
    double scale = (target_sum - cap_sum) / below_sum;
    const double below_max = linalg::max_of(comm_, n_, [&](std::size_t i) {
      const double q = pressure(i);
      return q < upper ? q : 0.0;
    });
    if (scale * below_max <= upper) return CappedScale{scale, true};
    constexpr int kMaxPasses = 100;
    for (int pass = 0; pass < kMaxPasses; ++pass) {
      const auto [force_sum, slope] = sums<2>(comm_, n_, [&](std::size_t i) {
        const double q = pressure(i);
        return q < upper && scale * q < upper ? std::array<double, 2>{scale * q, q} : std::array<double, 2>{upper, 0.0};
      });
      const double shortfall = target_sum - force_sum;
      if (shortfall <= 1e-15 * target_sum) break;
      if (!(slope > 0.0)) return std::nullopt;  // every loaded cell at the cap, and still short
      scale += shortfall / slope;
    }
    return CappedScale{scale, true};
  }

  // u = K p afresh, after the deferred scale of p (K c is superseded).
  void exact_displacement() {
    if (deferred_.scale != 1.0) {
      const double scale = deferred_.scale;
      for_each_index(n_, [&](std::size_t i) { pressure_[i] = bounds_.snap(pressure_[i] * scale); });
    }
    deferred_ = {};
    op_.apply({pressure_, n_}, {displacement_, n_});
    ++result_.operator_applications;
    updates_since_exact_ = 0;
  }

  // The approach under load control when every contact cell is at the cap,
  // from the surface s = g0 + u: the load then fixes no approach, and the
  // conditions (g <= 0 at the cap, g >= 0 out of contact) hold for any
  // between the highest cell at the cap and the lowest out of contact,
  // when the first is not above the second. Between the two, the midpoint:
  // if the iterate is wrong, cells at the cap then see an open gap (they
  // join the search set to give up pressure) while cells out of contact
  // see an overlap (they join it to take that pressure). At the highest
  // cell at the cap (the smallest approach without an open gap) no cell
  // at the cap could ever leave: a load of a whole number of cells at the
  // cap (F / (H dx dy) an integer) put every contact cell there and the
  // iteration cycled between that and all cells just below the cap. Every
  // cell at the cap (a load of H times the domain): the highest of them.
  double all_capped_approach() const {
    const double highest_capped = linalg::max_of(comm_, n_, [&](std::size_t i) {
      return pressure_[i] > 0.0 ? problem_.initial_gap[i] + displacement_[i] : -kInfinity;
    });
    const double lowest_free = linalg::min_of(comm_, n_, [&](std::size_t i) {
      return pressure_[i] > 0.0 ? kInfinity : problem_.initial_gap[i] + displacement_[i];
    });
    return std::isfinite(lowest_free) ? 0.5 * (highest_capped + lowest_free) : highest_capped;
  }

  // Step 1's two passes: the deferred work and the contact set's mean gap
  // (the approach), then g (not stored), the residual's sums, G = sum over the search set
  // of g^2 and sum over it of g t_old (Powell's test). With a
  // preconditioner, preconditioned_gap_ receives g on the search set.
  void measure() {
    const Deferred deferred = std::exchange(deferred_, Deferred{});
    const double scale = deferred.scale;
    const bool add = deferred.add_correction;
    const auto settled = linalg::sums_and_range<3>(comm_, n_, [&](std::size_t i) {
      double ui = displacement_[i];
      double pi = pressure_[i];
      if (add) ui += correction_image_[i];
      if (scale != 1.0) {
        ui *= scale;
        pi = bounds_.snap(pi * scale);
      }
      if (add || scale != 1.0) {
        displacement_[i] = ui;
        pressure_[i] = pi;
      }
      const double in_contact = pi > 0.0 ? 1.0 : 0.0;
      const double below_cap = set_.in_contact(i) ? 1.0 : 0.0;
      const double surface = problem_.initial_gap[i] + ui;
      return std::pair{std::array<double, 3>{below_cap * surface, below_cap, in_contact}, ui};
    });
    contact_cells_ = settled.sums[2];
    // Under load control the approach makes the mean gap on the contact set
    // below the cap vanish (where the gap is zero at the solution).
    if (problem_.load_controlled) {
      if (settled.sums[1] > 0.0) {
        approach_ = settled.sums[0] / settled.sums[1];
      } else {
        approach_ = all_capped_approach();
      }
    }
    const bool store_gap = preconditioner_ != nullptr;
    const double approach = approach_;
    // With a cap, interpenetration is admissible at the cap: a cell's
    // overlap counts by how far below the cap it is, (H - p)/H, and the
    // pressure-weighted gap by its positive part only (see the header).
    const bool capped = bounds_.capped();
    const double upper = bounds_.upper;
    std::uint8_t* const in_set_mask = in_set_.data();
    const auto [weighted_gap, overlap, pressure_sum, gap_norm, gap_along, released, direction_sum, set_cells,
                set_gap_sum] = sums<9>(comm_, n_, [&](std::size_t i) {
      const double g = problem_.initial_gap[i] + displacement_[i] - approach;
      const bool contained = set_.contains(i, g);
      in_set_mask[i] = contained ? 1 : 0;
      const double in_set = contained ? 1.0 : 0.0;  // a mask, not a branch
      if (store_gap) preconditioned_gap_[i] = static_cast<Work>(in_set * g);
      const double over = std::max(-g, 0.0);
      const double weighted = capped ? pressure_[i] * std::max(g, 0.0) : pressure_[i] * std::abs(g);
      const double overlap_weight = capped ? (upper - pressure_[i]) / upper : 1.0;
      const double release = capped && bounds_.at_cap(pressure_[i]) && g > 0.0 ? 1.0 : 0.0;
      return std::array<double, 9>{
          weighted, overlap_weight * over,  pressure_[i], in_set * (g * g), in_set * (g * direction_[i]),
          release,  in_set * direction_[i], in_set,       in_set * g};
    });
    set_cells_ = set_cells;
    set_gap_sum_ = set_gap_sum;
    released_cells_ = released;
    direction_sum_ = direction_sum;
    gap_norm_ = gap_norm;
    gap_along_direction_ = gap_along;
    const double cells = cells_;
    // Never below the range the same load gives spread uniformly: a flat
    // punch in full contact has ptp(g0) = ptp(K p) = 0 at its solution.
    const double load_range = uniform_response_range_ * pressure_sum / cells;
    const double gap_scale = problem_.initial_gap_range + std::max(settled.max - settled.min, load_range);
    const double numerator = (pressure_sum > 0.0 ? weighted_gap * cells / pressure_sum : 0.0) + overlap;
    residual_ = numerator == 0.0 ? 0.0 : numerator / (cells * gap_scale);
  }

  InfluenceOperator& op_;
  InfluenceOperator& inner_;               // the step's products K t and K c (see the header)
  const SinglePrecisionProducts& single_;  // the same on single-precision work vectors
  const bool refined_;                     // inner_ is not op_: refine (kRefinementFactor)
  Preconditioner* preconditioner_;
  const PolonskyKeerOptions& options_;
  const Problem& problem_;
  SolveResult& result_;
  const linalg::Communicator& comm_;  // the processes the fields are spread over
  const std::size_t n_;               // the cells this process holds
  const double cells_;                // the cells of the whole grid
  double* pressure_;                  // p
  double* displacement_;              // u = K p
  Work* direction_;                   // the conjugate direction t
  // One array of the solver's workspace in four successive roles: g on the
  // search set, made z = M^-1 g in place (steps 1-2); the image K t of the
  // direction (steps 4-5); the step's correction c (steps 6-9), made K c in
  // place (added to u at step 1).
  Work* preconditioned_gap_;
  Work* image_;
  Work* correction_;
  Work* correction_image_;
  const bool projected_;  // the form (see the header)
  // The search set of the last measure(), a byte per cell: set_ reads it
  // (search_mask) until advance() moves p and u.
  std::vector<std::uint8_t> in_set_;
  const SearchSet set_;
  const PressureBounds bounds_;
  double& uniform_response_range_;  // ptp(K 1), the solver's

  int updates_since_exact_ = 0;
  double exact_residual_ = kInfinity;  // the residual at the last exact product
  Deferred deferred_;
  double approach_;
  double residual_ = 0.0;
  double contact_cells_ = 0.0;
  double released_cells_ = 0.0;       // cells at the cap whose gap is positive
  double gap_norm_ = 0.0;             // sum over the search set of g^2
  double gap_along_direction_ = 0.0;  // sum over the search set of g t_old
  double direction_sum_ = 0.0;        // sum over the search set of t_old
  double set_cells_ = 0.0;            // cells in the search set (measure())
  double set_gap_sum_ = 0.0;          // sum over the search set of g (measure())
  double gap_along_new_ = 0.0;        // sum over the search set of g t (conjugate())
  bool z_is_gap_ = true;              // z: g itself, or M^-1 g (preconditioned_gap_)
  double z_mean_ = 0.0;
  double search_cells_ = 0.0;
  double search_gap_sum_ = 0.0;
  double search_norm_ = 0.0;          // G = sum over the search set of g (z - mean z)
  double previous_norm_ = 1.0;        // G of the previous step
  bool conjugate_ = false;            // false right after a restart
  double best_residual_ = kInfinity;  // the least residual by a tenth, and when
  int best_iteration_ = 0;
  bool load_by_shift_ = false;  // the load restored by load_shift, not by scaling
  bool stop_ = false;           // the progress callback asked to stop
  double tau_ = 0.0;
};

// Steps 0 to 9 until the iteration ends, then the result's summary.
template <class Work>
void iterate(Iteration<Work>& it, bool warm) {
  it.start(warm);  // 0: starting pressure
  int k = 0;
  for (;; ++k) {
    it.evaluate(k);                                // 1: gap, approach, residual
    if (it.finished(k)) break;                     //    converged or stopped
    if (it.restarted_without_contact()) continue;  //    (displacement control)
    it.precondition();                             // 2: z = M^-1 g on the search set
    it.conjugate();                                // 3: t = z + beta t
    if (!it.step_length(k)) break;                 // 4-5: K t, tau
    it.advance();                                  // 6-9: p = P(p - tau t), u, load
  }
  it.summarise(k);
}

}  // namespace

void PolonskyKeerOptions::validate() const {
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw InputError(fmt::format("tolerance = {} is invalid: allowed range is (0, 1)", format_number(tolerance)));
  }
  if (max_iterations < 1) {
    throw InputError(fmt::format("max_iterations = {} is invalid: must be at least 1", max_iterations));
  }
}

PolonskyKeer::PolonskyKeer(InfluenceOperator& op, PolonskyKeerOptions options, const InterfaceLaw& law,
                           Preconditioner* preconditioner, InfluenceOperator* inner, SinglePrecisionProducts single)
    : ContactSolver(op.grid(), law),
      op_(op),
      inner_(inner ? *inner : op),
      options_(std::move(options)),
      preconditioner_(preconditioner),
      name_(preconditioner ? fmt::format("{}-polonsky-keer", preconditioner->kind()) : "polonsky-keer"),
      single_(std::move(single)) {
  options_.validate();
  if (inner_.local_size() != op_.local_size()) {
    throw InputError(
        fmt::format("the inner operator holds {} cells, but the operator {}", inner_.local_size(), op_.local_size()));
  }
  if (preconditioner_ && options_.form != PolonskyKeerForm::projected) {
    throw InputError("a preconditioner needs the projected form of Polonsky-Keer (PolonskyKeerForm::projected)");
  }
  if (single_ && preconditioner_ && !single_.precondition) {
    throw InputError("single-precision work vectors with a preconditioner need its single-precision M^-1");
  }
  // The work vectors are made when a solve begins (run) and given back
  // when it ends, so that a phase before it (workspace) holds no float ones
  // beside its own, and the result's gap takes their place at the end.
}

std::span<double> PolonskyKeer::workspace(int which) {
  Eigen::ArrayXd& field = which == 0 ? direction_ : image_;
  const auto n = static_cast<Eigen::Index>(op_.local_size());
  if (single_) {
    // The float ones of an earlier solve are not needed during the phase.
    single_direction_.resize(0);
    single_image_.resize(0);
  }
  if (field.size() != n) field.setZero(n);  // single-precision work vectors: made on first use
  return {field.data(), static_cast<std::size_t>(field.size())};
}

std::span<float> PolonskyKeer::single_workspace(int which) {
  if (!single_) throw std::logic_error("PolonskyKeer::single_workspace without single-precision work vectors");
  direction_.resize(0);
  image_.resize(0);
  Eigen::ArrayXf& field = which == 0 ? single_direction_ : single_image_;
  const auto n = static_cast<Eigen::Index>(op_.local_size());
  if (field.size() != n) field.setZero(n);
  return {field.data(), static_cast<std::size_t>(field.size())};
}

SolveResult PolonskyKeer::do_solve(std::span<const double> initial_gap, const Loading& loading,
                                   std::span<const double> initial_pressure) {
  const std::size_t n = op_.local_size();
  if (initial_pressure.empty()) return run(initial_gap, loading, Eigen::ArrayXd(static_cast<Eigen::Index>(n)), false);
  check_field_size("initial pressure", initial_pressure.size(), op_.grid(), n);
  return run(initial_gap, loading,
             Eigen::Map<const Eigen::ArrayXd>(initial_pressure.data(), static_cast<Eigen::Index>(n)), true);
}

SolveResult PolonskyKeer::do_solve_from(std::span<const double> initial_gap, const Loading& loading,
                                        Eigen::ArrayXd&& start) {
  check_field_size("initial pressure", static_cast<std::size_t>(start.size()), op_.grid(), op_.local_size());
  return run(initial_gap, loading, std::move(start), true);
}

SolveResult PolonskyKeer::run(std::span<const double> initial_gap, const Loading& loading, Eigen::ArrayXd pressure,
                              bool warm) {
  const auto start = std::chrono::steady_clock::now();
  const Problem problem = make_problem(op_, initial_gap, loading, interface_law().bounds());
  const auto n = static_cast<Eigen::Index>(op_.local_size());
  if (single_) {
    // The double workspace of a phase before this solve is given back
    // before the float work vectors and the result's fields are made.
    direction_.resize(0);
    image_.resize(0);
    if (single_direction_.size() != n) single_direction_.setZero(n);
    if (single_image_.size() != n) single_image_.setZero(n);
  } else {
    if (direction_.size() != n) direction_.setZero(n);
    if (image_.size() != n) image_.setZero(n);
  }
  SolveResult result;
  result.solver = name_;
  result.tolerance = options_.tolerance;
  // Room for a typical solve only: a huge iteration limit must not reserve
  // memory the solve never uses; past 1024 iterations the history grows by
  // doubling (a handful of reallocations in a long solve).
  result.residual_history.reserve(static_cast<std::size_t>(std::min(options_.max_iterations, 1024)) + 1);
  result.pressure = std::move(pressure);
  result.displacement.setZero(n);
  if (preconditioner_) preconditioner_->begin_solve();

  if (single_) {
    Iteration<float> it(op_, inner_, single_, preconditioner_, options_, problem, result, single_direction_.data(),
                        single_image_.data(), uniform_response_range_);
    iterate(it, warm);
  } else {
    Iteration<double> it(op_, inner_, single_, preconditioner_, options_, problem, result, direction_.data(),
                         image_.data(), uniform_response_range_);
    iterate(it, warm);
  }
  // The work vectors are given back and the gap takes their place: the
  // scratch of the independent check first, then g0 + u - approach as the
  // iteration computed it.
  direction_.resize(0);
  image_.resize(0);
  single_direction_.resize(0);
  single_image_.resize(0);
  result.gap.resize(n);
  if (result.converged() && !options_.start_only) {
    // "Converged" must mean the conditions hold, checked apart from the
    // residual (contact_conditions.hpp): a false one becomes a breakdown.
    const ContactConditionReport check =
        check_contact_conditions(op_, initial_gap, loading, problem.bounds, result,
                                 ContactConditionTolerances::for_solver_tolerance(options_.tolerance),
                                 std::span<double>(result.gap.data(), static_cast<std::size_t>(n)));
    ++result.operator_applications;
    if (!check.holds) {
      result.status = SolveStatus::breakdown;
      result.message = fmt::format("the residual {:.3e} met the tolerance, but the independent check failed: {}",
                                   result.residual, check.violation);
    }
  }
  const double approach = result.approach;
  double* gap = result.gap.data();
  const double* displacement = result.displacement.data();
  for_each_index(static_cast<std::size_t>(n),
                 [&](std::size_t i) { gap[i] = initial_gap[i] + displacement[i] - approach; });

  if (preconditioner_) preconditioner_->report(result);
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace halfspace::solvers
