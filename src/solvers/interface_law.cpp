// Validation of the interface law and the plastic fields it implies.
#include "halfspace/solvers/interface_law.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <cmath>

#include "halfspace/error.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::solvers {

void InterfaceLaw::validate() const {
  if (!hardness) return;
  const double h = *hardness;
  if (!(std::isfinite(h) && h >= kMinHardness && h <= kMaxHardness)) {
    throw SolverOptionError("hardness", format_number(h),
                            fmt::format("Pa is invalid: allowed range is {:g} to {:g} Pa", kMinHardness, kMaxHardness));
  }
}

void InterfaceLaw::check_load(const Grid& grid, const Loading& loading) const {
  if (!hardness || !loading.load_controlled()) return;
  const double area = grid.domain_area();
  const double force = loading.target_force(area);
  // The largest force the surface carries: every cell at the cap.
  if (force > *hardness * area) {
    throw InputError(fmt::format(
        "the load is infeasible with hardness = {} Pa: the force {} {} exceeds the hardness times the domain area "
        "{} {} = {} {} (the largest force a fully plastic surface carries); lower the load or raise the hardness",
        format_number(*hardness), format_number(force), grid.dimension() == 1 ? "N/m" : "N", format_number(area),
        grid.dimension() == 1 ? "m" : "m^2", format_number(*hardness * area), grid.dimension() == 1 ? "N/m" : "N"));
  }
}

PressureBounds InterfaceLaw::bounds() const {
  return hardness ? PressureBounds::capped_at(*hardness) : PressureBounds{};
}

Eigen::Array<unsigned char, Eigen::Dynamic, 1> plastic_cells(std::span<const double> pressure,
                                                             std::optional<double> hardness) {
  const auto n = static_cast<Eigen::Index>(pressure.size());
  Eigen::Array<unsigned char, Eigen::Dynamic, 1> plastic = Eigen::Array<unsigned char, Eigen::Dynamic, 1>::Zero(n);
  if (!hardness) return plastic;
  const PressureBounds bounds = PressureBounds::capped_at(*hardness);
  for (Eigen::Index i = 0; i < n; ++i) plastic[i] = bounds.at_cap(pressure[static_cast<std::size_t>(i)]) ? 1 : 0;
  return plastic;
}

Eigen::ArrayXd plastic_displacement(std::span<const double> pressure, std::span<const double> gap,
                                    std::optional<double> hardness) {
  assert(pressure.size() == gap.size());
  const auto n = static_cast<Eigen::Index>(pressure.size());
  Eigen::ArrayXd displacement = Eigen::ArrayXd::Zero(n);
  if (!hardness) return displacement;
  const PressureBounds bounds = PressureBounds::capped_at(*hardness);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (bounds.at_cap(pressure[k])) displacement[i] = std::max(-gap[k], 0.0);
  }
  return displacement;
}

}  // namespace halfspace::solvers
