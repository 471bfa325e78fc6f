// Polonsky-Keer constrained conjugate gradient (Polonsky & Keer 1999, Wear
// 231, 206-219). The steps below follow the paper's numbering; the stopping
// test is ours (see the header) because the paper's relative pressure change
// says little about how well the contact conditions hold.
#include "halfspace/solvers/polonsky_keer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::solvers {
namespace {

using linalg::for_each_index;
using linalg::sums;

// The displacement is updated incrementally between exact products K p; an
// exact one every this many updates keeps rounding from accumulating.
constexpr int kUpdatesBetweenExactProducts = 50;

// ConjugacyRestart::powell: Powell's threshold, and the share of the contact
// cells that may enter in one step without a restart.
constexpr double kPowellRestart = 0.2;
constexpr double kEntriesKept = 0.01;

// Deflation joins once a step clips at most this share of the search set:
// while the contact set still moves by thousands of cells, the coarse
// correction's block-wide pressure changes clip more cells than they settle
// (at 2048^2 the iteration then fails to converge), and once it has settled
// the correction takes the iterations' rate from 0.7-0.75 to about 0.3
// (docs/performance.md).
constexpr double kDeflateBelowClipped = 0.01;
// ... and only where the iteration without it is slow: a deflated iteration
// costs about twice as many products and converges at about 0.3 per
// iteration, which pays against a rate above 0.3^(1/2) = 0.55, measured
// over two settled undeflated steps. Rough contacts run at 0.7-0.8 there; a
// Hertz contact at 0.2-0.4, where deflation saved one iteration in ten and
// doubled the time (docs/performance.md).
constexpr double kDeflateAboveRate = 0.55;
constexpr int kRateSteps = 2;

struct Problem {
  std::span<const double> initial_gap;
  bool load_controlled;
  double target_force;  // load control only
  double approach;      // displacement control only
  double cell_area;
  double initial_gap_range;  // ptp(initial_gap)
};

void check_size(std::string_view what, std::size_t got, std::size_t expected) {
  if (got != expected) {
    throw InputError(fmt::format("{} has {} entries, but the grid has {} cells", what, got, expected));
  }
}

// Starting pressure for displacement control: each cell pushed in by the
// local overlap alone, p = max(approach - g0, 0) / K_ii.
void local_overlap_pressure(std::span<const double> gap, double self_influence, double* pressure) {
  for_each_index(gap.size(), [&](std::size_t i) { pressure[i] = std::max(-gap[i], 0.0) / self_influence; });
}

}  // namespace

void PolonskyKeerOptions::validate() const {
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw InputError(fmt::format("tolerance = {} is invalid: allowed range is (0, 1)", tolerance));
  }
  if (max_iterations < 1) {
    throw InputError(fmt::format("max_iterations = {} is invalid: must be at least 1", max_iterations));
  }
}

PolonskyKeer::PolonskyKeer(InfluenceOperator& op, PolonskyKeerOptions options, Preconditioner* preconditioner,
                           BlockDeflation* deflation)
    : op_(op), options_(std::move(options)), preconditioner_(preconditioner), deflation_(deflation) {
  options_.validate();
  if (deflation_ && !preconditioner_) throw InputError("block deflation needs a preconditioner");
  if (deflation_ && deflation_->grid().size() != op_.grid().size()) {
    throw InputError("block deflation was built for a different grid than the operator's");
  }
  const auto n = static_cast<Eigen::Index>(op_.grid().size());
  direction_.setZero(n);
  direction_image_.setZero(n);
}

SolveResult PolonskyKeer::solve(std::span<const double> initial_gap, const Loading& loading,
                                std::span<const double> initial_pressure) {
  const std::size_t n = op_.grid().size();
  if (initial_pressure.empty()) return run(initial_gap, loading, Eigen::ArrayXd(static_cast<Eigen::Index>(n)), false);
  check_size("initial pressure", initial_pressure.size(), n);
  return run(initial_gap, loading,
             Eigen::Map<const Eigen::ArrayXd>(initial_pressure.data(), static_cast<Eigen::Index>(n)), true);
}

