// The independent check of a solved contact (contact_conditions.hpp): one
// product K p, then one pass over the cells for the conditions and one for
// the force.
#include "halfspace/solvers/contact_conditions.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::solvers {

ContactConditionTolerances ContactConditionTolerances::for_solver_tolerance(double tolerance) {
  ContactConditionTolerances tolerances;
  tolerances.gap = std::max(1e-6, std::sqrt(tolerance));
  return tolerances;
}

ContactConditionReport check_contact_conditions(InfluenceOperator& op, std::span<const double> initial_gap,
                                                const Loading& loading, const PressureBounds& bounds,
                                                const SolveResult& result, const ContactConditionTolerances& tolerances,
                                                std::span<double> scratch) {
  const linalg::Communicator& comm = op.communicator();
  const std::size_t n = op.local_size();
  const auto size = static_cast<std::size_t>(result.pressure.size());
  if (initial_gap.size() != n || size != n || scratch.size() != n ||
      static_cast<std::size_t>(result.displacement.size()) != n) {
    throw InputError(
        fmt::format("contact check: the initial gap, the pressure, the displacement and the scratch "
                    "have {}, {}, {} and {} entries, but the operator's grid has {} cells",
                    initial_gap.size(), size, result.displacement.size(), scratch.size(), n));
  }
  ContactConditionReport report;
  auto fail = [&](std::string why) {
    if (report.holds) report.violation = std::move(why);
    report.holds = false;
  };
  const double* p = result.pressure.data();
  const double* u_result = result.displacement.data();
  // 1. Finite fields and scalars.
  const double non_finite = linalg::sum(comm, n, [&](std::size_t i) {
    return std::isfinite(p[i]) && std::isfinite(u_result[i]) && std::isfinite(initial_gap[i]) ? 0.0 : 1.0;
  });
  if (non_finite > 0.0 || !std::isfinite(result.approach) || !std::isfinite(result.total_force)) {
    fail(
        fmt::format("{:g} cells hold a non-finite pressure or displacement, or the approach ({:g} m) or force "
                    "({:g}) is not finite",
                    non_finite, result.approach, result.total_force));
    return report;
  }
  // 2. u = K p afresh.
  op.apply({p, n}, scratch);
  const double* u = scratch.data();
  const auto surface = linalg::sums_and_range<1>(comm, n, [&](std::size_t i) {
    return std::pair{std::array<double, 1>{0.0}, initial_gap[i]};
  });
  const auto response = linalg::sums_and_range<1>(comm, n, [&](std::size_t i) {
    return std::pair{std::array<double, 1>{p[i]}, u[i]};
  });
  // The floor max |K p| keeps the scale from vanishing on a flat punch in
  // full contact, where ptp(g0) = 0 and ptp(K p) is rounding.
  const double gap_scale =
      (surface.max - surface.min) +
      std::max(response.max - response.min, std::max(std::abs(response.max), std::abs(response.min)));
  const double scale = gap_scale > 0.0 ? gap_scale : 1.0;
  // 3. Bounds, complementarity (on the frictionless law, lower bound 0) and
  // the displacement the result reports.
  const bool frictionless = bounds.lower == 0.0;
  const double approach = result.approach;
  const auto worst = linalg::sums_and_range<1>(comm, n, [&](std::size_t i) {
    const double g = initial_gap[i] + u[i] - approach;
    double violation = 0.0;
    if (frictionless) {
      if (p[i] <= 0.0) violation = std::max(-g, 0.0);                   // no interpenetration
      if (p[i] > 0.0 && !bounds.at_cap(p[i])) violation = std::abs(g);  // closed below the cap
      if (bounds.at_cap(p[i])) violation = std::max(g, 0.0);            // not open at the cap
    }
    return std::pair{std::array<double, 1>{0.0}, violation};
  });
  const double below = linalg::min_of(comm, n, [&](std::size_t i) { return p[i] - bounds.lower; });
  const double above = linalg::max_of(comm, n, [&](std::size_t i) { return p[i] - bounds.upper; });
  const double displacement_error =
      linalg::max_of(comm, n, [&](std::size_t i) { return std::abs(u[i] - u_result[i]); });
  report.worst_gap = worst.max / scale;
  report.displacement_error = displacement_error / scale;
  if (below < 0.0 || above > 0.0) {
    fail(fmt::format("a pressure lies outside the bounds [{:g}, {:g}] Pa (by {:.3e} Pa)", bounds.lower, bounds.upper,
                     std::max(-below, above)));
  }
  if (report.worst_gap > tolerances.gap) {
    fail(
        fmt::format("the contact conditions fail by a gap of {:.3e} m, {:.2e} of the gap scale {:.3e} m "
                    "(tolerance {:.1e})",
                    worst.max, report.worst_gap, gap_scale, tolerances.gap));
  }
  if (report.displacement_error > tolerances.gap) {
    fail(fmt::format("the displacement differs from K p by {:.3e} m, {:.2e} of the gap scale (tolerance {:.1e})",
                     displacement_error, report.displacement_error, tolerances.gap));
  }
  // 4. The load: the force asked for, or the approach imposed.
  const Grid& grid = op.grid();
  const double force = grid.cell_area() * response.sums[0];
  if (loading.load_controlled()) {
    const double target = loading.target_force(grid.domain_area());
    report.force_error = std::abs(force - target) / std::abs(target);
    if (report.force_error > tolerances.force) {
      fail(fmt::format("the force {:.6g} differs from the load {:.6g} by {:.2e} of it (tolerance {:.1e})", force,
                       target, report.force_error, tolerances.force));
    }
  } else {
    report.force_error = std::abs(approach - loading.value) / scale;
    if (report.force_error > tolerances.force) {
      fail(fmt::format("the approach {:.6g} m differs from the imposed {:.6g} m by {:.2e} of the gap scale", approach,
                       loading.value, report.force_error));
    }
  }
  if (std::abs(result.total_force - force) > tolerances.force * std::max(std::abs(force), 1e-300)) {
    fail(fmt::format("the reported force {:.6g} differs from the pressure's {:.6g}", result.total_force, force));
  }
  return report;
}

}  // namespace halfspace::solvers
