// The primal-dual active-set phase of active_set_start.hpp. Each outer
// iteration is one semismooth Newton step on min(p, g) = 0 (Hintermueller,
// Ito & Kunisch 2002): a linear solve on the current set by preconditioned
// conjugate gradients, then the set update.
#include "halfspace/solvers/active_set_start.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::solvers {
namespace {

using linalg::for_each_index;
using linalg::sums;

}  // namespace

void ActiveSetOptions::validate() const {
  if (!(inner_reduction > 0.0 && inner_reduction < 1.0)) {
    throw SolverOptionError("active_set.inner_reduction", fmt::format("{}", inner_reduction),
                            "is invalid: allowed range is (0, 1)");
  }
  if (min_inner < 1) {
    throw SolverOptionError("active_set.min_inner", fmt::format("{}", min_inner), "is invalid: must be at least 1");
  }
  if (max_inner < min_inner) {
    throw SolverOptionError("active_set.max_inner", fmt::format("{}", max_inner),
                            fmt::format("is invalid: must be at least active_set.min_inner ({})", min_inner));
  }
  if (max_outer < 1) {
    throw SolverOptionError("active_set.max_outer", fmt::format("{}", max_outer), "is invalid: must be at least 1");
  }
  if (!(settled_changes >= 0.0 && settled_changes < 1.0)) {
    throw SolverOptionError("active_set.settled_changes", fmt::format("{}", settled_changes),
                            "is invalid: allowed range is [0, 1)");
  }
}

ActiveSetStart::ActiveSetStart(InfluenceOperator& op, Preconditioner& preconditioner,
                               std::unique_ptr<PolonskyKeer> finish, ActiveSetOptions options)
    : op_(op),
      preconditioner_(preconditioner),
      finish_(std::move(finish)),
      options_(options),
      name_(fmt::format("active-set-{}", finish_->name())) {
  options_.validate();
  inner_norms_.reserve(static_cast<std::size_t>(options_.max_inner) + 1);
}

SolveResult ActiveSetStart::do_solve(std::span<const double> initial_gap, const Loading& loading,
                                     std::span<const double> initial_pressure) {
  record_ = {};
  return finish_->solve(initial_gap, loading, initial_pressure);
}

SolveResult ActiveSetStart::do_solve_from(std::span<const double> initial_gap, const Loading& loading,
                                          Eigen::ArrayXd&& start) {
  const std::size_t n = op_.local_size();
  if (initial_gap.size() != n || static_cast<std::size_t>(start.size()) != n) {
    // Polonsky-Keer names the wrong size.
    record_ = {};
    return finish_->solve_from(initial_gap, loading, std::move(start));
  }
  loading.validate();
  record_ = run(initial_gap, loading, start);
  SolveResult result = finish_->solve_from(initial_gap, loading, std::move(start));
  result.iterations += record_.inner;
  result.operator_applications += record_.operator_applications;
  result.preconditioner_applications += record_.preconditioner_applications;
  result.active_set_outer = record_.outer;
  result.active_set_inner = record_.inner;
  return result;
}

// The phase, in numbered steps. Fields: p (the pressure, in place), u = K p
// and the set's mask (both made here and freed before Polonsky-Keer makes
// its own), t and K t in Polonsky-Keer's workspace. The gap r on the set
// is not stored: it is recomputed from u when needed.
ActiveSetRecord ActiveSetStart::run(std::span<const double> initial_gap, const Loading& loading,
                                    Eigen::ArrayXd& pressure) {
  if (finish_->single_products()) return run_on<float>(initial_gap, loading, pressure);
  return run_on<double>(initial_gap, loading, pressure);
}