SolveResult PolonskyKeer::solve_from(std::span<const double> initial_gap, const Loading& loading,
                                     Eigen::ArrayXd&& start) {
  check_size("initial pressure", static_cast<std::size_t>(start.size()), op_.grid().size());
  return run(initial_gap, loading, std::move(start), true);
}

// B r = Q r + (I - Q K) M^-1 (I - K Q) r, Q = Z A^-1 Z^T, with r the gap on
// the search set (less its mean there under load control: the iteration
// moves in the mean-free directions, and B must act on those alone to stay
// symmetric there). The coarse functions live on the contact cells, for
// which the caller has updated deflation_.
template <class InSearch>
void PolonskyKeer::apply_balancing(bool load_controlled, InSearch&& in_search, SolveResult& result) {
  const std::size_t n = op_.grid().size();
  const double* g = result.gap.data();
  double* z = direction_image_.data();
  // One field holds Z y1, then its image (K in place), then K of M^-1's
  // output: post_correction needs the coarse y1 alone, which it keeps.
  double* field = coarse_field_.data();
  const auto [count, gap_sum] = sums<2>(n, [&](std::size_t i) {
    const double inside = in_search(i) ? 1.0 : 0.0;
    return std::array<double, 2>{inside, inside * g[i]};
  });
  const double shift = load_controlled ? gap_sum / count : 0.0;
  for_each_index(n, [&](std::size_t i) { z[i] = in_search(i) ? g[i] - shift : 0.0; });
  // values = values - minus on the set, zero elsewhere, mean-free on the set
  // under load control.
  auto onto_set = [&](double* values, const double* minus) {
    double mean = 0.0;
    if (load_controlled) {
      mean = linalg::sum(n, [&](std::size_t i) { return in_search(i) ? values[i] - (minus ? minus[i] : 0.0) : 0.0; }) /
             count;
    }
    for_each_index(
        n, [&](std::size_t i) { values[i] = in_search(i) ? values[i] - (minus ? minus[i] : 0.0) - mean : 0.0; });
  };
  deflation_->pre_correction({z, n}, {field, n}, load_controlled);
  op_.apply({field, n}, {field, n});
  ++result.operator_applications;
  onto_set(z, field);
  preconditioner_->apply({z, n}, {z, n});
  ++result.preconditioner_applications;
  onto_set(z, nullptr);
  op_.apply({z, n}, {field, n});
  ++result.operator_applications;
  deflation_->post_correction({field, n}, {z, n}, load_controlled);
}

