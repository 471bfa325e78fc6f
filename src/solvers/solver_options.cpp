#include "halfspace/solvers/solver_options.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <cmath>
#include <utility>

#include "halfspace/solvers/block_deflation.hpp"

namespace halfspace::solvers {
namespace {

constexpr std::array<std::pair<SolverType, std::string_view>, 5> kSolverNames{{
    {SolverType::pk_multilevel, "pk-multilevel"},
    {SolverType::pk_fourier, "pk-fourier"},
    {SolverType::pk, "pk"},
    {SolverType::lemke, "lemke"},
    {SolverType::lcpquad, "lcpquad"},
}};

constexpr std::array<std::pair<Precision, std::string_view>, 2> kPrecisionNames{{
    {Precision::double_precision, "double"},
    {Precision::mixed, "mixed"},
}};

constexpr std::array<std::pair<MultilevelOptions::ActiveSet, std::string_view>, 3> kActiveSetNames{{
    {MultilevelOptions::ActiveSet::on, "on"},
    {MultilevelOptions::ActiveSet::off, "off"},
    {MultilevelOptions::ActiveSet::automatic, "automatic"},
}};

constexpr std::array<std::pair<DeflationOptions::Mode, std::string_view>, 3> kDeflationModeNames{{
    {DeflationOptions::Mode::off, "off"},
    {DeflationOptions::Mode::on, "on"},
    {DeflationOptions::Mode::automatic, "automatic"},
}};

std::string text(double value) {
  return format_number(value);
}

// The name of `value` in `names`.
template <class Value, std::size_t N>
std::string_view name_of(const std::array<std::pair<Value, std::string_view>, N>& names, Value value) {
  for (const auto& [known, name] : names) {
    if (known == value) return name;
  }
  return "unknown";
}

// The value named `name` in `names`; else SolverOptionError naming `option`
// and listing the allowed names after `allowed`.
template <class Value, std::size_t N>
Value parse(const std::array<std::pair<Value, std::string_view>, N>& names, std::string_view name,
            std::string_view option, std::string_view allowed) {
  std::vector<std::string_view> all;
  for (const auto& [value, known] : names) {
    if (known == name) return value;
    all.push_back(known);
  }
  throw SolverOptionError(std::string(option), std::string(name),
                          fmt::format("is invalid: {} {}", allowed, fmt::join(all, ", ")));
}

}  // namespace

std::string_view to_string(SolverType type) {
  return name_of(kSolverNames, type);
}

SolverType parse_solver_type(std::string_view name) {
  return parse(kSolverNames, name, "solver", "the solver must be one of");
}

std::string_view to_string(Precision precision) {
  return name_of(kPrecisionNames, precision);
}

Precision parse_precision(std::string_view name) {
  return parse(kPrecisionNames, name, "precision", "the precision must be one of");
}

std::string_view to_string(MultilevelOptions::ActiveSet mode) {
  return name_of(kActiveSetNames, mode);
}

MultilevelOptions::ActiveSet parse_active_set(std::string_view name) {
  return parse(kActiveSetNames, name, "multilevel.active_set", "allowed values are");
}

std::vector<SolverType> solver_types() {
  std::vector<SolverType> types;
  for (const auto& [type, name] : kSolverNames) types.push_back(type);
  return types;
}

bool uses_fft(SolverType type) {
  return type == SolverType::pk_multilevel || type == SolverType::pk_fourier || type == SolverType::pk;
}

std::string_view to_string(DeflationOptions::Mode mode) {
  return name_of(kDeflationModeNames, mode);
}

bool DeflationOptions::automatic_applies(const Grid& grid) const {
  return grid.size() >= kAutomaticFromCells && BlockDeflation::covers(grid, block);
}

bool DeflationOptions::automatic_applies_with_active_set(const Grid& grid) const {
  return grid.size() >= kAutomaticWithActiveSetFromCells && BlockDeflation::covers(grid, block);
}

bool MultilevelOptions::active_set_applies(const Grid& grid, bool capped, bool coated) const {
  if (active_set == ActiveSet::off || grid.dimension() != 2 || capped) return false;
  return active_set == ActiveSet::on || (!coated && grid.periodic() && grid.size() >= kActiveSetAutomaticFromCells);
}

void MultilevelOptions::validate() const {
  if (!(coarse_tolerance > 0.0 && coarse_tolerance < 1.0)) {
    throw SolverOptionError("multilevel.coarse_tolerance", text(coarse_tolerance),
                            "is invalid: allowed range is (0, 1)");
  }
  if (min_cells_per_axis < 2) {
    throw SolverOptionError("multilevel.min_cells_per_axis", fmt::format("{}", min_cells_per_axis),
                            "is invalid: must be at least 2");
  }
  if (!(warm_start_max_load_ratio >= 1.0)) {
    throw SolverOptionError("multilevel.warm_start_max_load_ratio", text(warm_start_max_load_ratio),
                            "is invalid: must be at least 1");
  }
  active_set_options.validate();
}

void SolverOptions::validate() const {
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw SolverOptionError("tolerance", text(tolerance), "is invalid: the tolerance must be in (0, 1)");
  }
  if (max_iterations) {
    if (*max_iterations < 1) {
      throw SolverOptionError("max_iterations", fmt::format("{}", *max_iterations), "is invalid: must be at least 1");
    }
    if (type == SolverType::lcpquad) {
      // Silently ignoring the limit would let a user believe it applied.
      throw SolverOptionError("max_iterations", fmt::format("{}", *max_iterations),
                              "does not apply to solver 'lcpquad': ALGLIB's dense interior-point method has no "
                              "iteration limit (it stops at its own tolerance); leave it unset, or use solver "
                              "'lemke', whose pivots it limits");
    }
  }
  multilevel.validate();
  deflation.validate();
  // The law's own values are checked by every solver when it is made
  // (ContactSolver); here only whether this solver takes it.
  if (interface_law.hardness && type == SolverType::lemke) {
    throw SolverOptionError("hardness", text(*interface_law.hardness),
                            "does not apply to solver 'lemke': Lemke's pivoting solves the plain LCP without an "
                            "upper bound on the pressure; use 'lcpquad' for a dense solution with a hardness cap");
  }
  if (deflation.mode == DeflationOptions::Mode::on && type != SolverType::pk_fourier &&
      type != SolverType::pk_multilevel) {
    throw SolverOptionError(
        "deflation.mode", std::string(to_string(deflation.mode)),
        fmt::format("does not apply to solver '{}': deflation needs pk-fourier or pk-multilevel", to_string(type)));
  }
  if (precision == Precision::mixed && !uses_fft(type)) {
    throw SolverOptionError("precision", "mixed",
                            fmt::format("does not apply to solver '{}': the dense path assembles and solves in double "
                                        "only; use precision double, or a Polonsky-Keer solver (pk, pk-fourier, "
                                        "pk-multilevel) for mixed",
                                        to_string(type)));
  }
  if (precision == Precision::mixed && adhesion) {
    throw SolverOptionError("precision", "mixed",
                            "does not apply to the adhesive solver (its energy minimisation runs in double only); "
                            "use precision double");
  }
  if (adhesion) {
    // The law's own rules, restated with the option's name here.
    const AdhesionLaw& law = adhesion->law;
    if (!(std::isfinite(law.work) && law.work > 0.0)) {
      throw SolverOptionError("adhesion.work", text(law.work), "is invalid: must be positive and finite (J/m^2)");
    }
    if (!(std::isfinite(law.range) && law.range > 0.0)) {
      throw SolverOptionError("adhesion.range", text(law.range), "is invalid: must be positive and finite (m)");
    }
    law.validate();
    if (!(adhesion->tolerance > 0.0 && adhesion->tolerance < 1.0)) {
      throw SolverOptionError("adhesion.tolerance", text(adhesion->tolerance),
                              "is invalid: the tolerance must be in (0, 1)");
    }
    if (deflation.mode == DeflationOptions::Mode::on) {
      throw SolverOptionError("deflation.mode", "on", "does not apply to the adhesive solver");
    }
  }
}

void SolverOptions::validate(const Grid& grid) const {
  validate();
  if (deflation.mode == DeflationOptions::Mode::on) BlockDeflation::require_covers(grid, deflation.block);
}

void SolverOptions::validate(const Grid& grid, const LayeredMaterial& /*coating*/) const {
  validate(grid);
  if (type == SolverType::lemke || type == SolverType::lcpquad) {
    throw SolverOptionError("type", std::string(to_string(type)),
                            "is invalid for a coated half-space (its dense matrix is the homogeneous one): allowed "
                            "are pk, pk-fourier and pk-multilevel");
  }
}

}  // namespace halfspace::solvers