template <class Work>
ActiveSetRecord ActiveSetStart::run_on(std::span<const double> initial_gap, const Loading& loading,
                                       Eigen::ArrayXd& pressure) {
  constexpr bool kSingle = std::is_same_v<Work, float>;
  ActiveSetRecord record;
  const linalg::Communicator& comm = op_.communicator();
  const Grid& grid = op_.grid();
  const std::size_t n = op_.local_size();
  const bool load_controlled = loading.load_controlled();
  const double target_sum = load_controlled ? loading.target_force(grid.domain_area()) / grid.cell_area() : 0.0;
  const double* g0 = initial_gap.data();
  double* p = pressure.data();
  std::span<Work> direction;
  std::span<Work> image;
  if constexpr (kSingle) {
    direction = finish_->single_workspace(0);
    image = finish_->single_workspace(1);
  } else {
    direction = finish_->workspace(0);
    image = finish_->workspace(1);
  }
  Work* t = direction.data();
  Work* kt = image.data();
  const SinglePrecisionProducts& single = finish_->single_products();
  Eigen::ArrayXd displacement(static_cast<Eigen::Index>(n));
  // A byte per cell: the phase holds u besides what Polonsky-Keer's
  // iteration holds, so that its mask must stay small for the phase not to
  // set the solve's peak.
  std::vector<std::uint8_t> mask(n);
  double* u = displacement.data();
  std::uint8_t* in_set = mask.data();  // 1 on the set C, 0 elsewhere

  // 0. The set of the start: its cells with positive pressure.
  for_each_index(n, [&](std::size_t i) { in_set[i] = p[i] > 0.0 && std::isfinite(p[i]) ? 1 : 0; });
  double set_size = linalg::sum(comm, n, [&](std::size_t i) { return static_cast<double>(in_set[i]); });
  if (!(set_size > 0.0)) return record;
  const SearchSet set = SearchSet::of_mask(in_set, load_controlled);
  preconditioner_.begin_solve();
  double previous_changes = std::numeric_limits<double>::infinity();
  double approach = load_controlled ? 0.0 : loading.value;

  for (int outer = 1; outer <= options_.max_outer; ++outer) {
    // 1. The pressure on C; under load control the force restored by a
    //    uniform shift there (values may turn negative: C is fixed).
    double shift = 0.0;
    if (load_controlled) {
      const double sum = linalg::sum(comm, n, [&](std::size_t i) { return in_set[i] * p[i]; });
      shift = (target_sum - sum) / set_size;
    }
    for_each_index(n, [&](std::size_t i) { p[i] = in_set[i] * (p[i] + shift); });
    op_.apply({p, n}, {u, n});
    ++record.operator_applications;

    // 2. Conjugate gradients on C for K_CC p = a - g0 (under load control
    //    on the mean-free fields of C, a making the mean gap on C vanish).
    inner_norms_.clear();
    double first_norm = 0.0;
    double previous_norm = 1.0;
    bool conjugate = false;
    for (int inner = 0; inner < options_.max_inner; ++inner) {
      if (load_controlled) {
        approach = linalg::sum(comm, n, [&](std::size_t i) { return in_set[i] * (g0[i] + u[i]); }) / set_size;
      }
      // The residual r on C and its norm, tested before M^-1 is applied:
      // the application that would only confirm the end is not made.
      const double rr = linalg::sum(comm, n, [&](std::size_t i) {
        const double r = in_set[i] * (g0[i] + u[i] - approach);
        kt[i] = static_cast<Work>(r);
        return r * r;
      });
      inner_norms_.push_back(std::sqrt(rr));
      if (inner == 0) first_norm = rr;
      const bool reduced = !(rr > options_.inner_reduction * options_.inner_reduction * first_norm);
      if (!(rr > 0.0) || (reduced && inner >= options_.min_inner)) break;
      if (preconditioner_.adapt(set, inner_norms_)) conjugate = false;
      if constexpr (kSingle) {
        single.precondition({kt, n}, {kt, n});
      } else {
        preconditioner_.apply({kt, n}, {kt, n});
      }
      ++record.preconditioner_applications;
      const auto [z_sum, gz] = sums<2>(comm, n, [&](std::size_t i) {
        const double z = kt[i];
        return std::array<double, 2>{in_set[i] * z, in_set[i] * (g0[i] + u[i] - approach) * z};
      });
      const double z_mean = load_controlled ? z_sum / set_size : 0.0;
      // The gap is mean-free on C, so sum g (z - mean z) = sum g z.
      const double norm = gz;
      const double beta = conjugate ? norm / previous_norm : 0.0;
      previous_norm = norm;
      for_each_index(n, [&](std::size_t i) { t[i] = static_cast<Work>(in_set[i] * ((kt[i] - z_mean) + beta * t[i])); });
      if constexpr (kSingle) {
        single.kernel({t, n}, {kt, n});
      } else {
        op_.apply({t, n}, {kt, n});
      }
      ++record.operator_applications;
      const auto [kt_sum, t_sum, gt, tkt] = sums<4>(comm, n, [&](std::size_t i) {
        const double c = static_cast<double>(in_set[i]);
        const double ti = t[i];
        const double kti = kt[i];
        return std::array<double, 4>{c * kti, c * ti, c * (g0[i] + u[i] - approach) * ti, c * ti * kti};
      });
      const double kt_mean = load_controlled ? kt_sum / set_size : 0.0;
      const double curvature = tkt - kt_mean * t_sum;
      const double tau = gt / curvature;
      if (!(curvature > 0.0) || !std::isfinite(tau)) break;  // rounding at the end of a solve: stop here
      for_each_index(n, [&](std::size_t i) {
        p[i] -= tau * t[i];
        u[i] -= tau * kt[i];
      });
      preconditioner_.observe_step({0.0, set_size});
      conjugate = true;
      ++record.inner;
    }

    // 3. The set update from the full gap: C+ = {C, p > 0} + {not C, g < 0}.
    if (load_controlled) {
      approach = linalg::sum(comm, n, [&](std::size_t i) { return in_set[i] * (g0[i] + u[i]); }) / set_size;
    }
    const auto [changes, new_size] = sums<2>(comm, n, [&](std::size_t i) {
      const bool now = in_set[i] != 0 ? p[i] > 0.0 : g0[i] + u[i] - approach < 0.0;
      const double changed = now != (in_set[i] != 0) ? 1.0 : 0.0;
      in_set[i] = now ? 1 : 0;
      return std::array<double, 2>{changed, now ? 1.0 : 0.0};
    });
    record.outer = outer;
    record.last_changes = changes;
    const bool settled = changes <= options_.settled_changes * set_size;
    const bool stalled = changes >= previous_changes;
    set_size = new_size;
    previous_changes = changes;
    if (settled || stalled || !(set_size > 0.0)) break;
  }
  // 4. The start of Polonsky-Keer: max(p, 0) (its start scales it to the load).
  for_each_index(n, [&](std::size_t i) { p[i] = std::max(p[i], 0.0); });
  // The preconditioner's own products (block deflation's two per
  // application and its kernel), counted by its report.
  SolveResult preconditioner_work;
  preconditioner_.report(preconditioner_work);
  record.operator_applications += preconditioner_work.operator_applications;
  // Polonsky-Keer continues on the set the phase found: whether the
  // correction pays was measured here already.
  preconditioner_.continue_next_solve();
  return record;
}

}  // namespace halfspace::solvers