SolveResult PolonskyKeer::run(std::span<const double> initial_gap, const Loading& loading, Eigen::ArrayXd pressure,
                              bool warm) {
  const auto start = std::chrono::steady_clock::now();
  const Grid& grid = op_.grid();
  const std::size_t n = grid.size();
  const double cells = static_cast<double>(n);
  check_size("initial gap", initial_gap.size(), n);
  loading.validate();

  const double gap_max = linalg::max_of(n, [&](std::size_t i) { return initial_gap[i]; });
  const double gap_min = linalg::min_of(n, [&](std::size_t i) { return initial_gap[i]; });
  if (!std::isfinite(gap_max) || !std::isfinite(gap_min)) {
    throw InputError("initial gap holds a non-finite value");
  }

  Problem problem{initial_gap, loading.load_controlled(), 0.0, 0.0, grid.cell_area(), gap_max - gap_min};
  if (problem.load_controlled) {
    problem.target_force = loading.target_force(grid.domain_area());
  } else {
    problem.approach = loading.value;
  }
  if (!problem.load_controlled && grid.periodic()) {
    // With a zero-mean displacement the mean gap is mean(g0) - approach, and
    // it cannot be negative: at mean(g0) the pressure is already infinite.
    const double mean_gap = linalg::sum(n, [&](std::size_t i) { return initial_gap[i]; }) / cells;
    if (problem.approach >= mean_gap) {
      throw InputError(
          fmt::format("approach = {} m is invalid for a periodic surface: it must be below the mean initial gap {} m "
                      "(full contact needs infinite pressure there)",
                      problem.approach, mean_gap));
    }
  }

  SolveResult result;
  result.solver = std::string(name());
  result.tolerance = options_.tolerance;
  result.residual_history.reserve(static_cast<std::size_t>(options_.max_iterations) + 1);
  result.pressure = std::move(pressure);
  result.displacement.setZero(static_cast<Eigen::Index>(n));
  result.gap.setZero(static_cast<Eigen::Index>(n));
  double* p = result.pressure.data();
  double* u = result.displacement.data();
  double* g = result.gap.data();
  double* t = direction_.data();
  double* r = direction_image_.data();
  const std::span<const double> pressure_view(p, n);
  const std::span<double> displacement_view(u, n);
  const double k_self = op_.self_influence();

  // Step 0: starting pressure. Load control: the warm start or a uniform
  // pressure, scaled to the target force. Displacement control: the warm
  // start or the local-overlap guess.
  if (warm) {
    for_each_index(n, [&](std::size_t i) { p[i] = std::max(p[i], 0.0); });
  } else {
    for_each_index(n, [&](std::size_t i) { p[i] = 0.0; });
  }
  if (problem.load_controlled) {
    double force = problem.cell_area * linalg::sum(n, [&](std::size_t i) { return p[i]; });
    if (!(force > 0.0)) {
      for_each_index(n, [&](std::size_t i) { p[i] = 1.0; });
      force = problem.cell_area * cells;
    }
    const double scale = problem.target_force / force;
    for_each_index(n, [&](std::size_t i) { p[i] *= scale; });
  } else if (!warm) {
    for_each_index(n, [&](std::size_t i) { g[i] = initial_gap[i] - problem.approach; });
    local_overlap_pressure({g, n}, k_self, p);
  }

  if (uniform_response_range_ < 0.0) {
    // ptp(K 1) for the gap scale (see the header), once per solver; t and r
    // are free until the iteration starts.
    direction_.setOnes();
    op_.apply({t, n}, {r, n});
    ++result.operator_applications;
    uniform_response_range_ =
        linalg::max_of(n, [&](std::size_t i) { return r[i]; }) - linalg::min_of(n, [&](std::size_t i) { return r[i]; });
  }
  direction_.setZero();
  // Deflation (see apply_balancing): whether it is on, and the last step's
  // clipped cells and search set, which decide it.
  bool deflating = false;
  bool deflation_declined = false;
  const BlockDeflationStats deflation_before = deflation_ ? deflation_->stats() : BlockDeflationStats{};
  double clipped_before = std::numeric_limits<double>::infinity();
  double searched_before = 0.0;
  int settled_steps = 0;        // consecutive undeflated steps that clipped little
  bool deflation_pays = false;  // their rate was slow (kDeflateAboveRate)
  double previous_norm = 1.0;   // G_old
  bool conjugate = false;       // delta: false right after a reset
  double approach = problem.approach;
  double residual = 0.0;
  double contact_cells = 0.0;
  double gap_norm = 0.0;
  double gap_along_direction = 0.0;  // sum over the search set of g t_old (restart tests)
  const bool powell_restart = options_.restart == ConjugacyRestart::powell;
  const bool search_overlap = options_.search_set == SearchSet::contact_and_overlap;
  // Whether cell i is in the search set (see SearchSet); g must be the
  // current gap, which it is from step 1 until K c is stored in it (step 8).
  // Bitwise, not short-circuit, so that the masks stay free of branches; the
  // test of search_overlap is the same in every cell (the loops unswitch).
  auto searched = [&](std::size_t i) { return search_overlap ? (p[i] > 0.0) | (g[i] < 0.0) : p[i] > 0.0; };
  double search_cells = 0.0;    // cells in the search set
  double search_gap_sum = 0.0;  // sum over the search set of g

  // Work that steps 6-9 leave to the next evaluation, which does it in its
  // first pass rather than in passes of its own: the load-restoring scale of
  // p and u, and adding K c (held in g) to u.
  double pending_scale = 1.0;
  bool pending_correction = false;

  // u = K p computed afresh (rather than updated, see steps 6-8).
  int updates_since_exact = 0;
  auto compute_displacement = [&] {
    if (pending_scale != 1.0) {
      const double scale = pending_scale;
      for_each_index(n, [&](std::size_t i) { p[i] *= scale; });
    }
    pending_scale = 1.0;
    pending_correction = false;
    op_.apply(pressure_view, displacement_view);
    ++result.operator_applications;
    updates_since_exact = 0;
  };
  // Step 1: the pending work, then the gap of the current pressure, its
  // approach under load control, the residual (see the header) and G = sum
  // over the search set of g^2. With a preconditioner, r receives g
  // restricted to the search set.
  auto evaluate = [&] {
    const double scale = pending_scale;
    const bool add = pending_correction;
    pending_scale = 1.0;
    pending_correction = false;
    const auto settled = linalg::sums_and_range<2>(n, [&](std::size_t i) {
      double ui = u[i];
      double pi = p[i];
      if (add) ui += g[i];
      if (scale != 1.0) {
        ui *= scale;
        pi *= scale;
      }
      if (add || scale != 1.0) {
        u[i] = ui;
        p[i] = pi;
      }
      const double in_contact = pi > 0.0 ? 1.0 : 0.0;
      return std::pair{std::array<double, 2>{in_contact * (initial_gap[i] + ui), in_contact}, ui};
    });
    contact_cells = settled.sums[1];
    if (problem.load_controlled) {
      // The approach makes the mean gap on the contact set vanish.
      approach = settled.sums[0] / contact_cells;
    }
    const bool restrict_to_contact = preconditioner_ != nullptr;
    const auto [weighted_gap, overlap, pressure_sum, searched_gap_norm, gap_along] = sums<5>(n, [&](std::size_t i) {
      g[i] = initial_gap[i] + u[i] - approach;
      const double in_search = searched(i) ? 1.0 : 0.0;  // a mask, not a branch: contact edges are everywhere
      if (restrict_to_contact) r[i] = in_search * g[i];
      return std::array<double, 5>{p[i] * std::abs(g[i]), std::max(-g[i], 0.0), p[i], in_search * (g[i] * g[i]),
                                   in_search * (g[i] * t[i])};
    });
    gap_norm = searched_gap_norm;
    gap_along_direction = gap_along;
    // Never below the range the same load gives spread uniformly: a flat
    // punch in full contact has ptp(g0) = ptp(K p) = 0 at its solution.
    const double load_range = uniform_response_range_ * pressure_sum / cells;
    const double gap_scale = problem.initial_gap_range + std::max(settled.max - settled.min, load_range);
    const double numerator = (pressure_sum > 0.0 ? weighted_gap * cells / pressure_sum : 0.0) + overlap;
    residual = numerator == 0.0 ? 0.0 : numerator / (cells * gap_scale);
  };

  compute_displacement();
  int iteration = 0;
  for (;; ++iteration) {
    if (updates_since_exact >= kUpdatesBetweenExactProducts) compute_displacement();
    evaluate();
    if (residual <= options_.tolerance && updates_since_exact > 0) {
      // Convergence is judged on the exact product only.
      compute_displacement();
      evaluate();
    }
    result.residual_history.push_back(residual);
    if (options_.progress) options_.progress(iteration, residual);

    if (residual <= options_.tolerance) {
      result.status = SolveStatus::converged;
      break;
    }
    if (!std::isfinite(residual)) {
      result.status = SolveStatus::breakdown;
      result.message = fmt::format("residual became non-finite at iteration {}", iteration);
      break;
    }
    if (iteration == options_.max_iterations) {
      result.status = SolveStatus::iteration_limit;
      result.message = fmt::format("no convergence after {} iterations: residual {:.3e} > tolerance {:.3e}", iteration,
                                   residual, options_.tolerance);
      break;
    }
    if (contact_cells == 0.0) {
      // Displacement control lost every contact cell: restart from the local
      // overlap of the current gap.
      local_overlap_pressure({g, n}, k_self, p);
      compute_displacement();
      conjugate = false;
      continue;
    }

    // Step 2: z = g, or with a preconditioner z = M^-1 g, on the search set
    // (g there is already in r, which is free until step 4); under load
    // control mean-free on the search set, so that the step keeps the force;
    // G = sum over the search set of g z. (On C alone, g is mean-free
    // already: the approach makes it so.)
    // The size of the search set and the sum of g over it are counted here,
    // not in step 1, whose pass already holds five sums.
    double* z = g;
    double z_sum = 0.0;
    double gz = gap_norm;
    if (preconditioner_) {
      z = r;
      // The coarse correction joins once clipping has died down; a change
      // of preconditioner restarts the conjugate directions.
      if (deflation_ != nullptr && !deflation_pays && settled_steps >= kRateSteps) {
        const std::vector<double>& history = result.residual_history;
        const double ratio = history.back() / history[history.size() - 1 - kRateSteps];
        const double rate = std::pow(ratio, 1.0 / kRateSteps);
        deflation_pays = rate > kDeflateAboveRate;
        result.deflation.fast_rate = deflation_pays ? 0.0 : rate;
      }
      bool deflate = deflation_pays && !deflation_declined && clipped_before <= kDeflateBelowClipped * searched_before;
      auto in_contact = [&](std::size_t i) { return p[i] > 0.0; };  // the coarse functions' cells
      if (deflate && !kernel_known_ && deflation_->decline_if_dense(in_contact)) {
        deflate = false;  // too dense a contact: not in this solve, and no kernel or fields made for it
        deflation_declined = true;
      }
      if (deflate && !kernel_known_) {
        // The correction's field, and the kernel in real space, K e_0, for
        // the coarse matrix: once per solver, when first needed, so that a
        // solve that never deflates holds neither (8 B per cell).
        coarse_field_.setZero(static_cast<Eigen::Index>(n));
        coarse_field_[0] = 1.0;
        double* unit = coarse_field_.data();
        op_.apply({unit, n}, {unit, n});
        ++result.operator_applications;
        deflation_->set_kernel({unit, n});
        kernel_known_ = true;
      }
      if (deflate) {
        deflation_->update(in_contact);
        deflation_declined = !deflation_->ready();  // too dense a contact: not in this solve
        deflate = !deflation_declined;
      }
      if (deflate != deflating) conjugate = false;
      deflating = deflate;
      if (deflating) {
        apply_balancing(problem.load_controlled, searched, result);
        ++result.deflation.deflated_iterations;
      } else {
        preconditioner_->apply({z, n}, {z, n});
        ++result.preconditioner_applications;
      }
      const auto [searched_z, searched_gz, searched_count, searched_gap] = sums<4>(n, [&](std::size_t i) {
        const double in_search = searched(i) ? 1.0 : 0.0;
        return std::array<double, 4>{in_search * z[i], in_search * (g[i] * z[i]), in_search, in_search * g[i]};
      });
      z_sum = searched_z;
      gz = searched_gz;
      search_cells = searched_count;
      search_gap_sum = searched_gap;
    } else if (search_overlap) {
      const auto [searched_count, searched_gap] = sums<2>(n, [&](std::size_t i) {
        const double in_search = searched(i) ? 1.0 : 0.0;
        return std::array<double, 2>{in_search, in_search * g[i]};
      });
      search_cells = searched_count;
      search_gap_sum = searched_gap;
      z_sum = search_gap_sum;  // z = g
    } else {
      // Plain Polonsky-Keer on C, where g is mean-free already.
      search_cells = contact_cells;
      search_gap_sum = 0.0;
    }
    const bool mean_free = problem.load_controlled && (preconditioner_ != nullptr || search_overlap);
    const double z_mean = mean_free ? z_sum / search_cells : 0.0;
    const double search_norm = gz - z_mean * search_gap_sum;

    // Step 3: conjugate direction on the search set, unless restarting.
    if (powell_restart && !(std::abs(gap_along_direction) <= kPowellRestart * search_norm)) conjugate = false;
    const double beta = conjugate ? search_norm / previous_norm : 0.0;
    for_each_index(n, [&](std::size_t i) { t[i] = searched(i) ? (z[i] - z_mean) + beta * t[i] : 0.0; });
    previous_norm = search_norm;

    // Step 4: its image r = K t, mean-corrected on the search set under load
    // control.
    op_.apply({t, n}, {r, n});
    ++result.operator_applications;
    const auto [r_sum, t_sum, gt, rt] = sums<4>(n, [&](std::size_t i) {
      const double in_search = searched(i) ? 1.0 : 0.0;
      return std::array<double, 4>{in_search * r[i], in_search * t[i], in_search * (g[i] * t[i]),
                                   in_search * (r[i] * t[i])};
    });
    const double r_mean = problem.load_controlled ? r_sum / search_cells : 0.0;
    const double curvature = rt - r_mean * t_sum;

    // Step 5: step length, the exact minimiser along t on the current contact
    // set. After a restart (t = z on C) it is positive; a conjugate direction
    // can give a negative one, which is still a valid step, but then no cell
    // enters (its pressure -tau g would be negative) and the next step restarts.
    const double tau = gt / curvature;
    if (!(curvature > 0.0) || !std::isfinite(tau)) {
      result.status = SolveStatus::breakdown;
      result.message = fmt::format("non-positive curvature t.Kt = {:.3e} at iteration {}", curvature, iteration);
      break;
    }

    // Steps 6-8: move along t, clip to p >= 0, and (search set C only) let
    // cells that are out of contact but interpenetrate (g < 0) enter with
    // pressure -tau g. Entries reset the conjugacy: any entry under
    // ConjugacyRestart::on_entry, more than 1% of the contact cells under
    // powell. The projected-gradient search set has no entries: its
    // interpenetrating cells were in the direction, and the step has given
    // them pressure or not (then they stay in the set while g < 0). The
    // displacement follows without a new product: K(p - tau t) = u - tau r,
    // plus K c for the correction c that clipping and entries add, which is
    // zero once the contact set settles.
    // r is not needed after this pass, so it receives c.
    const auto [new_pressure_sum, entered, corrected] = sums<3>(n, [&](std::size_t i) {
      const double moved = p[i] - tau * t[i];
      double pi = std::max(moved, 0.0);
      double entry = 0.0;
      if (!search_overlap && pi == 0.0 && g[i] < 0.0 && tau > 0.0) {
        pi = -tau * g[i];
        entry = 1.0;
      }
      p[i] = pi;
      u[i] -= tau * r[i];
      r[i] = pi - moved;
      return std::array<double, 3>{pi, entry, r[i] != 0.0 ? 1.0 : 0.0};
    });
    const double entries_kept = powell_restart ? kEntriesKept * contact_cells : 0.0;
    conjugate = entered <= entries_kept && tau > 0.0;
    clipped_before = corrected;
    searched_before = search_cells;
    settled_steps = !deflating && corrected <= kDeflateBelowClipped * search_cells ? settled_steps + 1 : 0;
    if (corrected > 0.0) {
      // g is recomputed from u in step 1, so it can hold K c until then.
      op_.apply({r, n}, {g, n});
      ++result.operator_applications;
      pending_correction = true;
    }
    ++updates_since_exact;

    // Step 9: restore the load (K is linear: u scales with p), in the next
    // evaluation's first pass.
    if (problem.load_controlled) pending_scale = problem.target_force / (problem.cell_area * new_pressure_sum);
  }

  if (deflation_) {
    // This solve's share of the correction's counters.
    const BlockDeflationStats& after = deflation_->stats();
    result.deflation.block = deflation_->block();
    result.deflation.rebuilds = after.rebuilds - deflation_before.rebuilds;
    result.deflation.updates = after.updates - deflation_before.updates;
    result.deflation.declined = after.declined - deflation_before.declined;
    result.deflation.coarse_iterations = after.coarse_iterations - deflation_before.coarse_iterations;
    result.deflation.unconverged_coarse_solves =
        after.unconverged_coarse_solves - deflation_before.unconverged_coarse_solves;
    if (result.deflation.unconverged_coarse_solves > 0) {
      result.warnings.push_back(
          fmt::format("block deflation: {} of {} coarse solves stopped short of their tolerance (iteration limit or "
                      "non-positive curvature), so the coarse correction was inexact",
                      result.deflation.unconverged_coarse_solves, 2 * result.deflation.deflated_iterations));
    }
  }
  // Summary of the final iterate, whose displacement and gap are current.
  const auto [pressure_total, contact_total] = sums<2>(n, [&](std::size_t i) {
    return std::array<double, 2>{p[i], p[i] > 0.0 ? 1.0 : 0.0};
  });
  result.iterations = iteration;
  result.residual = residual;
  result.approach = approach;
  result.total_force = problem.cell_area * pressure_total;
  result.mean_pressure = result.total_force / grid.domain_area();
  result.max_pressure = linalg::max_of(n, [&](std::size_t i) { return p[i]; });
  result.contact_fraction = contact_total / cells;
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace halfspace::solvers
